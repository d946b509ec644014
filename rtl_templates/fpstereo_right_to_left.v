`resetall
`default_nettype none
// The 180-degree path (docs/path180-hardware.md, docs/semantics.md section 3): a mirrored
// aggregator (fpstereo_aggregator with MIRROR) whose chain k works on row ta - 1 - k from the
// row's end, reading the cost words from a second read of the RAM that holds them (mirror_raddr,
// mirror_q: the cost reorder RAM's copy, or on LR2's match side its lane banks' copies); its path
// costs go into the L_180 RAM at the cost RAM's addresses (row slot, pixel, group), so the forward
// aggregator, which runs K + 2 row-times behind the writes (CHAIN_BASE), reads a word's L_180
// beside its costs at the same address and step. The L_180 RAM holds COST_ROWS rows, the cost
// RAM's.
module fpstereo_right_to_left #(
  parameter W = 64,
  parameter ROW_SLOTS = 64,
  parameter K = 2,
  parameter SEGMENT = 32,
  parameter G = 4,
  parameter UF = 8,
  parameter COST_W = 5,
  parameter COST_MAX = 24,
  parameter PATH_W = 7,
  // the P2 fields above each word's costs (adaptive P2: the base side's paths, the 0-degree first)
  parameter PENALTIES = 0,
  parameter LEVELS_PER_STAGE = 3,
  parameter PATH_TREE_LAT = 1,
  parameter COST_AW = 10,
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter G_W = 2,
  parameter K_W = 1,
  parameter COST_ROWS = 2,
  parameter COST_ROW_W = 1,
  // LR2's match side (fpstereo_aggregator's MATCH_SIDE and MIN_DISP)
  parameter MATCH_SIDE = 0,
  parameter MIN_DISP = 0
) (
  input  wire                   clk,
  input  wire                   restart,
  input  wire                   adv,
  input  wire [X_W-1:0]         frame_width,
  input  wire [Y_W-1:0]         frame_height,
  input  wire [PATH_W-1:0]      p1,
  input  wire [PATH_W-1:0]      p2,
  input  wire                   agg_on,
  input  wire                   overlap,
  input  wire                   wrapped,
  // the mirrored aggregator's reads of the cost words, answered a step later
  output wire [COST_AW-1:0]     mirror_raddr,
  input  wire [UF*COST_W+PENALTIES*PATH_W-1:0] mirror_q,
  // the forward aggregator's read address, and L_180 of its word a step later
  input  wire [COST_AW-1:0]     path_raddr,
  output wire [UF*PATH_W-1:0]   path_q
);
  localparam DEPTH = COST_ROWS * ROW_SLOTS * G;
  wire [UF*PATH_W-1:0]  mirror_sums;
  wire                  mirror_active;
  wire [X_W-1:0]        mirror_x;
  wire [G_W-1:0]        mirror_group;
  wire [COST_ROW_W-1:0] mirror_slot;
  localparam EDGE_W = (UF + 1) * PATH_W;
  /* verilator lint_off PINCONNECTEMPTY */
  fpstereo_aggregator #(
    .W(W), .ROW_SLOTS(ROW_SLOTS), .K(K), .SEGMENT(SEGMENT), .G(G), .UF(UF), .COST_W(COST_W),
    .COST_MAX(COST_MAX), .PATH_W(PATH_W), .SUM_W(PATH_W), .PATHS(1), .PENALTIES(PENALTIES),
    .LEVELS_PER_STAGE(LEVELS_PER_STAGE), .PATH_TREE_LAT(PATH_TREE_LAT), .OUT_ROWS(COST_ROWS),
    .OUT_ROW_W(COST_ROW_W), .COST_AW(COST_AW), .X_W(X_W), .Y_W(Y_W), .G_W(G_W), .K_W(K_W),
    .COST_ROWS(COST_ROWS), .COST_ROW_W(COST_ROW_W), .CHAIN_BASE(1), .MIRROR(1), .MATCH_SIDE(MATCH_SIDE),
    .MIN_DISP(MIN_DISP)
  ) mirror (
    .clk(clk), .restart(restart), .adv(adv), .frame_width(frame_width), .frame_height(frame_height),
    .p1(p1), .p2(p2), .agg_on(agg_on), .overlap(overlap), .wrapped(wrapped),
    .cost_raddr(mirror_raddr), .cost_schedule(), .cost_q(mirror_q),
    .sums(mirror_sums), .sums_active(mirror_active), .sums_x(mirror_x), .sums_group(mirror_group),
    .sums_chain(), .sums_slot(mirror_slot),
    .edge_in({2*EDGE_W{1'b0}}), .edge135_in({EDGE_W{1'b0}}), .edge_out(), .edge135_out());
  /* verilator lint_on PINCONNECTEMPTY */

  // The sums' slot is the row's slot in the cost RAM (OUT_ROWS = COST_ROWS).
  /* verilator lint_off WIDTH */
  wire [COST_AW-1:0] path_waddr = (mirror_slot * ROW_SLOTS + mirror_x) * G + mirror_group;
  /* verilator lint_on WIDTH */
  fpstereo_ram_sdp #(.WIDTH(UF*PATH_W), .DEPTH(DEPTH), .ADDR_W(COST_AW)) paths (
    .clk(clk), .we(adv && mirror_active), .waddr(path_waddr), .wdata(mirror_sums),
    .re(adv), .raddr(path_raddr), .rdata(path_q));
endmodule
`resetall
