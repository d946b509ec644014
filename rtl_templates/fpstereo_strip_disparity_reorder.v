`resetall
`default_nettype none
// The disparity reorder RAM over P strips of a row and the output's raster order at P pixels a slot
// (docs/ppc-hardware.md, "Memories"; fpstereo_strip_aggregation places it). Strip s's
// winner-take-all writes one word a step in the strip's chain order; from out_on on, one slot (P
// consecutive pixels, which lie in one strip) is read a step in raster order. Strip s has P banks,
// bank q holding its pixels x with x mod P = q, so that a slot's P words are read at once, each
// bank written a word at a time. Strip s writes a row from the row-time s * K after its first
// chain's to K - 1 later, and the output reads it P * K row-times after strip 0 began it: the
// strip's RAM holds (P - s) * K + 1 rows, and it and the output keep the row's slot modulo that,
// each a counter. The read stream as fpstereo_disparity_reorder's: read_done in the step after each
// slot's read, read_event where the slot holds pixels of the frame, its slot read_x (pixels read_x
// * P + q) and row, and the P words; rows below the frame and bubble slots read invalid words, and
// EXTRA_ROWS rows more are read (invalid words) for gap interpolation, one row behind.
module fpstereo_strip_disparity_reorder #(
  parameter P = 2,
  parameter K = 5,
  // pixels of a strip (K * SEGMENT, a multiple of P)
  parameter STRIP_PIXELS = 20,
  parameter DISP_W = 5,
  // width of a pixel's x (and of a slot's), of a row, and of the strips' row slots
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter SLOT_W = 5,
  parameter EXTRA_ROWS = 0
) (
  input  wire               clk,
  input  wire               restart,
  input  wire               adv,
  input  wire               out_on,
  // back-to-back frames (fpstereo_front_end): the read rows wrap after the frame's last
  input  wire               overlap,
  input  wire [X_W-1:0]     frame_width,
  input  wire [Y_W-1:0]     frame_height,
  // strip s's word: active, its pixel's x, its row slot (modulo the strip's rows), the word
  input  wire [P-1:0]        active,
  input  wire [P*X_W-1:0]    x,
  input  wire [P*SLOT_W-1:0] slot,
  input  wire [P*(DISP_W+1)-1:0] word,
  output reg                read_done,
  output reg                read_event,
  output reg  [X_W-1:0]     read_x,
  output reg  [Y_W-1:0]     read_y,
  output wire [P*(DISP_W+1)-1:0] read_word,
  // each strip's row slot of the read row (fpstereo_strip_lr_check's banks follow them)
  output reg  [P*SLOT_W-1:0] read_slots
);
  localparam WORDS = STRIP_PIXELS / P;  // a strip's slots per row
  localparam LOG_P = $clog2(P);
  localparam WORD_W = DISP_W + 1;
  localparam STRIP_W = $clog2(P);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if ((P != 2 && P != 4) || STRIP_PIXELS % P != 0 || P * STRIP_PIXELS > (1 << X_W) ||
        P * K + 1 > (1 << SLOT_W)) begin : invalid
      fpstereo_invalid_parameters_strip_disparity_reorder_P_STRIP_PIXELS_or_widths failed ();
    end
  endgenerate

  // The output's raster order: slot so of row to, a slot a step from out_on on, over row-times of
  // STRIP_PIXELS steps (K * SEGMENT, the aggregation's). The compares that decide a step are
  // registers set a step ahead (so that adv's and the frame size's paths end in one gate): whether
  // so is the row-time's last slot, and whether so lies in the frame's width.
  localparam integer BEFORE_LAST_I = STRIP_PIXELS - 2;
  localparam [X_W-1:0] BEFORE_LAST_SLOT = BEFORE_LAST_I[X_W-1:0];
  wire step = adv && out_on;
  reg  [X_W-1:0] so;
  reg  so_last;
  wire [Y_W-1:0] to;
  wire to_last;
  wire row_ends = step && so_last;
  always @(posedge clk)
    if (restart) begin
      so <= {X_W{1'b0}};
      so_last <= 1'b0;  // STRIP_PIXELS >= 2
    end else if (step) begin
      so <= row_ends ? {X_W{1'b0}} : so + 1'b1;
      so_last <= !row_ends && so == BEFORE_LAST_SLOT;
    end
  // The strip of slot so and the slot within it, counters (no division by WORDS).
  localparam integer BEFORE_LAST_WORD_I = WORDS - 2;
  localparam [X_W-1:0] BEFORE_LAST_WORD = BEFORE_LAST_WORD_I[X_W-1:0];
  reg [STRIP_W-1:0] strip_of;
  reg [X_W-1:0] in_strip;
  reg in_strip_last;  // in_strip == WORDS - 1
  always @(posedge clk)
    if (restart || row_ends) begin
      strip_of <= {STRIP_W{1'b0}};
      in_strip <= {X_W{1'b0}};
      in_strip_last <= WORDS == 1;
    end else if (step) begin
      if (in_strip_last) strip_of <= strip_of + 1'b1;
      in_strip <= in_strip_last ? {X_W{1'b0}} : in_strip + 1'b1;
      in_strip_last <= WORDS == 1 || (!in_strip_last && in_strip == BEFORE_LAST_WORD);
    end
  fpstereo_frame_row #(.Y_W(Y_W)) output_row (
    .clk(clk), .restart(restart), .next(row_ends), .wrap(overlap), .height(frame_height), .row(to), .last(to_last));
  // Whether so lies in the frame's width: from slot 0 of each row (frames are at least P wide) to
  // the width's last slot, a register (the frame size holds while a frame runs).
  reg [X_W-1:0] last_width_slot;
  always @(posedge clk) last_width_slot <= (frame_width >> LOG_P) - 1'b1;
  reg in_width;
  always @(posedge clk)
    if (restart || row_ends) in_width <= 1'b1;
    else if (step && so == last_width_slot) in_width <= 1'b0;
  // Whether row to lies in the frame, and in the rows with events (the frame's, and EXTRA_ROWS more
  // for gap interpolation), as flags that follow the row counter: a wrap returns to row 0, the
  // frame's last row leaves the frame, and with EXTRA_ROWS the row before the events' end
  // (compared while the row-time runs: a row-time is STRIP_PIXELS >= 3 steps) leaves the events.
  wire wraps = overlap && to_last;
  reg  in_frame_rows;
  always @(posedge clk)
    if (restart) in_frame_rows <= 1'b1;
    else if (row_ends) in_frame_rows <= wraps || (in_frame_rows && !to_last);
  wire in_rows;
  generate
    if (EXTRA_ROWS != 0) begin : extra_rows
      reg [Y_W-1:0] last_event_row;
      always @(posedge clk) last_event_row <= frame_height + (EXTRA_ROWS - 1);
      reg at_last_event_row, in_event_rows;
      always @(posedge clk) at_last_event_row <= to == last_event_row;
      always @(posedge clk)
        if (restart) in_event_rows <= 1'b1;
        else if (row_ends) in_event_rows <= wraps || (in_event_rows && !at_last_event_row);
      assign in_rows = in_event_rows;
    end else begin : frame_rows
      assign in_rows = in_frame_rows;
    end
  endgenerate
  wire read_now = out_on && in_width && in_rows;
  wire read_valid = read_now && in_frame_rows;
  reg [STRIP_W-1:0] strip_q;
  reg read_was_valid;
  always @(posedge clk)
    if (restart) begin
      read_done <= 1'b0;
      read_event <= 1'b0;
      read_was_valid <= 1'b0;
    end else if (adv) begin
      read_done <= out_on;
      read_event <= read_now;
      read_was_valid <= read_valid;
    end
  // The read's position, without a reset (their enable is adv alone: logic depth).
  always @(posedge clk)
    if (adv) begin
      read_x <= so;
      read_y <= to;
      strip_q <= strip_of;
    end

  wire [P*P*WORD_W-1:0] banks_q;  // strip s's P words at s * P * WORD_W
  genvar s, q;
  generate
    for (s = 0; s < P; s = s + 1) begin : strip
      localparam ROWS = (P - s) * K + 1;
      localparam DEPTH = ROWS * WORDS;
      localparam AW = $clog2(DEPTH);
      localparam integer FIRST_I = s * STRIP_PIXELS;
      localparam [X_W-1:0] FIRST = FIRST_I[X_W-1:0];
      localparam integer LAST_ROW_I = ROWS - 1;
      localparam [SLOT_W-1:0] LAST_ROW = LAST_ROW_I[SLOT_W-1:0];
      // The output's row slot in this strip's RAM.
      reg [SLOT_W-1:0] out_slot;
      always @(posedge clk)
        if (restart) out_slot <= {SLOT_W{1'b0}};
        else if (row_ends) out_slot <= out_slot == LAST_ROW ? {SLOT_W{1'b0}} : out_slot + 1'b1;
      always @(posedge clk)
        if (adv) read_slots[s*SLOT_W +: SLOT_W] <= out_slot;
      wire [X_W-1:0] wx = x[s*X_W +: X_W] - FIRST;
      /* verilator lint_off WIDTH */  // products of narrow values and constants, cut to the address
      wire [AW-1:0] waddr = slot[s*SLOT_W +: SLOT_W] * WORDS + (wx >> LOG_P);
      wire [AW-1:0] raddr = out_slot * WORDS + in_strip;
      /* verilator lint_on WIDTH */
      for (q = 0; q < P; q = q + 1) begin : bank
        wire write = adv && active[s] && wx[LOG_P-1:0] == q;
        fpstereo_ram_sdp #(.WIDTH(WORD_W), .DEPTH(DEPTH), .ADDR_W(AW)) ram (
          .clk(clk), .we(write), .waddr(waddr), .wdata(word[s*WORD_W +: WORD_W]),
          .re(adv), .raddr(raddr), .rdata(banks_q[(s*P + q)*WORD_W +: WORD_W]));
      end
    end
  endgenerate
  localparam [WORD_W-1:0] INVALID_WORD = {1'b1, {DISP_W{1'b0}}};
  assign read_word = read_was_valid ? banks_q[strip_q*P*WORD_W +: P*WORD_W] : {P{INVALID_WORD}};
endmodule
`resetall
