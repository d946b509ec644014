`resetall
`default_nettype none
// The centre of the window that forms when the word of slot x of row-time y enters it: ROW_LAG rows
// and LAG slots behind (ROW_LAG = LAG but with several pixels a slot), back into the previous
// row-time near a row's start (docs/architecture.md).
// Rows are signed: a centre may lie above the image. Once the rows have wrapped (`wrapped`: an
// earlier frame's rows came before these, docs/architecture.md, "Back-to-back frames"), a row
// above is the previous frame's, `height` rows further on. The centre's row modulo ROWS (its slot
// in a ROWS-row RAM) follows from the entering row's slot with small numbers only (a wide modulo
// would be slow logic). row_y is the centre row of the entering column (no borrow).
module fpstereo_window_centre #(
  parameter LAG = 2,
  parameter ROW_LAG = LAG,
  parameter ROW_SLOTS = 64,
  parameter X_W = 7,
  // signed row width
  parameter SIGNED_Y_W = 8,
  // rows of the RAM the slots index, and the slot width
  parameter ROWS = 2,
  parameter SLOT_W = 1
) (
  input  wire [X_W-1:0]         x,
  input  wire signed [SIGNED_Y_W-1:0] y,
  input  wire [SLOT_W-1:0]      slot,
  input  wire                   wrapped,
  input  wire signed [SIGNED_Y_W-1:0] height,
  output wire [X_W-1:0]         centre_x,
  output wire signed [SIGNED_Y_W-1:0] centre_y,
  output wire [SLOT_W-1:0]      centre_slot,
  output wire signed [SIGNED_Y_W-1:0] row_y
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (LAG < 0 || LAG >= ROW_SLOTS) begin : invalid_LAG
      fpstereo_invalid_parameters_window_centre_LAG_is_not_within_a_row_time failed ();
    end
    if (ROWS < 1 || ROWS > (1 << SLOT_W) || ROW_SLOTS - 1 >= (1 << X_W)) begin : invalid_widths
      fpstereo_invalid_parameters_window_centre_SLOT_W_or_X_W_too_narrow failed ();
    end
  endgenerate
  localparam integer LAG_I = LAG;
  localparam integer BACK_I = ROW_SLOTS - LAG;
  localparam [X_W-1:0] LAG_X = LAG_I[X_W-1:0];
  localparam [X_W-1:0] BACK = BACK_I[X_W-1:0];
  localparam integer ROW_LAG_I = ROW_LAG;
  localparam signed [SIGNED_Y_W-1:0] LAG_Y = ROW_LAG_I[SIGNED_Y_W-1:0];

  localparam integer SLOT_BIAS = ROWS * ((ROW_LAG + ROWS) / ROWS);  // a multiple of ROWS above ROW_LAG

  wire borrow = x < LAG_X;  // the centre lies in the previous row-time
  assign centre_x = borrow ? x + BACK : x - LAG_X;
  localparam signed [SIGNED_Y_W-1:0] LAG_PREV_Y = LAG_Y + 1;
  // Both rows and their wrapped forms in parallel, then chosen.
  wire signed [SIGNED_Y_W-1:0] lagged = y - LAG_Y, lagged_prev = y - LAG_PREV_Y;
  wire signed [SIGNED_Y_W-1:0] wrapped_row = y + (height - LAG_Y), wrapped_prev = y + (height - LAG_PREV_Y);
  assign row_y = wrapped && lagged < 0 ? wrapped_row : lagged;
  wire signed [SIGNED_Y_W-1:0] prev_y = wrapped && lagged_prev < 0 ? wrapped_prev : lagged_prev;
  assign centre_y = borrow ? prev_y : row_y;
  /* verilator lint_off WIDTH */  // a few bits of slot arithmetic against integer constants
  assign centre_slot = (slot + SLOT_BIAS - ROW_LAG - borrow) % ROWS;
  /* verilator lint_on WIDTH */
endmodule
`resetall
