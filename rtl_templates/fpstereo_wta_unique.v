`resetall
`default_nettype none
// Winner-take-all with the uniqueness check (docs/semantics.md, section 4): per step the range
// summaries of one group's lanes (fpstereo_unique_tree), joined over the groups of the pixel
// (fpstereo_unique_join), then registered; the next step registers the two products of the test,
// the one after compares their halves, and in the step after that (TREE_LAT + 3 steps after the
// pixel's last group) word is the winner
// or the invalid word when S2 * (100 - u) < S1 * 100, with S1 and S2 beside it (best_sum,
// second_sum: the confidence uses them). The tag travels along. The tree is registered every
// LEVELS_PER_STAGE joins; a join's compare-selects are several LUT levels deep, so 1 keeps a step
// within the pipeline's depth.
module fpstereo_wta_unique #(
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
  // the uniqueness ratio in percent (0: every winner is kept)
  input  wire [6:0]          uniqueness,
  output wire [G_W-1:0]      group_out,
  output wire [TAG_W-1:0]    tag_out,
  output wire [DISP_W:0]     word,
  output wire [SUM_W-1:0]    best_sum,
  output wire [SUM_W-1:0]    second_sum
);
  // fpstereo_reduction_tree checks UF, LANE_W, LEVELS_PER_STAGE and TREE_LAT.
  localparam [DISP_W:0] INVALID_WORD = {1'b1, {DISP_W{1'b0}}};
  localparam S_W = 5 * SUM_W + DISP_W + 2;
  wire [G_W-1:0] group_tree;  // the group whose summary leaves the tree
  wire [TAG_W-1:0] tag_tree;
  fpstereo_delay #(.WIDTH(TAG_W + G_W), .DEPTH(TREE_LAT), .RESET(1)) tag_to_wta (
    .clk(clk), .rst(restart), .en(adv), .in({tag, group}), .out({tag_tree, group_tree}));
  fpstereo_delay #(.WIDTH(TAG_W + G_W), .DEPTH(3), .RESET(1)) tag_to_word (
    .clk(clk), .rst(restart), .en(adv), .in({tag_tree, group_tree}), .out({tag_out, group_out}));
  wire [SUM_W-1:0]  best, all, but_first, but_last, second;
  wire [LANE_W-1:0] lane;
  wire              first, last;
  fpstereo_unique_tree #(.N(UF), .W(SUM_W), .IDX_W(LANE_W), .LEVELS_PER_STAGE(LEVELS_PER_STAGE),
                        .LAT(TREE_LAT)) tree (
    .clk(clk), .en(adv), .values(sums), .best(best), .index(lane), .first(first), .last(last), .all(all),
    .but_first(but_first), .but_last(but_last), .second(second));
  /* verilator lint_off WIDTH */  // group * UF + lane, cut to the disparity width
  wire [DISP_W-1:0] group_disparity = group_tree * UF + lane;
  /* verilator lint_on WIDTH */
  wire [S_W-1:0] group_summary = {best, all, but_first, but_last, second, group_disparity, first, last};
  reg  [S_W-1:0] running;  // groups 0 .. group_out - 1
  wire [S_W-1:0] joined;
  fpstereo_unique_join #(.W(SUM_W), .IDX_W(DISP_W)) join_groups (.a(running), .b(group_summary), .joined(joined));
  wire [S_W-1:0] total = group_tree == 0 ? group_summary : joined;
  always @(posedge clk)
    if (adv) running <= total;
  wire [SUM_W-1:0]  s1 = running[S_W-1 -: SUM_W];
  wire [SUM_W-1:0]  s2 = running[S_W-4*SUM_W-1 -: SUM_W];
  // Invalid iff S2 * (100 - u) < S1 * 100: one integer comparison, no division (u = 0 never
  // invalidates: S2 >= S1). The products are registered, then compared in halves (a compare
  // of their full width maps to a deep LUT chain), then the halves' results joined.
  reg  [7:0] keep;
  always @(posedge clk) keep <= 8'd100 - {1'b0, uniqueness};
  localparam P_W = SUM_W + 8, LOW_W = P_W / 2;
  reg  [P_W-1:0]    scaled_second, scaled_best;
  reg  [SUM_W-1:0]  s1_q, s2_q, s1_c, s2_c;
  reg  [DISP_W-1:0] winner, winner_c;
  always @(posedge clk)
    if (adv) begin
      /* verilator lint_off WIDTH */  // products widened to their full width
      scaled_second <= s2 * keep;
      scaled_best <= s1 * 8'd100;
      /* verilator lint_on WIDTH */
      s1_c <= s1;
      s2_c <= s2;
      winner_c <= running[DISP_W+1:2];
    end
  reg high_below, high_equal, low_below;
  always @(posedge clk)
    if (adv) begin
      high_below <= scaled_second[P_W-1:LOW_W] < scaled_best[P_W-1:LOW_W];
      high_equal <= scaled_second[P_W-1:LOW_W] == scaled_best[P_W-1:LOW_W];
      low_below <= scaled_second[LOW_W-1:0] < scaled_best[LOW_W-1:0];
      s1_q <= s1_c;
      s2_q <= s2_c;
      winner <= winner_c;
    end
  assign word = (high_below || (high_equal && low_below)) ? INVALID_WORD : {1'b0, winner};
  assign best_sum = s1_q;
  assign second_sum = s2_q;
endmodule
`resetall
