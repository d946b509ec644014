`resetall
`default_nettype none
// Which rows and columns of a SIDE x SIDE window centred on (x, y) lie inside the width x height
// image (docs/semantics.md, section 1: outside, a window reads zeros). COLS and COL_LAG widen the
// columns: column v is image column x + v - COL_LAG (the P windows of a front end that takes P
// pixels a slot, centred on x .. x + P - 1: COLS = SIDE + P - 1).
// The bounds' limits (the frame size plus each column's and row's offset) are registers: the frame
// size holds while a frame runs (the settings), so the compares with x and y start from registers
// and no adder lies on their paths (logic depth, docs/timing.md). They follow a new size a clock
// later, long before a frame's first window centre (R rows behind its input) lies in the image.
module fpstereo_window_bounds #(
  parameter SIDE = 5,
  parameter COLS = SIDE,
  parameter COL_LAG = SIDE / 2,
  parameter X_W = 7,
  // signed row width
  parameter SIGNED_Y_W = 8
) (
  input  wire                   clk,
  input  wire [X_W-1:0]         x,
  input  wire signed [SIGNED_Y_W-1:0] y,
  input  wire [X_W:0]           width,
  input  wire signed [SIGNED_Y_W-1:0] height,
  output wire [SIDE-1:0]        row_valid,
  output wire [COLS-1:0]        col_valid
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (SIDE < 1 || SIDE % 2 == 0) begin : invalid
      fpstereo_invalid_parameters_window_bounds_SIDE_is_not_odd failed ();
    end
    if (COLS < 1 || COL_LAG < 0 || COL_LAG >= COLS) begin : invalid_cols
      fpstereo_invalid_parameters_window_bounds_COL_LAG_outside_COLS failed ();
    end
  endgenerate
  localparam LAG = SIDE / 2;

  // Window column v is image column x + v - COL_LAG, inside where COL_LAG - v <= x < width +
  // COL_LAG - v (the limit, a register); row v likewise with LAG.
  genvar v;
  generate
    for (v = 0; v < COLS; v = v + 1) begin : column
      localparam signed [31:0] OFFSET = COL_LAG - v;
      localparam signed [X_W+2:0] OFFSET_X = OFFSET[X_W+2:0];
      wire signed [X_W+2:0] at = $signed({3'b000, x});
      reg signed [X_W+2:0] limit;
      always @(posedge clk) limit <= $signed({2'b00, width}) + OFFSET_X;
      assign col_valid[v] = at >= OFFSET_X && at < limit;
    end
    for (v = 0; v < SIDE; v = v + 1) begin : position
      localparam signed [31:0] OFFSET = LAG - v;
      localparam signed [SIGNED_Y_W:0] OFFSET_Y = OFFSET[SIGNED_Y_W:0];
      wire signed [SIGNED_Y_W:0]  row = $signed({y[SIGNED_Y_W-1], y});
      reg signed [SIGNED_Y_W:0] limit;
      always @(posedge clk) limit <= $signed({height[SIGNED_Y_W-1], height}) + OFFSET_Y;
      assign row_valid[v] = row >= OFFSET_Y && row < limit;
    end
  endgenerate
endmodule
`resetall
