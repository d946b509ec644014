`resetall
`default_nettype none
// Rank of an N x N window's centre: the number of neighbours darker than it. Pixels outside
// the image (row_valid / col_valid low) read as 0 (docs/semantics.md, section 1).
module fpstereo_rank #(
  // window side
  parameter N = 7,
  // result width: clog2(N*N)
  parameter RANK_W = 6
) (
  input  wire [N*N*8-1:0] window,
  input  wire [N-1:0]     row_valid,
  input  wire [N-1:0]     col_valid,
  output reg  [RANK_W-1:0] rank
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 3 || N % 2 == 0) begin : invalid_N
      fpstereo_invalid_parameters_rank_N_is_not_odd_and_at_least_3 failed ();
    end
    if (N * N - 1 >= (1 << RANK_W)) begin : invalid_RANK_W
      fpstereo_invalid_parameters_rank_RANK_W_does_not_hold_N_times_N_minus_1 failed ();
    end
  endgenerate
  localparam CENTRE = (N / 2) * N + N / 2;
  wire [7:0] centre = window[CENTRE*8 +: 8];

  integer p;
  reg [7:0] q;
  always @* begin
    rank = 0;
    for (p = 0; p < N * N; p = p + 1) begin
      q = (row_valid[p / N] && col_valid[p % N]) ? window[p*8 +: 8] : 8'd0;
      if (p != CENTRE && q < centre) rank = rank + 1'b1;
    end
  end
endmodule
`resetall
