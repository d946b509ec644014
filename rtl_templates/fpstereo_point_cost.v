`resetall
`default_nettype none
// Cost stage for census and rank (one code per pixel): the base code waits a slot next to the
// match ring, which holds the last DMAX match codes; the lanes give UF costs per step
// (docs/architecture.md, "Front end"). history_x / history_y / history_slot are the centre whose
// costs the lanes compute in this slot; fpstereo_cost_history holds them, with the disparity
// offset's delays.
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
  // the cost lanes' latency the stage plans with (fpstereo_cost_lanes checks it)
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
  input  wire [X_W-1:0]         transform_x,
  input  wire signed [SIGNED_Y_W-1:0] transform_y,
  input  wire [COST_ROW_W-1:0]    transform_slot,
  output wire [X_W-1:0]         history_x,
  output wire signed [SIGNED_Y_W-1:0] history_y,
  output wire [COST_ROW_W-1:0]    history_slot,
  output wire [UF*COST_W-1:0]   costs
);
  localparam POSITION_W = X_W + SIGNED_Y_W + COST_ROW_W;
  wire [CODE_W-1:0]     code_base_h;
  wire [POSITION_W-1:0] history;
  wire [UF*CODE_W-1:0]  match_lanes;
  fpstereo_cost_history #(.BASE_W(CODE_W), .POSITION_W(POSITION_W), .COLUMN_W(CODE_W), .SPAN(1), .DMAX(DMAX),
                          .UF(UF), .G_W(G_W), .MIN_DISP(MIN_DISP)) cost_history (
    .clk(clk), .adv(adv), .slot_end(slot_end), .shift(shift), .base(code_base),
    .position({transform_x, transform_y, transform_slot}), .column(code_match), .base_held(code_base_h),
    .position_held(history), .view(match_lanes));
  assign {history_x, history_y, history_slot} = history;
  fpstereo_cost_lanes #(.HAMMING(HAMMING), .CODE_W(CODE_W), .UF(UF), .COST_W(COST_W), .COST_MAX(COST_MAX),
                        .GROUP_W(G_W), .X_W(X_W), .MIN_DISP(MIN_DISP), .LAT(LAT)) lanes (
    .clk(clk), .en(adv), .base_code(code_base_h), .match_codes(match_lanes), .group(group),
    .x(history_x), .width(frame_width), .costs(costs));
endmodule
`resetall
