`resetall
`default_nettype none
// The last DMAX match-image codes, in a ring that rotates by UF each step, so lane l always
// reads disparity g*UF + l in step g of a slot from ring[l], without a wide multiplexer. In a
// slot's last step the ring completes its turn and shifts the next code in:
// after it, ring[i] holds the code of the pixel i columns left of the new one.
module fpstereo_match_ring #(
  // code width
  parameter CODE_W = 48,
  // disparity range
  parameter DMAX = 128,
  // disparities per step
  parameter UF = 32
) (
  input  wire               clk,
  input  wire               en,
  input  wire               slot_end,
  input  wire [CODE_W-1:0]  code_in,
  output wire [UF*CODE_W-1:0] lanes
);
  reg [DMAX*CODE_W-1:0] ring;
  assign lanes = ring[UF*CODE_W-1:0];

  integer i;
  always @(posedge clk)
    if (en)
      for (i = 0; i < DMAX; i = i + 1)
        if (!slot_end) ring[i*CODE_W +: CODE_W] <= ring[((i + UF) % DMAX)*CODE_W +: CODE_W];
        else if (i == 0) ring[0 +: CODE_W] <= code_in;
        else ring[i*CODE_W +: CODE_W] <= ring[((i - 1 + UF) % DMAX)*CODE_W +: CODE_W];
endmodule
`resetall
