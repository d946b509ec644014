`resetall
`default_nettype none
// The match side's disparity Dm(x') for the left-right check (fpstereo_lr_check), two steps: the
// RAMs are read with x' in the first, Dm is there (combinational, from the RAMs' registered
// outputs) in the second. The match side writes Dm of its completed pixels into the completed
// RAM and, with ROW_END (LR1), the last DMAX - 1 of each row into the row-end RAM, one word of
// UF per group: x' reads the row end where e = frame_width - 1 - MIN_DISP - x' < DMAX - 1, and
// is 0 where no base pixel of the row meets it (e < 0 or e > frame_width - 1 + DMAX - 1).
module fpstereo_match_lookup #(
  parameter ROW_SLOTS = 64,
  parameter G = 4,
  parameter UF = 8,
  parameter DMAX = 32,
  parameter DISP_W = 5,
  parameter OUT_ROWS = 3,
  parameter OUT_ROW_W = 2,
  parameter DISP_AW = 8,
  parameter ROW_END = 1,
  parameter END_AW = 4,
  parameter X_W = 7,
  parameter LANE_W = 3,
  parameter MIN_DISP = 0
) (
  input  wire                 clk,
  input  wire                 adv,
  /* verilator lint_off UNUSEDSIGNAL */  // only LR1's row ends need the width
  input  wire [X_W-1:0]       frame_width,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire                 completed_we,
  input  wire [DISP_AW-1:0]   completed_waddr,
  input  wire [DISP_W-1:0]    completed_wdata,
  /* verilator lint_off UNUSEDSIGNAL */  // LR2 has no row-end RAM
  input  wire                 row_end_we,
  input  wire [END_AW-1:0]    row_end_waddr,
  input  wire [UF*DISP_W-1:0] row_end_wdata,
  /* verilator lint_on UNUSEDSIGNAL */
  // first step: the row's slot in the RAMs and x'
  input  wire [OUT_ROW_W-1:0]   slot_row,
  input  wire [X_W-1:0]       xm,
  // second step
  output wire [DISP_W-1:0]    dm
);
  generate
    if (DISP_AW < $clog2(OUT_ROWS * ROW_SLOTS) || (ROW_END != 0 && END_AW < $clog2(OUT_ROWS * G))) begin : invalid
      fpstereo_invalid_parameters_match_lookup_addresses_too_narrow failed ();
    end
  endgenerate
  // Addresses are products of narrow counters and constants, cut to the RAMs' address widths.
  // verilator lint_off WIDTH
  wire [DISP_W-1:0] completed_q;
  wire [DISP_AW-1:0] completed_raddr = slot_row * ROW_SLOTS + xm;
  fpstereo_ram_sdp #(.WIDTH(DISP_W), .DEPTH(OUT_ROWS * ROW_SLOTS), .ADDR_W(DISP_AW)) completed (
    .clk(clk), .we(completed_we), .waddr(completed_waddr), .wdata(completed_wdata),
    .re(adv), .raddr(completed_raddr), .rdata(completed_q));
  generate
    if (ROW_END != 0) begin : row_end
      // e = frame_width - 1 - MIN_DISP - x', as (frame_width - 1 + AHEAD) - (x' + BEHIND)
      localparam integer BEHIND = MIN_DISP > 0 ? MIN_DISP : 0;
      localparam integer AHEAD = MIN_DISP < 0 ? -MIN_DISP : 0;
      localparam P_W = X_W + 10;
      wire [P_W-1:0] last_ahead = frame_width - 1 + AHEAD;
      wire [P_W-1:0] xm_behind = xm + BEHIND;
      wire from_row_end = xm_behind + (DMAX - 1) > last_ahead;
      wire [DISP_W-1:0] from_end = last_ahead - xm_behind;  // the row-end entry of x'
      // no base pixel: right of the last one's reach (MIN_DISP > 0), or left of the first's
      wire none = (MIN_DISP > 0 && xm_behind > last_ahead) ||
                  (MIN_DISP < -(DMAX - 1) && xm + (DMAX - 1) < AHEAD);
      reg none_q;
      wire [UF*DISP_W-1:0] end_q;
      wire [END_AW-1:0] end_raddr = slot_row * G + from_end / UF;
      fpstereo_ram_sdp #(.WIDTH(UF*DISP_W), .DEPTH(OUT_ROWS * G), .ADDR_W(END_AW)) row_end (
        .clk(clk), .we(row_end_we), .waddr(row_end_waddr), .wdata(row_end_wdata),
        .re(adv), .raddr(end_raddr), .rdata(end_q));
      reg              from_row_end_q;
      reg [LANE_W-1:0] lane_q;
      always @(posedge clk)
        if (adv) begin
          from_row_end_q <= from_row_end;
          lane_q <= from_end % UF;
          none_q <= none;
        end
      assign dm = none_q ? {DISP_W{1'b0}} : from_row_end_q ? end_q[lane_q * DISP_W +: DISP_W] : completed_q;
    end else begin : completed_only
      assign dm = completed_q;
    end
  endgenerate
  // verilator lint_on WIDTH
endmodule
`resetall
