`resetall
`default_nettype none
// DEPTH registers in a row (DEPTH >= 1), advancing when en is high, cleared by rst (so that a
// valid flag travelling in it never starts out set).
module fpstereo_delay #(
  parameter WIDTH = 8,
  parameter DEPTH = 1
) (
  input  wire             clk,
  input  wire             rst,
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
  generate
    if (DEPTH == 1) begin : one
      always @(posedge clk)
        if (rst) line <= {WIDTH*DEPTH{1'b0}};
        else if (en) line <= in;
    end else begin : several
      always @(posedge clk)
        if (rst) line <= {WIDTH*DEPTH{1'b0}};
        else if (en) line <= {line[WIDTH*(DEPTH-1)-1:0], in};
    end
  endgenerate
  assign out = line[WIDTH*DEPTH-1 -: WIDTH];
endmodule
`resetall
