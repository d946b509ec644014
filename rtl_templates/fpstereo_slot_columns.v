`resetall
`default_nettype none
// Which columns of the P windows centred on a slot's P pixels lie inside the frame's width: column
// v is image column x * P + v - LAG, for the slot x (the width a multiple of P). Each bound is a
// compare of a counter with a constant, not of two counters: abc9 maps a compare of two 12-bit
// counters as a ripple of LUT5s that the project's logic depth counts as 7 (docs/timing.md, large
// frames). x + v - LAG >= 0 is x >= ceil((LAG - v) / P), and x * P + v - LAG < width is slots_left
// >= floor((v - LAG) / P), where slots_left = width / P - 1 - x is a counter of its own: it
// follows the shifts that move x, back to width / P - 1 with the one that takes x to slot 0
// (`to_first`) and one down with every other, as x counts up. A restart sets it for x = START;
// without one it is right from the first return to slot 0 on.
module fpstereo_slot_columns #(
  parameter COLS = 5,
  parameter LAG = 2,
  parameter P = 1,
  parameter X_W = 7,
  parameter START = 0
) (
  input  wire            clk,
  input  wire            restart,
  input  wire            shift,
  input  wire            to_first,
  input  wire [X_W-1:0]  frame_width,
  // the slot, a register that moves with the shifts
  input  wire [X_W-1:0]  x,
  output wire [COLS-1:0] col_valid
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if ((P != 1 && P != 2 && P != 4) || COLS < 1 || LAG < 0 || LAG >= COLS || START < 0 ||
        START >= (1 << X_W)) begin : invalid
      fpstereo_invalid_parameters_slot_columns_P_LAG_or_START_out_of_range failed ();
    end
  endgenerate
  localparam LOG_P = $clog2(P);
  // slots_left lies between -2^X_W and 2^X_W
  localparam LEFT_W = X_W + 2;
  localparam integer START_LEFT_I = START + 1;
  localparam [LEFT_W-1:0] START_LEFT = START_LEFT_I[LEFT_W-1:0];
  wire [LEFT_W-1:0] width_slots = {2'b00, frame_width >> LOG_P};
  // (a register: the frame size holds while a frame runs)
  reg  signed [LEFT_W-1:0] width_slots_left;
  always @(posedge clk) width_slots_left <= $signed(width_slots - 1'b1);
  reg  signed [LEFT_W-1:0] slots_left;
  always @(posedge clk)
    if (restart) slots_left <= $signed(width_slots - START_LEFT);
    else if (shift) slots_left <= to_first ? width_slots_left : slots_left - 1'b1;
  genvar v;
  generate
    for (v = 0; v < COLS; v = v + 1) begin : column
      // floor((v - LAG) / P) and ceil((LAG - v) / P) as integers of either sign
      localparam integer ABOVE = v - LAG >= 0 ? (v - LAG) / P : -((LAG - v + P - 1) / P);
      localparam integer FIRST = LAG - v > 0 ? (LAG - v + P - 1) / P : 0;
      localparam signed [LEFT_W-1:0] ABOVE_LEFT = ABOVE[LEFT_W-1:0];
      localparam [X_W-1:0] FIRST_X = FIRST[X_W-1:0];
      if (FIRST != 0) begin : left_edge
        assign col_valid[v] = x >= FIRST_X && slots_left >= ABOVE_LEFT;
      end else begin : inside_left
        assign col_valid[v] = slots_left >= ABOVE_LEFT;
      end
    end
  endgenerate
endmodule
`resetall
