`default_nettype none
// The rules the proofs share (tests/formal/run_proof.sh reads this file with every wrapper).
//   formal_start     the run starts in reset; past_valid once a cycle has passed (the solver's
//                    first cycle has no past), past_rst the previous cycle's reset
//   formal_axis_in   a stream the environment drives obeys AXI4-Stream (assumed)
//   formal_axis_out  a stream the unit drives obeys it (asserted)
// AXI4-Stream here: TVALID low in reset and in the cycle after it; once high, held with its
// payload (TDATA and the side bands) until TREADY.
module formal_start (
  input  wire clk,
  input  wire rst,
  output reg  past_valid = 1'b0,
  output reg  past_rst = 1'b1
);
`ifdef FORMAL
  always @(posedge clk) begin
    past_valid <= 1'b1;
    past_rst <= rst;
  end
  always @* if (!past_valid) assume(rst);
`endif
endmodule

module formal_axis_in #(
  parameter W = 8
) (
  input wire         clk,
  input wire         rst,
  input wire         valid,
  input wire         ready,
  input wire [W-1:0] payload
);
`ifdef FORMAL
  // With registered past values in always @*: an assumption in a clocked block would bind one
  // cycle late.
  reg         past_valid = 1'b0, past_rst = 1'b1, stall;
  reg [W-1:0] was;
  always @(posedge clk) begin
    past_valid <= 1'b1;
    past_rst <= rst;
    stall <= valid && !ready;
    was <= payload;
  end
  always @*
    if (past_valid) begin
      if (rst || past_rst) assume(!valid);
      else if (stall) assume(valid && payload == was);
    end
`endif
endmodule

module formal_axis_out #(
  parameter W = 8
) (
  input wire         clk,
  input wire         rst,
  input wire         valid,
  input wire         ready,
  input wire [W-1:0] payload
);
`ifdef FORMAL
  reg past_valid = 1'b0;
  always @(posedge clk) past_valid <= 1'b1;
  always @(posedge clk)
    if (past_valid) begin
      if ($past(rst)) assert(!valid);
      else if ($past(valid && !ready)) assert(valid && payload == $past(payload));
    end
`endif
endmodule
`resetall
