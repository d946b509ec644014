`resetall
`default_nettype none
// Rank of an N x N window's centre: the number of neighbours darker than it. Pixels outside
// the image (row_valid / col_valid low) read as 0 (docs/semantics.md, section 1). The flags are
// counted in chunks, registered at a shift, and summed after it: `rank` is the rank of the window
// of the previous shift (a slot later than census codes, fpstereo_transform).
module fpstereo_rank #(
  // window side
  parameter N = 7,
  // result width: clog2(N*N)
  parameter RANK_W = 6
) (
  input  wire             clk,
  input  wire             shift,
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

  // Each neighbour's flag (one outside the image reads 0: darker while the centre is not 0), the
  // flags counted in chunks of 6 (one LUT level each), the counts registered and summed in a
  // balanced tree: a chain of N*N increments would be as many LUT levels deep, the compares, the
  // counts and the tree 7 (docs/timing.md).
  localparam CHUNKS = (N * N + 5) / 6;
  reg [CHUNKS*6-1:0] darker;
  reg [CHUNKS*3-1:0] counts;
  integer p, k, b;
  always @* begin
    darker = {CHUNKS*6{1'b0}};
    for (p = 0; p < N * N; p = p + 1)
      if (p != CENTRE)
        darker[p] = (row_valid[p / N] && col_valid[p % N]) ? window[p*8 +: 8] < centre : centre != 8'd0;
    for (k = 0; k < CHUNKS; k = k + 1) begin
      counts[k*3 +: 3] = 3'd0;
      for (b = 0; b < 6; b = b + 1) counts[k*3 +: 3] = counts[k*3 +: 3] + {2'b00, darker[k*6 + b]};
    end
  end
  reg [CHUNKS*3-1:0] counts_q;
  always @(posedge clk)
    if (shift) counts_q <= counts;
  wire [RANK_W-1:0] total;
  fpstereo_sum_tree #(.N(CHUNKS), .IN_W(3), .SUM_W(RANK_W), .REGISTER_LEVEL(0)) chunk_sum (
    .clk(1'b0), .en(1'b0), .values(counts_q), .sum(total));
  always @* rank = total;
endmodule
`resetall
