`resetall
`default_nettype none
// Left-right check (docs/semantics.md, section 5), three steps: for the read stream's pixel x
// with index D, Dm of x' = x - MIN_DISP - D is looked up (fpstereo_match_lookup: the match side's
// completed pixels, with ROW_END, as LR1 does, its row ends), and the word becomes invalid where
// x' lies outside the image or |D - Dm(x')| > lr_threshold. The RAMs are read in the first step,
// Dm is registered in the second, the check's result in the third, and the stream leaves three
// steps later.
// With sub-pixel output (REFINED_W > 0) the read word carries the refined disparity above the
// whole D: the check uses D (semantics section 5), and the word that leaves is {invalid, refined}.
// With RIGHT_VIEW, Dm(x) itself leaves beside the checked word (right_word, the right view's
// disparity at x), from a second lookup.
module fpstereo_lr_check #(
  parameter ROW_SLOTS = 64,
  parameter G = 4,
  parameter UF = 8,
  parameter DMAX = 32,
  parameter DISP_W = 5,
  // bits of the refined disparity carried above D in the read word, 0 without sub-pixel output
  parameter REFINED_W = 0,
  parameter OUT_ROWS = 3,
  parameter OUT_ROW_W = 2,
  parameter DISP_AW = 8,
  // LR1: the row ends come from the row-end RAM
  parameter ROW_END = 1,
  parameter END_AW = 4,
  parameter RIGHT_VIEW = 0,
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter LANE_W = 3,
  parameter MIN_DISP = 0
) (
  input  wire                 clk,
  input  wire                 restart,
  input  wire                 adv,
  input  wire [X_W-1:0]       frame_width,
  input  wire [3:0]           lr_threshold,
  input  wire                 completed_we,
  input  wire [DISP_AW-1:0]   completed_waddr,
  input  wire [DISP_W-1:0]    completed_wdata,
  input  wire                 row_end_we,
  input  wire [END_AW-1:0]    row_end_waddr,
  input  wire [UF*DISP_W-1:0] row_end_wdata,
  // the read stream (fpstereo_disparity_reorder)
  input  wire                 read_done,
  input  wire                 read_event,
  input  wire [X_W-1:0]       read_x,
  input  wire [Y_W-1:0]       read_y,
  input  wire [OUT_ROW_W-1:0]   read_slot_row,
  input  wire [REFINED_W+DISP_W:0] read_word,
  output reg                  checked_done,
  output reg                  checked_event,
  output reg  [X_W-1:0]       checked_x,
  output reg  [Y_W-1:0]       checked_y,
  output wire [(REFINED_W > 0 ? REFINED_W : DISP_W):0] checked_word,
  // with RIGHT_VIEW: Dm(checked_x)
  output reg  [DISP_W-1:0]    right_word
);
  localparam IN_W = REFINED_W + DISP_W;  // the read word's bits under its invalid flag
  localparam OUT_W = REFINED_W > 0 ? REFINED_W : DISP_W;
  localparam [OUT_W:0] INVALID_WORD = {1'b1, {OUT_W{1'b0}}};
  // Disparities against positions and the threshold's 4 bits: the compares widen them.
  // verilator lint_off WIDTH
  wire [DISP_W-1:0] d = read_word[DISP_W-1:0];
  // x' = x - MIN_DISP - D as (x + AHEAD) - (D + BEHIND)
  localparam integer BEHIND = MIN_DISP > 0 ? MIN_DISP : 0;
  localparam integer AHEAD = MIN_DISP < 0 ? -MIN_DISP : 0;
  localparam P_W = X_W + 10;
  wire [P_W-1:0] x_ahead = read_x + AHEAD;
  wire [P_W-1:0] d_behind = d + BEHIND;
  wire outside = read_word[IN_W] || x_ahead < d_behind || (MIN_DISP < 0 && x_ahead >= d_behind + frame_width);
  wire [X_W-1:0] xm = x_ahead - d_behind;  // wraps where x' lies outside, and then goes unused
  wire [DISP_W-1:0] dm;
  fpstereo_match_lookup #(
    .ROW_SLOTS(ROW_SLOTS), .G(G), .UF(UF), .DMAX(DMAX), .DISP_W(DISP_W), .OUT_ROWS(OUT_ROWS),
    .OUT_ROW_W(OUT_ROW_W), .DISP_AW(DISP_AW), .ROW_END(ROW_END), .END_AW(END_AW), .X_W(X_W), .LANE_W(LANE_W),
    .MIN_DISP(MIN_DISP)
  ) lookup (
    .clk(clk), .adv(adv), .frame_width(frame_width), .completed_we(completed_we),
    .completed_waddr(completed_waddr), .completed_wdata(completed_wdata), .row_end_we(row_end_we),
    .row_end_waddr(row_end_waddr), .row_end_wdata(row_end_wdata), .slot_row(read_slot_row),
    .xm(xm), .dm(dm));
  reg [IN_W:0]   word_c;
  reg            outside_c, done_c, event_c;
  reg [X_W-1:0]  x_c;
  reg [Y_W-1:0]  y_c;
  always @(posedge clk)
    if (restart) begin
      done_c <= 1'b0;
      event_c <= 1'b0;
    end else if (adv) begin
      done_c <= read_done;
      event_c <= read_event;
      x_c <= read_x;
      y_c <= read_y;
      word_c <= read_word;
      outside_c <= outside;
    end
  // Second step: Dm registered with the stream, so that the RAM reads and the check lie in
  // different steps; third: the check's result registered with the stream.
  reg              done_q, event_q;
  reg [X_W-1:0]    x_q;
  reg [Y_W-1:0]    y_q;
  reg [DISP_W-1:0] dm_q;
  reg [IN_W:0]     word_q;
  reg [OUT_W:0]    checked_word_q;
  reg              outside_q;
  // |D - Dm| > threshold as Dm > D + threshold or Dm < D - threshold, with D's two bounds
  // registered in the second step: the third compares Dm with registers only (logic depth).
  wire [DISP_W-1:0] db_c = word_c[DISP_W-1:0];
  reg  signed [DISP_W+1:0] db_high_q, db_low_q;
  wire signed [DISP_W+1:0] dm_signed = $signed({2'b00, dm_q});
  always @(posedge clk)
    if (restart) begin
      done_q <= 1'b0;
      event_q <= 1'b0;
      checked_done <= 1'b0;
      checked_event <= 1'b0;
    end else if (adv) begin
      done_q <= done_c;
      event_q <= event_c;
      x_q <= x_c;
      y_q <= y_c;
      word_q <= word_c;
      outside_q <= outside_c;
      dm_q <= dm;
      db_high_q <= $signed({2'b00, db_c}) + $signed({2'b00, lr_threshold});
      db_low_q <= $signed({2'b00, db_c}) - $signed({2'b00, lr_threshold});
      checked_done <= done_q;
      checked_event <= event_q;
      checked_x <= x_q;
      checked_y <= y_q;
      checked_word_q <= (outside_q || dm_signed > db_high_q || dm_signed < db_low_q) ? INVALID_WORD : {word_q[IN_W], word_q[IN_W-1 -: OUT_W]};
    end
  // verilator lint_on WIDTH
  assign checked_word = checked_word_q;

  generate
    if (RIGHT_VIEW != 0) begin : right_view
      wire [DISP_W-1:0] dm_right;
      fpstereo_match_lookup #(
        .ROW_SLOTS(ROW_SLOTS), .G(G), .UF(UF), .DMAX(DMAX), .DISP_W(DISP_W), .OUT_ROWS(OUT_ROWS),
        .OUT_ROW_W(OUT_ROW_W), .DISP_AW(DISP_AW), .ROW_END(ROW_END), .END_AW(END_AW), .X_W(X_W), .LANE_W(LANE_W),
        .MIN_DISP(MIN_DISP)
      ) lookup (
        .clk(clk), .adv(adv), .frame_width(frame_width), .completed_we(completed_we),
        .completed_waddr(completed_waddr), .completed_wdata(completed_wdata), .row_end_we(row_end_we),
        .row_end_waddr(row_end_waddr), .row_end_wdata(row_end_wdata), .slot_row(read_slot_row),
        .xm(read_x), .dm(dm_right));
      reg [DISP_W-1:0] dm_right_q;
      always @(posedge clk)
        if (adv) begin
          dm_right_q <= dm_right;
          right_word <= dm_right_q;
        end
    end else begin : no_right_view
      always @(posedge clk) right_word <= {DISP_W{1'b0}};
    end
  endgenerate
endmodule
`resetall
