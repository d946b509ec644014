`resetall
`default_nettype none
// True dual-port RAM, one clock, registered reads, read-first on each port: two independent
// read/write ports, as a block RAM offers them, for a memory written from two places in one clock.
// A port's read register only loads when its re is high. Both ports writing one address in the
// same clock is the user's to avoid (the stored word is then port B's).
module fpstereo_ram_tdp #(
  // word width in bits
  parameter WIDTH = 8,
  // number of words
  parameter DEPTH = 16,
  // address bits, at least clog2(DEPTH)
  parameter ADDR_W = 4
) (
  input  wire              clk,
  input  wire              we_a,
  input  wire              re_a,
  input  wire [ADDR_W-1:0] addr_a,
  input  wire [WIDTH-1:0]  wdata_a,
  output reg  [WIDTH-1:0]  rdata_a,
  input  wire              we_b,
  input  wire              re_b,
  input  wire [ADDR_W-1:0] addr_b,
  input  wire [WIDTH-1:0]  wdata_b,
  output reg  [WIDTH-1:0]  rdata_b
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (DEPTH < 1 || ADDR_W < $clog2(DEPTH)) begin : invalid
      fpstereo_invalid_parameters_ram_tdp_ADDR_W_below_clog2_DEPTH failed ();
    end
  endgenerate
  reg [WIDTH-1:0] mem [0:DEPTH-1];

  always @(posedge clk) begin
    if (re_a) rdata_a <= mem[addr_a];
    if (we_a) mem[addr_a] <= wdata_a;
  end
  always @(posedge clk) begin
    if (re_b) rdata_b <= mem[addr_b];
    if (we_b) mem[addr_b] <= wdata_b;
  end
endmodule
`resetall
