`resetall
`default_nettype none
// Gap interpolation (docs/semantics.md, section 7), one row behind its input. Each input event
// brings the word of (x, y); the stage stores row y and, in the same event, emits its result for
// (x, y - 1), so the caller sends one more (dummy) row after the image. Every maximal run of invalid
// words in a row is filled with the smaller of the two valid words around it, or with the one there
// is at a row end; a row without valid words stays invalid.
//   Writing row y: each word is stored with the start of the invalid run it belongs to; when a run
//   ends, its right neighbour (or "none" at the row end) is stored under the run's start.
//   Reading row y - 1: the left neighbour is the last valid word read; the right one is fetched
//   by the run start stored with the word. Two rows of each (ping-pong by row parity, counted
//   from the rows' first words so that it alternates across back-to-back frames too).
// Once wrapped (back-to-back frames), the next frame's row 0 brings the result of this frame's
// last row, in place of the dummy row.
// Latency: the result for (x, y - 1) leaves 4 adv-steps after the event of (x, y): the first
// registers the event with the compares on its position, so that no compare lies on a path into
// a RAM's write enable (logic depth, docs/timing.md).
module fpstereo_gap_fill #(
  // the largest image width (the RAMs hold two rows of it)
  parameter W = 64,
  // word: disparity bits with the invalid flag on top
  parameter WORD_W = 8,
  parameter X_W = 7,
  parameter Y_W = 6
) (
  input  wire              clk,
  input  wire              restart,
  input  wire              adv,
  // the frame's size
  input  wire [Y_W-1:0]    frame_height,
  // the frame's last column and row, registers of the core (the frame's size holds while it runs)
  input  wire [X_W-1:0]    frame_last_x,
  input  wire [Y_W-1:0]    frame_last_y,
  input  wire              wrapped,
  input  wire              in_event,
  input  wire [X_W-1:0]    in_x,
  input  wire [Y_W-1:0]    in_y,
  input  wire [WORD_W-1:0] in_word,
  output reg               out_event,
  output reg  [X_W-1:0]    out_x,
  output reg  [Y_W-1:0]    out_y,
  output reg  [WORD_W-1:0] out_word
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (W < 1 || W >= (1 << X_W) || WORD_W < 2) begin : invalid
      fpstereo_invalid_parameters_gap_fill_needs_X_W_holding_W_and_WORD_W_at_least_2 failed ();
    end
  endgenerate
  localparam ADDR_W = $clog2(2 * W);
  localparam [WORD_W-1:0] INVALID = {1'b1, {(WORD_W-1){1'b0}}};
  // ---- Stage 0: the event and what its position is.
  reg              event0, writing0, reading0, first0, last0;
  reg  [X_W-1:0]   x0;
  reg  [Y_W-1:0]   y_above0;  // the row read: in_y - 1, or the frame's last row above row 0
  reg  [WORD_W-1:0] word0;
  // Only the event flags take restart: the words and positions beside them matter only with an
  // event, and their enables stay free of restart's logic (depth, docs/timing.md).
  always @(posedge clk)
    if (restart) begin
      event0 <= 1'b0;
      writing0 <= 1'b0;
      reading0 <= 1'b0;
    end else if (adv) begin
      event0 <= in_event;
      writing0 <= in_event && in_y < frame_height;
      reading0 <= in_event && (in_y != 0 || wrapped);
    end
  always @(posedge clk)
    if (adv) begin
      first0 <= in_x == 0;
      last0 <= in_x == frame_last_x;
      x0 <= in_x;
      y_above0 <= in_y == 0 ? frame_last_y : in_y - 1'b1;
      word0 <= in_word;
    end

  function [ADDR_W-1:0] address(input parity, input [X_W-1:0] x);
    // verilator lint_off WIDTH
    address = parity * W + x;
    // verilator lint_on WIDTH
  endfunction

  // The row's half of the RAMs.
  reg  parity_q;
  wire parity = first0 ? !parity_q : parity_q;
  always @(posedge clk)
    if (restart) parity_q <= 1'b1;
    else if (adv && event0) parity_q <= parity;

  // ---- Writing row in_y.
  wire writing = writing0;
  wire word_invalid = word0[WORD_W-1];
  reg  run_open;  // the previous word of the row was invalid
  reg  [X_W-1:0] run_start;
  wire continues = run_open && !first0;
  wire [X_W-1:0] start = continues ? run_start : x0;
  always @(posedge clk)
    if (restart) run_open <= 1'b0;
    else if (adv && writing) begin
      run_open <= word_invalid;
      run_start <= start;
    end
  // Right neighbour of a run, stored under its start: the valid word that ends it, or invalid.
  wire side_we = adv && writing && (word_invalid ? last0 : continues);
  wire [ADDR_W-1:0] side_waddr = address(parity, word_invalid ? start : run_start);

  // ---- Reading row in_y - 1 (stage 1: the stored word; stage 2: the run's right neighbour).
  wire reading = reading0;
  wire [WORD_W+X_W-1:0] stored;
  fpstereo_ram_sdp #(.WIDTH(WORD_W + X_W), .DEPTH(2 * W), .ADDR_W(ADDR_W)) words (
    .clk(clk), .we(adv && writing), .waddr(address(parity, x0)), .wdata({word0, start}),
    .re(adv), .raddr(address(!parity, x0)), .rdata(stored));
  reg           event1, first1;  // first1: x1 is the row's first column
  reg [X_W-1:0] x1;
  reg [Y_W-1:0] y1;
  reg           parity1;
  always @(posedge clk)
    if (restart) event1 <= 1'b0;
    else if (adv) event1 <= reading;
  always @(posedge clk)
    if (adv) begin
      first1 <= first0;
      x1 <= x0;
      y1 <= y_above0;
      parity1 <= !parity;
    end
  wire [WORD_W-1:0] word1 = stored[WORD_W+X_W-1 -: WORD_W];
  wire [X_W-1:0]    start1 = stored[X_W-1:0];
  wire [WORD_W-1:0] right2;
  fpstereo_ram_sdp #(.WIDTH(WORD_W), .DEPTH(2 * W), .ADDR_W(ADDR_W)) right_neighbours (
    .clk(clk), .we(side_we), .waddr(side_waddr), .wdata(word_invalid ? INVALID : word0),
    .re(adv), .raddr(address(parity1, start1)), .rdata(right2));

  reg  [WORD_W-1:0] left;  // last valid word of the row read so far (invalid: none yet)
  wire [WORD_W-1:0] left_before = first1 ? INVALID : left;
  reg               event2;
  reg  [X_W-1:0]    x2;
  reg  [Y_W-1:0]    y2;
  reg  [WORD_W-1:0] word2, left2;
  // left is read only behind a row's first column (left_before), so no restart needs to clear it.
  always @(posedge clk)
    if (restart) event2 <= 1'b0;
    else if (adv) event2 <= event1;
  always @(posedge clk)
    if (adv) begin
      x2 <= x1;
      y2 <= y1;
      word2 <= word1;
      left2 <= left_before;
      if (event1) left <= word1[WORD_W-1] ? left_before : word1;
    end

  // ---- Stage 3: the result.
  wire left_ok = !left2[WORD_W-1], right_ok = !right2[WORD_W-1];
  wire [WORD_W-1:0] filled = (left_ok && right_ok) ? (right2 < left2 ? right2 : left2)
                         : left_ok ? left2 : right2;
  always @(posedge clk)
    if (restart) out_event <= 1'b0;
    else if (adv) out_event <= event2;
  always @(posedge clk)
    if (adv) begin
      out_x <= x2;
      out_y <= y2;
      out_word <= word2[WORD_W-1] ? filled : word2;
    end
endmodule
`resetall
