`resetall
`default_nettype none
// The match image's last DMAX + SPAN - 1 columns (a column: what one slot contributes, e.g. a
// code, or SPAN pixels of a window column), in a ring that rotates by UF each step: in step g of
// a slot, view column p holds the column g*UF + p slots back from the newest, so lane l of the
// group reads its columns l .. l + SPAN - 1 from fixed registers, without wide multiplexers. The
// slot's last step completes the ring's turn and shifts the next column in (docs/architecture.md).
module fpstereo_match_ring #(
  // bits of one column
  parameter COLUMN_W = 48,
  // window side the lanes need (1: one code per disparity)
  parameter SPAN = 1,
  // disparity range
  parameter DMAX = 128,
  // disparities per step
  parameter UF = 32
) (
  input  wire                            clk,
  input  wire                            en,
  input  wire                            slot_end,
  input  wire [COLUMN_W-1:0]             column_in,
  output wire [(UF+SPAN-1)*COLUMN_W-1:0] view
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (UF < 1 || SPAN < 1 || DMAX < UF || DMAX % (UF > 0 ? UF : 1) != 0) begin : invalid
      fpstereo_invalid_parameters_match_ring_DMAX_is_not_a_multiple_of_UF failed ();
    end
  endgenerate
  localparam LENGTH = DMAX + SPAN - 1;
  // Where each register takes its column from: a turn by UF, or (in a slot's last step) the
  // turn that completes the slot plus the shift by one slot.
  localparam TURN = UF % LENGTH;
  localparam SHIFT = (UF + SPAN - 2) % LENGTH;

  reg [LENGTH*COLUMN_W-1:0] ring;
  assign view = ring[(UF+SPAN-1)*COLUMN_W-1:0];

  integer p;
  always @(posedge clk)
    if (en)
      for (p = 0; p < LENGTH; p = p + 1)
        if (!slot_end) ring[p*COLUMN_W +: COLUMN_W] <= ring[((p + TURN) % LENGTH)*COLUMN_W +: COLUMN_W];
        else if (p == 0) ring[0 +: COLUMN_W] <= column_in;
        else ring[p*COLUMN_W +: COLUMN_W] <= ring[((p + SHIFT) % LENGTH)*COLUMN_W +: COLUMN_W];
endmodule
`resetall
