`resetall
`default_nettype none
// Winner-take-all (docs/semantics.md, section 4): per step the minimum over the UF lanes of one
// group (fpstereo_min_tree), then a running minimum over the groups of the pixel, the earlier
// group winning ties. word is the pixel's word (invalid flag on top, never set here) including
// the group in group_out; it is the pixel's result in its last group's step. The tag (the
// pixel's position) travels along, TREE_LAT steps (the tree's latency, which it checks).
module fpstereo_wta #(
  parameter UF = 8,
  parameter SUM_W = 9,
  parameter DISP_W = 5,
  parameter LANE_W = 3,
  parameter G_W = 2,
  parameter TAG_W = 8,
  parameter LEVELS_PER_STAGE = 3,
  parameter TREE_LAT = 1
) (
  input  wire                clk,
  input  wire                restart,
  input  wire                adv,
  input  wire [UF*SUM_W-1:0] sums,
  input  wire [G_W-1:0]      group,
  input  wire [TAG_W-1:0]    tag,
  output wire [G_W-1:0]      group_out,
  output wire [TAG_W-1:0]    tag_out,
  output wire [DISP_W:0]     word
);
  // fpstereo_reduction_tree checks UF, LANE_W, LEVELS_PER_STAGE and TREE_LAT.
  fpstereo_delay #(.WIDTH(TAG_W + G_W), .DEPTH(TREE_LAT), .RESET(1)) tag_to_wta (
    .clk(clk), .rst(restart), .en(adv), .in({tag, group}), .out({tag_out, group_out}));
  wire [SUM_W-1:0]  group_min;
  wire [LANE_W-1:0] group_lane;
  fpstereo_min_tree #(.N(UF), .W(SUM_W), .IDX_W(LANE_W), .LEVELS_PER_STAGE(LEVELS_PER_STAGE),
                     .LAT(TREE_LAT)) tree (
    .clk(clk), .en(adv), .values(sums), .min_value(group_min), .min_index(group_lane));
  /* verilator lint_off WIDTH */  // group * UF + lane, cut to the disparity width
  wire [DISP_W-1:0] group_disparity = group_out * UF + group_lane;
  /* verilator lint_on WIDTH */
  reg  [SUM_W-1:0]  best_sum;
  reg  [DISP_W-1:0] best_disparity;
  wire take_group = group_out == 0 || group_min < best_sum;
  always @(posedge clk)
    if (adv && take_group) begin
      best_sum <= group_min;
      best_disparity <= group_disparity;
    end
  assign word = {1'b0, take_group ? group_disparity : best_disparity};
endmodule
`resetall
