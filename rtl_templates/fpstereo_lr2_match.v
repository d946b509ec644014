`resetall
`default_nettype none
// LR2 match side (docs/semantics.md, section 5): a second cost volume and aggregation with the
// images' roles swapped, and its winner-take-all (no uniqueness). Every cost is symmetric, so the
// match side's C(x', d) is the base side's C(x' + m + d, d) (m = MIN_DISP): lane l of each base
// cost word goes to its own RAM bank at match pixel x - m - d where that lies in the row, and a
// word of the match side reads all banks at one address.
// From match_on on, completed_* writes Dm(x') of each match pixel. With the 180-degree path
// (FORWARD_LAG not 0) the match side has it too (fpstereo_right_to_left on copies of the banks),
// and its forward chains run FORWARD_LAG row-times later, as the base side's.
module fpstereo_lr2_match #(
  parameter W = 64,
  parameter ROW_SLOTS = 64,
  parameter K = 2,
  parameter SEGMENT = 32,
  parameter G = 4,
  parameter UF = 8,
  parameter DMAX = 32,
  parameter COST_W = 5,
  parameter COST_MAX = 24,
  parameter PATH_W = 7,
  parameter SUM_W = 9,
  parameter DISP_W = 5,
  parameter PATHS = 15,
  parameter LEVELS_PER_STAGE = 3,
  parameter PATH_TREE_LAT = 1,
  parameter WTA_TREE_LAT = 1,
  parameter OUT_ROWS = 3,
  parameter OUT_ROW_W = 2,
  parameter DISP_AW = 8,
  parameter COST_ROWS = 3,
  parameter COST_ROW_W = 2,
  parameter COST_AW = 10,
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter G_W = 2,
  parameter K_W = 1,
  parameter LANE_W = 3,
  parameter MIN_DISP = 0,
  // the row-times the forward chains run behind the cost writes (the base side's CHAIN_BASE):
  // not 0 with the 180-degree path only, whose mirrored chains go first
  parameter FORWARD_LAG = 0
) (
  input  wire                 clk,
  input  wire                 restart,
  input  wire                 adv,
  input  wire                 match_on,
  // back-to-back frames, as fpstereo_aggregator takes them
  input  wire                 overlap,
  input  wire                 wrapped,
  input  wire [X_W-1:0]       frame_width,
  input  wire [Y_W-1:0]       frame_height,
  input  wire [PATH_W-1:0]    p1,
  input  wire [PATH_W-1:0]    p2,
  // the base side's cost words as the cost reorder RAM takes them
  input  wire                 cost_valid,
  input  wire [X_W-1:0]       cost_x,
  input  wire [COST_ROW_W-1:0]  cost_row_slot,
  input  wire [G_W-1:0]       cost_group,
  input  wire [UF*COST_W-1:0] costs,
  output wire                 completed_we,
  output wire [DISP_AW-1:0]   completed_waddr,
  output wire [DISP_W-1:0]    completed_wdata
);
  localparam COST_DEPTH = COST_ROWS * ROW_SLOTS * G;
  localparam RIGHT_TO_LEFT = FORWARD_LAG != 0 ? 1 : 0;
  localparam integer LAST_GROUP_I = G - 1;
  localparam [G_W-1:0] LAST_GROUP = LAST_GROUP_I[G_W-1:0];
  generate
    if (DMAX != G * UF || COST_ROWS != K + FORWARD_LAG + 1) begin : invalid
      fpstereo_invalid_parameters_lr2_needs_DMAX_G_times_UF_and_K_plus_FORWARD_LAG_plus_1_cost_rows failed ();
    end
  endgenerate
  // Addresses and disparities are products of narrow counters and constants, cut to width.
  // verilator lint_off WIDTH
  wire [UF*COST_W-1:0] match_costs;
  wire [COST_AW-1:0]   match_raddr;
  /* verilator lint_off UNUSEDSIGNAL */  // read with the 180-degree path only
  wire [UF*COST_W-1:0] mirror_costs;
  wire [COST_AW-1:0]   mirror_raddr;
  /* verilator lint_on UNUSEDSIGNAL */
  // x - m - d as (x + AHEAD) - (d + BEHIND)
  localparam integer BEHIND = MIN_DISP > 0 ? MIN_DISP : 0;
  localparam integer AHEAD = MIN_DISP < 0 ? -MIN_DISP : 0;
  localparam P_W = X_W + 10;
  wire [P_W-1:0] x_ahead = cost_x + AHEAD;
  genvar l;
  generate
    for (l = 0; l < UF; l = l + 1) begin : bank
      wire [P_W-1:0] d_behind = cost_group * UF + l + BEHIND;
      wire in_row = x_ahead >= d_behind && (MIN_DISP >= 0 || x_ahead < d_behind + frame_width);
      wire [COST_AW-1:0] waddr = (cost_row_slot * ROW_SLOTS + (x_ahead - d_behind)) * G + cost_group;
      fpstereo_ram_sdp #(.WIDTH(COST_W), .DEPTH(COST_DEPTH), .ADDR_W(COST_AW)) costs_of_lane (
        .clk(clk), .we(adv && cost_valid && in_row),
        .waddr(waddr),
        .wdata(costs[l*COST_W +: COST_W]), .re(adv), .raddr(match_raddr),
        .rdata(match_costs[l*COST_W +: COST_W]));
      // The 180-degree path's mirrored reads: a copy of the bank.
      if (RIGHT_TO_LEFT != 0) begin : second
        fpstereo_ram_sdp #(.WIDTH(COST_W), .DEPTH(COST_DEPTH), .ADDR_W(COST_AW)) costs_of_lane (
          .clk(clk), .we(adv && cost_valid && in_row), .waddr(waddr),
          .wdata(costs[l*COST_W +: COST_W]), .re(adv), .raddr(mirror_raddr),
          .rdata(mirror_costs[l*COST_W +: COST_W]));
      end else begin : no_second
        assign mirror_costs[l*COST_W +: COST_W] = {COST_W{1'b0}};
      end
    end
  endgenerate
  // The words the forward chains read: the costs, with the 180-degree path's above them.
  wire [UF*COST_W+RIGHT_TO_LEFT*UF*PATH_W-1:0] match_words;
  generate
    if (RIGHT_TO_LEFT != 0) begin : right_to_left
      wire [UF*PATH_W-1:0] path180_q;
      fpstereo_right_to_left #(
        .W(W), .ROW_SLOTS(ROW_SLOTS), .K(K), .SEGMENT(SEGMENT), .G(G), .UF(UF), .COST_W(COST_W),
        .COST_MAX(COST_MAX), .PATH_W(PATH_W), .LEVELS_PER_STAGE(LEVELS_PER_STAGE), .PATH_TREE_LAT(PATH_TREE_LAT),
        .COST_AW(COST_AW), .X_W(X_W), .Y_W(Y_W), .G_W(G_W), .K_W(K_W), .COST_ROWS(COST_ROWS),
        .COST_ROW_W(COST_ROW_W), .MATCH_SIDE(1), .MIN_DISP(MIN_DISP)
      ) mirror (
        .clk(clk), .restart(restart), .adv(adv), .frame_width(frame_width), .frame_height(frame_height),
        .p1(p1), .p2(p2), .agg_on(match_on), .overlap(overlap), .wrapped(wrapped),
        .mirror_raddr(mirror_raddr), .mirror_q(mirror_costs), .path_raddr(match_raddr), .path_q(path180_q));
      assign match_words = {path180_q, match_costs};
    end else begin : no_right_to_left
      assign mirror_raddr = {COST_AW{1'b0}};
      assign match_words = match_costs;
    end
  endgenerate
  wire [UF*SUM_W-1:0] sums;
  wire                active;
  wire [X_W-1:0]      x;
  wire [G_W-1:0]      group;
  /* verilator lint_off UNUSEDSIGNAL */  // the match side needs no chain state after the sums
  wire [K_W-1:0]      chain;
  /* verilator lint_on UNUSEDSIGNAL */
  wire [OUT_ROW_W-1:0]  slot;
  // One strip: the edge inputs, never read, take the aggregator's own (zero) edge outputs.
  /* verilator lint_off UNUSEDSIGNAL */
  wire [2*(UF+1)*PATH_W-1:0] edges;
  wire [(UF+1)*PATH_W-1:0]   edges135;
  /* verilator lint_on UNUSEDSIGNAL */
  /* verilator lint_off PINCONNECTEMPTY */  // the schedule serves a chain-order cost stage only
  fpstereo_aggregator #(.W(W), .ROW_SLOTS(ROW_SLOTS), .K(K), .SEGMENT(SEGMENT), .G(G), .UF(UF),
                        .COST_W(COST_W), .COST_MAX(COST_MAX), .PATH_W(PATH_W), .SUM_W(SUM_W),
                        .PATHS(PATHS), .MATCH_SIDE(1), .LEVELS_PER_STAGE(LEVELS_PER_STAGE),
                        .PATH_TREE_LAT(PATH_TREE_LAT), .OUT_ROWS(OUT_ROWS), .OUT_ROW_W(OUT_ROW_W),
                        .COST_AW(COST_AW), .X_W(X_W), .Y_W(Y_W), .G_W(G_W), .K_W(K_W),
                        .COST_ROWS(COST_ROWS), .COST_ROW_W(COST_ROW_W), .MIN_DISP(MIN_DISP),
                        .CHAIN_BASE(FORWARD_LAG), .RIGHT_TO_LEFT(RIGHT_TO_LEFT)) match_aggregation (
    .clk(clk), .restart(restart), .adv(adv), .frame_width(frame_width), .frame_height(frame_height), .p1(p1),
    .p2(p2), .agg_on(match_on), .overlap(overlap), .wrapped(wrapped), .cost_raddr(match_raddr), .cost_schedule(),
    .cost_q(match_words), .sums(sums), .sums_active(active), .sums_x(x), .sums_group(group), .sums_chain(chain),
    .sums_slot(slot), .edge_in(edges), .edge135_in(edges135), .edge_out(edges), .edge135_out(edges135));
  /* verilator lint_on PINCONNECTEMPTY */
  wire              active_w;
  wire [X_W-1:0]    x_w;
  wire [OUT_ROW_W-1:0] slot_w;
  wire [G_W-1:0]    group_w;
  /* verilator lint_off UNUSEDSIGNAL */  // the match side's disparities are never invalid
  wire [DISP_W:0]   word_w;
  /* verilator lint_on UNUSEDSIGNAL */
  fpstereo_wta #(.UF(UF), .SUM_W(SUM_W), .DISP_W(DISP_W), .LANE_W(LANE_W), .G_W(G_W),
                 .TAG_W(1 + X_W + OUT_ROW_W), .LEVELS_PER_STAGE(LEVELS_PER_STAGE), .TREE_LAT(WTA_TREE_LAT)) wta (
    .clk(clk), .restart(restart), .adv(adv), .sums(sums), .group(group), .tag({active, x, slot}),
    .group_out(group_w), .tag_out({active_w, x_w, slot_w}), .word(word_w));
  assign completed_we = adv && active_w && group_w == LAST_GROUP;
  assign completed_waddr = slot_w * ROW_SLOTS + x_w;
  assign completed_wdata = word_w[DISP_W-1:0];
  // verilator lint_on WIDTH
endmodule
`resetall
