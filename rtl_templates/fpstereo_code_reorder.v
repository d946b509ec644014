`resetall
`default_nettype none
// Code reorder RAM (docs/architecture.md, "Code reorder"): instead of the cost words, each
// pixel's entries, written in raster order as the transform delivers them and read in the
// aggregation's chain order, where fpstereo_chain_cost computes the costs. The entry at (row, x)
// is the base pixel x's and the match pixel x - MIN_DISP's (the match entries wait MIN_DISP slots:
// a match history then serves d = 0 .. DMAX - 1 from its newest entry back; below MIN_DISP 0 the
// base entries and where they go wait -MIN_DISP slots instead, and the aggregation reads that
// much later; a row's first match entries, left of its first pixel's,
// come to fpstereo_chain_cost as its prefix). Rows outside the
// image are never written, so only valid rows' slots (row mod ROWS) matter. With EXTRA_W above 0
// (adaptive P2's penalties, which leave fpstereo_adaptive_p2 with the costs the raster stage
// would compute: a slot and EXTRA_LAT steps after the codes) a second RAM holds them per pixel,
// written at their position then, read at the same address.
module fpstereo_code_reorder #(
  parameter ROW_SLOTS = 64,
  parameter ENTRY_W = 24,
  parameter ROWS = 2,
  parameter ROW_W = 1,
  parameter AW = 7,
  parameter X_W = 7,
  parameter MIN_DISP = 0,
  parameter EXTRA_W = 0,
  parameter EXTRA_LAT = 2
) (
  input  wire                   clk,
  input  wire                   adv,
  input  wire                   shift,
  input  wire [ENTRY_W-1:0]     base_entry,
  input  wire [ENTRY_W-1:0]     match_entry,
  input  wire [X_W-1:0]         transform_x,
  input  wire [ROW_W-1:0]       transform_slot,
  // whether transform_x and its row lie in the frame (fpstereo_front_end)
  input  wire                   transform_in_frame,
  /* verilator lint_off UNUSEDSIGNAL */  // without EXTRA_W
  input  wire [(EXTRA_W > 0 ? EXTRA_W : 1)-1:0] extra,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [AW-1:0]          raddr,
  output wire [2*ENTRY_W-1:0]   q,
  output wire [(EXTRA_W > 0 ? EXTRA_W : 1)-1:0] extra_q
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (AW < $clog2(ROWS * ROW_SLOTS) || ROWS > (1 << ROW_W) || ROW_SLOTS - 1 >= (1 << X_W)) begin : invalid
      fpstereo_invalid_parameters_code_reorder_widths_too_narrow failed ();
    end
  endgenerate
  localparam POSITION_W = 1 + ROW_W + X_W;  // {in frame, row slot, x}
  wire [ENTRY_W-1:0] match_now, base_now;
  wire [POSITION_W-1:0] write_at;
  generate
    if (MIN_DISP > 0) begin : match_late
      fpstereo_delay #(.WIDTH(ENTRY_W), .DEPTH(MIN_DISP)) match_wait (
        .clk(clk), .rst(1'b0), .en(shift), .in(match_entry), .out(match_now));
    end else begin : match_in_time
      assign match_now = match_entry;
    end
    if (MIN_DISP < 0) begin : base_late
      // No reset: the wait carries a frame's last pixels into what follows it.
      fpstereo_delay #(.WIDTH(POSITION_W + ENTRY_W), .DEPTH(-MIN_DISP), .RESET(0)) base_wait (
        .clk(clk), .rst(1'b0), .en(shift), .in({transform_in_frame, transform_slot, transform_x, base_entry}),
        .out({write_at, base_now}));
    end else begin : base_in_time
      assign write_at = {transform_in_frame, transform_slot, transform_x};
      assign base_now = base_entry;
    end
  endgenerate
  // The address is a product of narrow counters and constants, cut to the RAM's address width.
  /* verilator lint_off WIDTH */
  wire [AW-1:0] waddr = write_at[ROW_W+X_W-1 -: ROW_W] * ROW_SLOTS + write_at[X_W-1:0];
  /* verilator lint_on WIDTH */
  fpstereo_ram_sdp #(.WIDTH(2*ENTRY_W), .DEPTH(ROWS * ROW_SLOTS), .ADDR_W(AW)) code_ram (
    .clk(clk), .we(shift && write_at[POSITION_W-1]), .waddr(waddr), .wdata({match_now, base_now}),
    .re(adv), .raddr(raddr), .rdata(q));
  generate
    if (EXTRA_W > 0) begin : extras
      // The position as the raster cost stage holds it (a slot), then EXTRA_LAT steps. Below
      // MIN_DISP 0 the penalties need not wait with the base entries (they pair with nothing):
      // written up to -MIN_DISP slots before their entries, they still find their slot read,
      // as the RAM's rows leave a row-time's ROW_SLOTS >= DMAX - MIN_DISP slots of slack.
      reg [POSITION_W-1:0] held;
      wire [POSITION_W-1:0] at;
      always @(posedge clk)
        if (shift) held <= {transform_in_frame, transform_slot, transform_x};
      fpstereo_delay #(.WIDTH(POSITION_W), .DEPTH(EXTRA_LAT)) extra_position (
        .clk(clk), .rst(1'b0), .en(adv), .in(held), .out(at));
      /* verilator lint_off WIDTH */
      wire [AW-1:0] extra_waddr = at[ROW_W+X_W-1 -: ROW_W] * ROW_SLOTS + at[X_W-1:0];
      /* verilator lint_on WIDTH */
      fpstereo_ram_sdp #(.WIDTH(EXTRA_W), .DEPTH(ROWS * ROW_SLOTS), .ADDR_W(AW)) extra_ram (
        .clk(clk), .we(adv && at[POSITION_W-1]), .waddr(extra_waddr), .wdata(extra),
        .re(adv), .raddr(raddr), .rdata(extra_q));
    end else begin : no_extras
      assign extra_q = 1'b0;
    end
  endgenerate
endmodule
`resetall
