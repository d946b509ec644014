`resetall
`default_nettype none
// Cost stage for census and rank (one code per pixel): the base code waits a slot next to the
// match ring, which holds the last DMAX match codes; the lanes give UF costs per step
// (docs/architecture.md, "Front end"). history_x / history_y / history_slot are the centre whose
// costs the lanes compute in this slot; fpstereo_cost_history holds them, with the disparity
// offset's delays. With the fused cost (WEIGHT above 0) each code travels with its pixel's feature
// (fpstereo_fused_features) through the history; fpstereo_point_lanes computes the costs.
module fpstereo_point_cost #(
  // 1: census codes (Hamming distance); 0: ranks (absolute difference)
  parameter HAMMING = 1,
  parameter CODE_W = 24,
  parameter DMAX = 32,
  parameter UF = 8,
  parameter COST_W = 5,
  parameter COST_MAX = 24,
  parameter COST_ROW_W = 1,
  parameter X_W = 7,
  parameter SIGNED_Y_W = 8,
  parameter G_W = 2,
  parameter MIN_DISP = 0,
  // the fused cost: WEIGHT in eighths (0: off), TRUNC, the features' width and signedness
  parameter WEIGHT = 0,
  parameter TRUNC = 20,
  parameter FEATURE_W = 8,
  parameter GRADIENT = 0,
  // the cost lanes' latency, and the stage's (the lanes' plus the fused term's step, or the same);
  // fpstereo_cost_lanes and fpstereo_fused_term check them
  parameter LANES_LAT = 2,
  parameter LAT = 2
) (
  input  wire                   clk,
  input  wire                   adv,
  input  wire                   slot_end,
  input  wire                   shift,
  input  wire [G_W-1:0]         group,
  input  wire [X_W-1:0]         frame_width,
  input  wire [CODE_W-1:0]      code_base,
  input  wire [CODE_W-1:0]      code_match,
  /* verilator lint_off UNUSEDSIGNAL */  // the fused cost's only
  input  wire [FEATURE_W-1:0]   feature_base,
  input  wire [FEATURE_W-1:0]   feature_match,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [X_W-1:0]         transform_x,
  input  wire signed [SIGNED_Y_W-1:0] transform_y,
  input  wire [COST_ROW_W-1:0]    transform_slot,
  output wire [X_W-1:0]         history_x,
  output wire signed [SIGNED_Y_W-1:0] history_y,
  output wire [COST_ROW_W-1:0]    history_slot,
  output wire [UF*COST_W-1:0]   costs
);
  localparam POSITION_W = X_W + SIGNED_Y_W + COST_ROW_W;
  // A history entry: the code, with the fused cost its pixel's feature above it.
  localparam FUSED = WEIGHT != 0;
  localparam ENTRY_W = CODE_W + (FUSED ? FEATURE_W : 0);
  wire [ENTRY_W-1:0]    base_entry, match_entry, base_entry_h;
  wire [POSITION_W-1:0] history;
  wire [UF*ENTRY_W-1:0] match_view;
  generate
    if (FUSED) begin : with_features
      assign base_entry = {feature_base, code_base};
      assign match_entry = {feature_match, code_match};
    end else begin : codes_only
      assign base_entry = code_base;
      assign match_entry = code_match;
    end
  endgenerate
  fpstereo_cost_history #(.BASE_W(ENTRY_W), .POSITION_W(POSITION_W), .COLUMN_W(ENTRY_W), .SPAN(1), .DMAX(DMAX),
                          .UF(UF), .G_W(G_W), .MIN_DISP(MIN_DISP)) cost_history (
    .clk(clk), .adv(adv), .slot_end(slot_end), .shift(shift), .base(base_entry),
    .position({transform_x, transform_y, transform_slot}), .column(match_entry), .base_held(base_entry_h),
    .position_held(history), .view(match_view));
  assign {history_x, history_y, history_slot} = history;
  fpstereo_point_lanes #(.HAMMING(HAMMING), .CODE_W(CODE_W), .UF(UF), .COST_W(COST_W), .COST_MAX(COST_MAX), .X_W(X_W),
                         .G_W(G_W), .MIN_DISP(MIN_DISP), .WEIGHT(WEIGHT), .TRUNC(TRUNC), .FEATURE_W(FEATURE_W),
                         .GRADIENT(GRADIENT), .LANES_LAT(LANES_LAT), .LAT(LAT), .ENTRY_W(ENTRY_W)) lanes (
    .clk(clk), .en(adv), .group(group), .x(history_x), .frame_width(frame_width), .base_entry(base_entry_h),
    .match_entries(match_view), .costs(costs));
endmodule
`resetall
