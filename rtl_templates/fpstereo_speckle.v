`resetall
`default_nettype none
// Speckle filter (docs/semantics.md section 5a) in the streaming form of docs/speckle-hardware.md:
// a labeller with a stack of open sets, the row-end resolution of the labels, a kill chain over
// the runs of closed small regions, and the exit, which gives each word ROWS rows after it
// entered, invalid if its region has at most S pixels. This first form takes a word at most every
// 4 clocks (in_ready is high one clock in four): the labeller's step is spread over 4 phases so
// that every memory read is registered. Rows follow each other without a gap; the first word of
// each frame comes with in_first (nothing above it connects), and the last frame leaves when
// ROWS more rows (of any words, in_first on the first) push it out.
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
  localparam LABELS = 2 << X_W;               // {bank, label}: two rows' labels
  localparam SLOT_W = $clog2(ROWS);
  localparam integer BIG_I = S + 1, LAST_X_I = W - 1, LAST_SLOT_I = ROWS - 1, LAST_POS_I = POS - 1;
  localparam [C_W-1:0] BIG = BIG_I[C_W-1:0];
  localparam [X_W-1:0] LAST_X = LAST_X_I[X_W-1:0];
  localparam [SLOT_W-1:0] LAST_SLOT = LAST_SLOT_I[SLOT_W-1:0];
  localparam [P_W-1:0] LAST_POS = LAST_POS_I[P_W-1:0];

  // --- memories ---
  reg [WORD_W-1:0] words_mem [0:POS-1];       // the held words
  reg              kill_mem  [0:POS-1];       // a run's kill bit, at its first pixel
  reg [P_W-1:0]    next_mem  [0:POS-1];       // the runs lists and the kill chain
  reg [WORD_W-1:0] above_word [0:W-1];        // the row above
  reg              above_has  [0:W-1];        // the row above's pixel is valid (has a label)
  reg [X_W-1:0]    above_label [0:W-1];
  reg [X_W-1:0]    parent_mem [0:LABELS-1];   // {bank, label}
  reg [X_W-1:0]    root_mem   [0:W-1];        // the previous row's labels, resolved
  reg [C_W-1:0]    cls_count [0:LABELS-1];    // class records {bank, root label}
  reg [X_W-1:0]    cls_last  [0:LABELS-1];
  reg [P_W-1:0]    cls_head  [0:LABELS-1];
  reg [P_W-1:0]    cls_tail  [0:LABELS-1];
  // Met by the next row. A met class is the top of the stack (the stack lemma), so the hardware
  // needs no tag to find it; the cycle-level model checks the lemma with tags.
  reg              cls_met   [0:LABELS-1];
  // stack entries below the top: {label, count, head, tail, last_left, last_right}
  localparam E_W = X_W + C_W + 2 * P_W + 2 * X_W;
  reg [E_W-1:0]    stack_mem [0:DEPTH-1];

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

  // --- position and phase ---
  reg [1:0]        phase;                     // 0: waiting for a word; 1 .. 3: its steps
  reg [X_W-1:0]    x;
  reg [SLOT_W-1:0] slot;
  reg              bank;                      // this row's bank; the row above's is ~bank
  reg              full;                      // ROWS rows have entered: the exit gives words
  reg              no_above;                  // this row is a frame's first
  reg              have_above;                // a row has entered since reset
  reg [P_W-1:0]    pos;                       // slot * W + x
  assign in_ready = phase == 2'd0 && !rst;
  wire accept = in_valid && in_ready;

  // --- registered reads of the word's step ---
  reg [WORD_W-1:0] word_q, aw_q, ex_word_q;
  reg              first_q, ah_q, ex_kill_q;
  reg              left_q;                    // the word joins the pixel left of it (phase 2)
  reg              up_q;                      // the word joins the pixel above it (phase 3)
  reg              top_at_x_q;                // the top's last pixel above is at x (phase 3)
  reg [X_W-1:0]    al_q, c_q;
  reg [C_W-1:0]    rc_count;
  reg [X_W-1:0]    rc_last;
  reg [P_W-1:0]    rc_head, rc_tail;
  reg              rc_met;
  reg [E_W-1:0]    below_q;                   // the entry under the top

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
  reg              k_pending;
  reg [P_W-1:0]    k_at, k_tail;
  reg              late_valid;                // the set a row's last pixel finalised, written a clock later
  reg              late_bank;
  reg [X_W-1:0]    late_label, late_last;
  reg [C_W-1:0]    late_count;
  reg [P_W-1:0]    late_head, late_tail;

  // --- the exit ---
  reg [WORD_W-1:0] ex_left;
  reg              ex_killed;

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
    sum = {C_W{1'b0}}; absorbed = 1'b0; extended = 1'b0;
    // Joins: the class above, or (met before) its set, which is the top of the stack.
    if (up_q) begin
      if (rc_met) begin
        if (!cur_on) begin  // the current set joins the top
          sum = sat_add(top_count, cur_count);
          if (sum != BIG) begin
            wr_next = 1'b1; wr_next_at = top_tail; wr_next_data = cur_head;
            n_top_tail = cur_tail;
          end
          n_top_count = sum;
          n_top_last = x;
          wr_parent = 1'b1;
          if (cur_label < top_label) begin
            wr_parent_at = top_label; wr_parent_data = cur_label; n_top_label = cur_label;
          end else begin
            wr_parent_at = cur_label; wr_parent_data = top_label;
          end
          n_cur_on = 1'b1;
        end
      end else begin  // the class joins the current set (on the stack or not)
        absorbed = 1'b1;
        sum = sat_add(cur_on ? top_count : cur_count, rc_count);
        if (sum != BIG) begin
          wr_next = 1'b1; wr_next_at = cur_on ? top_tail : cur_tail; wr_next_data = rc_head;
        end
        wr_met = 1'b1;
        if (cur_on) begin
          n_top_count = sum;
          if (sum != BIG) n_top_tail = rc_tail;
          if (rc_last > top_right) begin
            n_top_right = rc_last;
            extended = 1'b1;
          end
        end else begin
          n_cur_count = sum;
          if (sum != BIG) n_cur_tail = rc_tail;
          if (rc_last > x) begin  // open: push it
            push = 1'b1;
            n_top_label = cur_label; n_top_count = sum;
            n_top_head = cur_head; n_top_tail = (sum != BIG) ? rc_tail : cur_tail;
            n_top_last = cur_last; n_top_right = rc_last;
            n_sp = sp + 1'b1;
            n_cur_on = 1'b1;
          end
        end
      end
    end
    // A class of the row above not met by its last pixel is closed; a small one is killed.
    if (have_above && ah_q && rc_last == x && !rc_met && !absorbed && rc_count != BIG) enqueue = 1'b1;
    // The top whose last pixel above is at x leaves the stack (an entry pushed or extended now
    // reaches beyond x: a stack entry's last pixel above is never left of the cursor).
    if (top_at_x_q && !push && !extended) begin
      if (n_cur_on) begin
        n_cur_label = n_top_label; n_cur_count = n_top_count; n_cur_head = n_top_head;
        n_cur_tail = n_top_tail; n_cur_last = n_top_last;
        n_cur_on = 1'b0;
      end else begin
        wr_fin = 1'b1;
        fin_label = n_top_label; fin_count = n_top_count; fin_head = n_top_head; fin_tail = n_top_tail;
        fin_last = n_top_last;
      end
      n_sp = n_sp - 1'b1;
      {n_top_label, n_top_count, n_top_head, n_top_tail, n_top_last, n_top_right} = below_q;
    end
    this_label = n_cur_on ? n_top_label : n_cur_label;
    // The row's end finalises the current set (the stack is empty by now).
    if (x == LAST_X && n_cur_act) begin
      wr_late = 1'b1;
      n_cur_act = 1'b0;
    end
  end

  // Phase 2's run bookkeeping: the current run ends where a pixel is not connected to its left.
  wire run_ends = cur_act && !left_q;
  wire starts = word_q != INVALID && !left_q;

  wire [X_W-1:0] res_parent = parent_mem[{~bank, res_next[X_W-1:0]}];
  wire k_last = k_at == k_tail;

  always @(posedge clk) begin
    if (rst) begin
      phase <= 2'd0; x <= {X_W{1'b0}}; slot <= {SLOT_W{1'b0}}; bank <= 1'b0; full <= 1'b0;
      no_above <= 1'b1; pos <= {P_W{1'b0}};
      cur_act <= 1'b0; cur_on <= 1'b0; sp <= {SP_W{1'b0}}; next_label <= {(X_W + 1){1'b0}};
      res_next <= {(X_W + 1){1'b0}}; res_count <= {(X_W + 1){1'b0}};
      k_pending <= 1'b0; late_valid <= 1'b0; out_valid <= 1'b0;
      have_above <= 1'b0;
    end else begin
      out_valid <= 1'b0;
      // The row-end resolution: one label a clock, parents always smaller.
      if (res_next < res_count) begin
        root_mem[res_next[X_W-1:0]] <= res_parent == res_next[X_W-1:0] ? res_parent : root_mem[res_parent];
        res_next <= res_next + 1'b1;
      end
      // The late finalisation of a row's last set.
      if (late_valid) begin
        cls_count[{late_bank, late_label}] <= late_count; cls_last[{late_bank, late_label}] <= late_last;
        cls_head[{late_bank, late_label}] <= late_head; cls_tail[{late_bank, late_label}] <= late_tail;
        cls_met[{late_bank, late_label}] <= 1'b0;
        late_valid <= 1'b0;
      end
      // The kill chain: one run a clock; a new list starts it or goes behind its tail.
      if (k_pending) kill_mem[k_at] <= 1'b1;
      if (phase == 2'd3 && enqueue) begin
        if (k_pending && !k_last) begin
          next_mem[k_tail] <= rc_head;
          k_at <= next_mem[k_at];
        end else begin
          k_at <= rc_head;
        end
        k_tail <= rc_tail;
        k_pending <= 1'b1;
      end else if (k_pending) begin
        if (k_last) k_pending <= 1'b0;
        else k_at <= next_mem[k_at];
      end
      case (phase)
        2'd0: if (accept) begin
          word_q <= in_word;
          first_q <= in_first;
          aw_q <= above_word[x];
          ah_q <= above_has[x];
          al_q <= above_label[x];
          ex_word_q <= words_mem[pos];
          ex_kill_q <= kill_mem[pos];
          phase <= 2'd1;
        end
        2'd1: begin
          // The exit: a run's kill bit is at its first pixel.
          if (x == 0 || !connected(ex_left, ex_word_q)) begin
            ex_killed <= ex_kill_q;
            out_word <= (ex_word_q != INVALID && ex_kill_q) ? INVALID : ex_word_q;
          end else begin
            out_word <= (ex_word_q != INVALID && ex_killed) ? INVALID : ex_word_q;
          end
          ex_left <= ex_word_q;
          out_valid <= full;
          words_mem[pos] <= word_q;
          kill_mem[pos] <= 1'b0;
          above_word[x] <= word_q;
          c_q <= root_mem[al_q];
          left_q <= x != 0 && connected(left_word, word_q);
          if (x == 0) no_above <= first_q;
          phase <= 2'd2;
        end
        2'd2: begin
          rc_count <= cls_count[{~bank, c_q}]; rc_last <= cls_last[{~bank, c_q}];
          rc_head <= cls_head[{~bank, c_q}]; rc_tail <= cls_tail[{~bank, c_q}];
          rc_met <= cls_met[{~bank, c_q}];
          up_q <= !no_above && have_above && ah_q && connected(aw_q, word_q);
          top_at_x_q <= sp != 0 && top_right == x;
          below_q <= stack_mem[sp >= 2 ? sp - 2 : 0];
          if (run_ends && !cur_on) begin  // finalised
            cls_count[{bank, cur_label}] <= cur_count; cls_last[{bank, cur_label}] <= cur_last;
            cls_head[{bank, cur_label}] <= cur_head; cls_tail[{bank, cur_label}] <= cur_tail;
            cls_met[{bank, cur_label}] <= 1'b0;
          end
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
            parent_mem[{bank, next_label[X_W-1:0]}] <= next_label[X_W-1:0];
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
          cur_act <= n_cur_act; cur_on <= n_cur_on; cur_label <= n_cur_label; cur_last <= n_cur_last;
          cur_count <= n_cur_count; cur_head <= n_cur_head; cur_tail <= n_cur_tail;
          top_label <= n_top_label; top_last <= n_top_last; top_right <= n_top_right;
          top_count <= n_top_count; top_head <= n_top_head; top_tail <= n_top_tail;
          sp <= n_sp;
          if (push && sp != 0)
            stack_mem[sp - 1] <= {top_label, top_count, top_head, top_tail, top_last, top_right};
          if (wr_next) next_mem[wr_next_at] <= wr_next_data;
          if (wr_parent) parent_mem[{bank, wr_parent_at}] <= wr_parent_data;
          if (wr_met) cls_met[{~bank, c_q}] <= 1'b1;
          if (wr_fin) begin
            cls_count[{bank, fin_label}] <= fin_count; cls_last[{bank, fin_label}] <= fin_last;
            cls_head[{bank, fin_label}] <= fin_head; cls_tail[{bank, fin_label}] <= fin_tail;
            cls_met[{bank, fin_label}] <= 1'b0;
          end
          if (wr_late) begin
            late_valid <= 1'b1; late_bank <= bank; late_label <= n_cur_label; late_count <= n_cur_count;
            late_head <= n_cur_head; late_tail <= n_cur_tail; late_last <= n_cur_last;
          end
          above_has[x] <= word_q != INVALID;
          above_label[x] <= this_label;
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
    end
  end
endmodule
`resetall
