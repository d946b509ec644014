`resetall
`default_nettype none
// One aggregation path for UF lanes (docs/semantics.md, section 3):
//   L(d) = C(d) + min(P(d), P(d-1) + P1, P(d+1) + P1, m + P2) - m
// where P are the predecessor's path costs and m their minimum; without a predecessor L = C.
// prev holds the predecessor's lanes of this group; prev_below / prev_above its lanes d-1 of
// the first lane and d+1 of the last lane, all ones where they do not exist. Two register steps
// (LATENCY): the neighbours' and the jump's minima, then the best and the sum.
module fpstereo_path_lanes #(
  parameter UF = 32,
  parameter COST_W = 6,
  parameter PATH_W = 8
) (
  input  wire                 clk,
  input  wire                 en,
  // penalties, at most the path cost's maximum minus the largest cost (docs/semantics.md)
  input  wire [PATH_W-1:0]    p1,
  input  wire [PATH_W-1:0]    p2,
  input  wire [UF*COST_W-1:0] cost,
  input  wire                 has_pred,
  input  wire [UF*PATH_W-1:0] prev,
  input  wire [PATH_W-1:0]    prev_below,
  input  wire [PATH_W-1:0]    prev_above,
  input  wire [PATH_W-1:0]    prev_min,
  output reg  [UF*PATH_W-1:0] path
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (UF < 1 || COST_W < 1 || PATH_W < COST_W) begin : invalid
      fpstereo_invalid_parameters_path_lanes_PATH_W_below_COST_W failed ();
    end
  endgenerate
  // One extra bit so that a missing neighbour (all ones) plus P1 does not wrap.
  localparam EXT_W = PATH_W + 1;
  wire [(UF+2)*PATH_W-1:0] around = {prev_above, prev, prev_below};  // lane l at (l+1)
  wire [EXT_W-1:0] jump = {1'b0, prev_min} + {1'b0, p2};

  // Step 1 also keeps what step 2 needs besides the candidates.
  reg [UF*COST_W-1:0] cost_q;
  reg [PATH_W-1:0]    prev_min_q;
  reg                 has_pred_q;
  always @(posedge clk)
    if (en) begin
      cost_q <= cost;
      prev_min_q <= prev_min;
      has_pred_q <= has_pred;
    end

  genvar l;
  generate
    for (l = 0; l < UF; l = l + 1) begin : lane
      wire [EXT_W-1:0] below = {1'b0, around[l*PATH_W +: PATH_W]};
      wire [EXT_W-1:0] same  = {1'b0, around[(l+1)*PATH_W +: PATH_W]};
      wire [EXT_W-1:0] above = {1'b0, around[(l+2)*PATH_W +: PATH_W]};
      // Step 1: the smaller neighbour plus P1, and the smaller of the same disparity and the jump.
      reg  [EXT_W-1:0] neighbour, stay;
      always @(posedge clk)
        if (en) begin
          neighbour <= (below < above ? below : above) + {1'b0, p1};
          stay <= same < jump ? same : jump;
        end
      // Step 2: the best, and the path cost.
      wire [EXT_W-1:0] best = stay < neighbour ? stay : neighbour;
      wire [EXT_W-1:0] c = {{(EXT_W-COST_W){1'b0}}, cost_q[l*COST_W +: COST_W]};
      // best - prev_min lies in 0 .. P2, so the sum fits PATH_W bits (its top bit is 0).
      /* verilator lint_off UNUSEDSIGNAL */
      wire [EXT_W-1:0] sum = c + best - {1'b0, prev_min_q};
      /* verilator lint_on UNUSEDSIGNAL */
      always @(posedge clk)
        if (en) path[l*PATH_W +: PATH_W] <= has_pred_q ? sum[PATH_W-1:0] : c[PATH_W-1:0];
    end
  endgenerate
endmodule
`resetall
