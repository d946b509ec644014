`resetall
`default_nettype none
// Winner-take-all with what the uniqueness test needs (docs/semantics.md, section 4): over N
// sums, the minimum and its index (ties keep the lower index) and the second minimum S2, the
// smallest sum at least two indices away from the winner. A pipelined tree, registered every
// LEVELS_PER_STAGE levels and at the output, of summaries of index ranges:
//   best, index        the range's minimum and where it is
//   first / last       whether that index is the range's first / last
//   all, but_first, but_last   minimum of the range, without its first, without its last element
//   second             minimum over the range's elements two or more away from the winner
// Joining a lower range A with a higher range B (fpstereo_unique_join): the winner is B's if
// B.best < A.best, else A's; of the other range, only its element next to the border can be near
// the winner, so
//   second = min(A.second, A.last ? B.but_first : B.all)   (A wins)
//          = min(B.second, B.first ? A.but_last : A.all)   (B wins).
// The same join continues across the groups of a pixel (fpstereo_sgm_core). A missing value is
// all ones (no sum reaches it). The tree is fpstereo_reduction_tree over these summaries.
// Latency LAT: max(1, ceil(clog2(N) / LEVELS_PER_STAGE)).
module fpstereo_unique_tree #(
  parameter N = 8,
  parameter W = 10,
  parameter IDX_W = 3,
  parameter LEVELS_PER_STAGE = 3,
  // the latency the caller plans with (fpstereo_reduction_tree checks it)
  parameter LAT = 1
) (
  input  wire             clk,
  input  wire             en,
  input  wire [N*W-1:0]   values,
  output wire [W-1:0]     best,
  output wire [IDX_W-1:0] index,
  output wire             first,
  output wire             last,
  output wire [W-1:0]     all,
  output wire [W-1:0]     but_first,
  output wire [W-1:0]     but_last,
  output wire [W-1:0]     second
);
  localparam NONE = {W{1'b1}};
  // One summary: {best, all, but_first, but_last, second} values, the index and two flags.
  localparam S_W = 5 * W + IDX_W + 2;
  wire [N*S_W-1:0] leaves;
  genvar i;
  generate
    for (i = 0; i < N; i = i + 1) begin : leaf
      wire [W-1:0] v = values[i*W +: W];
      wire [IDX_W-1:0] at = i;
      assign leaves[i*S_W +: S_W] = {v, v, NONE, NONE, NONE, at, 1'b1, 1'b1};
    end
  endgenerate
  wire [S_W-1:0] root;
  fpstereo_reduction_tree #(.N(N), .W(W), .IDX_W(IDX_W), .UNIQUE(1), .S_W(S_W),
                            .LEVELS_PER_STAGE(LEVELS_PER_STAGE), .LAT(LAT)) tree (
    .clk(clk), .en(en), .leaves(leaves), .root(root));
  assign best      = root[S_W-1 -: W];
  assign all       = root[S_W-W-1 -: W];
  assign but_first = root[S_W-2*W-1 -: W];
  assign but_last  = root[S_W-3*W-1 -: W];
  assign second    = root[S_W-4*W-1 -: W];
  assign index     = root[IDX_W+1:2];
  assign first     = root[1];
  assign last      = root[0];
endmodule
`resetall
