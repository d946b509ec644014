`resetall
`default_nettype none
// Simple dual-port RAM with a registered read port (what block RAM inference needs). The read
// register only loads when re is high, so a stalled pipeline keeps its read data.
module fpstereo_ram_sdp #(
  // word width in bits
  parameter WIDTH = 8,
  // number of words
  parameter DEPTH = 16,
  // address bits, at least clog2(DEPTH)
  parameter ADDR_W = 4
) (
  input  wire              clk,
  input  wire              we,
  input  wire [ADDR_W-1:0] waddr,
  input  wire [WIDTH-1:0]  wdata,
  input  wire              re,
  input  wire [ADDR_W-1:0] raddr,
  output reg  [WIDTH-1:0]  rdata
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (DEPTH < 1 || ADDR_W < $clog2(DEPTH)) begin : invalid
      fpstereo_invalid_parameters_ram_sdp_ADDR_W_below_clog2_DEPTH failed ();
    end
  endgenerate
  reg [WIDTH-1:0] mem [0:DEPTH-1];

  always @(posedge clk) begin
    if (we) mem[waddr] <= wdata;
    if (re) rdata <= mem[raddr];
  end
endmodule
`resetall
