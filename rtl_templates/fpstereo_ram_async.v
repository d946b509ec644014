`resetall
`default_nettype none
// Small RAM with two asynchronous read ports (distributed RAM): per-chain state that must be
// read in the cycle it is needed. Writes take effect at the clock edge, so reads in the same
// cycle see the old word.
module fpstereo_ram_async #(
  // word width in bits
  parameter WIDTH = 8,
  // number of words
  parameter DEPTH = 4,
  // address bits, at least clog2(DEPTH)
  parameter ADDR_W = 2
) (
  input  wire              clk,
  input  wire              we,
  input  wire [ADDR_W-1:0] waddr,
  input  wire [WIDTH-1:0]  wdata,
  input  wire [ADDR_W-1:0] raddr_a,
  output wire [WIDTH-1:0]  rdata_a,
  input  wire [ADDR_W-1:0] raddr_b,
  output wire [WIDTH-1:0]  rdata_b
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (DEPTH < 1 || ADDR_W < $clog2(DEPTH)) begin : invalid
      fpstereo_invalid_parameters_ram_async_ADDR_W_below_clog2_DEPTH failed ();
    end
  endgenerate
  reg [WIDTH-1:0] mem [0:DEPTH-1];

  always @(posedge clk)
    if (we) mem[waddr] <= wdata;

  assign rdata_a = mem[raddr_a];
  assign rdata_b = mem[raddr_b];
endmodule
`resetall
