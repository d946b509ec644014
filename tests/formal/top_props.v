`default_nettype none
// Formal properties of a generated top's output port m_axis_disp (tests/formal/run_top_proof.sh
// generates the design; FORMAL_TOP names its top module, FORMAL_PPC its pixels per beat, each an
// 8-bit pixel in and an 8-bit word out). The input streams obey AXI4-Stream
// (assumed); m_axis_disp (asserted): TVALID low in reset and in the cycle after it, held until
// TREADY with TDATA, TUSER and TLAST stable while stalled. The output register slice holds its
// word whatever the core does, so this holds by induction over the whole design.
`ifndef FORMAL_PPC
`define FORMAL_PPC 1
`endif
module top_props #(
  parameter W = 8 * `FORMAL_PPC
) (
  input wire         aclk,
  input wire         aresetn,
  input wire [W-1:0] left_tdata,
  input wire       left_tvalid,
  input wire       left_tuser,
  input wire       left_tlast,
  input wire [W-1:0] right_tdata,
  input wire       right_tvalid,
  input wire       right_tuser,
  input wire       right_tlast,
  input wire       disp_tready
);
  wire       left_tready, right_tready, disp_tvalid, disp_tuser, disp_tlast;
  wire [W-1:0] disp_tdata;
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
  formal_start run_start (.clk(aclk), .rst(rst), .past_valid(), .past_rst());

  // ---- The input streams (environment) and m_axis_disp.
  formal_axis_in #(.W(W + 2)) left_stream (.clk(aclk), .rst(rst), .valid(left_tvalid), .ready(left_tready),
                                        .payload({left_tuser, left_tlast, left_tdata}));
  formal_axis_in #(.W(W + 2)) right_stream (.clk(aclk), .rst(rst), .valid(right_tvalid), .ready(right_tready),
                                         .payload({right_tuser, right_tlast, right_tdata}));
  formal_axis_out #(.W(W + 2)) disp_stream (.clk(aclk), .rst(rst), .valid(disp_tvalid), .ready(disp_tready),
                                         .payload({disp_tuser, disp_tlast, disp_tdata}));
`endif
endmodule
`resetall
