`resetall
`default_nettype none
// Speckle filter (docs/semantics.md section 5a) in the streaming form of docs/speckle-hardware.md:
// a labeller with a stack of open sets, the row-end resolution of the labels, a kill chain over
// the runs of closed small regions, and the exit, which gives each word ROWS rows after it
// entered, invalid if its region has at most S pixels. This first form takes a word at most every
// 4 clocks (in_ready is high one clock in four): the labeller's step is spread over 4 phases so
// that every memory read is registered. Rows follow each other without a gap; the first word of
// each frame comes with in_first (nothing above it connects), and the last frame leaves when
// ROWS more rows (of any words, in_first on the first) push it out. Every memory is a RAM
// template with a registered read (fpstereo_ram_sdp; the kill bits fpstereo_ram_tdp), so that
// the row-sized and ROWS x W tables map to block RAM.
module fpstereo_speckle #(
  // pixels a row
  parameter W = 32,
  // the speckle size S: a region of at most S pixels is removed
  parameter S = 8,
  // the largest step between neighbours of a region, in word units (r << sub-pixel bits)
  parameter R = 2,
  // width of a word
  parameter WORD_W = 8,
  // the invalid word, never part of a region
  parameter [WORD_W-1:0] INVALID = {WORD_W{1'b1}},
  // rows held, the latency in rows: S + 2 + ceil(S / 4) at a word every 4 clocks
  parameter ROWS = S + 2 + (S + 3) / 4
) (
  input  wire              clk,
  input  wire              rst,
  input  wire              in_valid,
  output wire              in_ready,
  input  wire              in_first,  // the word is the first of a frame
  input  wire [WORD_W-1:0] in_word,
  output reg               out_valid,
  output reg  [WORD_W-1:0] out_word
);
  generate
    if (W < 2) begin : invalid_W
      fpstereo_invalid_parameters_speckle_W_below_2 failed ();
    end
    if (S < 1) begin : invalid_S
      fpstereo_invalid_parameters_speckle_S_below_1 failed ();
    end
    if (ROWS < S + 2 + (S + 3) / 4) begin : invalid_ROWS
      fpstereo_invalid_parameters_speckle_ROWS_below_S_plus_2_plus_ceil_S_over_4 failed ();
    end
  endgenerate

  localparam X_W = $clog2(W);                 // x, labels and root labels of a row
  localparam POS = ROWS * W;                  // positions of the held words; a run is known by its first
  localparam P_W = $clog2(POS);
  localparam C_W = $clog2(S + 2);             // counts 0 .. S + 1 (S + 1: big)
  localparam DEPTH = (W + 1) / 2;             // the stack's entries at most
  localparam SP_W = $clog2(DEPTH + 1);
  localparam SA_W = DEPTH > 1 ? $clog2(DEPTH) : 1;  // the entries below the top: sp - 1 of them
  localparam LABELS = 2 << X_W;               // {bank, label}: two rows' labels
  localparam SLOT_W = $clog2(ROWS);
  localparam integer BIG_I = S + 1, LAST_X_I = W - 1, LAST_SLOT_I = ROWS - 1, LAST_POS_I = POS - 1;
  localparam [C_W-1:0] BIG = BIG_I[C_W-1:0];
  localparam [X_W-1:0] LAST_X = LAST_X_I[X_W-1:0];
  localparam [SLOT_W-1:0] LAST_SLOT = LAST_SLOT_I[SLOT_W-1:0];
  localparam [P_W-1:0] LAST_POS = LAST_POS_I[P_W-1:0];

  // stack entries below the top: {label, count, head, tail, last_left, last_right}
  localparam E_W = X_W + C_W + 2 * P_W + 2 * X_W;
  // a class record of a row: {count, last x, runs list head, tail, met by the next row}. A met
  // class is the top of the stack (the stack lemma), so the hardware needs no tag to find it;
  // the cycle-level model checks the lemma with tags.
  localparam CLS_W = C_W + X_W + 2 * P_W + 1;
  localparam ABOVE_W = WORD_W + 1 + X_W;      // the row above: {word, valid, label}

  localparam integer R_I = R;
  localparam [WORD_W:0] RANGE = R_I[WORD_W:0];
  function connected(input [WORD_W-1:0] a, input [WORD_W-1:0] b);
    reg [WORD_W-1:0] d;
    begin
      d = a > b ? a - b : b - a;
      connected = a != INVALID && b != INVALID && {1'b0, d} <= RANGE;
    end
  endfunction
  function [C_W-1:0] sat_add(input [C_W-1:0] a, input [C_W-1:0] b);
    sat_add = ({1'b0, a} + {1'b0, b} > {1'b0, BIG}) ? BIG : a + b;
  endfunction
  // a + b + 1, and whether it reaches S + 1 (then the sum is S + 1: big for good)
  function [C_W:0] big_and_sum_plus_1(input [C_W-1:0] a, input [C_W-1:0] b);
    reg [C_W:0] total;
    begin
      total = {1'b0, a} + {1'b0, b} + 1'b1;
      big_and_sum_plus_1 = total >= {1'b0, BIG} ? {1'b1, BIG} : {1'b0, total[C_W-1:0]};
    end
  endfunction

  // --- position and phase ---
  reg [1:0]        phase;                     // 0: waiting for a word; 1 .. 3: its steps
  reg [X_W-1:0]    x;
  reg [SLOT_W-1:0] slot;
  reg              bank;                      // this row's bank; the row above's is ~bank
  reg              full;                      // ROWS rows have entered: the exit gives words
  reg              no_above;                  // this row is a frame's first
  reg              have_above;                // a row has entered since reset
  reg [P_W-1:0]    pos;                       // slot * W + x
  // The word's position again, as the write address of the words and the row above: with the
  // read's own address Yosys (0.23) takes the two ports for one and maps them to LUTRAM.
  reg [P_W-1:0]    pos_w;
  reg [X_W-1:0]    x_w;
  assign in_ready = phase == 2'd0 && !rst;
  wire accept = in_valid && in_ready;

  // --- the word's step ---
  reg [WORD_W-1:0] word_q;
  reg              first_q;
  reg              word_valid_q;              // the word is not the invalid word
  reg              up_raw_q;                  // the word is within range of the one above (phase 2)
  reg              left_q;                    // the word joins the pixel left of it (phase 2)
  reg              top_at_x_q;                // the top's last pixel above is at x (phase 3)
  reg              x0_q;                      // the word is a row's first (phase 1)
  reg [X_W-1:0]    c_q;                       // the class of the pixel above (phase 2)
  // The reads of the big memories, registered once more: a memory of many block RAMs ends in a
  // multiplexer, which should not add to the logic after it.
  reg [WORD_W-1:0] ex_word_q;                 // the exit's word and kill bit (phase 2)
  reg              ex_kill_q;
  reg [C_W-1:0]    rc_count;                  // the class record of the pixel above (phase 3)
  reg [X_W-1:0]    rc_last;
  reg [P_W-1:0]    rc_head, rc_tail;
  reg              rc_met;
  reg [E_W-1:0]    below_q;                   // the entry under the top (phase 3)
  // Phase 3's compares and sums, prepared in phase 2 from the class record and the counts as
  // phase 2 leaves them.
  reg              closes_q;                  // the class's last pixel above is at x
  reg              beyond_x_q;                // ... right of x
  reg              beyond_right_q;            // ... right of the top's
  reg              small_q;                   // the class has at most S pixels
  reg              row_end_q;                 // x is the row's last
  reg              cur_smaller_q;             // the current set's label is below the top's
  reg [C_W-1:0]    join_sum_q, absorb_sum_q;  // the top with the current set; the class with the set
  reg              join_big_q, absorb_big_q;  // the sum is S + 1 or more: its list is dropped
  reg              ex_joins_q;                // the exit's word joins the one left of it (phase 3)
  reg              join_q;                    // the current set joins the top (the class above was met)
  reg              absorb_q;                  // the class above joins the current set

  // --- the labeller's sets: the current run's, and the top of the stack ---
  reg              cur_act, cur_on;           // a current run; its set is the top
  reg [X_W-1:0]    cur_label, cur_last;
  reg [C_W-1:0]    cur_count;
  reg [P_W-1:0]    cur_head, cur_tail;
  reg [X_W-1:0]    top_label, top_last, top_right;
  reg [C_W-1:0]    top_count;
  reg [P_W-1:0]    top_head, top_tail;
  reg [SP_W-1:0]   sp;                        // entries on the stack, the top included
  reg [X_W:0]      next_label;
  reg [WORD_W-1:0] left_word;

  // --- the row-end resolution and the kill chain ---
  reg [X_W:0]      res_next, res_count;
  reg              res1_valid, res2_valid;    // the resolution's pipeline: parent read, root read, write
  reg [X_W-1:0]    res1_label, res2_label, res2_root_prev;
  reg              res2_self, res2_forward;   // the label is its own root; its parent is the label written now
  reg              k_pending;
  reg [P_W-1:0]    k_at, k_tail;
  // An append behind a continuing chain writes the old tail's link (k_appended_link) two clocks
  // before a read sees it (the link RAM's write is registered): if the chain comes to the old
  // tail meanwhile, it reads the tail's mark and takes k_appended_link instead, once.
  reg [1:0]        k_appended;                // the append's first and second clock after
  reg [P_W-1:0]    k_appended_link;
  // The class write left over from phase 3 (the met mark, or the set a row's last pixel
  // finalised), done in the next clock, where no other class write can be.
  reg              post_valid;
  reg              post_late;                 // the row's last set (else the met mark)
  reg [X_W:0]      post_addr;

  // --- the exit ---
  reg [WORD_W-1:0] ex_left;
  reg              ex_killed;

  // --- the memories ---
  // The held words: read in phase 0 (the exit's word, ROWS rows old), written in phase 1.
  wire [WORD_W-1:0] ex_word;
  fpstereo_ram_sdp #(.WIDTH(WORD_W), .DEPTH(POS), .ADDR_W(P_W)) words_mem (
    .clk(clk), .we(phase == 2'd1), .waddr(pos_w), .wdata(word_q),
    .re(accept), .raddr(pos), .rdata(ex_word));
  // A run's kill bit, at its first pixel: the exit reads it (phase 0) and clears it (phase 1) on
  // one port, the kill chain sets it on the other, every clock.
  wire ex_kill, unused_kill_b;
  fpstereo_ram_tdp #(.WIDTH(1), .DEPTH(POS), .ADDR_W(P_W)) kill_mem (
    .clk(clk), .we_a(phase == 2'd1), .re_a(accept), .addr_a(pos), .wdata_a(1'b0), .rdata_a(ex_kill),
    .we_b(k_pending), .re_b(1'b0), .addr_b(k_at), .wdata_b(1'b1), .rdata_b(unused_kill_b));
  // The runs lists and the kill chain: a run's link {linked, next run}, its tail's not linked. A
  // new run (phase 2) marks its own; the labeller's splice or the chain's append (never both at
  // one pixel, phase 3) links a tail. The write is registered, so that the compares and the
  // labeller's choices behind it stay off the RAM's write enable and address decode (logic depth,
  // docs/timing.md). The chain reads the link of the run it goes to. The flag has a RAM of its
  // own: a bit more beside the run numbers would take a column of block RAMs more where those
  // fill a port's 18 bits (A6: 101 BRAM36 against 5), and a number no run has for the tail's mark
  // two LUT levels more behind the read (8 at A4's size).
  wire             link_we;
  wire [P_W-1:0]   link_waddr, k_at_next;
  wire [P_W:0]     link_wdata, next_rdata;
  reg              link_we_q;
  reg  [P_W-1:0]   link_waddr_q;
  reg  [P_W:0]     link_wdata_q;
  always @(posedge clk) begin
    link_we_q <= link_we && !rst;
    link_waddr_q <= link_waddr;
    link_wdata_q <= link_wdata;
  end
  fpstereo_ram_sdp #(.WIDTH(P_W), .DEPTH(POS), .ADDR_W(P_W)) next_mem (
    .clk(clk), .we(link_we_q), .waddr(link_waddr_q), .wdata(link_wdata_q[P_W-1:0]),
    .re(1'b1), .raddr(k_at_next), .rdata(next_rdata[P_W-1:0]));
  fpstereo_ram_sdp #(.WIDTH(1), .DEPTH(POS), .ADDR_W(P_W)) linked_mem (
    .clk(clk), .we(link_we_q), .waddr(link_waddr_q), .wdata(link_wdata_q[P_W]),
    .re(1'b1), .raddr(k_at_next), .rdata(next_rdata[P_W]));
  // The row above: the next pixel's read in phase 3 (a clock ahead of its root), this pixel's
  // write.
  wire [WORD_W-1:0] aw;
  wire              ah;
  wire [X_W-1:0]    al;
  wire [X_W-1:0]    this_label_w;
  fpstereo_ram_sdp #(.WIDTH(ABOVE_W), .DEPTH(W), .ADDR_W(X_W)) above_mem (
    .clk(clk), .we(phase == 2'd3), .waddr(x_w), .wdata({word_q, word_q != INVALID, this_label_w}),
    .re(phase == 2'd3), .raddr(x == LAST_X ? {X_W{1'b0}} : x + 1'b1), .rdata({aw, ah, al}));
  // Parents {bank, label}: a new label (phase 2) or a join (phase 3) writes this row's bank; the
  // resolution reads the row above's.
  wire             parent_we;
  wire [X_W-1:0]   parent_wlabel, parent_wdata, res_parent;
  wire res_go = res_next < res_count;
  fpstereo_ram_sdp #(.WIDTH(X_W), .DEPTH(LABELS), .ADDR_W(X_W + 1)) parent_mem (
    .clk(clk), .we(parent_we), .waddr({bank, parent_wlabel}), .wdata(parent_wdata),
    .re(res_go), .raddr({~bank, res_next[X_W-1:0]}), .rdata(res_parent));
  // The row above's labels resolved, in two copies written together: the resolution reads one
  // (a parent's root), the labeller the other (phase 0; label 0 is its own root, and the labeller
  // may read it before the resolution has written it).
  wire [X_W-1:0]   res_root_w, parent_root, c_root;
  fpstereo_ram_sdp #(.WIDTH(X_W), .DEPTH(W), .ADDR_W(X_W)) root_res_mem (
    .clk(clk), .we(res2_valid), .waddr(res2_label), .wdata(res_root_w),
    .re(res1_valid), .raddr(res_parent), .rdata(parent_root));
  fpstereo_ram_sdp #(.WIDTH(X_W), .DEPTH(W), .ADDR_W(X_W)) root_mem (
    .clk(clk), .we(res2_valid), .waddr(res2_label), .wdata(res_root_w),
    .re(phase == 2'd0), .raddr(al), .rdata(c_root));
  wire [X_W-1:0]   c = c_root & {X_W{!x0_q}};
  // The class records {bank, root label}: this row's sets finalised (phase 2, phase 3, or the
  // clock after phase 3), the row above's read in phase 1 and marked met the clock after phase 3.
  wire             cls_we;
  wire [X_W:0]     cls_waddr;
  wire [CLS_W-1:0] cls_wdata;
  wire [CLS_W-1:0] cls_rdata;
  fpstereo_ram_sdp #(.WIDTH(CLS_W), .DEPTH(LABELS), .ADDR_W(X_W + 1)) cls_mem (
    .clk(clk), .we(cls_we), .waddr(cls_waddr), .wdata(cls_wdata),
    .re(phase == 2'd1), .raddr({~bank, c}), .rdata(cls_rdata));
  // The stack's entries below the top: the one under the top is read in phase 1, a push written
  // in phase 3.
  wire [E_W-1:0]   below;
  wire             stack_we;
  localparam [SA_W-1:0] TWO = 2;
  wire [SA_W-1:0]  stack_push_at = sp[SA_W-1:0] - 1'b1;  // sp - 1 < DEPTH: no wrap
  wire [SA_W-1:0]  stack_below_at = sp >= 2 ? sp[SA_W-1:0] - TWO : {SA_W{1'b0}};
  fpstereo_ram_sdp #(.WIDTH(E_W), .DEPTH(DEPTH), .ADDR_W(SA_W)) stack_mem (
    .clk(clk), .we(stack_we), .waddr(stack_push_at),
    .wdata({top_label, top_count, top_head, top_tail, top_last, top_right}),
    .re(phase == 2'd1), .raddr(stack_below_at), .rdata(below));

  // Phase 3: the step of docs/speckle-hardware.md after the run bookkeeping of phase 2, as
  // blocking updates of copies of the state; the clocked block below stores the results.
  reg              n_cur_act, n_cur_on;
  reg [X_W-1:0]    n_cur_label, n_cur_last;
  reg [C_W-1:0]    n_cur_count;
  reg [P_W-1:0]    n_cur_head, n_cur_tail;
  reg [X_W-1:0]    n_top_label, n_top_last, n_top_right;
  reg [C_W-1:0]    n_top_count;
  reg [P_W-1:0]    n_top_head, n_top_tail;
  reg [SP_W-1:0]   n_sp;
  reg              wr_next, wr_parent, wr_met, wr_fin, wr_late, push, enqueue;
  reg [P_W-1:0]    wr_next_at, wr_next_data;
  reg [X_W-1:0]    wr_parent_at, wr_parent_data, this_label;
  reg [X_W-1:0]    fin_label, fin_last;
  reg [C_W-1:0]    fin_count, sum;
  reg              big;
  reg [P_W-1:0]    fin_head, fin_tail;
  reg              absorbed, extended;

  always @(*) begin
    n_cur_act = cur_act; n_cur_on = cur_on; n_cur_label = cur_label; n_cur_last = cur_last;
    n_cur_count = cur_count; n_cur_head = cur_head; n_cur_tail = cur_tail;
    n_top_label = top_label; n_top_last = top_last; n_top_right = top_right;
    n_top_count = top_count; n_top_head = top_head; n_top_tail = top_tail;
    n_sp = sp;
    wr_next = 1'b0; wr_next_at = {P_W{1'b0}}; wr_next_data = {P_W{1'b0}};
    wr_parent = 1'b0; wr_parent_at = {X_W{1'b0}}; wr_parent_data = {X_W{1'b0}};
    wr_met = 1'b0;
    wr_fin = 1'b0; wr_late = 1'b0; fin_label = {X_W{1'b0}}; fin_last = {X_W{1'b0}};
    fin_count = {C_W{1'b0}}; fin_head = {P_W{1'b0}}; fin_tail = {P_W{1'b0}};
    push = 1'b0; enqueue = 1'b0;
    sum = {C_W{1'b0}}; big = 1'b0; absorbed = 1'b0; extended = 1'b0;
    // Joins: the class above, or (met before) its set, which is the top of the stack.
    if (join_q) begin  // the current set joins the top (met before)
      sum = join_sum_q; big = join_big_q;
      if (!big) begin
        wr_next = 1'b1; wr_next_at = top_tail; wr_next_data = cur_head;
        n_top_tail = cur_tail;
      end
      n_top_count = sum;
      n_top_last = x;
      wr_parent = 1'b1;
      if (cur_smaller_q) begin
        wr_parent_at = top_label; wr_parent_data = cur_label; n_top_label = cur_label;
      end else begin
        wr_parent_at = cur_label; wr_parent_data = top_label;
      end
      n_cur_on = 1'b1;
    end else if (absorb_q) begin  // the class joins the current set (on the stack or not)
      absorbed = 1'b1;
      sum = absorb_sum_q; big = absorb_big_q;
      if (!big) begin
        wr_next = 1'b1; wr_next_at = cur_on ? top_tail : cur_tail; wr_next_data = rc_head;
      end
      wr_met = 1'b1;
      if (cur_on) begin
        n_top_count = sum;
        if (!big) n_top_tail = rc_tail;
        if (beyond_right_q) begin
          n_top_right = rc_last;
          extended = 1'b1;
        end
      end else begin
        n_cur_count = sum;
        if (!big) n_cur_tail = rc_tail;
        if (beyond_x_q) begin  // open: push it
          push = 1'b1;
          n_top_label = cur_label; n_top_count = sum;
          n_top_head = cur_head; n_top_tail = big ? cur_tail : rc_tail;
          n_top_last = cur_last; n_top_right = rc_last;
          n_sp = sp + 1'b1;
          n_cur_on = 1'b1;
        end
      end
    end
    // A class of the row above not met by its last pixel is closed; a small one is killed.
    if (have_above && ah && closes_q && !rc_met && !absorbed && small_q) enqueue = 1'b1;
    // The top whose last pixel above is at x leaves the stack (an entry pushed or extended now
    // reaches beyond x: a stack entry's last pixel above is never left of the cursor).
    if (top_at_x_q && !push && !extended) begin
      if (n_cur_on) begin
        n_cur_label = n_top_label; n_cur_count = n_top_count; n_cur_head = n_top_head;
        n_cur_tail = n_top_tail; n_cur_last = n_top_last;
        n_cur_on = 1'b0;
      end else begin
        // The top as this step found it: a join, a push or an absorb into the top would have left
        // the current set on the stack (n_cur_on), so the record written comes from registers
        // (logic depth, docs/timing.md).
        wr_fin = 1'b1;
        fin_label = top_label; fin_count = top_count; fin_head = top_head; fin_tail = top_tail;
        fin_last = top_last;
      end
      n_sp = n_sp - 1'b1;
      {n_top_label, n_top_count, n_top_head, n_top_tail, n_top_last, n_top_right} = below_q;
    end
    this_label = n_cur_on ? n_top_label : n_cur_label;
    // The row's end finalises the current set (the stack is empty by now).
    if (row_end_q && n_cur_act) begin
      wr_late = 1'b1;
      n_cur_act = 1'b0;
    end
  end

  // Phase 2's run bookkeeping: the current run ends where a pixel is not connected to its left.
  wire run_ends = cur_act && !left_q;
  wire starts = word_valid_q && !left_q;
  // Phase 3's sums with the counts phase 2 leaves: the word's own pixel is the + 1 (a new run's
  // count, or the one phase 2 adds to the current or the top set).
  wire up_next = !no_above && have_above && ah && up_raw_q;  // the word joins the pixel above
  wire cur_on_next = cur_on && !run_ends && !starts;         // cur_on as phase 2 leaves it
  wire [C_W-1:0] cls_count_r = cls_rdata[CLS_W-1 -: C_W];
  wire [X_W-1:0] cls_last_r = cls_rdata[CLS_W-1-C_W -: X_W];
  wire [C_W:0] join_next = big_and_sum_plus_1(top_count, starts ? {C_W{1'b0}} : cur_count);
  wire [C_W:0] absorb_next = big_and_sum_plus_1(starts ? {C_W{1'b0}} : cur_on ? top_count : cur_count, cls_count_r);

  assign this_label_w = this_label;
  assign parent_we = (phase == 2'd2 && starts) || (phase == 2'd3 && wr_parent);
  assign parent_wlabel = phase == 2'd2 ? next_label[X_W-1:0] : wr_parent_at;
  assign parent_wdata = phase == 2'd2 ? next_label[X_W-1:0] : wr_parent_data;
  wire fin_run = run_ends && !cur_on;        // phase 2: the run's set is finalised
  assign cls_we = post_valid || (phase == 2'd2 && fin_run) || (phase == 2'd3 && wr_fin);
  assign cls_waddr = post_valid ? post_addr : {bank, phase == 2'd2 ? cur_label : fin_label};
  // The post write's record is in registers by then: the set phase 3 left in cur_*, or the class
  // read in phase 2 (rc_*, kept until the next phase 2).
  wire [CLS_W-1:0] post_data = post_late ? {cur_count, cur_last, cur_head, cur_tail, 1'b0}
                                         : {rc_count, rc_last, rc_head, rc_tail, 1'b1};
  assign cls_wdata = post_valid ? post_data
                   : phase == 2'd2 ? {cur_count, cur_last, cur_head, cur_tail, 1'b0}
                   : {fin_count, fin_last, fin_head, fin_tail, 1'b0};
  assign stack_we = phase == 2'd3 && push && sp != 0;
  // The resolution's root of a label: itself, or its parent's root (forwarded when the parent is
  // the label written in this clock, which the read could not see yet).
  assign res_root_w = res2_self ? res2_label : res2_forward ? res2_root_prev : parent_root;

  // The kill chain walks one run a clock; a closed small region's list starts it or goes behind
  // its tail. The labeller's splices are to open lists, never the chain's, so only an append can
  // write the link the chain reads.
  wire k_stale = k_appended != 2'b00 && !next_rdata[P_W];  // the old tail, read before the append's write
  wire k_last = !next_rdata[P_W] && !k_stale;
  wire k_continue = k_pending && !k_last;
  wire append = phase == 2'd3 && enqueue;
  wire [P_W-1:0] k_link = k_stale ? k_appended_link : next_rdata[P_W-1:0];
  assign k_at_next = (append && !k_continue) ? rc_head : k_link;
  wire splice = phase == 2'd3 && wr_next;
  wire mark = phase == 2'd2 && starts;
  assign link_we = mark || splice || (append && k_continue);
  assign link_waddr = mark ? pos : splice ? wr_next_at : k_tail;
  assign link_wdata = mark ? {1'b0, pos} : {1'b1, splice ? wr_next_data : rc_head};

  always @(posedge clk) begin
    out_valid <= 1'b0;
    // The row-end resolution: one label a clock, parents always smaller.
    if (res_go) res_next <= res_next + 1'b1;
    res1_valid <= res_go;
    res1_label <= res_next[X_W-1:0];
    res2_valid <= res1_valid;
    res2_label <= res1_label;
    res2_self <= res_parent == res1_label;
    res2_forward <= res2_valid && res_parent == res2_label;
    res2_root_prev <= res_root_w;
    post_valid <= 1'b0;
    // The kill chain (its link read bypassed while an append's write is on its way).
    if (append && k_continue) begin
      k_appended <= 2'b01;
      k_appended_link <= rc_head;
    end else begin
      k_appended <= k_stale ? 2'b00 : {k_appended[0], 1'b0};
    end
    if (append) begin
      k_at <= k_at_next;
      k_tail <= rc_tail;
      k_pending <= 1'b1;
    end else if (k_pending) begin
      if (k_last) k_pending <= 1'b0;
      else k_at <= k_at_next;
    end
    case (phase)
      2'd0: if (accept) begin
        word_q <= in_word;
        first_q <= in_first;
        word_valid_q <= in_word != INVALID;
        pos_w <= pos;
        x_w <= x;
        x0_q <= x == 0;
        phase <= 2'd1;
      end
      2'd1: begin
        ex_word_q <= ex_word;
        ex_kill_q <= ex_kill;
        c_q <= c;
        left_q <= x != 0 && connected(left_word, word_q);
        up_raw_q <= connected(aw, word_q);
        if (x == 0) no_above <= first_q;
        phase <= 2'd2;
      end
      2'd2: begin
        ex_joins_q <= !x0_q && connected(ex_left, ex_word_q);
        ex_left <= ex_word_q;
        {rc_count, rc_last, rc_head, rc_tail, rc_met} <= cls_rdata;
        closes_q <= cls_last_r == x;
        beyond_x_q <= cls_last_r > x;
        beyond_right_q <= cls_last_r > top_right;
        small_q <= cls_count_r != BIG;
        row_end_q <= x == LAST_X;
        cur_smaller_q <= (starts ? next_label[X_W-1:0] : cur_label) < top_label;
        {join_big_q, join_sum_q} <= join_next;
        {absorb_big_q, absorb_sum_q} <= absorb_next;
        below_q <= below;
        join_q <= up_next && cls_rdata[0] && !cur_on_next;
        absorb_q <= up_next && !cls_rdata[0];
        top_at_x_q <= sp != 0 && top_right == x;
        if (run_ends) begin
          cur_act <= 1'b0;
          cur_on <= 1'b0;
        end
        if (starts) begin
          cur_act <= 1'b1;
          cur_on <= 1'b0;
          cur_label <= next_label[X_W-1:0];
          cur_count <= {{(C_W - 1){1'b0}}, 1'b1};
          cur_head <= pos;
          cur_tail <= pos;
          cur_last <= x;
          next_label <= next_label + 1'b1;
        end else if (left_q) begin
          if (cur_on) begin
            top_count <= sat_add(top_count, {{(C_W - 1){1'b0}}, 1'b1});
            top_last <= x;
          end else begin
            cur_count <= sat_add(cur_count, {{(C_W - 1){1'b0}}, 1'b1});
            cur_last <= x;
          end
        end
        phase <= 2'd3;
      end
      default: begin
        // The exit: a run's kill bit is at its first pixel.
        if (!ex_joins_q) begin
          ex_killed <= ex_kill_q;
          out_word <= (ex_word_q != INVALID && ex_kill_q) ? INVALID : ex_word_q;
        end else begin
          out_word <= (ex_word_q != INVALID && ex_killed) ? INVALID : ex_word_q;
        end
        out_valid <= full;
        cur_act <= n_cur_act; cur_on <= n_cur_on; cur_label <= n_cur_label; cur_last <= n_cur_last;
        cur_count <= n_cur_count; cur_head <= n_cur_head; cur_tail <= n_cur_tail;
        top_label <= n_top_label; top_last <= n_top_last; top_right <= n_top_right;
        top_count <= n_top_count; top_head <= n_top_head; top_tail <= n_top_tail;
        sp <= n_sp;
        // The row's last set goes in the next clock; the met mark of the row's last pixel is
        // then dropped (the next row overwrites this bank before the row after reads it).
        if (wr_late) begin
          post_valid <= 1'b1;
          post_late <= 1'b1;
          post_addr <= {bank, n_cur_label};
        end else if (wr_met) begin
          post_valid <= 1'b1;
          post_late <= 1'b0;
          post_addr <= {~bank, c_q};
        end
        left_word <= word_q;
        if (x == LAST_X) begin
          x <= {X_W{1'b0}};
          slot <= (slot == LAST_SLOT) ? {SLOT_W{1'b0}} : slot + 1'b1;
          pos <= (pos == LAST_POS) ? {P_W{1'b0}} : pos + 1'b1;
          if (slot == LAST_SLOT) full <= 1'b1;
          bank <= ~bank;
          have_above <= 1'b1;
          res_next <= {(X_W + 1){1'b0}};
          res_count <= next_label;
          next_label <= {(X_W + 1){1'b0}};
        end else begin
          x <= x + 1'b1;
          pos <= pos + 1'b1;
        end
        phase <= 2'd0;
      end
    endcase
    // A reset overrides the control registers only: the data beside them is read only where
    // those say so, and their enables stay free of the reset's logic (logic depth, docs/timing.md).
    if (rst) begin
      phase <= 2'd0; x <= {X_W{1'b0}}; slot <= {SLOT_W{1'b0}}; bank <= 1'b0; full <= 1'b0;
      no_above <= 1'b1; pos <= {P_W{1'b0}};
      cur_act <= 1'b0; cur_on <= 1'b0; sp <= {SP_W{1'b0}}; next_label <= {(X_W + 1){1'b0}};
      res_next <= {(X_W + 1){1'b0}}; res_count <= {(X_W + 1){1'b0}};
      res1_valid <= 1'b0; res2_valid <= 1'b0;
      k_pending <= 1'b0; k_appended <= 2'b00; post_valid <= 1'b0; out_valid <= 1'b0;
      have_above <= 1'b0;
    end
  end
endmodule
`resetall
