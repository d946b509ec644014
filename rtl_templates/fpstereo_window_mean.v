`resetall
`default_nettype none
// ZSAD's window mean (docs/semantics.md, section 2): floor(sum / N^2) of an N x N window of
// pixels, as (sum * MEAN_MUL) >> MEAN_SHIFT, over three steps of en: the rows' sums, their total,
// the constant multiply. mean is the window's of three steps before.
module fpstereo_window_mean #(
  parameter N = 5,
  // width of a row's pixel sum (it holds 255 * N)
  parameter COLUMN_SUM_W = 11,
  parameter MEAN_MUL = 1,
  parameter MEAN_SHIFT = 0
) (
  input  wire           clk,
  input  wire           en,
  input  wire [N*N*8-1:0] window,
  output reg  [7:0]     mean
);
  localparam WINSUM_W = COLUMN_SUM_W + 4;  // a window's pixel sum (N <= 11)
  wire [N*COLUMN_SUM_W-1:0] row_sums;
  genvar r;
  generate
    for (r = 0; r < N; r = r + 1) begin : row
      fpstereo_sum_tree #(.N(N), .IN_W(8), .SUM_W(COLUMN_SUM_W)) row_total (
        .clk(clk), .en(en), .values(window[r*N*8 +: N*8]), .sum(row_sums[r*COLUMN_SUM_W +: COLUMN_SUM_W]));
    end
  endgenerate
  reg  [N*COLUMN_SUM_W-1:0] row_sums_q;
  wire [WINSUM_W-1:0]       total;
  fpstereo_sum_tree #(.N(N), .IN_W(COLUMN_SUM_W), .SUM_W(WINSUM_W)) window_total (
    .clk(clk), .en(en), .values(row_sums_q), .sum(total));
  reg  [WINSUM_W-1:0] total_q;
  always @(posedge clk)
    if (en) begin
      row_sums_q <= row_sums;
      total_q <= total;
      /* verilator lint_off WIDTH */  // constant multiply and shift, cut to the 8-bit mean
      mean <= (total_q * MEAN_MUL) >> MEAN_SHIFT;
      /* verilator lint_on WIDTH */
    end
endmodule
`resetall
