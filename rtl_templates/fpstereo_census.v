`resetall
`default_nettype none
// Census code of an N x N window: one bit per neighbour in raster order (the centre skipped,
// the first position in the most significant bit), 1 where the centre is brighter. Pixels
// outside the image (row_valid / col_valid low) read as 0 (docs/semantics.md, section 1).
module fpstereo_census #(
  // window side
  parameter N = 7
) (
  input  wire [N*N*8-1:0] window,
  input  wire [N-1:0]     row_valid,
  input  wire [N-1:0]     col_valid,
  output wire [N*N-2:0]   code
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 3 || N % 2 == 0) begin : invalid
      fpstereo_invalid_parameters_census_N_is_not_odd_and_at_least_3 failed ();
    end
  endgenerate
  localparam CENTRE = (N / 2) * N + N / 2;
  wire [7:0] centre = window[CENTRE*8 +: 8];

  genvar p;
  generate
    for (p = 0; p < N * N; p = p + 1) begin : position
      if (p != CENTRE) begin : neighbour
        wire [7:0] q = (row_valid[p / N] && col_valid[p % N]) ? window[p*8 +: 8] : 8'd0;
        assign code[N*N - 2 - (p < CENTRE ? p : p - 1)] = centre > q;
      end
    end
  endgenerate
endmodule
`resetall
