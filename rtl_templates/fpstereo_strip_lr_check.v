`resetall
`default_nettype none
// The left-right check (docs/semantics.md, section 5) over P strips of a row at P words a slot
// (docs/ppc-hardware.md, "The left-right check in strips"): fpstereo_lr_check's check for each of
// a slot's P words. Strip b's LR1 match side (fpstereo_lr1_match with STRIPS) writes the
// Dm it completes at the completing pixel's place in the strip, row slot * STRIP_PIXELS + x -
// b * STRIP_PIXELS, its row slots modulo (P - b) * K + 1 (the strip's disparity RAM's), and the
// strip holding the row's last pixel its row end. Word q of the read slot looks Dm(x') up, x' =
// x - MIN_DISP - D (fpstereo_strip_match_lookup: a copy of every strip's bank and of the row-end
// RAM per word). read_slots are the strips' row slots of the read row
// (fpstereo_strip_disparity_reorder's), with the read stream. uf = dmax. The read stream is
// registered first (its words come from the disparity RAMs' read multiplexer), beside each
// lookup's bank addresses summed but for the words' disparities, so the check takes four steps
// (and VIEW_WAIT) where the one-pixel check takes three. As in fpstereo_lr_check, a read word with REFINED_W > 0 carries the refined disparity
// above the whole D, which the check uses, and leaves as {invalid, refined}; CARRY_W bits above
// the invalid flag (the confidence) pass unchanged. With RIGHT_VIEW each word also looks up
// Dm(x) itself, which leaves beside the checked word (right_word, the right view's disparity).
// With LR2 the writes are LR2's match side's (fpstereo_strip_aggregation's MATCH_SIDE): strip b
// writes Dm(x') of its own pixels x' at their places in the strip, and no row ends.
module fpstereo_strip_lr_check #(
  parameter P = 2,
  parameter K = 5,
  parameter STRIP_PIXELS = 20,
  parameter DMAX = 16,
  parameter DISP_W = 4,
  // bits of the refined disparity carried above D in a read word, 0 without sub-pixel output
  parameter REFINED_W = 0,
  // bits carried above a word's invalid flag, unchecked (the confidence)
  parameter CARRY_W = 0,
  // width of a completed write's address (strip 0's: (P * K + 1) * STRIP_PIXELS words)
  parameter CAW = 9,
  parameter SLOT_W = 5,
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter MIN_DISP = 0,
  // 1: the writes are LR2's match side's, each at its match pixel's place (no row ends)
  parameter LR2 = 0,
  parameter RIGHT_VIEW = 0,
  // steps the registered read stream waits before the lookups: with LR1, RIGHT_VIEW and
  // MIN_DISP > 0, ceil(MIN_DISP / P), for Dm(x) is completed by x + MIN_DISP + DMAX - 1, MIN_DISP
  // pixels further right than any pixel the check looks up from x; with LR2, the steps the match
  // side's writes land after the base side's words
  parameter VIEW_WAIT = 0
) (
  input  wire                   clk,
  input  wire                   restart,
  input  wire                   adv,
  input  wire [X_W-1:0]         frame_width,
  input  wire [3:0]             lr_threshold,
  input  wire [P-1:0]           completed_we,
  /* verilator lint_off UNUSEDSIGNAL */  // the strips right of 0 have fewer rows: their top bits
  input  wire [P*CAW-1:0]       completed_waddr,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [P*DISP_W-1:0]    completed_wdata,
  input  wire [P-1:0]           row_end_we,
  input  wire [P*SLOT_W-1:0]    row_end_waddr,
  input  wire [P*DMAX*DISP_W-1:0] row_end_wdata,
  // the read stream (fpstereo_strip_disparity_reorder): slot read_x, pixels read_x * P + q
  input  wire                   read_done,
  input  wire                   read_event,
  input  wire [X_W-1:0]         read_x,
  input  wire [Y_W-1:0]         read_y,
  input  wire [P*SLOT_W-1:0]    read_slots,
  input  wire [P*(CARRY_W+1+REFINED_W+DISP_W)-1:0] read_word,
  output wire                   checked_done,
  output wire                   checked_event,
  output wire [X_W-1:0]         checked_x,
  output wire [Y_W-1:0]         checked_y,
  output wire [P*(CARRY_W+1+(REFINED_W > 0 ? REFINED_W : DISP_W))-1:0] checked_word,
  // with RIGHT_VIEW: Dm(checked_x * P + q) for each word q
  output wire [P*DISP_W-1:0]    right_word
);
  localparam R = STRIP_PIXELS;
  localparam LOG_P = $clog2(P);
  localparam B_W = P > 1 ? $clog2(P) : 1;
  localparam END_ROWS = P * K + 1;  // strip 0's rows, the most
  localparam END_AW = $clog2(END_ROWS);
  localparam integer BEHIND = MIN_DISP > 0 ? MIN_DISP : 0;
  localparam integer AHEAD = MIN_DISP < 0 ? -MIN_DISP : 0;
  localparam P_W = X_W + 10;
  localparam IN_W = CARRY_W + 1 + REFINED_W + DISP_W;  // a read word: {carried, invalid, refined, D}
  localparam INVALID_BIT = REFINED_W + DISP_W;
  localparam OUT_W = REFINED_W > 0 ? REFINED_W : DISP_W;
  localparam CHECKED_W = CARRY_W + 1 + OUT_W;  // a checked word: {carried, invalid, refined or D}
  localparam [OUT_W:0] INVALID_WORD = {1'b1, {OUT_W{1'b0}}};
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if ((P != 2 && P != 4) || R % P != 0 || (1 << CAW) < END_ROWS * R || END_ROWS > (1 << SLOT_W) ||
        (1 << DISP_W) < DMAX) begin : invalid
      fpstereo_invalid_parameters_strip_lr_check_P_STRIP_PIXELS_or_widths failed ();
    end
  endgenerate
  // Each lookup's bank addresses but for the disparity, from the read stream's registers before
  // it is registered: bank b's row slot * R + x + OFFSET - b * R, so that a lookup's address is
  // one subtraction of the word's D from registers (the check's: LR1, the completing pixel x - D +
  // DMAX - 1; LR2, x' = x - MIN_DISP - D; the right view's Dm(x), no D: x + MIN_DISP + DMAX - 1
  // with LR1, x with LR2). Lookup l of word q: bases[((q * LOOKUPS) + l) * P + b].
  localparam LOOKUPS = RIGHT_VIEW != 0 ? 2 : 1;
  localparam integer CHECK_OFFSET = LR2 != 0 ? -MIN_DISP : DMAX - 1;
  localparam integer RIGHT_OFFSET = LR2 != 0 ? 0 : MIN_DISP + DMAX - 1;
  localparam BASES_W = P * LOOKUPS * P * CAW;
  wire [BASES_W-1:0] read_bases, in_bases;
  genvar q, b, l;
  generate
    for (q = 0; q < P; q = q + 1) begin : word_base
      localparam [LOG_P-1:0] Q = q;
      for (l = 0; l < LOOKUPS; l = l + 1) begin : lookup_base
        localparam integer OFFSET = l == 0 ? CHECK_OFFSET : RIGHT_OFFSET;
        for (b = 0; b < P; b = b + 1) begin : bank_base
          // modulo 2^CAW: the bank that holds the place reads within its rows
          // verilator lint_off WIDTH
          assign read_bases[((q * LOOKUPS + l) * P + b) * CAW +: CAW] =
              read_slots[b*SLOT_W +: SLOT_W] * R + {read_x, Q} + OFFSET - b * R;
          // verilator lint_on WIDTH
        end
      end
    end
  endgenerate
  // The read stream, registered (step 0) and VIEW_WAIT steps more: the lookups' (in_).
  wire                  in_done, in_event;
  wire [X_W-1:0]        in_x;
  wire [Y_W-1:0]        in_y;
  wire [P*SLOT_W-1:0]   in_slots;
  wire [P*IN_W-1:0]     in_word;
  fpstereo_delay #(.WIDTH(2), .DEPTH(1 + VIEW_WAIT), .RESET(1)) read_flags (
    .clk(clk), .rst(restart), .en(adv), .in({read_done, read_event}), .out({in_done, in_event}));
  fpstereo_delay #(.WIDTH(X_W + Y_W + P * SLOT_W + P * IN_W + BASES_W), .DEPTH(1 + VIEW_WAIT)) read_stream (
    .clk(clk), .rst(1'b0), .en(adv), .in({read_x, read_y, read_slots, read_word, read_bases}),
    .out({in_x, in_y, in_slots, in_word, in_bases}));
  // The strip that writes the row ends: the one holding the frame's last pixel (a register: the
  // frame size holds while a frame runs).
  wire [P-1:0] reaches;  // reaches[s]: the frame's last pixel lies in strip s or right of it
  generate
    for (b = 0; b < P; b = b + 1) begin : strip_reach
      localparam integer FIRST_I = b * R;
      localparam [P_W-1:0] FIRST = FIRST_I[P_W-1:0];
      assign reaches[b] = {{(P_W-X_W){1'b0}}, frame_width} > FIRST;
    end
  endgenerate
  reg [B_W-1:0] end_strip;
  integer s;
  always @(posedge clk) begin
    end_strip <= {B_W{1'b0}};
    for (s = 1; s < P; s = s + 1)
      if (reaches[s]) end_strip <= s[B_W-1:0];
  end
  // The row-end write: the writing strip's, whichever it is.
  reg              end_we;
  reg [END_AW-1:0] end_waddr;
  reg [DMAX*DISP_W-1:0] end_wdata;
  always @* begin
    end_we = 1'b0;
    end_waddr = {END_AW{1'b0}};
    end_wdata = {DMAX*DISP_W{1'b0}};
    for (s = 0; s < P; s = s + 1)
      if (row_end_we[s]) begin
        end_we = 1'b1;
        end_waddr = row_end_waddr[s*SLOT_W +: END_AW];
        end_wdata = row_end_wdata[s*DMAX*DISP_W +: DMAX*DISP_W];
      end
  end
  // Positions and disparities against the frame's width and constants: the compares widen them.
  // verilator lint_off WIDTH
  wire [END_AW-1:0] end_slot = in_slots[end_strip*SLOT_W +: SLOT_W];
  // The stream's tag beside the three steps of the words: the RAMs' outputs there, Dm
  // registered, checked.
  fpstereo_delay #(.WIDTH(2), .DEPTH(3), .RESET(1)) checked_flags (
    .clk(clk), .rst(restart), .en(adv), .in({in_done, in_event}), .out({checked_done, checked_event}));
  fpstereo_delay #(.WIDTH(X_W + Y_W), .DEPTH(3)) checked_tag (
    .clk(clk), .rst(1'b0), .en(adv), .in({in_x, in_y}), .out({checked_x, checked_y}));
  generate
    for (q = 0; q < P; q = q + 1) begin : word
      localparam [LOG_P-1:0] Q = q;
      wire [IN_W-1:0] w = in_word[q*IN_W +: IN_W];
      wire [DISP_W-1:0] d = w[DISP_W-1:0];
      wire [P_W-1:0] x_ahead = {in_x, Q} + AHEAD;
      wire [P_W-1:0] d_behind = d + BEHIND;
      wire outside = w[INVALID_BIT] || x_ahead < d_behind || (MIN_DISP < 0 && x_ahead >= d_behind + frame_width);
      // the lookup's place: LR1, x - D + DMAX - 1, the completing pixel; LR2, x' = x - MIN_DISP - D
      wire [P_W-1:0] completing = {in_x, Q} + (DMAX - 1) - d;
      wire [P_W-1:0] x_match = x_ahead - d_behind;
      wire [P*CAW-1:0] addrs;
      for (b = 0; b < P; b = b + 1) begin : bank_addr
        assign addrs[b*CAW +: CAW] = in_bases[(q * LOOKUPS * P + b) * CAW +: CAW] - d;
      end
      wire [DISP_W-1:0] dm;
      fpstereo_strip_match_lookup #(.P(P), .K(K), .STRIP_PIXELS(R), .DMAX(DMAX), .DISP_W(DISP_W), .CAW(CAW),
                                    .X_W(X_W), .MIN_DISP(MIN_DISP), .LR2(LR2)) lookup (
        .clk(clk), .adv(adv), .frame_width(frame_width), .completed_we(completed_we),
        .completed_waddr(completed_waddr), .completed_wdata(completed_wdata), .end_we(end_we),
        .end_waddr(end_waddr), .end_wdata(end_wdata), .addrs(addrs), .end_slot(end_slot),
        .xm_behind(x_ahead - d),  // x' + BEHIND
        .completing(LR2 != 0 ? x_match : completing), .dm(dm));
      reg              outside_c, outside_q;
      reg [IN_W-1:0]   word_c, word_q;
      reg [CHECKED_W-1:0] checked_q;
      reg [DISP_W-1:0] dm_q;
      reg signed [DISP_W+1:0] db_high_q, db_low_q;
      wire signed [DISP_W+1:0] dm_signed = $signed({2'b00, dm_q});
      always @(posedge clk)
        if (adv) begin
          outside_c <= outside;
          word_c <= w;
          dm_q <= dm;
          outside_q <= outside_c;
          word_q <= word_c;
          db_high_q <= $signed({2'b00, word_c[DISP_W-1:0]}) + $signed({2'b00, lr_threshold});
          db_low_q <= $signed({2'b00, word_c[DISP_W-1:0]}) - $signed({2'b00, lr_threshold});
          // the carried bits shifted down to 0 and up above the checked word (none if CARRY_W is 0)
          checked_q <= ((word_q >> (INVALID_BIT + 1)) << (OUT_W + 1)) |
                       ((outside_q || dm_signed > db_high_q || dm_signed < db_low_q) ? INVALID_WORD
                                                                                     : {word_q[INVALID_BIT], word_q[INVALID_BIT-1 -: OUT_W]});
        end
      assign checked_word[q*CHECKED_W +: CHECKED_W] = checked_q;
      if (RIGHT_VIEW != 0) begin : right_view
        // Dm(x): x' + BEHIND = x + BEHIND, completed by x + MIN_DISP + DMAX - 1 (LR2: at x)
        wire [P_W-1:0] right_completing = {in_x, Q} + (MIN_DISP + DMAX - 1);
        wire [P_W-1:0] right_x = {in_x, Q};
        wire [P_W-1:0] right_behind = {in_x, Q} + BEHIND;
        wire [DISP_W-1:0] dm_right;
        fpstereo_strip_match_lookup #(.P(P), .K(K), .STRIP_PIXELS(R), .DMAX(DMAX), .DISP_W(DISP_W), .CAW(CAW),
                                      .X_W(X_W), .MIN_DISP(MIN_DISP), .LR2(LR2)) lookup (
          .clk(clk), .adv(adv), .frame_width(frame_width), .completed_we(completed_we),
          .completed_waddr(completed_waddr), .completed_wdata(completed_wdata), .end_we(end_we),
          .end_waddr(end_waddr), .end_wdata(end_wdata), .addrs(in_bases[(q * LOOKUPS + 1) * P * CAW +: P * CAW]),
          .end_slot(end_slot),
          .xm_behind(right_behind),
          .completing(LR2 != 0 ? right_x : right_completing), .dm(dm_right));
        reg [DISP_W-1:0] dm_right_q, right_q;
        always @(posedge clk)
          if (adv) begin
            dm_right_q <= dm_right;
            right_q <= dm_right_q;
          end
        assign right_word[q*DISP_W +: DISP_W] = right_q;
      end else begin : no_right_view
        assign right_word[q*DISP_W +: DISP_W] = {DISP_W{1'b0}};
      end
    end
  endgenerate
  // verilator lint_on WIDTH
endmodule
`resetall
