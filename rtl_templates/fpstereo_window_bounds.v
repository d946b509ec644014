`resetall
`default_nettype none
// Which rows and columns of a SIDE x SIDE window centred on (x, y) lie inside the width x height
// image (docs/semantics.md, section 1: outside, a window reads zeros).
module fpstereo_window_bounds #(
  parameter SIDE = 5,
  parameter X_W = 7,
  // signed row width
  parameter YS_W = 8
) (
  input  wire [X_W-1:0]         x,
  input  wire signed [YS_W-1:0] y,
  input  wire [X_W:0]           width,
  input  wire signed [YS_W-1:0] height,
  output wire [SIDE-1:0]        row_valid,
  output wire [SIDE-1:0]        col_valid
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (SIDE < 1 || SIDE % 2 == 0) begin : invalid
      fpstereo_invalid_parameters_window_bounds_SIDE_is_not_odd failed ();
    end
  endgenerate
  localparam LAG = SIDE / 2;
  localparam [X_W:0] LAG_X = LAG;
  localparam signed [YS_W-1:0] LAG_Y = LAG;

  genvar v;
  generate
    for (v = 0; v < SIDE; v = v + 1) begin : position
      localparam [X_W:0] V_X = v;
      localparam signed [YS_W-1:0] V_Y = v;
      wire [X_W:0] column = {1'b0, x} + V_X;  // image column + LAG
      wire signed [YS_W-1:0] row = y + V_Y;   // image row + LAG
      assign col_valid[v] = column >= LAG_X && column < width + LAG_X;
      assign row_valid[v] = row >= LAG_Y && row < height + LAG_Y;
    end
  endgenerate
endmodule
`resetall
