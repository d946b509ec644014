`resetall
`default_nettype none
// The sum of N unsigned values as a balanced tree of two-input adders: ceil(log2 N) adders
// deep, where a chain of additions would be N - 1 deep. Level v's nodes are IN_W + v bits wide
// (at most SUM_W), so no adder is wider than its operands need. The sum is taken modulo
// 2^SUM_W: the caller sizes SUM_W for its largest sum. Combinational, or with the partial sums
// of level REGISTER_LEVEL registered (latency 1), which splits the tree's logic from whatever
// computes the values.
module fpstereo_sum_tree #(
  parameter N = 7,
  parameter IN_W = 8,
  parameter SUM_W = 11,
  // 0: combinational; 1 .. ceil(log2 N): that level's partial sums are registered
  parameter REGISTER_LEVEL = 0
) (
  /* verilator lint_off UNUSEDSIGNAL */  // with REGISTER_LEVEL 0
  input  wire              clk,
  input  wire              en,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [N*IN_W-1:0] values,
  output wire [SUM_W-1:0]  sum
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 1 || IN_W < 1) begin : invalid_N
      fpstereo_invalid_parameters_sum_tree_N_or_IN_W_below_1 failed ();
    end
    if (SUM_W < IN_W) begin : invalid_SUM_W
      fpstereo_invalid_parameters_sum_tree_SUM_W_below_IN_W failed ();
    end
    if (REGISTER_LEVEL < 0 || REGISTER_LEVEL > ((N > 1) ? $clog2(N) : 0)) begin : invalid_REGISTER_LEVEL
      fpstereo_invalid_parameters_sum_tree_REGISTER_LEVEL_is_not_a_level failed ();
    end
  endgenerate
  localparam LEVELS = (N > 1) ? $clog2(N) : 0;

  genvar v, i;
  generate
    for (v = 0; v <= LEVELS; v = v + 1) begin : level
      // Level v holds ceil(N / 2^v) partial sums of LEVEL_W bits.
      localparam COUNT = (N + (1 << v) - 1) >> v;
      localparam PREV_COUNT = (N + (1 << v) / 2 - 1) / ((1 << v) / 2 > 0 ? (1 << v) / 2 : 1);
      localparam LEVEL_W = IN_W + v < SUM_W ? IN_W + v : SUM_W;
      localparam PREV_W = IN_W + v - 1 < SUM_W ? IN_W + v - 1 : SUM_W;
      wire [COUNT*LEVEL_W-1:0] nodes_d;  // the level's sums
      wire [COUNT*LEVEL_W-1:0] nodes;    // as the next level reads them
      if (v > 0 && v == REGISTER_LEVEL) begin : stage
        reg [COUNT*LEVEL_W-1:0] nodes_q;
        always @(posedge clk)
          if (en) nodes_q <= nodes_d;
        assign nodes = nodes_q;
      end else begin : wire_through
        assign nodes = nodes_d;
      end
      // a level's nodes are one bit wider than the level below, until SUM_W
      localparam GROWS = LEVEL_W > PREV_W;
      for (i = 0; i < COUNT; i = i + 1) begin : node
        if (v == 0) begin : leaf
          assign nodes_d[i*LEVEL_W +: LEVEL_W] = values[i*IN_W +: IN_W];
        end else if (2 * i + 1 < PREV_COUNT) begin : pair
          wire [PREV_W-1:0] a = level[v-1].nodes[(2*i)*PREV_W +: PREV_W];
          wire [PREV_W-1:0] b = level[v-1].nodes[(2*i+1)*PREV_W +: PREV_W];
          if (GROWS) begin : wider
            assign nodes_d[i*LEVEL_W +: LEVEL_W] = {1'b0, a} + {1'b0, b};
          end else begin : capped
            assign nodes_d[i*LEVEL_W +: LEVEL_W] = a + b;
          end
        end else begin : single  // the last node of an odd level passes up alone
          wire [PREV_W-1:0] a = level[v-1].nodes[(2*i)*PREV_W +: PREV_W];
          if (GROWS) begin : wider
            assign nodes_d[i*LEVEL_W +: LEVEL_W] = {1'b0, a};
          end else begin : capped
            assign nodes_d[i*LEVEL_W +: LEVEL_W] = a;
          end
        end
      end
    end
  endgenerate

  localparam TOP_W = IN_W + LEVELS < SUM_W ? IN_W + LEVELS : SUM_W;
  generate
    if (TOP_W < SUM_W) begin : widen
      assign sum = {{(SUM_W-TOP_W){1'b0}}, level[LEVELS].nodes};
    end else begin : full
      assign sum = level[LEVELS].nodes;
    end
  endgenerate
endmodule
`resetall
