`resetall
`default_nettype none
// Pipelined minimum (and its index) over N values. A binary tree of compare-selects with a
// register after every LEVELS_PER_STAGE levels and at the output, so the delay per stage does
// not grow with N. Ties keep the lower index. Latency: max(1, ceil(clog2(N) / LEVELS_PER_STAGE)).
module fpstereo_min_tree #(
  // number of values
  parameter N = 8,
  // value width
  parameter W = 8,
  // index width, at least clog2(N) (at least 1)
  parameter IDX_W = 3,
  // compare-select levels between registers
  parameter LEVELS_PER_STAGE = 3
) (
  input  wire             clk,
  input  wire             en,
  input  wire [N*W-1:0]   values,
  output wire [W-1:0]     min_value,
  output wire [IDX_W-1:0] min_index
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 1 || W < 1) begin : invalid_N
      fpstereo_invalid_parameters_min_tree_N_or_W_below_1 failed ();
    end
    if (IDX_W < 1 || N - 1 >= (1 << IDX_W)) begin : invalid_IDX_W
      fpstereo_invalid_parameters_min_tree_IDX_W_does_not_hold_N_minus_1 failed ();
    end
    if (LEVELS_PER_STAGE < 1) begin : invalid_LEVELS_PER_STAGE
      fpstereo_invalid_parameters_min_tree_LEVELS_PER_STAGE_below_1 failed ();
    end
  endgenerate
  localparam LEVELS = (N > 1) ? $clog2(N) : 0;

  genvar l, i;
  generate
    for (l = 0; l <= LEVELS; l = l + 1) begin : level
      // Level l holds ceil(N / 2^l) candidates.
      localparam COUNT = (N + (1 << l) - 1) >> l;
      localparam PREV_COUNT = (N + (1 << l) / 2 - 1) / ((1 << l) / 2 > 0 ? (1 << l) / 2 : 1);
      localparam REGISTERED = (l == LEVELS) || (l > 0 && l % LEVELS_PER_STAGE == 0);
      wire [COUNT*W-1:0]     v_d;
      wire [COUNT*IDX_W-1:0] x_d;
      wire [COUNT*W-1:0]     v;
      wire [COUNT*IDX_W-1:0] x;
      for (i = 0; i < COUNT; i = i + 1) begin : node
        if (l == 0) begin : leaf
          assign v_d[i*W +: W]         = values[i*W +: W];
          assign x_d[i*IDX_W +: IDX_W] = i;
        end else if (2 * i + 1 < PREV_COUNT) begin : pair
          wire [W-1:0]     a  = level[l-1].v[(2*i)*W +: W];
          wire [W-1:0]     b  = level[l-1].v[(2*i+1)*W +: W];
          wire [IDX_W-1:0] ai = level[l-1].x[(2*i)*IDX_W +: IDX_W];
          wire [IDX_W-1:0] bi = level[l-1].x[(2*i+1)*IDX_W +: IDX_W];
          wire             take_b = b < a;
          assign v_d[i*W +: W]         = take_b ? b : a;
          assign x_d[i*IDX_W +: IDX_W] = take_b ? bi : ai;
        end else begin : single
          assign v_d[i*W +: W]         = level[l-1].v[(2*i)*W +: W];
          assign x_d[i*IDX_W +: IDX_W] = level[l-1].x[(2*i)*IDX_W +: IDX_W];
        end
      end
      if (REGISTERED) begin : stage
        reg [COUNT*W-1:0]     v_q;
        reg [COUNT*IDX_W-1:0] x_q;
        always @(posedge clk)
          if (en) begin
            v_q <= v_d;
            x_q <= x_d;
          end
        assign v = v_q;
        assign x = x_q;
      end else begin : wire_through
        assign v = v_d;
        assign x = x_d;
      end
    end
  endgenerate

  assign min_value = level[LEVELS].v[W-1:0];
  assign min_index = level[LEVELS].x[IDX_W-1:0];
endmodule
`resetall
