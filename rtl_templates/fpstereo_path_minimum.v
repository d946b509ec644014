`resetall
`default_nettype none
// Minimum of one pixel's path costs over all DMAX = G * UF disparities: a pipelined tree over
// the UF lanes of each group, then a running minimum over the groups. minimum is the pixel's
// result in the step where the tree delivers its last group (group == G - 1).
module fpstereo_path_minimum #(
  parameter UF = 32,
  parameter PATH_W = 8,
  parameter G_W = 2,
  parameter LEVELS_PER_STAGE = 3,
  // the tree's latency the caller plans with (fpstereo_reduction_tree checks it)
  parameter TREE_LAT = 2
) (
  input  wire               clk,
  input  wire               en,
  input  wire [UF*PATH_W-1:0] path,
  // group of the values the tree delivers in this step
  input  wire [G_W-1:0]     group,
  output wire [PATH_W-1:0]  minimum
);
  // fpstereo_reduction_tree checks UF, LEVELS_PER_STAGE and TREE_LAT.
  localparam LANE_W = UF > 1 ? $clog2(UF) : 1;
  wire [PATH_W-1:0] group_min;
  wire [LANE_W-1:0] unused_lane;
  fpstereo_min_tree #(.N(UF), .W(PATH_W), .IDX_W(LANE_W), .LEVELS_PER_STAGE(LEVELS_PER_STAGE),
                     .LAT(TREE_LAT)) tree (
    .clk(clk), .en(en), .values(path), .min_value(group_min), .min_index(unused_lane));

  reg [PATH_W-1:0] running;
  assign minimum = (group == 0 || group_min < running) ? group_min : running;
  always @(posedge clk)
    if (en) running <= minimum;
endmodule
`resetall
