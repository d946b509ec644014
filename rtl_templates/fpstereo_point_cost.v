`resetall
`default_nettype none
// Cost stage for census and rank (one code per pixel): the base code waits a slot next to the
// match ring, which holds the last DMAX match codes; the lanes give UF costs per step
// (docs/architecture.md, "Front end"). history_x / history_y / history_slot are the centre whose
// costs the lanes compute in this slot. A disparity offset MIN_DISP delays the match codes by
// MIN_DISP slots before the ring or, when negative, the base code and its centre by -MIN_DISP
// slots (fpstereo_offset_delays).
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
  output reg  [X_W-1:0]         history_x,
  output reg  signed [SIGNED_Y_W-1:0] history_y,
  output reg  [COST_ROW_W-1:0]    history_slot,
  output wire [UF*COST_W-1:0]   costs
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (UF < 1 || DMAX % (UF > 0 ? UF : 1) != 0 || DMAX / (UF > 0 ? UF : 1) - 1 >= (1 << G_W)) begin : invalid
      fpstereo_invalid_parameters_point_cost_needs_DMAX_a_multiple_of_UF_and_G_W_holding_the_group failed ();
    end
  endgenerate
  wire [CODE_W-1:0]      code_base_o, code_match_o;
  wire [X_W-1:0]         transform_x_o;
  wire signed [SIGNED_Y_W-1:0] transform_y_o;
  wire [COST_ROW_W-1:0]    transform_slot_o;
  fpstereo_offset_delays #(.BASE_W(CODE_W + X_W + SIGNED_Y_W + COST_ROW_W), .MATCH_W(CODE_W), .MIN_DISP(MIN_DISP)) offset (
    .clk(clk), .shift(shift), .base({code_base, transform_x, transform_y, transform_slot}), .match(code_match),
    .base_out({code_base_o, transform_x_o, transform_y_o, transform_slot_o}), .match_out(code_match_o));
  reg [CODE_W-1:0] code_base_h;
  always @(posedge clk)
    if (shift) begin
      code_base_h  <= code_base_o;
      history_x    <= transform_x_o;
      history_y    <= transform_y_o;
      history_slot <= transform_slot_o;
    end
  wire [UF*CODE_W-1:0] match_lanes;
  fpstereo_match_ring #(.COLUMN_W(CODE_W), .SPAN(1), .DMAX(DMAX), .UF(UF)) match_history (
    .clk(clk), .en(adv), .slot_end(slot_end), .column_in(code_match_o), .view(match_lanes));
  fpstereo_cost_lanes #(.HAMMING(HAMMING), .CODE_W(CODE_W), .UF(UF), .COST_W(COST_W), .COST_MAX(COST_MAX),
                        .GROUP_W(G_W), .X_W(X_W), .MIN_DISP(MIN_DISP), .LAT(LAT)) lanes (
    .clk(clk), .en(adv), .base_code(code_base_h), .match_codes(match_lanes), .group(group),
    .x(history_x), .width(frame_width), .costs(costs));
endmodule
`resetall
