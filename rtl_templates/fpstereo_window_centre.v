`resetall
`default_nettype none
// The centre of the window that forms when the word of slot x of row-time y enters it: LAG rows
// and LAG slots behind, back into the previous row-time near a row's start (docs/architecture.md).
// Rows are signed: a centre may lie above the image.
module fpstereo_window_centre #(
  parameter LAG = 2,
  parameter ROW_SLOTS = 64,
  parameter X_W = 7,
  // signed row width
  parameter YS_W = 8
) (
  input  wire [X_W-1:0]         x,
  input  wire signed [YS_W-1:0] y,
  output wire [X_W-1:0]         centre_x,
  output wire signed [YS_W-1:0] centre_y,
  // the centre went back a row-time
  output wire                   borrow
);
  localparam integer LAG_I = LAG;
  localparam integer BACK_I = ROW_SLOTS - LAG;
  localparam [X_W-1:0] LAG_X = LAG_I[X_W-1:0];
  localparam [X_W-1:0] BACK = BACK_I[X_W-1:0];
  localparam signed [YS_W-1:0] LAG_Y = LAG_I[YS_W-1:0];

  assign borrow = x < LAG_X;
  assign centre_x = borrow ? x + BACK : x - LAG_X;
  assign centre_y = y - LAG_Y - (borrow ? 1 : 0);
endmodule
`resetall
