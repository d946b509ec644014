`resetall
`default_nettype none
// Median filter stage (docs/semantics.md, section 6): the stream's word of each slot (the invalid
// word outside the image) enters an M x M window; its centre, RM rows and RM slots behind, gets
// the median of the window's valid words (fpstereo_median_select, 3 * WORD_W steps), and leaves with
// its position: out_event for each pixel of the frame's rows (EXTRA_ROWS more for gap
// interpolation), with its word. With P words a slot (the core in strips, docs/ppc-hardware.md)
// the window is COLS columns wide and its P medians are those of the slot CENTRE_LAG slots behind
// (as fpstereo_front_end's windows), the slot's words in bits q * (DISP_W + 1) of the ports.
module fpstereo_median #(
  parameter M = 5,
  parameter ROW_SLOTS = 64,
  parameter DISP_W = 5,
  parameter EXTRA_ROWS = 0,
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter SIGNED_Y_W = 8,
  parameter P = 1,
  parameter CENTRE_LAG = (M / 2 + P - 1) / P,
  parameter COLS = P * (1 + CENTRE_LAG) + M / 2
) (
  input  wire             clk,
  input  wire             restart,
  input  wire             adv,
  input  wire [X_W-1:0]   frame_width,
  input  wire [Y_W-1:0]   frame_height,
  // back-to-back frames: once wrapped, the rows above row 0 are the previous frame's
  input  wire             wrapped,
  input  wire             in_done,
  input  wire [X_W-1:0]   in_x,
  input  wire [Y_W-1:0]   in_y,
  input  wire [P*(DISP_W+1)-1:0] in_word,
  output reg              out_event,
  output reg  [X_W-1:0]   out_x,
  output reg  [Y_W-1:0]   out_y,
  output reg  [P*(DISP_W+1)-1:0] out_word
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (M < 3 || M % 2 == 0) begin : invalid_M
      fpstereo_invalid_parameters_median_M_is_not_odd_and_at_least_3 failed ();
    end
    if (SIGNED_Y_W < Y_W + 2) begin : invalid_SIGNED_Y_W
      fpstereo_invalid_parameters_median_SIGNED_Y_W_below_Y_W_plus_2 failed ();
    end
    if ((P != 1 && P != 2 && P != 4) || ROW_SLOTS * P > (1 << X_W) || CENTRE_LAG * P < M / 2 ||
        COLS != P * (1 + CENTRE_LAG) + M / 2) begin : invalid_P
      fpstereo_invalid_parameters_median_P_not_1_2_4_or_X_W_CENTRE_LAG_COLS_wrong failed ();
    end
  endgenerate
  localparam RM = M / 2;
  localparam WORD_W = DISP_W + 1;
  localparam integer LAST_SLOT_I = ROW_SLOTS - 1;
  localparam [X_W-1:0] LAST_SLOT = LAST_SLOT_I[X_W-1:0];
  wire [X_W:0] width_x = {1'b0, frame_width};
  wire signed [SIGNED_Y_W-1:0] height_y = $signed({2'b00, frame_height});
  wire shift = adv && in_done;  // a slot's word (or the invalid word outside the image)
  wire [X_W-1:0] next_col = (in_x == LAST_SLOT) ? {X_W{1'b0}} : in_x + 1'b1;
  wire [M*COLS*WORD_W-1:0] window;
  fpstereo_window #(.N(M), .WORD_W(WORD_W), .P(P), .COLS(COLS), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) line_window (
    .clk(clk), .shift(shift), .col(in_x), .next_col(next_col), .word(in_word), .window(window));
  wire [X_W-1:0] centre_x;
  wire signed [SIGNED_Y_W-1:0] centre_y;
  /* verilator lint_off UNUSEDSIGNAL */  // the median needs no RAM slot
  wire centre_slot;
  wire signed [SIGNED_Y_W-1:0] newest_y;
  /* verilator lint_on UNUSEDSIGNAL */
  fpstereo_window_centre #(.LAG(CENTRE_LAG), .ROW_LAG(RM), .ROW_SLOTS(ROW_SLOTS), .X_W(X_W), .SIGNED_Y_W(SIGNED_Y_W), .ROWS(1), .SLOT_W(1)) centre (
    .x(in_x), .y($signed({2'b00, in_y})), .slot(1'b0), .wrapped(wrapped), .height(height_y), .centre_x(centre_x),
    .centre_y(centre_y), .centre_slot(centre_slot), .row_y(newest_y));
  reg [X_W-1:0] median_x;
  reg signed [SIGNED_Y_W-1:0] median_y;
  reg           fresh;     // high in the step after a shift: one result per slot
  always @(posedge clk)
    if (restart) fresh <= 1'b0;
    else if (adv) fresh <= in_done;
  always @(posedge clk)
    if (shift) begin
      median_x <= centre_x;
      median_y <= centre_y;
    end
  // The P windows' rows' and columns' bounds side by side, from the slot's first pixel; the
  // columns' from a counter of the slots left in the width (no restart: the centres before its
  // first return to slot 0 lie above the image).
  localparam integer LAG_I = CENTRE_LAG;
  localparam [X_W-1:0] LAG_X = LAG_I[X_W-1:0];
  wire [M-1:0] row_valid;
  wire [M+P-2:0] col_valid;
  /* verilator lint_off UNUSEDSIGNAL */  // the columns' bounds come from fpstereo_slot_columns
  wire [M-1:0] unused_columns;
  /* verilator lint_on UNUSEDSIGNAL */
  fpstereo_window_bounds #(.SIDE(M), .X_W(X_W), .SIGNED_Y_W(SIGNED_Y_W)) bounds (
    .clk(clk), .x(median_x), .y(median_y), .width(width_x), .height(height_y), .row_valid(row_valid),
    .col_valid(unused_columns));
  fpstereo_slot_columns #(.COLS(M + P - 1), .LAG(RM), .P(P), .X_W(X_W)) columns (
    .clk(clk), .restart(1'b0), .shift(shift), .to_first(in_x == LAG_X), .frame_width(frame_width), .x(median_x),
    .col_valid(col_valid));
  wire [P*WORD_W-1:0] selected;
  genvar q;
  generate
    for (q = 0; q < P; q = q + 1) begin : pixel
      wire [M*M*WORD_W-1:0] words;
      fpstereo_window_cut #(.N(M), .COLS(COLS), .WORD_W(WORD_W), .Q(q)) cut (.array(window), .window(words));
      fpstereo_median_select #(.M(M), .WORD_W(WORD_W)) select (
        .clk(clk), .en(adv), .window(words), .row_valid(row_valid), .col_valid(col_valid[q +: M]),
        .median(selected[q*WORD_W +: WORD_W]));
    end
  endgenerate
  // The centre's coordinates travel as long as the selection takes.
  // (the rows with events, a register: the frame size holds while a frame runs)
  reg signed [SIGNED_Y_W-1:0] event_rows_y;
  always @(posedge clk) event_rows_y <= height_y + EXTRA_ROWS;
  // (column RM is the slot's first pixel)
  wire in_image = col_valid[RM] && median_y >= 0 && median_y < event_rows_y;
  /* verilator lint_off UNUSEDSIGNAL */  // the top bits are 0 whenever in_image
  wire [SIGNED_Y_W-1:0] median_row = median_y;
  /* verilator lint_on UNUSEDSIGNAL */
  wire           done_m;
  wire [X_W-1:0] x_m;
  wire [Y_W-1:0] y_m;
  fpstereo_delay #(.WIDTH(1 + X_W + Y_W), .DEPTH(3 * (DISP_W + 1)), .RESET(1)) median_delay (
    .clk(clk), .rst(restart), .en(adv), .in({fresh && in_image, median_x, median_row[Y_W-1:0]}),
    .out({done_m, x_m, y_m}));
  always @(posedge clk)
    if (restart) out_event <= 1'b0;
    else if (adv) out_event <= done_m;
  // The pixel's position and its median, without a reset (their enable is adv alone: logic
  // depth).
  always @(posedge clk)
    if (adv) begin
      out_x <= x_m;
      out_y <= y_m;
      out_word <= selected;
    end
endmodule
`resetall
