`resetall
`default_nettype none
// Which rows and columns of a SIDE x SIDE window centred on (x, y) lie inside the width x height
// image (docs/semantics.md, section 1: outside, a window reads zeros).
module fpstereo_window_bounds #(
  parameter SIDE = 5,
  parameter X_W = 7,
  // signed row width
  parameter SIGNED_Y_W = 8
) (
  input  wire [X_W-1:0]         x,
  input  wire signed [SIGNED_Y_W-1:0] y,
  input  wire [X_W:0]           width,
  input  wire signed [SIGNED_Y_W-1:0] height,
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

  // Window column v is image column x + v - LAG, inside where LAG - v <= x < width + LAG - v:
  // the constants go to the frame-size side, so that no adder lies on the path from x or y.
  genvar v;
  generate
    for (v = 0; v < SIDE; v = v + 1) begin : position
      localparam signed [31:0] OFFSET = LAG - v;
      localparam signed [X_W+2:0] OFFSET_X = OFFSET[X_W+2:0];
      localparam signed [SIGNED_Y_W:0] OFFSET_Y = OFFSET[SIGNED_Y_W:0];
      wire signed [X_W+2:0] column = $signed({3'b000, x});
      wire signed [SIGNED_Y_W:0]  row = $signed({y[SIGNED_Y_W-1], y});
      assign col_valid[v] = column >= OFFSET_X && column < $signed({2'b00, width}) + OFFSET_X;
      assign row_valid[v] = row >= OFFSET_Y && row < $signed({height[SIGNED_Y_W-1], height}) + OFFSET_Y;
    end
  endgenerate
endmodule
`resetall
