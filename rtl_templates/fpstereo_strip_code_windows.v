`resetall
`default_nettype none
// SHD's code windows in strips (docs/ppc-hardware.md, "SHD in strips"): the transform's P census
// codes of each slot (its position transform_*) enter SHD_K x SHD_K windows of codes, base and
// match, P columns a shift, as fpstereo_front_end's windows take pixels; fpstereo_strip_window_cost
// sums the Hamming distances over them. The arrays are COLS columns wide: window q is columns
// q .. q + SHD_K - 1, centred on the slot CODE_LAG slots and SHD_K / 2 rows behind the entering
// codes. row_valid / col_valid / newest_row_valid are the bounds of the windows the arrays hold
// (zero outside the image, docs/semantics.md, section 2), and taken_* the position of the windows
// of the previous shift (what the cost stage takes at the next): in_frame where its centre row
// and its slot's first column lie in the frame. With the fused cost (FUSED) the pixels' features
// (fpstereo_fused_features, timed as the codes) enter windows of their own beside them, of which
// the cost stage reads the centre row.
module fpstereo_strip_code_windows #(
  parameter P = 2,
  parameter SHD_K = 3,
  parameter CODE_W = 24,
  parameter ROW_SLOTS = 64,
  // the row slots of the strips' RAMs: a centre's is its row modulo ROWS
  parameter ROWS = 2,
  parameter ROW_W = 1,
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter SIGNED_Y_W = 8,
  parameter CODE_LAG = (SHD_K / 2 + P - 1) / P,
  parameter COLS = P * (1 + CODE_LAG) + SHD_K / 2,
  parameter FUSED = 0,
  parameter FEATURE_W = 8
) (
  input  wire                   clk,
  input  wire                   restart,
  input  wire                   shift,
  input  wire [X_W-1:0]         frame_width,
  input  wire [Y_W-1:0]         frame_height,
  // back-to-back frames: once wrapped, the rows above row 0 are the previous frame's
  input  wire                   wrapped,
  input  wire [P*CODE_W-1:0]    code_base,
  input  wire [P*CODE_W-1:0]    code_match,
  /* verilator lint_off UNUSEDSIGNAL */  // the fused cost's only
  input  wire [P*FEATURE_W-1:0] feature_base,
  input  wire [P*FEATURE_W-1:0] feature_match,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [X_W-1:0]         transform_x,
  input  wire signed [SIGNED_Y_W-1:0] transform_y,
  input  wire [ROW_W-1:0]       transform_slot,
  output wire [SHD_K*COLS*CODE_W-1:0] codes_left,
  output wire [SHD_K*COLS*CODE_W-1:0] codes_right,
  output wire [SHD_K*COLS*FEATURE_W-1:0] features_left,
  output wire [SHD_K*COLS*FEATURE_W-1:0] features_right,
  output wire [SHD_K-1:0]       row_valid,
  output wire [SHD_K+P-2:0]     col_valid,
  output wire [SHD_K-1:0]       newest_row_valid,
  output reg                    taken_in_frame,
  output reg  [X_W-1:0]         taken_x,
  output reg  [ROW_W-1:0]       taken_slot
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if ((P != 2 && P != 4) || SHD_K < 3 || SHD_K % 2 == 0 || CODE_LAG * P < SHD_K / 2 ||
        COLS != P * (1 + CODE_LAG) + SHD_K / 2 || SIGNED_Y_W < Y_W + 2) begin : invalid
      fpstereo_invalid_parameters_strip_code_windows_P_SHD_K_CODE_LAG_COLS_or_SIGNED_Y_W failed ();
    end
  endgenerate
  localparam RS = SHD_K / 2;
  localparam LOG_P = $clog2(P);
  localparam integer LAST_SLOT_I = ROW_SLOTS - 1;
  localparam [X_W-1:0] LAST_SLOT = LAST_SLOT_I[X_W-1:0];
  localparam integer LAG_I = CODE_LAG;
  localparam [X_W-1:0] LAG_X = LAG_I[X_W-1:0];
  wire [X_W:0] width_x = {1'b0, frame_width};
  wire signed [SIGNED_Y_W-1:0] height_y = $signed({2'b00, frame_height});
  wire [X_W-1:0] next_col = (transform_x == LAST_SLOT) ? {X_W{1'b0}} : transform_x + 1'b1;
  fpstereo_window #(.N(SHD_K), .WORD_W(CODE_W), .P(P), .COLS(COLS), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) base_codes (
    .clk(clk), .shift(shift), .col(transform_x), .next_col(next_col), .word(code_base), .window(codes_left));
  fpstereo_window #(.N(SHD_K), .WORD_W(CODE_W), .P(P), .COLS(COLS), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) match_codes (
    .clk(clk), .shift(shift), .col(transform_x), .next_col(next_col), .word(code_match), .window(codes_right));
  generate
    if (FUSED != 0) begin : with_features
      fpstereo_window #(.N(SHD_K), .WORD_W(FEATURE_W), .P(P), .COLS(COLS), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) base_features (
        .clk(clk), .shift(shift), .col(transform_x), .next_col(next_col), .word(feature_base), .window(features_left));
      fpstereo_window #(.N(SHD_K), .WORD_W(FEATURE_W), .P(P), .COLS(COLS), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) match_features (
        .clk(clk), .shift(shift), .col(transform_x), .next_col(next_col), .word(feature_match), .window(features_right));
    end else begin : codes_only
      assign features_left = {SHD_K*COLS*FEATURE_W{1'b0}};
      assign features_right = {SHD_K*COLS*FEATURE_W{1'b0}};
    end
  endgenerate

  // The centre of the windows that form in this shift, registered with them; the entering
  // columns' row and whether their slot lies in the width (the slots in the width a register: the
  // frame size holds while a frame runs).
  wire [X_W-1:0] centre_x;
  wire signed [SIGNED_Y_W-1:0] centre_y, newest_y;
  wire [ROW_W-1:0] centre_slot;
  fpstereo_window_centre #(.LAG(CODE_LAG), .ROW_LAG(RS), .ROW_SLOTS(ROW_SLOTS), .X_W(X_W), .SIGNED_Y_W(SIGNED_Y_W),
                           .ROWS(ROWS), .SLOT_W(ROW_W)) centre (
    .x(transform_x), .y(transform_y), .slot(transform_slot), .wrapped(wrapped), .height(height_y),
    .centre_x(centre_x), .centre_y(centre_y), .centre_slot(centre_slot), .row_y(newest_y));
  reg [X_W-1:0] width_slots;
  always @(posedge clk) width_slots <= frame_width >> LOG_P;
  reg [X_W-1:0] codes_x;
  reg signed [SIGNED_Y_W-1:0] codes_y, codes_newest_y;
  reg [ROW_W-1:0] codes_slot;
  reg codes_newest_in_row;
  always @(posedge clk)
    if (shift) begin
      codes_x <= centre_x;
      codes_y <= centre_y;
      codes_slot <= centre_slot;
      codes_newest_y <= newest_y;
      codes_newest_in_row <= transform_x < width_slots;
    end
  // The bounds of the windows the arrays hold: rows from the centre row, the P windows' columns
  // from a counter of the slots left in the width (fpstereo_slot_columns; no restart: the centres
  // before its first return to slot 0 lie above the image).
  /* verilator lint_off UNUSEDSIGNAL */  // the columns' bounds come from fpstereo_slot_columns
  wire [SHD_K-1:0] unused_columns, newest_unused_columns;
  /* verilator lint_on UNUSEDSIGNAL */
  wire [SHD_K-1:0] newest_rows;
  fpstereo_window_bounds #(.SIDE(SHD_K), .X_W(X_W), .SIGNED_Y_W(SIGNED_Y_W)) bounds (
    .clk(clk), .x(codes_x), .y(codes_y), .width(width_x), .height(height_y), .row_valid(row_valid),
    .col_valid(unused_columns));
  fpstereo_window_bounds #(.SIDE(SHD_K), .X_W(X_W), .SIGNED_Y_W(SIGNED_Y_W)) newest_bounds (
    .clk(clk), .x(codes_x), .y(codes_newest_y), .width(width_x), .height(height_y), .row_valid(newest_rows),
    .col_valid(newest_unused_columns));
  assign newest_row_valid = codes_newest_in_row ? newest_rows : {SHD_K{1'b0}};
  fpstereo_slot_columns #(.COLS(SHD_K + P - 1), .LAG(RS), .P(P), .X_W(X_W)) columns (
    .clk(clk), .restart(1'b0), .shift(shift), .to_first(transform_x == LAG_X), .frame_width(frame_width),
    .x(codes_x), .col_valid(col_valid));

  // The position of the windows a shift later. For three shifts after a restart it is not a
  // window's of this frame (the transform's position is the front end's registers of before the
  // restart for two), so it is not in the frame.
  reg [2:0] stale;
  always @(posedge clk)
    if (restart) stale <= 3'b111;
    else if (shift) stale <= {1'b0, stale[2:1]};
  always @(posedge clk)
    if (restart) taken_in_frame <= 1'b0;
    else if (shift) taken_in_frame <= !stale[0] && row_valid[RS] && col_valid[RS];
  always @(posedge clk)
    if (shift) begin
      taken_x <= codes_x;
      taken_slot <= codes_slot;
    end
endmodule
`resetall
