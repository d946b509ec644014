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
// all ones (no sum reaches it). Latency: max(1, ceil(clog2(N) / LEVELS_PER_STAGE)).
module fpstereo_unique_tree #(
  parameter N = 8,
  parameter W = 10,
  parameter IDX_W = 3,
  parameter LEVELS_PER_STAGE = 3
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
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 1 || W < 1) begin : invalid_N
      fpstereo_invalid_parameters_unique_tree_N_or_W_below_1 failed ();
    end
    if (IDX_W < 1 || N - 1 >= (1 << IDX_W)) begin : invalid_IDX_W
      fpstereo_invalid_parameters_unique_tree_IDX_W_does_not_hold_N_minus_1 failed ();
    end
    if (LEVELS_PER_STAGE < 1) begin : invalid_LEVELS_PER_STAGE
      fpstereo_invalid_parameters_unique_tree_LEVELS_PER_STAGE_below_1 failed ();
    end
  endgenerate
  localparam LEVELS = (N > 1) ? $clog2(N) : 0;
  localparam NONE = {W{1'b1}};
  // One summary: {best, all, but_first, but_last, second} values, the index and two flags.
  localparam S_W = 5 * W + IDX_W + 2;

  genvar l, i;
  generate
    for (l = 0; l <= LEVELS; l = l + 1) begin : level
      localparam COUNT = (N + (1 << l) - 1) >> l;
      localparam PREV_COUNT = (N + (1 << l) / 2 - 1) / ((1 << l) / 2 > 0 ? (1 << l) / 2 : 1);
      localparam REGISTERED = (l == LEVELS) || (l > 0 && l % LEVELS_PER_STAGE == 0);
      wire [COUNT*S_W-1:0] s_d;
      wire [COUNT*S_W-1:0] s;
      for (i = 0; i < COUNT; i = i + 1) begin : node
        if (l == 0) begin : leaf
          wire [W-1:0] v = values[i*W +: W];
          wire [IDX_W-1:0] at = i;
          assign s_d[i*S_W +: S_W] = {v, v, NONE, NONE, NONE, at, 1'b1, 1'b1};
        end else if (2 * i + 1 < PREV_COUNT) begin : pair
          fpstereo_unique_join #(.W(W), .IDX_W(IDX_W)) join_ranges (
            .a(level[l-1].s[(2*i)*S_W +: S_W]), .b(level[l-1].s[(2*i+1)*S_W +: S_W]),
            .joined(s_d[i*S_W +: S_W]));
        end else begin : single
          assign s_d[i*S_W +: S_W] = level[l-1].s[(2*i)*S_W +: S_W];
        end
      end
      if (REGISTERED) begin : stage
        reg [COUNT*S_W-1:0] s_q;
        always @(posedge clk)
          if (en) s_q <= s_d;
        assign s = s_q;
      end else begin : wire_through
        assign s = s_d;
      end
    end
  endgenerate

  wire [S_W-1:0] root = level[LEVELS].s[S_W-1:0];
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
