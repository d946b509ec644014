`resetall
`default_nettype none
// UF matching costs per step: lane l is index d = group*UF + l, disparity MIN_DISP + d. Census:
// Hamming distance of the codes; rank: absolute difference. Where the match pixel x - MIN_DISP - d
// lies outside the row the cost is COST_MAX (docs/semantics.md, section 2). Two register steps: the
// Hamming distance's counts of 6-bit chunks (or the absolute difference) and the border flag,
// then their sum and the border's COST_MAX. Codes of more than 8 chunks (census windows above
// 7x7) take a step more: sums of up to 8 counts, then their total.
module fpstereo_cost_lanes #(
  // 1: census codes, cost = Hamming distance; 0: ranks, cost = absolute difference
  parameter HAMMING = 1,
  parameter CODE_W = 48,
  parameter UF = 32,
  parameter COST_W = 6,
  parameter COST_MAX = 48,
  // bits of the group index and of the x coordinate
  parameter GROUP_W = 2,
  parameter X_W = 11,
  // the smallest disparity (docs/semantics.md, section 2)
  parameter MIN_DISP = 0,
  // the latency the instantiating stage plans with (checked: 2, 3 for census codes of more than
  // 48 bits)
  parameter LAT = 2
) (
  input  wire                 clk,
  input  wire                 en,
  input  wire [CODE_W-1:0]    base_code,
  input  wire [UF*CODE_W-1:0] match_codes,
  input  wire [GROUP_W-1:0]   group,
  input  wire [X_W-1:0]       x,
  /* verilator lint_off UNUSEDSIGNAL */  // the right border matters only below MIN_DISP 0
  input  wire [X_W-1:0]       width,
  /* verilator lint_on UNUSEDSIGNAL */
  output reg  [UF*COST_W-1:0] costs
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (UF < 1 || UF > 512) begin : invalid_UF
      fpstereo_invalid_parameters_cost_lanes_UF_is_not_1_to_512 failed ();
    end
    if (COST_MAX >= (1 << COST_W) || (HAMMING != 0 && CODE_W >= (1 << COST_W)) || (HAMMING == 0 && COST_W < CODE_W)) begin : invalid_COST_W
      fpstereo_invalid_parameters_cost_lanes_COST_W_does_not_hold_the_costs failed ();
    end
    if (LAT != ((HAMMING != 0 && CODE_W > 48) ? 3 : 2)) begin : invalid_LAT
      fpstereo_invalid_parameters_cost_lanes_LAT_is_not_the_latency failed ();
    end
  endgenerate
  // wide enough for x + 256, any index + 256 and the width, plus one bit so all zero-extend
  localparam D_W = (X_W > GROUP_W + 9 ? X_W : GROUP_W + 9) + 2;
  wire [D_W-1:0] x_wide = {{(D_W-X_W){1'b0}}, x};
  wire [D_W-1:0] width_wide = {{(D_W-X_W){1'b0}}, width};
  wire [D_W-1:0] group_base = {{(D_W-GROUP_W){1'b0}}, group} * UF[D_W-1:0];
  // x - MIN_DISP - d, compared as x + AHEAD against d + BEHIND, both non-negative.
  localparam integer BEHIND = MIN_DISP > 0 ? MIN_DISP : 0;
  localparam integer AHEAD = MIN_DISP < 0 ? -MIN_DISP : 0;
  wire [D_W-1:0] x_ahead = x_wide + AHEAD[D_W-1:0];

  // Census: the XOR of the codes is counted in chunks of 6 bits, one LUT level each.
  localparam CHUNKS = (CODE_W + 5) / 6;
  localparam PART_W = HAMMING != 0 ? CHUNKS * 3 : CODE_W;
  // More than 8 chunks: the counts are summed in sets of 8 first (one more step).
  localparam SPLIT = HAMMING != 0 && CHUNKS > 8;
  localparam SETS = (CHUNKS + 7) / 8;

  genvar l;
  generate
    for (l = 0; l < UF; l = l + 1) begin : lane
      wire [CODE_W-1:0] m = match_codes[l*CODE_W +: CODE_W];
      wire [D_W-1:0]    d = group_base + l[D_W-1:0] + BEHIND[D_W-1:0];
      // Step 1: the partial counts (or the difference) and whether the match pixel lies
      // outside the row (right of it only when MIN_DISP < 0).
      reg  [PART_W-1:0] part;
      reg               beyond;
      wire [COST_W-1:0] cost;
      if (HAMMING) begin : hamming
        wire [CHUNKS*6-1:0] diff = {{(CHUNKS*6-CODE_W){1'b0}}, base_code ^ m};
        reg  [PART_W-1:0]   counts;
        reg  [SETS*COST_W-1:0] set_sums;
        reg  [COST_W-1:0]   total;
        integer k, b;
        always @* begin
          for (k = 0; k < CHUNKS; k = k + 1) begin
            counts[k*3 +: 3] = 3'd0;
            for (b = 0; b < 6; b = b + 1) counts[k*3 +: 3] = counts[k*3 +: 3] + {2'b00, diff[k*6 + b]};
          end
          set_sums = {SETS*COST_W{1'b0}};
          for (k = 0; k < CHUNKS; k = k + 1)
            set_sums[(k/8)*COST_W +: COST_W] = set_sums[(k/8)*COST_W +: COST_W] + {{(COST_W-3){1'b0}}, part[k*3 +: 3]};
        end
        always @(posedge clk)
          if (en) part <= counts;
        if (SPLIT) begin : in_sets
          // Step 2: the sets' sums; step 3 (below): their total.
          reg [SETS*COST_W-1:0] set_sums_q;
          always @(posedge clk)
            if (en) set_sums_q <= set_sums;
          integer j;
          always @* begin
            total = {COST_W{1'b0}};
            for (j = 0; j < SETS; j = j + 1) total = total + set_sums_q[j*COST_W +: COST_W];
          end
        end else begin : at_once
          always @* total = set_sums[COST_W-1:0];
        end
        assign cost = total;
      end else begin : absolute_difference
        always @(posedge clk)
          if (en) part <= base_code > m ? base_code - m : m - base_code;
        // the costs are wider than the rank values where they hold the fused cost's term too
        if (COST_W > CODE_W) begin : widened
          assign cost = {{(COST_W-CODE_W){1'b0}}, part};
        end else begin : same_width
          assign cost = part;
        end
      end
      always @(posedge clk)
        if (en) beyond <= x_ahead < d || (MIN_DISP < 0 && x_ahead >= d + width_wide);
      // The border flag waits for the sets' step; then (step 2, or 3) the cost.
      wire beyond_d;
      if (SPLIT) begin : beyond_wait
        reg beyond_q;
        always @(posedge clk)
          if (en) beyond_q <= beyond;
        assign beyond_d = beyond_q;
      end else begin : beyond_now
        assign beyond_d = beyond;
      end
      always @(posedge clk)
        if (en) costs[l*COST_W +: COST_W] <= beyond_d ? COST_MAX[COST_W-1:0] : cost;
    end
  endgenerate
endmodule
`resetall
