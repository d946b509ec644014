`resetall
`default_nettype none
// Confidence (docs/semantics.md, section 4): floor(255 * (S2 - S1) / S2), 0 where S2 = 0, from
// the winner-take-all's best sum S1 and second best S2 (two or more disparities from the winner).
// best and second are taken IN_DELAY steps before the data they belong to (the sub-pixel stage's
// latency, if it sits between), then divided in LAT steps: the difference, 255 times it, and
// one restoring step per quotient bit (the quotient is below 256 since S2 - S1 <= S2). data
// travels beside them, LAT steps, so that each word leaves with its pixel's confidence.
module fpstereo_confidence #(
  parameter SUM_W = 10,
  parameter DATA_W = 16,
  parameter IN_DELAY = 0,
  parameter LAT = 10
) (
  input  wire              clk,
  input  wire              restart,
  input  wire              adv,
  input  wire [SUM_W-1:0]  best,
  input  wire [SUM_W-1:0]  second,
  input  wire [DATA_W-1:0] data_in,
  output wire [DATA_W-1:0] data_out,
  output wire [7:0]        confidence
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (LAT != 10 || IN_DELAY < 0 || SUM_W < 1) begin : invalid
      fpstereo_invalid_parameters_confidence_LAT_is_not_10 failed ();
    end
  endgenerate
  fpstereo_delay #(.WIDTH(DATA_W), .DEPTH(LAT), .RESET(1)) beside (
    .clk(clk), .rst(restart), .en(adv), .in(data_in), .out(data_out));

  // The sums of the data's pixel.
  wire [SUM_W-1:0] s1, s2;
  generate
    if (IN_DELAY == 0) begin : now
      assign s1 = best;
      assign s2 = second;
    end else begin : waited
      fpstereo_delay #(.WIDTH(2 * SUM_W), .DEPTH(IN_DELAY)) wait_sums (
        .clk(clk), .rst(1'b0), .en(adv), .in({best, second}), .out({s1, s2}));
    end
  endgenerate

  // Step 1: the margin and the divisor; step 2: 255 times the margin, its part above bit 8 as
  // the first partial remainder (below S2, as 255 * margin < 256 * S2).
  reg [SUM_W-1:0] margin, divisor1;
  reg             zero1;
  always @(posedge clk)
    if (adv) begin
      margin <= s2 - s1;
      divisor1 <= s2;
      zero1 <= s2 == {SUM_W{1'b0}};
    end
  wire [SUM_W+7:0] scaled = {margin, 8'd0} - {8'd0, margin};
  reg  [SUM_W-1:0] rem [0:8];
  reg  [SUM_W-1:0] divisor [0:8];
  reg  [7:0]       low [0:8];
  reg  [7:0]       quotient [0:8];
  reg              zero [0:8];
  always @(posedge clk)
    if (adv) begin
      rem[0] <= scaled[SUM_W+7:8];
      low[0] <= scaled[7:0];
      divisor[0] <= divisor1;
      quotient[0] <= 8'd0;
      zero[0] <= zero1;
    end
  // Steps 3 to 10: bring down bit 7 - i of the low part, subtract the divisor where it fits.
  genvar i;
  generate
    for (i = 0; i < 8; i = i + 1) begin : divide
      wire [SUM_W:0] partial = {rem[i], low[i][7 - i]};
      wire           fits = partial >= {1'b0, divisor[i]};
      /* verilator lint_off UNUSEDSIGNAL */  // its top bit is 0: the remainder stays below the divisor
      wire [SUM_W:0] left_over = fits ? partial - {1'b0, divisor[i]} : partial;
      /* verilator lint_on UNUSEDSIGNAL */
      always @(posedge clk)
        if (adv) begin
          rem[i + 1] <= left_over[SUM_W-1:0];
          low[i + 1] <= low[i];
          divisor[i + 1] <= divisor[i];
          quotient[i + 1] <= {quotient[i][6:0], fits};
          zero[i + 1] <= zero[i];
        end
    end
  endgenerate
  assign confidence = zero[8] ? 8'd0 : quotient[8];
endmodule
`resetall
