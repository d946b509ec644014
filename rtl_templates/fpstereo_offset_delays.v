`resetall
`default_nettype none
// The disparity offset's delays in a cost stage (docs/semantics.md, section 2: base pixel x
// against match pixel x - MIN_DISP - d). The match ring serves d = 0 .. DMAX - 1 from its newest
// column back, so with MIN_DISP > 0 the match columns enter it MIN_DISP slots late; with
// MIN_DISP < 0 the base (its data and its centre's position) waits -MIN_DISP slots instead, so
// that the ring already holds the match columns right of it. Shift registers, advanced once per
// slot; pass-through at MIN_DISP = 0.
module fpstereo_offset_delays #(
  parameter BASE_W = 8,
  parameter MATCH_W = 8,
  parameter MIN_DISP = 0
) (
  /* verilator lint_off UNUSEDSIGNAL */  // at MIN_DISP = 0 nothing waits
  input  wire               clk,
  input  wire               shift,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [BASE_W-1:0]  base,
  input  wire [MATCH_W-1:0] match,
  output wire [BASE_W-1:0]  base_out,
  output wire [MATCH_W-1:0] match_out
);
  generate
    if (MIN_DISP > 0) begin : match_late
      fpstereo_delay #(.WIDTH(MATCH_W), .DEPTH(MIN_DISP)) match_wait (
        .clk(clk), .rst(1'b0), .en(shift), .in(match), .out(match_out));
    end else begin : match_now
      assign match_out = match;
    end
    if (MIN_DISP < 0) begin : base_late
      fpstereo_delay #(.WIDTH(BASE_W), .DEPTH(-MIN_DISP)) base_wait (
        .clk(clk), .rst(1'b0), .en(shift), .in(base), .out(base_out));
    end else begin : base_now
      assign base_out = base;
    end
  endgenerate
endmodule
`resetall
