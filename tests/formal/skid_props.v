`default_nettype none
// Formal properties of rtl_templates/fpstereo_axis_skid.v (tests/formal/run_proof.sh).
// The slave side is the environment: it obeys AXI4-Stream (assumed). The master side is the
// unit's (asserted): TVALID low in reset and in the cycle after it, held until TREADY with the
// data stable while stalled; every beat accepted is delivered once, unchanged and in order (the
// beats inside are counted, and one beat the solver chooses is followed to the output).
// The beat followed may wait in the skid register, which no port shows; the induction reads it:
// formal-probe: probe_skid_q dut.skid_q
module skid_props #(
  parameter DATA_W = 4
) (
  input wire              clk,
  input wire              rst,
  input wire [DATA_W-1:0] s_data,
  input wire              s_valid,
  input wire              m_ready,
  // the environment's choice: follow the beat accepted in this cycle
  input wire              follow
);
  wire              s_ready, m_valid;
  wire [DATA_W-1:0] m_data;
  fpstereo_axis_skid #(.DATA_W(DATA_W)) dut (
    .clk(clk), .rst(rst), .s_data(s_data), .s_valid(s_valid), .s_ready(s_ready),
    .m_data(m_data), .m_valid(m_valid), .m_ready(m_ready));

`ifdef FORMAL
  (* keep *) wire [DATA_W-1:0] probe_skid_q;

  wire past_valid, past_rst;
  formal_start run_start (.clk(clk), .rst(rst), .past_valid(past_valid), .past_rst(past_rst));

  wire s_take = s_valid && s_ready;
  wire m_take = m_valid && m_ready;

  // ---- The environment (slave side) and the unit's master side.
  formal_axis_in #(.W(DATA_W)) slave_side (.clk(clk), .rst(rst), .valid(s_valid), .ready(s_ready), .payload(s_data));
  formal_axis_out #(.W(DATA_W)) master_side (.clk(clk), .rst(rst), .valid(m_valid), .ready(m_ready), .payload(m_data));

  // ---- Beats inside: accepted minus delivered, at most two; TVALID exactly when one is inside,
  // s_ready low exactly when two are (so nothing is lost, duplicated or made up).
  reg [2:0] inside;
  always @(posedge clk)
    if (rst) inside <= 3'd0;
    else inside <= inside + {2'b00, s_take} - {2'b00, m_take};
  always @*
    if (past_valid && !past_rst) begin
      assert(inside <= 3'd2);
      assert(m_valid == (inside != 3'd0));
      assert(s_ready == (inside != 3'd2));
    end

  // ---- One beat followed: its data, and how many beats are ahead of it.
  reg              following;
  reg [DATA_W-1:0] f_data;
  reg [1:0]        f_ahead;
  always @(posedge clk)
    if (rst) following <= 1'b0;
    else if (following) begin
      if (m_take) begin
        if (f_ahead == 2'd0) following <= 1'b0;  // delivered
        else f_ahead <= f_ahead - 1'b1;
      end
    end else if (s_take && follow) begin
      following <= 1'b1;
      f_data <= s_data;
      f_ahead <= inside[1:0] - {1'b0, m_take};
    end
  always @*
    if (past_valid && !past_rst && following) begin
      assert({1'b0, f_ahead} < inside);
      // at the head it is the output word; delivered when taken, in order, unchanged
      if (f_ahead == 2'd0) assert(m_valid && m_data == f_data);
      // behind the head it waits in the skid register
      if (f_ahead == 2'd1) assert(probe_skid_q == f_data);
    end
`endif
endmodule
`resetall
