`resetall
`default_nettype none
// Transform stage: the census codes (or, with RANK, the ranks) of the base and match windows'
// centres, registered once per slot (docs/semantics.md, section 2).
module fpstereo_transform #(
  parameter N = 5,
  // 1: rank transform; 0: census
  parameter RANK = 0,
  // code width: N*N - 1 for census, clog2(N*N) for rank
  parameter CODE_W = 24
) (
  input  wire              clk,
  input  wire              shift,
  input  wire [N*N*8-1:0]  window_left,
  input  wire [N*N*8-1:0]  window_right,
  input  wire [N-1:0]      row_valid,
  input  wire [N-1:0]      col_valid,
  output reg  [CODE_W-1:0] code_base,
  output reg  [CODE_W-1:0] code_match
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 3 || N % 2 == 0) begin : invalid_N
      fpstereo_invalid_parameters_transform_N_is_not_odd_and_at_least_3 failed ();
    end
    if ((RANK == 0 && CODE_W != N * N - 1) || (RANK != 0 && N * N - 1 >= (1 << CODE_W))) begin : invalid_CODE_W
      fpstereo_invalid_parameters_transform_CODE_W_is_not_N_N_minus_1_for_census_or_too_narrow_for_rank failed ();
    end
  endgenerate
  wire [CODE_W-1:0] code_left, code_right;
  generate
    if (RANK) begin : rank
      fpstereo_rank #(.N(N), .RANK_W(CODE_W)) base (.window(window_left), .row_valid(row_valid),
                                                     .col_valid(col_valid), .rank(code_left));
      fpstereo_rank #(.N(N), .RANK_W(CODE_W)) match (.window(window_right), .row_valid(row_valid),
                                                      .col_valid(col_valid), .rank(code_right));
    end else begin : census
      fpstereo_census #(.N(N)) base (.window(window_left), .row_valid(row_valid), .col_valid(col_valid),
                                     .code(code_left));
      fpstereo_census #(.N(N)) match (.window(window_right), .row_valid(row_valid), .col_valid(col_valid),
                                      .code(code_right));
    end
  endgenerate
  always @(posedge clk)
    if (shift) begin
      code_base  <= code_left;
      code_match <= code_right;
    end
endmodule
`resetall
