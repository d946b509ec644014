`default_nettype none
// Formal properties of a generated top's output port m_axis_disp (tests/formal/run_top_proof.sh
// generates the design; FORMAL_TOP names its top module). The input streams obey AXI4-Stream
// (assumed); m_axis_disp (asserted): TVALID low in reset and in the cycle after it, held until
// TREADY with TDATA, TUSER and TLAST stable while stalled. The output register slice holds its
// word whatever the core does, so this holds by induction over the whole design.
module top_props (
  input wire       aclk,
  input wire       aresetn,
  input wire [7:0] left_tdata,
  input wire       left_tvalid,
  input wire       left_tuser,
  input wire       left_tlast,
  input wire [7:0] right_tdata,
  input wire       right_tvalid,
  input wire       right_tuser,
  input wire       right_tlast,
  input wire       disp_tready
);
  wire       left_tready, right_tready, disp_tvalid, disp_tuser, disp_tlast;
  wire [7:0] disp_tdata;
  `FORMAL_TOP dut (
    .aclk(aclk), .aresetn(aresetn),
    .s_axis_left_tdata(left_tdata), .s_axis_left_tvalid(left_tvalid), .s_axis_left_tready(left_tready),
    .s_axis_left_tuser(left_tuser), .s_axis_left_tlast(left_tlast),
    .s_axis_right_tdata(right_tdata), .s_axis_right_tvalid(right_tvalid),
    .s_axis_right_tready(right_tready), .s_axis_right_tuser(right_tuser), .s_axis_right_tlast(right_tlast),
    .m_axis_disp_tdata(disp_tdata), .m_axis_disp_tvalid(disp_tvalid), .m_axis_disp_tready(disp_tready),
    .m_axis_disp_tuser(disp_tuser), .m_axis_disp_tlast(disp_tlast));

`ifdef FORMAL
  wire rst = !aresetn;
  reg past_valid = 1'b0, past_rst = 1'b1;
  always @(posedge aclk) begin
    past_valid <= 1'b1;
    past_rst <= rst;
  end
  always @* if (!past_valid) assume(rst);

  // ---- The input streams (environment), with registered past values (an assumption in a
  // clocked block would bind one cycle late).
  reg        left_stall, right_stall;
  reg [9:0]  left_was, right_was;
  always @(posedge aclk) begin
    left_stall <= left_tvalid && !left_tready;
    right_stall <= right_tvalid && !right_tready;
    left_was <= {left_tuser, left_tlast, left_tdata};
    right_was <= {right_tuser, right_tlast, right_tdata};
  end
  always @*
    if (past_valid) begin
      if (rst || past_rst) assume(!left_tvalid && !right_tvalid);
      else begin
        if (left_stall) assume(left_tvalid && {left_tuser, left_tlast, left_tdata} == left_was);
        if (right_stall) assume(right_tvalid && {right_tuser, right_tlast, right_tdata} == right_was);
      end
    end

  // ---- m_axis_disp.
  always @(posedge aclk)
    if (past_valid) begin
      if ($past(rst)) assert(!disp_tvalid);
      else if ($past(disp_tvalid && !disp_tready)) begin
        assert(disp_tvalid);
        assert(disp_tdata == $past(disp_tdata) && disp_tuser == $past(disp_tuser) && disp_tlast == $past(disp_tlast));
      end
    end
`endif
endmodule
`resetall
