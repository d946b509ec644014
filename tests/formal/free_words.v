`default_nettype none
// Free words for the position proofs (median_order_props): the median's word path, its window and
// its selection, stand-ins whose outputs the solver picks anew in every cycle. A position
// proven with them holds whatever the words are, and the solver need not carry the word path.
module fpstereo_window #(
  parameter N = 7,
  parameter WORD_W = 8,
  parameter P = 1,
  parameter COLS = N + P - 1,
  parameter ROW_SLOTS = 64,
  parameter ADDR_W = 6
) (
  input  wire                     clk,
  input  wire                     shift,
  input  wire [ADDR_W-1:0]        col,
  input  wire [ADDR_W-1:0]        next_col,
  input  wire [P*WORD_W-1:0]      word,
  output wire [N*COLS*WORD_W-1:0] window
);
  assign window = $anyseq;
endmodule

module fpstereo_median_select #(
  parameter M = 5,
  parameter WORD_W = 8
) (
  input  wire                  clk,
  input  wire                  en,
  input  wire [M*M*WORD_W-1:0] window,
  input  wire [M-1:0]          row_valid,
  input  wire [M-1:0]          col_valid,
  output wire [WORD_W-1:0]     median
);
  assign median = $anyseq;
endmodule
`resetall
