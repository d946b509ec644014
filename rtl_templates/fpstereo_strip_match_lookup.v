`resetall
`default_nettype none
// The match side's disparity Dm(x') for one word of a slot in strips (docs/ppc-hardware.md, "The
// left-right check in strips"), two steps, as fpstereo_match_lookup at one pixel a clock: x' is
// given as x' + BEHIND (xm_behind) and with the place of the base pixel that completes it,
// x' + MIN_DISP + DMAX - 1 (completing; the caller forms each in one adder from its registers).
// Strip b's completed pixels are in a bank of their own, (P - b) * K + 1 rows of STRIP_PIXELS,
// at row slot * STRIP_PIXELS + completing - b * STRIP_PIXELS (addrs: the caller forms each bank's
// address in one subtraction from registers); every bank is read at once and the one holding the
// completing pixel picked in the second step. x' reads the row end where its
// completing pixel lies right of the row (from the row-end RAM, P * K + 1 rows), and is 0 where
// no base pixel of the row meets it. end_slot: the row slot of the row read in the row-end RAM
// (the strip's that wrote the row end). With LR2 the banks hold LR2's match side's Dm of
// every match pixel at its own place (strip b: its pixels x', completing = x'), and there is no row
// end.
module fpstereo_strip_match_lookup #(
  parameter P = 2,
  parameter K = 5,
  parameter STRIP_PIXELS = 20,
  parameter DMAX = 16,
  parameter DISP_W = 4,
  parameter CAW = 9,
  parameter X_W = 7,
  parameter MIN_DISP = 0,
  parameter LR2 = 0
) (
  input  wire                 clk,
  input  wire                 adv,
  input  wire [X_W-1:0]       frame_width,
  input  wire [P-1:0]         completed_we,
  /* verilator lint_off UNUSEDSIGNAL */  // the strips right of 0 have fewer rows: their top bits
  input  wire [P*CAW-1:0]     completed_waddr,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [P*DISP_W-1:0]  completed_wdata,
  // the row-end write, the writing strip's (unused with LR2)
  /* verilator lint_off UNUSEDSIGNAL */
  input  wire                 end_we,
  input  wire [$clog2(P*K+1)-1:0] end_waddr,
  input  wire [DMAX*DISP_W-1:0] end_wdata,
  // first step: each bank's read address (the top bits unused as in the writes'), the row end's
  input  wire [P*CAW-1:0]     addrs,
  input  wire [$clog2(P*K+1)-1:0] end_slot,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [X_W+9:0]       xm_behind,
  input  wire [X_W+9:0]       completing,
  // second step
  output wire [DISP_W-1:0]    dm
);
  localparam R = STRIP_PIXELS;
  localparam B_W = P > 1 ? $clog2(P) : 1;
  localparam END_ROWS = P * K + 1;  // strip 0's rows, the most
  localparam END_AW = $clog2(END_ROWS);
  localparam LANE_W = $clog2(DMAX);
  localparam integer AHEAD = MIN_DISP < 0 ? -MIN_DISP : 0;
  localparam P_W = X_W + 10;
  // Positions against the frame's width and constants: the compares widen them.
  // verilator lint_off WIDTH
  wire [P_W-1:0] last_ahead = frame_width - 1 + AHEAD;
  // x' from the row end where its completing pixel lies right of the row
  wire from_row_end = xm_behind + (DMAX - 1) > last_ahead;
  wire [LANE_W-1:0] from_end = last_ahead - xm_behind;  // the row-end lane, where it is one
  wire none = (MIN_DISP > 0 && xm_behind > last_ahead) ||
              (MIN_DISP < -(DMAX - 1) && xm_behind + (DMAX - 1) < AHEAD);
  // the completing pixel's strip: the last whose first pixel it reaches
  reg [B_W-1:0] bank;
  integer t;
  always @* begin
    bank = {B_W{1'b0}};
    for (t = 1; t < P; t = t + 1)
      if (completing >= t * R) bank = t[B_W-1:0];
  end
  wire [P*DISP_W-1:0] banks_q;
  genvar b;
  generate
    for (b = 0; b < P; b = b + 1) begin : bank_of_strip
      localparam ROWS = (P - b) * K + 1;
      localparam AW = $clog2(ROWS * R);
      fpstereo_ram_sdp #(.WIDTH(DISP_W), .DEPTH(ROWS * R), .ADDR_W(AW)) completed (
        .clk(clk), .we(completed_we[b]), .waddr(completed_waddr[b*CAW +: AW]),
        .wdata(completed_wdata[b*DISP_W +: DISP_W]), .re(adv), .raddr(addrs[b*CAW +: AW]), .rdata(banks_q[b*DISP_W +: DISP_W]));
    end
  endgenerate
  wire [DMAX*DISP_W-1:0] end_q;
  generate
    if (LR2 == 0) begin : with_row_end
      fpstereo_ram_sdp #(.WIDTH(DMAX*DISP_W), .DEPTH(END_ROWS), .ADDR_W(END_AW)) row_end (
        .clk(clk), .we(end_we), .waddr(end_waddr), .wdata(end_wdata), .re(adv), .raddr(end_slot), .rdata(end_q));
    end else begin : without_row_end
      assign end_q = {DMAX*DISP_W{1'b0}};
    end
  endgenerate
  reg [B_W-1:0]    bank_c;
  reg [LANE_W-1:0] lane_c;
  reg              from_row_end_c, none_c;
  always @(posedge clk)
    if (adv) begin
      bank_c <= bank;
      lane_c <= from_end;
      from_row_end_c <= LR2 == 0 && from_row_end;
      none_c <= LR2 == 0 && none;
    end
  assign dm = none_c ? {DISP_W{1'b0}} : from_row_end_c ? end_q[lane_c * DISP_W +: DISP_W] :
              banks_q[bank_c * DISP_W +: DISP_W];
  // verilator lint_on WIDTH
endmodule
`resetall
