`default_nettype none
`ifndef MEDIAN_EXTRA_ROWS
`define MEDIAN_EXTRA_ROWS 0
`endif
// Formal properties of the median stage's positions (rtl_templates/fpstereo_median.v fed by the
// disparity reorder's read stream, as in the core; tests/formal/run_proof.sh): rows of up to 5
// slots in 2 steps each (X_W 3), up to 7 rows (Y_W 3), a 3 x 3 median (RM 1) of 2-bit words.
// The median computes each position again from its window's centre, RM rows and RM slots behind
// the slot entering, and delays it by the selection's 3 * (DISP_W + 1) steps. The environment
// (assumed): as in output_order_props (`restart` first, a constant frame size with width <= the
// row's slots, out_on held, `overlap` constant, a lone frame restarted before its rows overflow);
// `wrapped` (the front end's rows have wrapped) low without overlap, rising at most once, low while
// the reader is in the first frame's rows 0..RM (the front end wraps at least two row-times after
// the first output push: overlap_height) and high once the reader has wrapped. The unit
// (asserted): the events it emits (out_event at an adv) are the frame's positions (x, y), x <
// width and y < height + EXTRA (the dummy row gap interpolation needs), each once and in raster
// order; with `overlap` the rows wrap after the frame's last and the next frame's follow. Word
// data is free: positions never depend on it. The induction walks the stage's pipeline (output
// register, delay line, the centre pending, the read stream's slot) from the next position
// expected, each valid entry being the next position, and ends at the reader's counter, whose
// next in-image centre must be the position after them all:
// formal-probe: probe_group reorder.output_position.group
// formal-probe: probe_slot reorder.output_position.slot
// formal-probe: probe_row reorder.output_position.frame_row.row
// formal-probe: probe_last reorder.output_position.frame_row.last
// formal-probe: probe_before_last reorder.output_position.frame_row.before_last
// formal-probe: probe_fresh median.fresh
// formal-probe: probe_median_x median.median_x
// formal-probe: probe_median_y median.median_y
// formal-probe: probe_line median.median_delay.line
// formal-probe: probe_slots_left median.columns.slots_left
// formal-probe: probe_width_slots_left median.columns.width_slots_left
module median_order_props #(
  parameter EXTRA_ROWS = `MEDIAN_EXTRA_ROWS,
  parameter X_W = 2
) (
  input wire       clk,
  input wire       restart,
  input wire       adv,
  input wire       out_on,
  input wire       overlap,
  input wire       wrapped,
  input wire [X_W-1:0] frame_width,
  input wire [2:0] frame_height,
  input wire       active,
  input wire [X_W-1:0] x,
  input wire [1:0] slot,
  input wire       group,
  input wire [1:0] word
);
  localparam ROW_SLOTS = 3, G = 2, Y_W = 3, SY_W = 5, M = 3, RM = M / 2, DISP_W = 1;
  localparam DEPTH = 3 * (DISP_W + 1), ENTRY_W = 1 + X_W + Y_W;
  wire           read_done, read_event;
  wire [X_W-1:0] read_x;
  wire [Y_W-1:0] read_y;
  wire [1:0]     read_slot_row;
  wire [DISP_W:0] read_word;
  fpstereo_disparity_reorder #(.ROW_SLOTS(ROW_SLOTS), .G(G), .DISP_W(DISP_W), .OUT_ROWS(3), .OUT_ROW_W(2),
                               .DISP_AW(4), .EXTRA_ROWS(EXTRA_ROWS), .X_W(X_W), .Y_W(Y_W), .G_W(1)) reorder (
    .clk(clk), .restart(restart), .adv(adv), .out_on(out_on), .overlap(overlap), .frame_width(frame_width),
    .frame_height(frame_height), .active(active), .x(x), .slot(slot), .group(group), .word(word),
    .read_done(read_done), .read_event(read_event), .read_x(read_x), .read_y(read_y),
    .read_slot_row(read_slot_row), .read_word(read_word));
  wire           out_event;
  wire [X_W-1:0] out_x;
  wire [Y_W-1:0] out_y;
  wire [DISP_W:0] out_word;
  fpstereo_median #(.M(M), .ROW_SLOTS(ROW_SLOTS), .DISP_W(DISP_W), .EXTRA_ROWS(EXTRA_ROWS), .X_W(X_W), .Y_W(Y_W),
                    .SIGNED_Y_W(SY_W)) median (
    .clk(clk), .restart(restart), .adv(adv), .frame_width(frame_width), .frame_height(frame_height),
    .wrapped(wrapped), .in_done(read_done), .in_x(read_x), .in_y(read_y), .in_word(read_word),
    .out_event(out_event), .out_x(out_x), .out_y(out_y), .out_word(out_word));

`ifdef FORMAL
  (* keep *) wire                   probe_group, probe_last, probe_fresh;
  (* keep *) wire [X_W-1:0]         probe_slot, probe_median_x;
  (* keep *) wire [Y_W-1:0]         probe_row, probe_before_last;
  (* keep *) wire signed [SY_W-1:0] probe_median_y;
  (* keep *) wire [ENTRY_W*DEPTH-1:0] probe_line;
  (* keep *) wire [X_W+1:0]         probe_slots_left, probe_width_slots_left;

  wire past_valid, past_rst;
  formal_start run_start (.clk(clk), .rst(restart), .past_valid(past_valid), .past_rst(past_rst));
  reg       past_out_on, past_overlap, past_wrapped;
  reg [X_W-1:0] past_width;
  reg [2:0] past_height;
  always @(posedge clk)
    {past_out_on, past_overlap, past_wrapped, past_width, past_height} <= {out_on, overlap, wrapped, frame_width, frame_height};

  // The reader has passed the first frame's last row (back-to-back frames only).
  reg reader_wrapped;
  always @(posedge clk)
    if (restart) reader_wrapped <= 1'b0;
    else if (adv && out_on && probe_group && probe_slot == ROW_SLOTS - 1 && probe_last && overlap) reader_wrapped <= 1'b1;

  // ---- The environment.
  wire [7:0] width = {{(8-X_W){1'b0}}, frame_width}, height = {5'd0, frame_height};
  wire [7:0] rows = overlap ? height : height + EXTRA_ROWS;  // the rows of positions emitted
  always @* begin
    assume(frame_width >= 1 && frame_width <= ROW_SLOTS && frame_height >= 2);
    assume(height + EXTRA_ROWS < 8'd8);
    // back-to-back frames hold more positions than the pipeline (fpstereo's overlap_height: more
    // row-times than the drain)
    if (overlap) assume(height * width > DEPTH + 3);
    if (past_valid) begin
      assume(frame_width == past_width && frame_height == past_height && overlap == past_overlap);
      if (past_rst) assume(!out_on && !wrapped);
      else begin
        if (past_out_on) assume(out_on);
        if (past_wrapped) assume(wrapped);
      end
    end
    if (!overlap) assume(!wrapped);
    if (reader_wrapped) assume(wrapped);
    else if ({5'd0, probe_row} <= RM) assume(!wrapped);
    if (adv && out_on && probe_group && probe_slot == ROW_SLOTS - 1 && probe_row == {Y_W{1'b1}}) assume(restart);
  end

  // ---- Positions as pairs {y, x} (no products: the solver is quicker); after the frame's last
  // (without overlap) the end, {rows, 0}.
  localparam P_W = X_W + Y_W;
  wire [P_W-1:0] frame_end = {rows[Y_W-1:0], {X_W{1'b0}}};
  function [P_W-1:0] after(input [P_W-1:0] p);
    if (p[X_W-1:0] != frame_width - 1'b1) after = {p[P_W-1:X_W], p[X_W-1:0] + 1'b1};
    else if (overlap && {5'd0, p[P_W-1:X_W]} == rows - 1'b1) after = {P_W{1'b0}};
    else after = {p[P_W-1:X_W] + 1'b1, {X_W{1'b0}}};
  endfunction
  function in_frame(input [X_W-1:0] px, input [Y_W-1:0] py);
    in_frame = px < frame_width && {5'd0, py} < rows;
  endfunction
  // The centre of the window when slot (sx, sy) enters (as fpstereo_window_centre computes it, said
  // again here): RM slots back, into the previous row near the row's start; rows above the frame
  // are the previous frame's once wrapped.
  function signed [SY_W:0] centre_row(input [X_W-1:0] sx, input [Y_W-1:0] sy);
    reg signed [SY_W:0] r;
    begin
      r = $signed({3'd0, sy}) - RM - (sx < RM ? 1 : 0);
      centre_row = wrapped && r < 0 ? r + $signed({3'd0, frame_height}) : r;
    end
  endfunction
  function [X_W:0] centre_col(input [X_W-1:0] sx);
    centre_col = sx < RM ? {1'b0, sx} + ROW_SLOTS - RM : {1'b0, sx} - RM;
  endfunction
  // The first position at or after the centre of slot (sx, sy) (slots past the row's width belong
  // to the next row; the frame's end wraps to (0, 0) with overlap).
  function [P_W-1:0] next_from(input [X_W-1:0] sx, input [Y_W-1:0] sy);
    reg signed [SY_W:0] r;
    reg [X_W:0] c;
    begin
      r = centre_row(sx, sy);
      c = centre_col(sx);
      if (r < 0) next_from = {P_W{1'b0}};
      else if ({3'd0, r[SY_W-1:0]} >= rows) next_from = overlap ? {P_W{1'b0}} : frame_end;
      else if (c < {1'b0, frame_width}) next_from = {r[Y_W-1:0], c[X_W-1:0]};
      else if ({3'd0, r[SY_W-1:0]} + 8'd1 == rows) next_from = overlap ? {P_W{1'b0}} : frame_end;
      else next_from = {r[Y_W-1:0] + 1'b1, {X_W{1'b0}}};
    end
  endfunction

  // ---- The positions emitted, counted: the next one expected.
  reg [P_W-1:0] expected;
  always @(posedge clk)
    if (restart) expected <= {P_W{1'b0}};
    else if (adv && out_event) expected <= after(expected);

  // The walk from the output register back to the reader's counter: walk[k] is the position the
  // k-th valid entry from the output must hold (a wire each: Yosys's immediate assertions would
  // see a variable's last value in a loop).
  wire [P_W-1:0] walk [0:DEPTH+3];
  wire check = past_valid && !past_rst;
  assign walk[0] = expected;
  // each event emitted is the next position of the frame
  assign walk[1] = out_event ? after(walk[0]) : walk[0];
  always @*
    if (check) begin
      assert(in_frame(expected[X_W-1:0], expected[P_W-1:X_W]) || (!overlap && expected == frame_end));
      if (out_event) assert(in_frame(out_x, out_y) && {out_y, out_x} == walk[0]);
    end
  genvar k;
  generate
    for (k = 0; k < DEPTH; k = k + 1) begin : delay_entry
      wire [ENTRY_W-1:0] entry = probe_line[ENTRY_W*(DEPTH-1-k) +: ENTRY_W];
      wire valid = entry[ENTRY_W-1];
      wire [X_W-1:0] ex = entry[X_W+Y_W-1:Y_W];
      wire [Y_W-1:0] ey = entry[Y_W-1:0];
      assign walk[k+2] = valid ? after(walk[k+1]) : walk[k+1];
      always @*
        if (check && valid) assert(in_frame(ex, ey) && {ey, ex} == walk[k+1]);
    end
  endgenerate
  // the centre selected now
  // (in the image as the median sees it: the frame's rows and EXTRA_ROWS more, which with overlap
  // must never hold a centre)
  wire [7:0] median_rows = height + EXTRA_ROWS;
  wire centre_in = probe_fresh && {1'b0, probe_median_x} < {1'b0, frame_width} && probe_median_y >= 0 &&
                   {3'd0, probe_median_y} < median_rows;
  assign walk[DEPTH+2] = centre_in ? after(walk[DEPTH+1]) : walk[DEPTH+1];
  // the slot read, entering the window at the next adv
  wire signed [SY_W:0] pending_row = centre_row(read_x, read_y);
  wire [X_W:0] pending_col = centre_col(read_x);
  wire pending_in = read_done && pending_col < {1'b0, frame_width} && pending_row >= 0 &&
                    {3'd0, pending_row[SY_W-1:0]} < median_rows;
  assign walk[DEPTH+3] = pending_in ? after(walk[DEPTH+2]) : walk[DEPTH+2];
  always @*
    if (check) begin
      if (centre_in) assert(in_frame(probe_median_x, probe_median_y[Y_W-1:0]) &&
                            {probe_median_y[Y_W-1:0], probe_median_x} == walk[DEPTH+1]);
      if (pending_in) assert(in_frame(pending_col[X_W-1:0], pending_row[Y_W-1:0]) &&
                             {pending_row[Y_W-1:0], pending_col[X_W-1:0]} == walk[DEPTH+2]);
      assert(next_from(probe_slot, probe_row) == walk[DEPTH+3]);
      // the reader's counter (output_order_props)
      if (!out_on) assert(probe_slot == 0 && probe_row == 0 && !probe_group && !read_done && !out_event && expected == 0);
      if (reader_wrapped) assert(overlap && out_on);
      // the slot read is the one before the counter's
      if (read_done) assert(!probe_group && read_x == (probe_slot == 0 ? ROW_SLOTS - 1 : probe_slot - 1'b1) &&
                            read_y == (probe_slot != 0 ? probe_row : probe_row == 0 ? frame_height - 1'b1 : probe_row - 1'b1) &&
                            (probe_slot != 0 || probe_row != 0 || (overlap && reader_wrapped)));
      assert(probe_slot < ROW_SLOTS && probe_before_last == frame_height - 2'd2);
      assert(probe_last == (probe_row == frame_height - 1'b1));
      if (overlap) assert({5'd0, probe_row} < height);
    end

  // ---- The median's column counter (fpstereo_slot_columns, no restart): from the centre's first
  // return to slot 0 (the slot read is the centre's lag, 1) on, slots_left = width - 1 - median_x;
  // before it, the one centre taken lies above the image. The walk: median_x is the centre of the
  // last slot shifted in, and the next slot read follows it.
  reg           shifted, returned;
  reg [X_W-1:0] last_x;
  always @(posedge clk)
    if (restart) {shifted, returned} <= 2'b00;
    else if (adv && read_done) begin
      shifted <= 1'b1;
      if (read_x == 1) returned <= 1'b1;
      last_x <= read_x;
    end
  function [X_W-1:0] slot_after(input [X_W-1:0] sx);
    slot_after = sx == ROW_SLOTS - 1 ? {X_W{1'b0}} : sx + 1'b1;
  endfunction
  wire [X_W+1:0] slots_left = {2'b00, frame_width} - 1'b1 - {2'b00, probe_median_x};
  wire [X_W:0]   last_centre = centre_col(last_x);
  always @*
    if (check) begin
      assert(probe_width_slots_left == {2'b00, frame_width} - 1'b1);
      if (shifted) begin
        assert(last_x < ROW_SLOTS && {1'b0, probe_median_x} == last_centre);
        if (read_done) assert(read_x == slot_after(last_x));
        assert(probe_slot == (read_done ? slot_after(slot_after(last_x)) : slot_after(last_x)));
        if (!returned)
          assert(last_x == 0 && probe_row == 0 && !reader_wrapped && probe_median_y == -RM - 1);
      end
      // (none yet: the reader is at row 0's first slot, or has read it and not yet shifted it in)
      if (!shifted) assert(!probe_fresh && probe_row == 0 && !reader_wrapped &&
                           (probe_slot == 0 ? !read_done : probe_slot == 1 && !probe_group && read_done && read_x == 0));
      if (returned) assert(shifted && probe_slots_left == slots_left);
    end
`endif
endmodule
`resetall
