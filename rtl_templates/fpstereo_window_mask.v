`resetall
`default_nettype none
// Zero extension (docs/semantics.md, section 1): words of an N x N window whose row or column
// lies outside the image read as 0.
module fpstereo_window_mask #(
  // window side
  parameter N = 5,
  // bits per word
  parameter WORD_W = 8
) (
  input  wire [N*N*WORD_W-1:0] window,
  input  wire [N-1:0]          row_valid,
  input  wire [N-1:0]          col_valid,
  output wire [N*N*WORD_W-1:0] masked
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 1 || WORD_W < 1) begin : invalid
      fpstereo_invalid_parameters_window_mask_N_or_WORD_W_below_1 failed ();
    end
  endgenerate
  genvar p;
  generate
    for (p = 0; p < N * N; p = p + 1) begin : position
      assign masked[p*WORD_W +: WORD_W] = (row_valid[p / N] && col_valid[p % N]) ? window[p*WORD_W +: WORD_W]
                                                                                 : {WORD_W{1'b0}};
    end
  endgenerate
endmodule
`resetall
