`resetall
`default_nettype none
// DEPTH registers in a row (DEPTH >= 1), advancing when en is high. With RESET, rst clears them,
// so that a valid flag travelling in it never starts out set; without, rst is unused: data that a
// valid flag qualifies needs no reset, and registers without one need no reset routing and can
// become shift-register LUTs.
module fpstereo_delay #(
  parameter WIDTH = 8,
  parameter DEPTH = 1,
  // 1: rst clears every register (flags, tags); 0: no reset (data)
  parameter RESET = 0
) (
  input  wire             clk,
  /* verilator lint_off UNUSEDSIGNAL */  // unused without RESET
  input  wire             rst,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire             en,
  input  wire [WIDTH-1:0] in,
  output wire [WIDTH-1:0] out
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (DEPTH < 1 || WIDTH < 1) begin : invalid
      fpstereo_invalid_parameters_delay_DEPTH_or_WIDTH_below_1 failed ();
    end
  endgenerate
  reg [WIDTH*DEPTH-1:0] line;
  wire [WIDTH*DEPTH-1:0] shifted;
  generate
    if (DEPTH == 1) begin : one
      assign shifted = in;
    end else begin : several
      assign shifted = {line[WIDTH*(DEPTH-1)-1:0], in};
    end
    if (RESET != 0) begin : cleared
      always @(posedge clk)
        if (rst) line <= {WIDTH*DEPTH{1'b0}};
        else if (en) line <= shifted;
    end else begin : uncleared
      always @(posedge clk)
        if (en) line <= shifted;
    end
  endgenerate
  assign out = line[WIDTH*DEPTH-1 -: WIDTH];
endmodule
`resetall
