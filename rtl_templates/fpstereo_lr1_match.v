`resetall
`default_nettype none
// LR1 match side (docs/semantics.md, section 5): Dm(x') = argmin_d S(x' + m + d, d) from the base
// side's sums (m = MIN_DISP). Each chain keeps, for the match pixels x - m - e (e < DMAX) of its
// current pixel x, the best (sum, disparity) over d <= e so far; the next pixel shifts them by one
// and offers its own S(x + 1, e + 1), smaller d winning ties (at a row's first pixel there is
// nothing to shift in: with m < 0 its match pixels start there). At e = DMAX - 1 a match pixel is
// complete (completed_*, if it lies in the row); at the row's end the rest are (row_end_*, one
// word of UF per group). The state follows the chains like the path costs do.
// In strips (STRIPS, uf = dmax; docs/ppc-hardware.md, "The left-right check in strips") one
// instance per strip: the strip's first pixel X_BASE continues the row from the state the strip to
// its left had after its last pixel (edge_in, that strip's edge_out), and a completed match pixel
// is written at the address of the base pixel that completes it, slot * ROW_SLOTS + x - X_BASE
// (its match pixel is x - MIN_DISP - (DMAX - 1)), so that each strip writes its own RAM bank.
module fpstereo_lr1_match #(
  parameter K = 2,
  parameter G = 4,
  parameter UF = 8,
  parameter DMAX = 32,
  parameter ROW_SLOTS = 64,
  parameter SUM_W = 9,
  parameter DISP_W = 5,
  parameter OUT_ROW_W = 2,
  parameter DISP_AW = 8,
  parameter END_AW = 4,
  parameter X_W = 7,
  parameter G_W = 2,
  parameter K_W = 1,
  parameter MIN_DISP = 0,
  // 1: one strip of several, X_BASE its first pixel (G = 1)
  parameter STRIPS = 0,
  parameter X_BASE = 0
) (
  input  wire                 clk,
  input  wire                 adv,
  input  wire [X_W-1:0]       frame_width,
  // the base side's sums of one group of one pixel, and where they belong
  input  wire [UF*SUM_W-1:0]  sums,
  input  wire                 active,
  input  wire [X_W-1:0]       x,
  input  wire [G_W-1:0]       group,
  input  wire [K_W-1:0]       chain,
  input  wire [OUT_ROW_W-1:0]   slot,
  output wire                 completed_we,
  output wire [DISP_AW-1:0]   completed_waddr,
  output wire [DISP_W-1:0]    completed_wdata,
  output wire                 row_end_we,
  output wire [END_AW-1:0]    row_end_waddr,
  output wire [UF*DISP_W-1:0] row_end_wdata,
  // with STRIPS: the state after the left strip's last pixel, and this strip's after its own
  /* verilator lint_off UNUSEDSIGNAL */  // in the first strip, or without STRIPS
  input  wire [UF*(SUM_W+DISP_W)-1:0] edge_in,
  /* verilator lint_on UNUSEDSIGNAL */
  output reg  [UF*(SUM_W+DISP_W)-1:0] edge_out
);
  localparam E_W = SUM_W + DISP_W;
  localparam STATE_DEPTH = K * G;
  localparam STATE_AW = STATE_DEPTH > 1 ? $clog2(STATE_DEPTH) : 1;
  localparam integer LAST_GROUP_I = G - 1;
  localparam [G_W-1:0] LAST_GROUP = LAST_GROUP_I[G_W-1:0];
  generate
    if (DMAX != G * UF) begin : invalid
      fpstereo_invalid_parameters_DMAX_is_not_G_times_UF failed ();
    end
    if (STRIPS != 0 && (G != 1 || X_BASE < 0 || X_BASE >= (1 << X_W))) begin : invalid_strip
      fpstereo_invalid_parameters_lr1_match_strips_need_G_1_and_X_BASE_within_X_W failed ();
    end
  endgenerate
  // Addresses and disparities are products of narrow counters and constants, cut to width.
  // verilator lint_off WIDTH
  wire [STATE_AW-1:0] entry_addr = chain * G + group;
  wire [UF*E_W-1:0]   stored, previous, updated;
  /* verilator lint_off UNUSEDSIGNAL */  // one read port is enough here
  wire [UF*E_W-1:0]   stored_unused;
  /* verilator lint_on UNUSEDSIGNAL */
  fpstereo_ram_async #(.WIDTH(UF*E_W), .DEPTH(STATE_DEPTH), .ADDR_W(STATE_AW)) entries (
    .clk(clk), .we(adv && active), .waddr(entry_addr), .wdata(updated),
    .raddr_a(entry_addr), .rdata_a(stored), .raddr_b(entry_addr), .rdata_b(stored_unused));
  localparam FROM_LEFT = STRIPS != 0 && X_BASE != 0;
  localparam integer X_FIRST_I = X_BASE, X_LAST_I = X_BASE + ROW_SLOTS - 1;
  localparam [X_W-1:0] X_FIRST = X_FIRST_I[X_W-1:0], X_LAST = X_LAST_I[X_W-1:0];
  assign previous = FROM_LEFT && x == X_FIRST ? edge_in : stored;
  // Only the first strip (or the whole row) holds the row's first pixel; right of it x is never 0,
  // and the compare would only deepen the take behind the left edge's multiplexer.
  localparam ROW_FIRST = !FROM_LEFT;
  // The strip's last pixel's state, for the next strip's first pixel K + 1 steps later (the
  // last strip's goes nowhere).
  always @(posedge clk)
    if (adv && active && x == X_LAST) edge_out <= updated;
  reg [E_W-1:0] below_q;  // the previous group's last entry, before this pixel overwrote it
  always @(posedge clk)
    if (adv) below_q <= previous[UF*E_W-1 -: E_W];
  genvar l;
  generate
    for (l = 0; l < UF; l = l + 1) begin : lane
      wire [DISP_W-1:0] disparity = group * UF + l;
      wire [E_W-1:0]    earlier = (l == 0) ? below_q : previous[(l-1)*E_W +: E_W];
      wire [SUM_W-1:0]  offered = sums[l*SUM_W +: SUM_W];
      wire              take = disparity == 0 || (MIN_DISP < 0 && ROW_FIRST && x == 0) || offered < earlier[E_W-1 -: SUM_W];
      assign updated[l*E_W +: E_W] = take ? {offered, disparity} : earlier;
      assign row_end_wdata[l*DISP_W +: DISP_W] = updated[l*E_W +: DISP_W];
    end
  endgenerate
  // The completed match pixel x - m - (DMAX - 1), as x + AHEAD - BEHIND - (DMAX - 1): inside the
  // row unless left of it or (far enough below 0) right of it.
  localparam integer BEHIND = MIN_DISP > 0 ? MIN_DISP : 0;
  localparam integer AHEAD = MIN_DISP < 0 ? -MIN_DISP : 0;
  localparam P_W = X_W + 10;
  wire [P_W-1:0] x_ahead = x + AHEAD;
  wire completed_inside = x_ahead >= DMAX - 1 + BEHIND &&
                          (MIN_DISP >= -(DMAX - 1) || x_ahead < frame_width + (DMAX - 1));
  assign completed_we = adv && active && group == LAST_GROUP && completed_inside;
  assign completed_waddr = slot * ROW_SLOTS + (STRIPS != 0 ? x - X_BASE : x_ahead - (DMAX - 1 + BEHIND));
  assign completed_wdata = updated[(UF-1)*E_W +: DISP_W];
  assign row_end_we = adv && active && x == frame_width - 1;
  assign row_end_waddr = slot * G + group;
  // verilator lint_on WIDTH
endmodule
`resetall
