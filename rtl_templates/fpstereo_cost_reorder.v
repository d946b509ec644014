`resetall
`default_nettype none
// Cost reorder RAM (docs/architecture.md): the cost words, written in raster order as the cost
// lanes deliver them (LAT steps after the centre's position), read in the aggregation's chain
// order. Rows outside the image are never written, so only valid rows' slots (row mod
// COST_ROWS) matter. The written word's position leaves as the cost tag (LR2's banks use it).
// A word may carry EXTRA_W bits above its costs (adaptive P2's penalties), stored with them.
// With SECOND_READ a copy of the RAM, written alike, answers a second reader (the mirrored
// chains of the 180-degree path): a block RAM has one read port beside its write.
module fpstereo_cost_reorder #(
  parameter ROW_SLOTS = 64,
  parameter G = 4,
  parameter UF = 8,
  parameter COST_W = 5,
  parameter EXTRA_W = 0,
  // register stages of the cost lanes
  parameter LAT = 1,
  parameter COST_ROWS = 2,
  parameter COST_ROW_W = 1,
  parameter COST_AW = 10,
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter SIGNED_Y_W = 8,
  parameter G_W = 2,
  parameter SECOND_READ = 0
) (
  input  wire                   clk,
  input  wire                   restart,
  input  wire                   adv,
  input  wire [X_W-1:0]         frame_width,
  input  wire [Y_W-1:0]         frame_height,
  input  wire [G_W-1:0]         group,
  input  wire [X_W-1:0]         history_x,
  input  wire signed [SIGNED_Y_W-1:0] history_y,
  input  wire [COST_ROW_W-1:0]    history_slot,
  input  wire [UF*COST_W+EXTRA_W-1:0] costs,
  output wire                   cost_valid,
  output wire [X_W-1:0]         cost_x,
  output wire [COST_ROW_W-1:0]    cost_row_slot,
  output wire [G_W-1:0]         cost_group,
  input  wire [COST_AW-1:0]     cost_raddr,
  output wire [UF*COST_W+EXTRA_W-1:0] cost_q,
  /* verilator lint_off UNUSEDSIGNAL */  // without SECOND_READ
  input  wire [COST_AW-1:0]     second_raddr,
  /* verilator lint_on UNUSEDSIGNAL */
  output wire [UF*COST_W+EXTRA_W-1:0] second_q
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (LAT < 1) begin : invalid_LAT
      fpstereo_invalid_parameters_cost_reorder_LAT_below_1 failed ();
    end
    if (COST_AW < $clog2(COST_ROWS * ROW_SLOTS * G) || COST_ROWS > (1 << COST_ROW_W) || G - 1 >= (1 << G_W) || ROW_SLOTS - 1 >= (1 << X_W) || SIGNED_Y_W < Y_W + 2) begin : invalid_widths
      fpstereo_invalid_parameters_cost_reorder_addresses_or_positions_too_narrow failed ();
    end
  endgenerate
  localparam COST_DEPTH = COST_ROWS * ROW_SLOTS * G;
  wire [X_W:0] width_x = {1'b0, frame_width};
  wire signed [SIGNED_Y_W-1:0] height_y = $signed({2'b00, frame_height});
  wire history_valid = {1'b0, history_x} < width_x && history_y >= 0 && history_y < height_y;
  fpstereo_delay #(.WIDTH(1 + X_W + COST_ROW_W + G_W), .DEPTH(LAT), .RESET(1)) cost_tag (
    .clk(clk), .rst(restart), .en(adv), .in({history_valid, history_x, history_slot, group}),
    .out({cost_valid, cost_x, cost_row_slot, cost_group}));
  // The address is a product of narrow counters and constants, cut to the RAM's address width.
  /* verilator lint_off WIDTH */
  wire [COST_AW-1:0] cost_waddr = (cost_row_slot * ROW_SLOTS + cost_x) * G + cost_group;
  /* verilator lint_on WIDTH */
  fpstereo_ram_sdp #(.WIDTH(UF*COST_W+EXTRA_W), .DEPTH(COST_DEPTH), .ADDR_W(COST_AW)) cost_ram (
    .clk(clk), .we(adv && cost_valid), .waddr(cost_waddr), .wdata(costs),
    .re(adv), .raddr(cost_raddr), .rdata(cost_q));
  generate
    if (SECOND_READ != 0) begin : second
      fpstereo_ram_sdp #(.WIDTH(UF*COST_W+EXTRA_W), .DEPTH(COST_DEPTH), .ADDR_W(COST_AW)) cost_ram (
        .clk(clk), .we(adv && cost_valid), .waddr(cost_waddr), .wdata(costs),
        .re(adv), .raddr(second_raddr), .rdata(second_q));
    end else begin : no_second
      assign second_q = {UF*COST_W+EXTRA_W{1'b0}};
    end
  endgenerate
endmodule
`resetall
