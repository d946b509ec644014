`resetall
`default_nettype none
// Median filter of one M x M window of disparity words (docs/semantics.md, section 6; words as
// in section 8: DISP_W = WORD_W - 1 disparity bits, the invalid flag on top). One window per
// step when en is high; en low freezes every register, so a stalled pipeline keeps its state.
//
// - An invalid centre gives the invalid word 1 << DISP_W (the median does not fill holes).
// - Otherwise the result is the lower median v_((k-1)/2) of the k used words, a word being used
//   when its row and column lie inside the image (row_valid, col_valid) and its flag is 0. The
//   centre is always inside the image; it is counted from its flag alone, so a caller that
//   lets the masks go low around a bubble slot still gets a defined (ignored) result.
//
// How: every word becomes a sort key, the word itself when used (flag 0) and all ones when not,
// so excluded words sort after every used one and the first k sorted keys are exactly the used
// words in ascending order. The N = M*M keys go through Batcher's odd-even merge sort: stage s
// (s = 0 .. L-1, L = clog2(N)) merges sorted runs of 2^s into runs of 2^(s+1) with s + 1 levels
// of compare-exchanges at distances 2^s, 2^(s-1), .., 1; L(L+1)/2 levels in all, every
// compare-exchange in a level independent of the others. The network is the one for 2^L inputs
// with the comparators that touch positions >= N left out: those positions would hold
// all-ones padding, which every comparator leaves in place, so dropping them changes nothing.
// Equal keys are identical words, so the network needs no tie-break. A register follows every
// LEVELS_PER_STAGE levels and the last level. Alongside, the number of used words other than the
// centre (k - 1) is counted per row in the first stage and summed in the second, halved, and
// delayed to meet the sorted keys; the output stage picks sorted key (k-1)/2 with a one-hot
// AND-OR multiplexer. Only keys 0 .. (N-1)/2 can be picked, so synthesis removes the
// comparators that only feed the upper half.
//
// Latency (en-high steps from window to median): with L = clog2(M*M),
//   LATENCY = ceil(L*(L+1)/2 / LEVELS_PER_STAGE) + 1
// which for the default LEVELS_PER_STAGE = 3 is 5 for M = 3 (10 levels), 6 for M = 5 (15 levels)
// and 8 for M = 7 (21 levels).
module fpstereo_median_select #(
  // window side (3, 5 or 7)
  parameter M = 5,
  // word width: disparity bits plus the invalid flag on top (at least 2)
  parameter WORD_W = 8,
  // compare-exchange levels between registers (1 .. 5, so that the count has two stages)
  parameter LEVELS_PER_STAGE = 3
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
  localparam N = M * M;
  localparam CENTRE = (M / 2) * M + M / 2;
  localparam L = $clog2(N);
  localparam LEVELS = L * (L + 1) / 2;
  localparam SORT_STAGES = (LEVELS + LEVELS_PER_STAGE - 1) / LEVELS_PER_STAGE;
  // highest sorted position the median can come from
  localparam HALF_MAX = (N - 1) / 2;
  // holds 0 .. N - 1, the used words besides the centre
  localparam CNT_W = $clog2(N);
  // holds 0 .. M, the used words of one row
  localparam ROW_CNT_W = $clog2(M + 1);
  localparam [WORD_W-1:0] EXCLUDED = {WORD_W{1'b1}};
  localparam [WORD_W-1:0] INVALID = {1'b1, {(WORD_W - 1){1'b0}}};

  // Level l (1-based) of the sorting network belongs to stage s, the largest s with
  // s(s+1)/2 < l; the levels of stage s compare at distances 2^s, 2^(s-1), .., 1.
  function integer stage_of(input integer l);
    integer s;
    begin
      stage_of = 0;
      for (s = 0; s < 32; s = s + 1)
        if (s * (s + 1) / 2 < l) stage_of = s;
    end
  endfunction

  function integer distance_of(input integer l);
    integer s;
    begin
      s = stage_of(l);
      distance_of = (1 << s) >> (l - 1 - s * (s + 1) / 2);
    end
  endfunction

  // 1 iff position a is the lower end of a compare-exchange (a, a + k) in level l: Batcher's
  // iterative form (pairs i + j, i + j + k with j = k mod p, k mod p + 2k, ..; i < k) whose two
  // ends lie in the same run of 2p being merged, restricted to positions below N.
  function is_lower(input integer a, input integer l);
    integer p, k, r;
    begin
      p = 1 << stage_of(l);
      k = distance_of(l);
      r = k % p;
      is_lower = a >= r && a + k < N && (a - r) % (2 * k) < k && a / (2 * p) == (a + k) / (2 * p);
    end
  endfunction

  // Used words: inside the image and not flagged; the centre by its flag alone.
  wire [N-1:0] used;
  wire         centre_invalid = window[CENTRE*WORD_W + WORD_W - 1];

  genvar l, e, h;
  generate
    for (e = 0; e < N; e = e + 1) begin : position
      wire flag = window[e*WORD_W + WORD_W - 1];
      if (e == CENTRE) begin : centre
        assign used[e] = !flag;
      end else begin : neighbour
        assign used[e] = row_valid[e / M] && col_valid[e % M] && !flag;
      end
    end

    for (l = 0; l <= LEVELS; l = l + 1) begin : level
      localparam REGISTERED = (l == LEVELS) || (l > 0 && l % LEVELS_PER_STAGE == 0);
      wire [N*WORD_W-1:0] key_d;
      // Only keys 0 .. HALF_MAX of the last level are ever picked.
      /* verilator lint_off UNUSEDSIGNAL */
      wire [N*WORD_W-1:0] key;
      /* verilator lint_on UNUSEDSIGNAL */
      if (l == 0) begin : keys
        for (e = 0; e < N; e = e + 1) begin : position
          assign key_d[e*WORD_W +: WORD_W] = used[e] ? window[e*WORD_W +: WORD_W] : EXCLUDED;
        end
      end else begin : exchange
        localparam K = distance_of(l);
        for (e = 0; e < N; e = e + 1) begin : position
          if (is_lower(e, l)) begin : low
            wire [WORD_W-1:0] a = level[l-1].key[e*WORD_W +: WORD_W];
            wire [WORD_W-1:0] b = level[l-1].key[(e+K)*WORD_W +: WORD_W];
            assign key_d[e*WORD_W +: WORD_W] = (b < a) ? b : a;
          end else if (e >= K && is_lower(e - K, l)) begin : high
            wire [WORD_W-1:0] a = level[l-1].key[(e-K)*WORD_W +: WORD_W];
            wire [WORD_W-1:0] b = level[l-1].key[e*WORD_W +: WORD_W];
            assign key_d[e*WORD_W +: WORD_W] = (b < a) ? a : b;
          end else begin : pass
            assign key_d[e*WORD_W +: WORD_W] = level[l-1].key[e*WORD_W +: WORD_W];
          end
        end
      end
      if (REGISTERED) begin : stage
        reg [N*WORD_W-1:0] key_q;
        always @(posedge clk)
          if (en) key_q <= key_d;
        assign key = key_q;
      end else begin : wire_through
        assign key = key_d;
      end
    end
  endgenerate

  // k - 1, in two stages: per-row counts (first stage), their sum halved (second stage).
  reg [M*ROW_CNT_W-1:0] row_count_d;
  reg [ROW_CNT_W-1:0]   row_acc;
  integer i, j;
  always @* begin
    for (i = 0; i < M; i = i + 1) begin
      row_acc = {ROW_CNT_W{1'b0}};
      for (j = 0; j < M; j = j + 1)
        if (i * M + j != CENTRE) row_acc = row_acc + {{(ROW_CNT_W - 1){1'b0}}, used[i*M + j]};
      row_count_d[i*ROW_CNT_W +: ROW_CNT_W] = row_acc;
    end
  end

  reg [M*ROW_CNT_W-1:0] row_count_q;
  reg                   centre_invalid_q;
  always @(posedge clk)
    if (en) begin
      row_count_q      <= row_count_d;
      centre_invalid_q <= centre_invalid;
    end

  reg [CNT_W-1:0] others;
  always @* begin
    others = {CNT_W{1'b0}};
    for (i = 0; i < M; i = i + 1)
      others = others + {{(CNT_W - ROW_CNT_W){1'b0}}, row_count_q[i*ROW_CNT_W +: ROW_CNT_W]};
  end

  // (k-1)/2 and the centre's flag, delayed to the last sorting register.
  wire [CNT_W-1:0] half_q;
  wire             invalid_q;
  fpstereo_delay #(.WIDTH(CNT_W + 1), .DEPTH(SORT_STAGES - 1)) side (
    .clk(clk), .en(en), .in({centre_invalid_q, others >> 1}), .out({invalid_q, half_q}));

  // Output stage: sorted key (k-1)/2, or the invalid word.
  generate
    for (h = 0; h <= HALF_MAX; h = h + 1) begin : pick
      localparam [CNT_W-1:0] INDEX = h;
      wire [WORD_W-1:0] hit = (half_q == INDEX) ? level[LEVELS].key[h*WORD_W +: WORD_W] : {WORD_W{1'b0}};
      wire [WORD_W-1:0] any;
      if (h == 0) begin : first
        assign any = hit;
      end else begin : next
        assign any = pick[h-1].any | hit;
      end
    end
  endgenerate

  reg [WORD_W-1:0] median_q;
  always @(posedge clk)
    if (en) median_q <= invalid_q ? INVALID : pick[HALF_MAX].any;
  assign median = median_q;
endmodule
`resetall
