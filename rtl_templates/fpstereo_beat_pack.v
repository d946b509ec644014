`resetall
`default_nettype none
// Pixels into video beats (ppc > 1, the streams' side; docs/hardware.md, "Pixels per clock"):
// gathers P consecutive pixels of a stream into one beat, pixel 0 in its lowest bits (UG934), with
// tuser from the first (a frame's first pixel) and tlast from the last (a row's last: rows are a
// whole number of beats). The beat leaves in the handshake of its last pixel, so s_ready depends
// on m_ready only while P - 1 pixels wait, and a pixel every cycle passes without a gap.
module fpstereo_beat_pack #(
  parameter P = 2,
  parameter PIXEL_W = 8,
  parameter COUNT_W = 2
) (
  input  wire                 clk,
  input  wire                 rst,
  input  wire [PIXEL_W-1:0]   s_data,
  input  wire                 s_first,
  input  wire                 s_last,
  input  wire                 s_valid,
  output wire                 s_ready,
  output wire [P*PIXEL_W-1:0] m_data,
  output wire                 m_first,
  output wire                 m_last,
  output wire                 m_valid,
  input  wire                 m_ready
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (P < 2 || PIXEL_W < 1 || P >= (1 << COUNT_W)) begin : invalid
      fpstereo_invalid_parameters_beat_pack_P_below_2_or_COUNT_W_too_narrow failed ();
    end
  endgenerate
  localparam [COUNT_W-1:0] ONE = 1, LAST_BUT_ONE = P - 2;
  // The pixels gathered so far, the newest on top; full: P - 1 of them wait.
  reg [(P-1)*PIXEL_W-1:0] held;
  reg                     held_first;
  reg [COUNT_W-1:0]       count;
  reg                     full;
  assign m_valid = s_valid && full;
  assign m_data = {s_data, held};
  assign m_first = held_first;
  assign m_last = s_last;
  assign s_ready = !full || m_ready;
  always @(posedge clk)
    if (rst) begin
      count <= {COUNT_W{1'b0}};
      full <= 1'b0;
    end else if (s_valid && s_ready) begin
      if (full) begin
        count <= {COUNT_W{1'b0}};
        full <= 1'b0;
      end else begin
        count <= count + ONE;
        full <= count == LAST_BUT_ONE;
      end
    end
  wire gather = s_valid && s_ready && !full;
  always @(posedge clk)
    if (gather && count == 0) held_first <= s_first;
  generate
    if (P > 2) begin : shifting
      always @(posedge clk)
        if (gather) held <= {s_data, held[(P-1)*PIXEL_W-1:PIXEL_W]};
    end else begin : single
      always @(posedge clk)
        if (gather) held <= s_data;
    end
  endgenerate
endmodule
`resetall
