`resetall
`default_nettype none
// The pixels of a video beat one at a time (ppc > 1, the streams' side; docs/hardware.md,
// "Pixels per clock"): holds a beat of P pixels, pixel 0 in its lowest bits as UG934 lays them
// out, and hands them on lowest first, one per handshake. A new beat is taken as the last pixel
// of the one held leaves, so a beat every P cycles passes without a gap.
module fpstereo_beat_split #(
  parameter P = 2,
  // bits of one pixel (of both images, for the core)
  parameter PIXEL_W = 16,
  parameter COUNT_W = 2
) (
  input  wire                 clk,
  input  wire                 rst,
  input  wire [P*PIXEL_W-1:0] s_data,
  input  wire                 s_valid,
  output wire                 s_ready,
  output wire [PIXEL_W-1:0]   m_data,
  output wire                 m_valid,
  input  wire                 m_ready
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (P < 2 || PIXEL_W < 1 || P >= (1 << COUNT_W)) begin : invalid
      fpstereo_invalid_parameters_beat_split_P_below_2_or_COUNT_W_too_narrow failed ();
    end
  endgenerate
  localparam [COUNT_W-1:0] ONE = 1, PIXELS = P;
  reg [P*PIXEL_W-1:0] held;
  reg [COUNT_W-1:0]   remaining;  // pixels of the held beat still to leave
  assign m_valid = remaining != 0;
  assign m_data = held[PIXEL_W-1:0];
  assign s_ready = remaining == 0 || (remaining == ONE && m_ready);
  always @(posedge clk)
    if (rst) remaining <= {COUNT_W{1'b0}};
    else if (s_valid && s_ready) begin
      held <= s_data;
      remaining <= PIXELS;
    end else if (m_valid && m_ready) begin
      held <= held >> PIXEL_W;
      remaining <= remaining - ONE;
    end
endmodule
`resetall
