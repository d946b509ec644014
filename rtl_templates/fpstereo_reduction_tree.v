`resetall
`default_nettype none
// The skeleton of the pipelined selection trees (fpstereo_min_tree, fpstereo_unique_tree): N
// summaries of S_W bits joined pairwise over clog2(N) levels, a register after every
// LEVELS_PER_STAGE levels and at the output, so the delay per stage does not grow with N. The
// last summary of an odd level passes up alone. A summary is {value (W bits), index (IDX_W)} for
// the minimum (UNIQUE 0: the lower value wins, ties keep the lower range), or the uniqueness
// summary that fpstereo_unique_join joins (UNIQUE 1). Latency: max(1, ceil(clog2(N) /
// LEVELS_PER_STAGE)) steps, which the caller states in LAT (checked here, the one place of the
// formula in Verilog; gen/pipeline/plan.cpp, min_tree_latency, is its C++ counterpart).
module fpstereo_reduction_tree #(
  parameter N = 8,
  parameter W = 8,
  parameter IDX_W = 3,
  parameter UNIQUE = 0,
  parameter S_W = 11,
  parameter LEVELS_PER_STAGE = 3,
  parameter LAT = 1
) (
  input  wire           clk,
  input  wire           en,
  input  wire [N*S_W-1:0] leaves,
  output wire [S_W-1:0] root
);
  localparam LEVELS = (N > 1) ? $clog2(N) : 0;
  localparam STAGES = (LEVELS + LEVELS_PER_STAGE - 1) / (LEVELS_PER_STAGE > 0 ? LEVELS_PER_STAGE : 1);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 1 || W < 1) begin : invalid_N
      fpstereo_invalid_parameters_reduction_tree_N_or_W_below_1 failed ();
    end
    if (IDX_W < 1 || N - 1 >= (1 << IDX_W)) begin : invalid_IDX_W
      fpstereo_invalid_parameters_reduction_tree_IDX_W_does_not_hold_N_minus_1 failed ();
    end
    if (LEVELS_PER_STAGE < 1) begin : invalid_LEVELS_PER_STAGE
      fpstereo_invalid_parameters_reduction_tree_LEVELS_PER_STAGE_below_1 failed ();
    end
    if (LAT != (STAGES > 1 ? STAGES : 1)) begin : invalid_LAT
      fpstereo_invalid_parameters_reduction_tree_LAT_is_not_the_tree_latency failed ();
    end
  endgenerate

  genvar l, i;
  generate
    for (l = 0; l <= LEVELS; l = l + 1) begin : level
      // Level l holds ceil(N / 2^l) summaries.
      localparam COUNT = (N + (1 << l) - 1) >> l;
      localparam PREV_COUNT = (N + (1 << l) / 2 - 1) / ((1 << l) / 2 > 0 ? (1 << l) / 2 : 1);
      localparam REGISTERED = (l == LEVELS) || (l > 0 && l % LEVELS_PER_STAGE == 0);
      wire [COUNT*S_W-1:0] s_d;
      wire [COUNT*S_W-1:0] s;
      for (i = 0; i < COUNT; i = i + 1) begin : node
        if (l == 0) begin : leaf
          assign s_d[i*S_W +: S_W] = leaves[i*S_W +: S_W];
        end else if (2 * i + 1 < PREV_COUNT) begin : pair
          wire [S_W-1:0] a = level[l-1].s[(2*i)*S_W +: S_W];
          wire [S_W-1:0] b = level[l-1].s[(2*i+1)*S_W +: S_W];
          if (UNIQUE != 0) begin : unique_join
            fpstereo_unique_join #(.W(W), .IDX_W(IDX_W)) join_ranges (.a(a), .b(b), .joined(s_d[i*S_W +: S_W]));
          end else begin : min_join
            wire take_b = b[S_W-1 -: W] < a[S_W-1 -: W];
            assign s_d[i*S_W +: S_W] = take_b ? b : a;
          end
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

  assign root = level[LEVELS].s[S_W-1:0];
endmodule
`resetall
