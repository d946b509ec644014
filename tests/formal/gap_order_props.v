`default_nettype none
// Formal properties of gap interpolation's positions (rtl_templates/fpstereo_gap_fill.v;
// tests/formal/run_proof.sh): rows of up to 7 pixels (X_W 3), up to 6 rows (Y_W 3), 2-bit words.
// The stage emits, for each event (x, y) it takes, the position (x, y - 1), computed again from
// the event's (and, at row 0 once wrapped, as (x, height - 1): the previous frame's last row).
// The environment (assumed): `restart` first, a constant frame size, `overlap` constant; the
// events taken (in_event at an adv) are the frame's positions in raster order, each once, over
// height + 1 rows (the dummy row after a lone frame) or, with overlap, over height rows wrapping
// to the next frame's; this is what feeds the stage in the core, the reorder's read events
// (output_order_props) or the median's (median_order_props), both with EXTRA_ROWS 1. `wrapped`
// (the front end's rows have wrapped) is low without overlap, rises at most once, low while the
// input is in the first frame's row 0 and high once the input has wrapped (the front end wraps
// at least two row-times after the first output push: overlap_height). Words are free. The unit
// (asserted): the events it emits (out_event at an adv) are the frame's positions (x, y), x <
// width and y < height, each once and in raster order, with overlap wrapping to the next frame's.
// The induction walks the stage's four registers from the next position expected, each valid
// one being the next position (the first step's as the row it reads), and ends at the input's
// next event, a row further on:
// formal-probe: probe_reading0 gap.reading0
// formal-probe: probe_x0 gap.x0
// formal-probe: probe_y0 gap.y_above0
// formal-probe: probe_event1 gap.event1
// formal-probe: probe_x1 gap.x1
// formal-probe: probe_y1 gap.y1
// formal-probe: probe_event2 gap.event2
// formal-probe: probe_x2 gap.x2
// formal-probe: probe_y2 gap.y2
module gap_order_props (
  input wire       clk,
  input wire       restart,
  input wire       adv,
  input wire       overlap,
  input wire       wrapped,
  input wire [2:0] frame_width,
  input wire [2:0] frame_height,
  input wire       in_event,
  input wire [2:0] in_x,
  input wire [2:0] in_y,
  input wire [1:0] in_word
);
  localparam W = 7, WORD_W = 2, X_W = 3, Y_W = 3, P_W = X_W + Y_W;
  wire           out_event;
  wire [X_W-1:0] out_x;
  wire [Y_W-1:0] out_y;
  wire [WORD_W-1:0] out_word;
  fpstereo_gap_fill #(.W(W), .WORD_W(WORD_W), .X_W(X_W), .Y_W(Y_W)) gap (
    .clk(clk), .restart(restart), .adv(adv), .frame_height(frame_height),
    .frame_last_x(frame_width - 3'd1), .frame_last_y(frame_height - 3'd1),
    .wrapped(wrapped), .in_event(in_event), .in_x(in_x), .in_y(in_y), .in_word(in_word),
    .out_event(out_event), .out_x(out_x), .out_y(out_y), .out_word(out_word));

`ifdef FORMAL
  (* keep *) wire           probe_reading0, probe_event1, probe_event2;
  (* keep *) wire [X_W-1:0] probe_x0, probe_x1, probe_x2;
  (* keep *) wire [Y_W-1:0] probe_y0, probe_y1, probe_y2;

  wire past_valid, past_rst;
  formal_start run_start (.clk(clk), .rst(restart), .past_valid(past_valid), .past_rst(past_rst));
  reg       past_overlap, past_wrapped;
  reg [2:0] past_width, past_height;
  always @(posedge clk) {past_overlap, past_wrapped, past_width, past_height} <= {overlap, wrapped, frame_width, frame_height};

  // ---- Positions as pairs {y, x} in a frame of `rows` rows; after its last (without overlap) the
  // end, {rows, 0}.
  wire [3:0] height = {1'b0, frame_height};
  wire [3:0] in_rows = overlap ? height : height + 4'd1;
  function [P_W-1:0] after(input [P_W-1:0] p, input [3:0] rows);
    if (p[X_W-1:0] != frame_width - 1'b1) after = {p[P_W-1:X_W], p[X_W-1:0] + 1'b1};
    else if (overlap && {1'b0, p[P_W-1:X_W]} == rows - 1'b1) after = {P_W{1'b0}};
    else after = {p[P_W-1:X_W] + 1'b1, {X_W{1'b0}}};
  endfunction
  function in_frame(input [P_W-1:0] p, input [3:0] rows);
    in_frame = p[X_W-1:0] < frame_width && {1'b0, p[P_W-1:X_W]} < rows;
  endfunction

  // ---- The events taken and emitted, counted: the next of each expected.
  reg [P_W-1:0] next_in, expected;
  reg input_wrapped;  // the input has passed the first frame's last position
  always @(posedge clk)
    if (restart) begin
      next_in <= {P_W{1'b0}};
      expected <= {P_W{1'b0}};
      input_wrapped <= 1'b0;
    end else if (adv) begin
      if (in_event) next_in <= after(next_in, in_rows);
      if (in_event && overlap && {in_y, in_x} == {frame_height - 1'b1, frame_width - 1'b1}) input_wrapped <= 1'b1;
      if (out_event) expected <= after(expected, height);
    end

  // ---- The environment.
  always @* begin
    assume(frame_width >= 1 && frame_height >= 2 && frame_height <= 3'd6);
    // back-to-back frames hold more positions than the stage
    if (overlap) assume(frame_height * frame_width > 4);
    if (past_valid) begin
      assume(frame_width == past_width && frame_height == past_height && overlap == past_overlap);
      if (past_rst) assume(!wrapped);
      else if (past_wrapped) assume(wrapped);
    end
    if (adv && in_event) assume({in_y, in_x} == next_in && in_frame(next_in, in_rows));
    if (!overlap) assume(!wrapped);
    if (input_wrapped) assume(wrapped);
    else if (next_in[P_W-1:X_W] == 0) assume(!wrapped);
  end

  // The walk from the output register back to the input: walk[k] is the position the k-th valid
  // register from the output must hold (a wire each: Yosys's immediate assertions would see a
  // variable's last value).
  wire [P_W-1:0] walk0 = expected;
  wire [P_W-1:0] walk1 = out_event ? after(walk0, height) : walk0;
  wire [P_W-1:0] walk2 = probe_event2 ? after(walk1, height) : walk1;
  wire [P_W-1:0] walk3 = probe_event1 ? after(walk2, height) : walk2;
  wire [P_W-1:0] walk4 = probe_reading0 ? after(walk3, height) : walk3;
  // the position the input's next event brings: a row up, from row 0 the previous frame's last
  // once wrapped, or none yet (the first output comes with row 1)
  wire [P_W-1:0] brought = next_in[P_W-1:X_W] != 0 ? {next_in[P_W-1:X_W] - 1'b1, next_in[X_W-1:0]}
                         : wrapped ? {frame_height - 1'b1, next_in[X_W-1:0]} : {P_W{1'b0}};
  always @*
    if (past_valid && !past_rst) begin
      assert(in_frame(expected, height) || (!overlap && expected == {frame_height, {X_W{1'b0}}}));
      assert(in_frame(next_in, in_rows) || (!overlap && next_in == {in_rows[Y_W-1:0], {X_W{1'b0}}}));
      // each event emitted is the next position of the frame
      if (out_event) assert(in_frame({out_y, out_x}, height) && {out_y, out_x} == walk0);
      if (probe_event2) assert(in_frame({probe_y2, probe_x2}, height) && {probe_y2, probe_x2} == walk1);
      if (probe_event1) assert(in_frame({probe_y1, probe_x1}, height) && {probe_y1, probe_x1} == walk2);
      if (probe_reading0) assert(in_frame({probe_y0, probe_x0}, height) && {probe_y0, probe_x0} == walk3);
      assert(brought == walk4);
      if (input_wrapped) assert(overlap);
    end
`endif
endmodule
`resetall
