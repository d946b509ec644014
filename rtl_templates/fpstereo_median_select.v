`resetall
`default_nettype none
// Median filter of one M x M window of disparity words (docs/semantics.md, section 6; words as
// in section 8: DISP_W = WORD_W - 1 disparity bits, the invalid flag on top). One window per
// step when en is high; en low freezes every register, so a stalled pipeline keeps its state.
//
// - An invalid centre gives the invalid word 1 << DISP_W (the median does not fill holes).
// - Otherwise the result is the lower median v_((k-1)/2) of the k used words, a word being used
//   when its row and column lie inside the image (row_valid, col_valid) and its flag is 0. The
//   centre is always inside the image; it is counted from its flag alone, so windows whose masks
//   leave out the centre (bubble slots) still give a defined, ignored result.
//
// How: radix selection, a binary search on the value bits from the most significant one, one bit
// per stage. The count stage finds the rank sought, r = (k-1)/2 = floor(#(used words besides the
// centre) / 2), and makes every used word a candidate. Stage b (b = DISP_W-1 .. 0) counts z, the
// candidates with bit b = 0. All candidates agree on the bits above b, so in sorted order those z
// come first: if r < z the answer has bit b = 0 and the candidates with a 1 drop out; otherwise
// it has bit b = 1, the candidates with a 0 drop out and r becomes r - z. After bit 0 the decided
// bits are the answer (equal words need no tie-break). A stage is one N-input population count
// (the rows' counts in one register step, their sum in the next), then a compare and a subtract in
// a third step, the same depth for every stage; the words travel down the pipeline losing their decided bit at each
// stage (shift registers, SRL16E on Xilinx). This takes far less logic than sorting the N keys:
// for M = 5, WORD_W = 8, Yosys synth_xilinx -abc9 maps a pipelined Batcher odd-even merge sort
// (3 compare-exchange levels per stage) to 2876 LUTs and 847 FFs at 6.9 ns (abc9 delay).
//
// Latency (en-high steps from window to median): LATENCY = 3 * WORD_W (three steps for the count
// stage and for each disparity bit, the last one holding the output), whatever M.
module fpstereo_median_select #(
  // window side (3, 5 or 7)
  parameter M = 5,
  // word width: disparity bits plus the invalid flag on top (at least 2)
  parameter WORD_W = 8
) (
  input  wire                  clk,
  input  wire                  en,
  // row i, column j at [(i*M + j)*WORD_W +: WORD_W] (row 0 = oldest, column 0 = leftmost)
  input  wire [M*M*WORD_W-1:0] window,
  // window rows / columns that lie inside the image
  input  wire [M-1:0]          row_valid,
  input  wire [M-1:0]          col_valid,
  output wire [WORD_W-1:0]     median
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (M != 3 && M != 5 && M != 7) begin : invalid_M
      fpstereo_invalid_parameters_median_select_M_is_not_3_5_or_7 failed ();
    end
    if (WORD_W < 2) begin : invalid_WORD_W
      fpstereo_invalid_parameters_median_select_WORD_W_below_2 failed ();
    end
  endgenerate
  localparam N = M * M;
  localparam DISP_W = WORD_W - 1;
  localparam CENTRE = (M / 2) * M + M / 2;
  // holds 0 .. N (a count of words)
  localparam CNT_W = $clog2(N + 1);
  // holds 0 .. M (a count of words in one row)
  localparam ROW_CNT_W = $clog2(M + 1);
  localparam [WORD_W-1:0] INVALID = {1'b1, {DISP_W{1'b0}}};

  // Population count of an N-bit mask in two register stages: the count of each window row, then
  // the sum of the rows, so that neither stage holds more than a few LUT levels.
  localparam ROWS_W = M * ROW_CNT_W;
  function [ROWS_W-1:0] row_counts(input [N-1:0] mask);
    integer i, j;
    begin
      row_counts = {ROWS_W{1'b0}};
      for (i = 0; i < M; i = i + 1)
        for (j = 0; j < M; j = j + 1)
          row_counts[i*ROW_CNT_W +: ROW_CNT_W] = row_counts[i*ROW_CNT_W +: ROW_CNT_W] + {{(ROW_CNT_W - 1){1'b0}}, mask[i*M + j]};
    end
  endfunction
  function [CNT_W-1:0] sum_of_rows(input [ROWS_W-1:0] rows);
    integer i;
    begin
      sum_of_rows = {CNT_W{1'b0}};
      for (i = 0; i < M; i = i + 1)
        sum_of_rows = sum_of_rows + {{(CNT_W - ROW_CNT_W){1'b0}}, rows[i*ROW_CNT_W +: ROW_CNT_W]};
    end
  endfunction

  // Count stage, first step: the window and its masks (compares with the frame size) registered.
  reg [M*M*WORD_W-1:0] window_q;
  reg [M-1:0]          row_valid_q, col_valid_q;
  always @(posedge clk)
    if (en) begin
      window_q    <= window;
      row_valid_q <= row_valid;
      col_valid_q <= col_valid;
    end

  // Used words (the centre by its flag alone) and the disparities.
  wire [N-1:0]        used;
  wire [N-1:0]        used_besides_centre;
  wire [N*DISP_W-1:0] values;

  genvar e, s;
  generate
    for (e = 0; e < N; e = e + 1) begin : position
      wire flag = window_q[e*WORD_W + DISP_W];
      assign values[e*DISP_W +: DISP_W] = window_q[e*WORD_W +: DISP_W];
      if (e == CENTRE) begin : centre
        assign used[e] = !flag;
        assign used_besides_centre[e] = 1'b0;
      end else begin : neighbour
        assign used[e] = row_valid_q[e / M] && col_valid_q[e % M] && !flag;
        assign used_besides_centre[e] = used[e];
      end
    end
  endgenerate

  // Second and third steps: the row counts of the used words besides the centre, then the rank
  // sought (half their sum); the candidates, the disparities and the centre's flag travel beside.
  reg [N + N*DISP_W:0] rows_along, count_along;
  reg [ROWS_W-1:0]     rows_others_q;
  reg [CNT_W-1:0]      count_rank_q;
  always @(posedge clk)
    if (en) begin
      rows_along    <= {used, values, window_q[CENTRE*WORD_W + DISP_W]};
      rows_others_q <= row_counts(used_besides_centre);
      count_along   <= rows_along;
      count_rank_q  <= sum_of_rows(rows_others_q) >> 1;
    end
  wire [N-1:0]        count_cand_q;
  wire [N*DISP_W-1:0] count_values_q;
  wire                count_invalid_q;
  assign {count_cand_q, count_values_q, count_invalid_q} = count_along;

  // Bit stages: stage s decides bit B = DISP_W-1-s and receives bits B .. 0 of every word, word i
  // at vals[i*(B+1) +: B+1]. Its first step counts the candidates with bit B = 0 per row, its
  // second sums the rows, its third decides. (The genvar counts up: some tools reject a genvar that goes negative.)
  reg [WORD_W-1:0] median_q;
  assign median = median_q;

  generate
    for (s = 0; s < DISP_W; s = s + 1) begin : bit_stage
      localparam B = DISP_W - 1 - s;
      wire [N-1:0]       cand;
      wire [CNT_W-1:0]   rank;
      wire [N*(B+1)-1:0] vals;
      // answer bits above B (bit B and below still 0)
      wire [DISP_W-1:0]  upper;
      wire               invalid;
      if (s == 0) begin : from_count
        assign cand    = count_cand_q;
        assign rank    = count_rank_q;
        assign vals    = count_values_q;
        assign upper   = {DISP_W{1'b0}};
        assign invalid = count_invalid_q;
      end else begin : from_above
        assign cand    = bit_stage[s-1].step.cand_q;
        assign rank    = bit_stage[s-1].step.rank_q;
        assign vals    = bit_stage[s-1].step.vals_q;
        assign upper   = bit_stage[s-1].step.upper_q;
        assign invalid = bit_stage[s-1].step.invalid_q;
      end

      wire [N-1:0] bit_here;
      for (e = 0; e < N; e = e + 1) begin : position
        assign bit_here[e] = vals[e*(B+1) + B];
      end
      // What the decision needs travels two steps beside the count: the rows' counts of the
      // candidates with bit B = 0, then their sum.
      localparam ALONG_W = 2 * N + N * (B + 1) + CNT_W + DISP_W + 1;
      reg  [ALONG_W-1:0] along_h, along_z;
      reg  [ROWS_W-1:0]  zeros_h;
      reg  [CNT_W-1:0]   zeros;
      always @(posedge clk)
        if (en) begin
          along_h <= {cand, bit_here, vals, rank, upper, invalid};
          zeros_h <= row_counts(cand & ~bit_here);
          along_z <= along_h;
          zeros   <= sum_of_rows(zeros_h);
        end
      /* verilator lint_off UNUSEDSIGNAL */  // the last stage needs only the decision
      wire [N-1:0]       cand_z, bit_z;
      wire [N*(B+1)-1:0] vals_z;
      /* verilator lint_on UNUSEDSIGNAL */
      wire [CNT_W-1:0]   rank_z;
      wire [DISP_W-1:0]  upper_z;
      wire               invalid_z;
      assign {cand_z, bit_z, vals_z, rank_z, upper_z, invalid_z} = along_z;

      wire              high = rank_z >= zeros;
      localparam [DISP_W-1:0] BIT = 1 << B;
      wire [DISP_W-1:0] answer = high ? upper_z | BIT : upper_z;

      if (B > 0) begin : step
        reg [N-1:0]      cand_q;
        reg [CNT_W-1:0]  rank_q;
        reg [N*B-1:0]    vals_q;
        reg [DISP_W-1:0] upper_q;
        reg              invalid_q;
        integer i;
        always @(posedge clk)
          if (en) begin
            // Candidates whose bit B differs from the answer's drop out.
            cand_q    <= cand_z & (high ? bit_z : ~bit_z);
            rank_q    <= high ? rank_z - zeros : rank_z;
            for (i = 0; i < N; i = i + 1) vals_q[i*B +: B] <= vals_z[i*(B+1) +: B];
            upper_q   <= answer;
            invalid_q <= invalid_z;
          end
      end else begin : last
        always @(posedge clk)
          if (en) median_q <= invalid_z ? INVALID : {1'b0, answer};
      end
    end
  endgenerate
endmodule
`resetall
