`resetall
`default_nettype none
// Pixel Q's N x N window out of an array that holds the P windows of a slot side by side
// (fpstereo_front_end, fpstereo_median: COLS columns of WORD_W bits a row): columns Q .. Q + N - 1
// of each of its N rows, row by row.
module fpstereo_window_cut #(
  parameter N = 5,
  parameter COLS = 5,
  parameter WORD_W = 8,
  parameter Q = 0
) (
  /* verilator lint_off UNUSEDSIGNAL */  // the other pixels' columns
  input  wire [N*COLS*WORD_W-1:0] array,
  /* verilator lint_on UNUSEDSIGNAL */
  output wire [N*N*WORD_W-1:0]    window
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 1 || Q < 0 || Q + N > COLS) begin : invalid
      fpstereo_invalid_parameters_window_cut_columns_Q_to_Q_plus_N_outside_COLS failed ();
    end
  endgenerate
  genvar i;
  generate
    for (i = 0; i < N; i = i + 1) begin : row
      assign window[i*N*WORD_W +: N*WORD_W] = array[(i*COLS + Q)*WORD_W +: N*WORD_W];
    end
  endgenerate
endmodule
`resetall
