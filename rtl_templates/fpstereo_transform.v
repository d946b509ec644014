`resetall
`default_nettype none
// Transform stage: the census codes (or, with RANK, the ranks) of the base and match windows'
// centres, registered once per slot (docs/semantics.md, section 2): census codes of the windows of
// the previous shift, ranks of those a shift earlier (fpstereo_rank counts at one shift and sums
// after it; the front end's TRANSFORM_SLOTS). With P pixels a slot the
// window arrays are COLS columns wide and hold P windows side by side (fpstereo_front_end):
// window q is columns q .. q + N - 1 (fpstereo_window_cut), its code in bits q * CODE_W of the
// outputs.
module fpstereo_transform #(
  parameter N = 5,
  // 1: rank transform; 0: census
  parameter RANK = 0,
  // code width: N*N - 1 for census, clog2(N*N) for rank
  parameter CODE_W = 24,
  parameter P = 1,
  parameter COLS = N
) (
  input  wire                clk,
  input  wire                shift,
  input  wire [N*COLS*8-1:0] window_left,
  input  wire [N*COLS*8-1:0] window_right,
  input  wire [N-1:0]        row_valid,
  input  wire [N+P-2:0]      col_valid,
  output reg  [P*CODE_W-1:0] code_base,
  output reg  [P*CODE_W-1:0] code_match
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 3 || N % 2 == 0) begin : invalid_N
      fpstereo_invalid_parameters_transform_N_is_not_odd_and_at_least_3 failed ();
    end
    if ((RANK == 0 && CODE_W != N * N - 1) || (RANK != 0 && N * N - 1 >= (1 << CODE_W))) begin : invalid_CODE_W
      fpstereo_invalid_parameters_transform_CODE_W_is_not_N_N_minus_1_for_census_or_too_narrow_for_rank failed ();
    end
    if (P < 1 || COLS < N + P - 1) begin : invalid_P
      fpstereo_invalid_parameters_transform_COLS_below_N_plus_P_minus_1 failed ();
    end
  endgenerate
  wire [P*CODE_W-1:0] code_left, code_right;
  genvar q;
  generate
    for (q = 0; q < P; q = q + 1) begin : pixel
      wire [N*N*8-1:0] left, right;
      fpstereo_window_cut #(.N(N), .COLS(COLS), .Q(q)) left_cut (.array(window_left), .window(left));
      fpstereo_window_cut #(.N(N), .COLS(COLS), .Q(q)) right_cut (.array(window_right), .window(right));
      wire [N-1:0] cols = col_valid[q +: N];
      if (RANK) begin : rank
        fpstereo_rank #(.N(N), .RANK_W(CODE_W)) base (.clk(clk), .shift(shift), .window(left),
          .row_valid(row_valid), .col_valid(cols), .rank(code_left[q*CODE_W +: CODE_W]));
        fpstereo_rank #(.N(N), .RANK_W(CODE_W)) match (.clk(clk), .shift(shift), .window(right),
          .row_valid(row_valid), .col_valid(cols), .rank(code_right[q*CODE_W +: CODE_W]));
      end else begin : census
        fpstereo_census #(.N(N)) base (.window(left), .row_valid(row_valid), .col_valid(cols),
                                       .code(code_left[q*CODE_W +: CODE_W]));
        fpstereo_census #(.N(N)) match (.window(right), .row_valid(row_valid), .col_valid(cols),
                                        .code(code_right[q*CODE_W +: CODE_W]));
      end
    end
  endgenerate
  always @(posedge clk)
    if (shift) begin
      code_base  <= code_left;
      code_match <= code_right;
    end
endmodule
`resetall
