`resetall
`default_nettype none
// Joins the winner-take-all summaries of two adjacent index ranges, A (lower) and B (higher), as
// fpstereo_unique_tree explains; packed as {best, all, but_first, but_last, second, index,
// first, last} with W-bit values and an IDX_W-bit index.
module fpstereo_unique_join #(
  parameter W = 10,
  parameter IDX_W = 3
) (
  input  wire [5*W+IDX_W+1:0] a,
  input  wire [5*W+IDX_W+1:0] b,
  output wire [5*W+IDX_W+1:0] joined
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (W < 1 || IDX_W < 1) begin : invalid
      fpstereo_invalid_parameters_unique_join_W_or_IDX_W_below_1 failed ();
    end
  endgenerate
  localparam S_W = 5 * W + IDX_W + 2;

  function [W-1:0] min2(input [W-1:0] x, input [W-1:0] y);
    min2 = y < x ? y : x;
  endfunction

  wire [W-1:0] a_best = a[S_W-1 -: W], a_all = a[S_W-W-1 -: W], a_but_first = a[S_W-2*W-1 -: W];
  wire [W-1:0] a_but_last = a[S_W-3*W-1 -: W], a_second = a[S_W-4*W-1 -: W];
  wire [IDX_W-1:0] a_index = a[IDX_W+1:2];
  wire a_first = a[1], a_last = a[0];
  wire [W-1:0] b_best = b[S_W-1 -: W], b_all = b[S_W-W-1 -: W], b_but_first = b[S_W-2*W-1 -: W];
  wire [W-1:0] b_but_last = b[S_W-3*W-1 -: W], b_second = b[S_W-4*W-1 -: W];
  wire [IDX_W-1:0] b_index = b[IDX_W+1:2];
  wire b_first = b[1], b_last = b[0];

  wire b_wins = b_best < a_best;  // ties keep the lower index
  wire [W-1:0] second = b_wins ? min2(b_second, b_first ? a_but_last : a_all)
                               : min2(a_second, a_last ? b_but_first : b_all);
  assign joined = {b_wins ? b_best : a_best, min2(a_all, b_all), min2(a_but_first, b_all),
                   min2(a_all, b_but_last), second, b_wins ? b_index : a_index,
                   !b_wins && a_first, b_wins && b_last};
endmodule
`resetall
