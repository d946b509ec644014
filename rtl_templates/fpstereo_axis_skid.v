`resetall
`default_nettype none
// Two-entry AXI4-Stream register slice: every output is registered, so no combinational path
// runs from m_ready to s_ready, and a word is accepted every cycle while the sink keeps up.
module fpstereo_axis_skid #(
  // data bits carried (tdata and any sideband packed together)
  parameter DATA_W = 8
) (
  input  wire              clk,
  input  wire              rst,
  input  wire [DATA_W-1:0] s_data,
  input  wire              s_valid,
  output wire              s_ready,
  output wire [DATA_W-1:0] m_data,
  output wire              m_valid,
  input  wire              m_ready
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (DATA_W < 1) begin : invalid
      fpstereo_invalid_parameters_axis_skid_DATA_W_below_1 failed ();
    end
  endgenerate
  reg [DATA_W-1:0] data_q, skid_q;
  reg              valid_q, skid_valid_q;

  assign s_ready = !skid_valid_q;
  assign m_data  = data_q;
  assign m_valid = valid_q;

  always @(posedge clk) begin
    if (rst) begin
      valid_q      <= 1'b0;
      skid_valid_q <= 1'b0;
    end else if (m_ready || !valid_q) begin
      // The output register is free: refill it from the skid register first.
      if (skid_valid_q) begin
        data_q       <= skid_q;
        valid_q      <= 1'b1;
        skid_valid_q <= 1'b0;
      end else begin
        data_q  <= s_data;
        valid_q <= s_valid;
      end
    end else if (s_valid && !skid_valid_q) skid_valid_q <= 1'b1;
  end
  // The skid register follows the input while empty, so that its enable is not m_ready's.
  always @(posedge clk)
    if (!skid_valid_q) skid_q <= s_data;
endmodule
`resetall
