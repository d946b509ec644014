`resetall
`default_nettype none
// The fused cost (docs/semantics.md, section 2, "Fused cost"): each lane's cost plus
// floor(WEIGHT * min(|F_B - F_M|, TRUNC) / 8), F the pixels' features (fpstereo_fused_features).
// The features enter with the lanes' inputs and the plain costs leave the lanes LANES_LAT steps
// later. The term takes three register steps (the absolute difference, its truncation, the
// weighting as shifts and adds: no multiplier), the shorter of the two waits for the other, and a
// last step adds them. A plain cost of COST_MAX marks a match pixel outside the row (in the row
// it stays at most COST_MAX - floor(WEIGHT * TRUNC / 8)): that cost stays COST_MAX.
module fpstereo_fused_term #(
  parameter UF = 8,
  parameter COST_W = 6,
  // the largest cost, the term's bound included (gen/core/widths.cpp)
  parameter COST_MAX = 40,
  // 1: signed features (the gradient, 9 bits); 0: intensities (8 bits)
  parameter GRADIENT = 0,
  parameter FEATURE_W = 8,
  // the weight in eighths (1 .. 32) and the truncation (1 .. 255)
  parameter WEIGHT = 4,
  parameter TRUNC = 32,
  // the lanes' latency, and the latency the instantiating stage plans with (checked:
  // max(LANES_LAT, 3) + 1)
  parameter LANES_LAT = 2,
  parameter LAT = 4
) (
  input  wire                    clk,
  input  wire                    en,
  input  wire [FEATURE_W-1:0]    base_feature,
  input  wire [UF*FEATURE_W-1:0] match_features,
  input  wire [UF*COST_W-1:0]    plain_costs,
  output reg  [UF*COST_W-1:0]    costs
);
  localparam TERM_STEPS = 3;
  localparam ALIGNED = LANES_LAT > TERM_STEPS ? LANES_LAT : TERM_STEPS;
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (WEIGHT < 1 || WEIGHT > 32 || TRUNC < 1 || TRUNC > 255 || FEATURE_W != (GRADIENT != 0 ? 9 : 8) ||
        COST_MAX >= (1 << COST_W) || WEIGHT * TRUNC / 8 > COST_MAX) begin : invalid
      fpstereo_invalid_parameters_fused_term_needs_WEIGHT_1_to_32_TRUNC_1_to_255_and_COST_MAX_holding_the_term failed ();
    end
    if (LANES_LAT < 1 || LAT != ALIGNED + 1) begin : invalid_LAT
      fpstereo_invalid_parameters_fused_term_LAT_is_not_the_latency failed ();
    end
  endgenerate
  // WEIGHT * TRUNC < 8 * (COST_MAX + 1): the weighted difference fits in COST_W + 3 bits, and so
  // does the truncated difference; the truncation compares in a width that holds both.
  localparam PRODUCT_W = COST_W + 3;
  localparam COMPARE_W = PRODUCT_W + FEATURE_W + 1;
  localparam [COMPARE_W-1:0] TRUNC_WIDE = TRUNC[COMPARE_W-1:0];

  wire [UF*COST_W-1:0] plain_aligned, terms_aligned;
  reg  [UF*COST_W-1:0] terms;
  genvar l;
  generate
    for (l = 0; l < UF; l = l + 1) begin : lane
      // Both features widened by one bit, signed: the gradient sign-extended, intensities as they are.
      wire signed [FEATURE_W:0] b = {GRADIENT != 0 ? base_feature[FEATURE_W-1] : 1'b0, base_feature};
      wire [FEATURE_W-1:0] mf = match_features[l*FEATURE_W +: FEATURE_W];
      wire signed [FEATURE_W:0] m = {GRADIENT != 0 ? mf[FEATURE_W-1] : 1'b0, mf};
      wire signed [FEATURE_W:0] b_minus_m = b - m, m_minus_b = m - b;
      // Step 1: the absolute difference (0 .. 510 fits FEATURE_W + 1 bits as a non-negative value).
      reg [FEATURE_W:0] difference;
      always @(posedge clk)
        if (en) difference <= b > m ? b_minus_m : m_minus_b;
      // Step 2: truncated at TRUNC.
      wire [COMPARE_W-1:0] difference_wide = {{PRODUCT_W{1'b0}}, difference};
      reg [PRODUCT_W-1:0] truncated;
      always @(posedge clk)
        if (en) truncated <= difference_wide > TRUNC_WIDE ? TRUNC_WIDE[PRODUCT_W-1:0] : difference_wide[PRODUCT_W-1:0];
      // Step 3: floor(WEIGHT * truncated / 8), the product as a sum of shifted copies.
      reg [PRODUCT_W-1:0] product;
      integer bit_i;
      always @* begin
        product = {PRODUCT_W{1'b0}};
        for (bit_i = 0; bit_i < 6; bit_i = bit_i + 1)
          if (((WEIGHT >> bit_i) & 1) != 0) product = product + (truncated << bit_i);
      end
      always @(posedge clk)
        if (en) terms[l*COST_W +: COST_W] <= product[PRODUCT_W-1:3];
    end
    // The shorter of the two paths waits for the longer.
    if (LANES_LAT < TERM_STEPS) begin : plain_waits
      fpstereo_delay #(.WIDTH(UF*COST_W), .DEPTH(TERM_STEPS - LANES_LAT)) plain_wait (
        .clk(clk), .rst(1'b0), .en(en), .in(plain_costs), .out(plain_aligned));
    end else begin : plain_in_time
      assign plain_aligned = plain_costs;
    end
    if (LANES_LAT > TERM_STEPS) begin : terms_wait
      fpstereo_delay #(.WIDTH(UF*COST_W), .DEPTH(LANES_LAT - TERM_STEPS)) term_wait (
        .clk(clk), .rst(1'b0), .en(en), .in(terms), .out(terms_aligned));
    end else begin : terms_in_time
      assign terms_aligned = terms;
    end
    // The last step: the sum, or COST_MAX outside the row.
    for (l = 0; l < UF; l = l + 1) begin : sum
      wire [COST_W-1:0] plain = plain_aligned[l*COST_W +: COST_W];
      always @(posedge clk)
        if (en) costs[l*COST_W +: COST_W] <= plain == COST_MAX[COST_W-1:0] ? COST_MAX[COST_W-1:0]
                                                                          : plain + terms_aligned[l*COST_W +: COST_W];
    end
  endgenerate
endmodule
`resetall
