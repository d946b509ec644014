`resetall
`default_nettype none
// The lanes of a point cost (census or rank: one code per pixel): UF costs per step from the
// base entry and UF match entries, each a code with, for the fused cost (WEIGHT above 0), its
// pixel's feature above it (fpstereo_fused_features); fpstereo_fused_term adds the pixel-wise
// term. The raster cost stage (fpstereo_point_cost) and the chain-order one (fpstereo_chain_cost)
// feed it.
module fpstereo_point_lanes #(
  // 1: census codes (Hamming distance); 0: ranks (absolute difference)
  parameter HAMMING = 1,
  parameter CODE_W = 24,
  parameter UF = 8,
  parameter COST_W = 5,
  parameter COST_MAX = 24,
  parameter X_W = 7,
  parameter G_W = 2,
  parameter MIN_DISP = 0,
  // the fused cost: WEIGHT in eighths (0: off), TRUNC, the features' width and signedness
  parameter WEIGHT = 0,
  parameter TRUNC = 20,
  parameter FEATURE_W = 8,
  parameter GRADIENT = 0,
  // the cost lanes' latency, and the whole latency (the lanes' plus the fused term's step, or the
  // same); fpstereo_cost_lanes and fpstereo_fused_term check them
  parameter LANES_LAT = 2,
  parameter LAT = 2,
  // an entry: the code, with the fused cost the feature above it
  parameter ENTRY_W = CODE_W
) (
  input  wire                  clk,
  input  wire                  en,
  input  wire [G_W-1:0]        group,
  input  wire [X_W-1:0]        x,
  input  wire [X_W-1:0]        frame_width,
  input  wire [ENTRY_W-1:0]    base_entry,
  input  wire [UF*ENTRY_W-1:0] match_entries,
  output wire [UF*COST_W-1:0]  costs
);
  localparam FUSED = WEIGHT != 0;
  generate
    if (ENTRY_W != CODE_W + (FUSED ? FEATURE_W : 0)) begin : invalid_ENTRY_W
      fpstereo_invalid_parameters_point_lanes_ENTRY_W_is_not_the_code_and_feature failed ();
    end
  endgenerate
  // Lane l reads entry l.
  reg [UF*CODE_W-1:0] match_codes;
  integer l;
  always @*
    for (l = 0; l < UF; l = l + 1) match_codes[l*CODE_W +: CODE_W] = match_entries[l*ENTRY_W +: CODE_W];
  wire [UF*COST_W-1:0] lane_costs;
  fpstereo_cost_lanes #(.HAMMING(HAMMING), .CODE_W(CODE_W), .UF(UF), .COST_W(COST_W), .COST_MAX(COST_MAX),
                        .GROUP_W(G_W), .X_W(X_W), .MIN_DISP(MIN_DISP), .LAT(LANES_LAT)) lanes (
    .clk(clk), .en(en), .base_code(base_entry[CODE_W-1:0]), .match_codes(match_codes), .group(group),
    .x(x), .width(frame_width), .costs(lane_costs));
  generate
    if (FUSED) begin : fused
      reg [UF*FEATURE_W-1:0] match_features;
      integer f;
      always @*
        for (f = 0; f < UF; f = f + 1)
          match_features[f*FEATURE_W +: FEATURE_W] = match_entries[f*ENTRY_W + CODE_W +: FEATURE_W];
      fpstereo_fused_term #(.UF(UF), .COST_W(COST_W), .COST_MAX(COST_MAX), .GRADIENT(GRADIENT), .FEATURE_W(FEATURE_W),
                            .WEIGHT(WEIGHT), .TRUNC(TRUNC), .LANES_LAT(LANES_LAT), .LAT(LAT)) term (
        .clk(clk), .en(en), .base_feature(base_entry[ENTRY_W-1 -: FEATURE_W]), .match_features(match_features),
        .plain_costs(lane_costs), .costs(costs));
    end else begin : plain
      if (LAT != LANES_LAT) begin : invalid_LAT
        fpstereo_invalid_parameters_point_lanes_LAT_is_not_LANES_LAT_without_the_fused_cost failed ();
      end
      assign costs = lane_costs;
    end
  endgenerate
endmodule
`resetall
