`resetall
`default_nettype none
// Sub-pixel refinement of a winner-take-all disparity (docs/semantics.md, section 4): from the
// aggregated sums a, b, c at d - 1, d and d + 1, the refined disparity in units of 2^-K,
//   d * 2^K + sign(a - c) * floor((|a - c| * 2^K + e) / (2e)),
// e = max(a, c) - b (EQUIANGULAR) or a + c - 2b (parabola); d * 2^K at d = 0 and d = DMAX - 1.
// The caller guarantees a > b and c >= b (d is the first minimum), so e > 0 and the offset is at
// most 2^(K-1). A pipeline advancing on en, one pixel per step: the offsets' numerator and e,
// then the dividend and divisor, then K restoring-division steps (one quotient bit each), then
// the sum; latency K + 3.
module fpstereo_subpixel_fit #(
  parameter DMAX = 64,
  parameter DISP_W = 6,
  parameter SUM_W = 10,
  // fraction bits, 1 to 5
  parameter K = 4,
  parameter EQUIANGULAR = 1,
  // bits of the refined disparity: enough for (DMAX - 1) * 2^K
  parameter OUT_W = 10
) (
  input  wire              clk,
  input  wire              en,
  input  wire [DISP_W-1:0] d,
  input  wire [SUM_W-1:0]  left,
  input  wire [SUM_W-1:0]  best,
  input  wire [SUM_W-1:0]  right,
  output reg  [OUT_W-1:0]  refined
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (K < 1 || K > 5) begin : invalid_K
      fpstereo_invalid_parameters_subpixel_fit_K_is_not_1_to_5 failed ();
    end
    if (DMAX < 2 || DMAX - 1 >= (1 << DISP_W) || ((DMAX - 1) << K) >= (1 << OUT_W)) begin : invalid_OUT_W
      fpstereo_invalid_parameters_subpixel_fit_DISP_W_or_OUT_W_does_not_hold_DMAX_minus_1 failed ();
    end
  endgenerate
  localparam E_W = SUM_W + 1;        // e <= 2 * max sum
  localparam Q_W = E_W + K + 1;      // the dividend |a - c| * 2^K + e, and 2e shifted
  localparam LAST = DMAX - 1;

  // Step 1: the numerator's magnitude and sign, e, and whether d is at an end of the range.
  wire [SUM_W:0] a_minus_c = {1'b0, left} - {1'b0, right};
  wire           towards_left = a_minus_c[SUM_W];  // a < c: the minimum lies below d
  wire [SUM_W-1:0] num = towards_left ? {SUM_W{1'b0}} - a_minus_c[SUM_W-1:0] : a_minus_c[SUM_W-1:0];
  wire [SUM_W-1:0] larger = towards_left ? right : left;
  wire [E_W-1:0] e = EQUIANGULAR != 0 ? {1'b0, larger} - {1'b0, best}
                                       : {1'b0, left} + {1'b0, right} - {best, 1'b0};
  reg  [SUM_W-1:0]  num_1;
  reg  [E_W-1:0]    e_1;
  reg               towards_left_1, whole_1;
  reg  [DISP_W-1:0] d_1;
  always @(posedge clk)
    if (en) begin
      num_1 <= num;
      e_1 <= e;
      towards_left_1 <= towards_left;
      whole_1 <= d == {DISP_W{1'b0}} || d == LAST[DISP_W-1:0];
      d_1 <= d;
    end

  // Step 2: dividend and divisor.
  reg [Q_W-1:0]    dividend_2, divisor_2;
  reg              towards_left_2, whole_2;
  reg [DISP_W-1:0] d_2;
  always @(posedge clk)
    if (en) begin
      dividend_2 <= ({{(Q_W-SUM_W){1'b0}}, num_1} << K) + {{(Q_W-E_W){1'b0}}, e_1};
      divisor_2 <= {{(Q_W-E_W-1){1'b0}}, e_1, 1'b0};
      towards_left_2 <= towards_left_1;
      whole_2 <= whole_1;
      d_2 <= d_1;
    end

  // Steps 3 .. K + 2: quotient bit K-1-i at step 3 + i, restoring: subtract divisor * 2^(K-1-i)
  // where it fits.
  genvar i;
  generate
    for (i = 0; i < K; i = i + 1) begin : divide
      wire [Q_W-1:0] rem_in, divisor_in;
      wire [K-1:0]   quotient_in;
      wire           towards_left_in, whole_in;
      wire [DISP_W-1:0] d_in;
      if (i == 0) begin : first
        assign rem_in = dividend_2;
        assign divisor_in = divisor_2;
        assign quotient_in = {K{1'b0}};
        assign towards_left_in = towards_left_2;
        assign whole_in = whole_2;
        assign d_in = d_2;
      end else begin : next
        assign rem_in = divide[i-1].rem_q;
        assign divisor_in = divide[i-1].divisor_q;
        assign quotient_in = divide[i-1].quotient_q;
        assign towards_left_in = divide[i-1].towards_left_q;
        assign whole_in = divide[i-1].whole_q;
        assign d_in = divide[i-1].d_q;
      end
      wire [Q_W-1:0] step = divisor_in << (K - 1 - i);
      wire           fits = rem_in >= step;
      /* verilator lint_off UNUSEDSIGNAL */  // the last step's remainder and divisor
      reg [Q_W-1:0]    rem_q, divisor_q;
      /* verilator lint_on UNUSEDSIGNAL */
      reg [K-1:0]      quotient_q;
      reg              towards_left_q, whole_q;
      reg [DISP_W-1:0] d_q;
      always @(posedge clk)
        if (en) begin
          rem_q <= fits ? rem_in - step : rem_in;
          divisor_q <= divisor_in;
          quotient_q <= quotient_in | ({{(K-1){1'b0}}, fits} << (K - 1 - i));
          towards_left_q <= towards_left_in;
          whole_q <= whole_in;
          d_q <= d_in;
        end
    end
  endgenerate

  // Step K + 3: the refined disparity.
  wire [K-1:0]      offset = divide[K-1].quotient_q;
  wire [DISP_W-1:0] d_last = divide[K-1].d_q;
  wire [OUT_W-1:0]  scaled = {{(OUT_W-DISP_W){1'b0}}, d_last} << K;
  wire [OUT_W-1:0]  offset_wide = {{(OUT_W-K){1'b0}}, offset};
  always @(posedge clk)
    if (en) refined <= divide[K-1].whole_q ? scaled : divide[K-1].towards_left_q ? scaled - offset_wide : scaled + offset_wide;
endmodule
`resetall
