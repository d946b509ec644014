`default_nettype none
// Formal properties of the output's raster order (rtl_templates/fpstereo_disparity_reorder.v and
// its fpstereo_raster_counter; tests/formal/run_proof.sh), rows of up to 5 slots in 2 steps each
// (X_W 3), up to 7 rows (Y_W 3). The read stream it asserts is where every output position comes
// from: the core registers tuser = (x, y) == (0, 0) and tlast = x == width - 1 from it (or from
// the median's and gap fill's delayed copies of it), and the output register slice passes the
// beats on in order (skid_props). The environment (assumed): `restart` in the first cycle; the
// frame size constant, width at most ROW_SLOTS and height at least 2; out_on low after a restart
// and, once high, high until the next; `overlap` constant; and the frame ended (a restart, or
// adv held low) before the read row would pass the last one Y_W counts. The unit (asserted): the
// events taken (read_event at an adv) are the frame's positions (x, y), x < width and y < height
// + EXTRA_ROWS, each once and in raster order; with `overlap` the rows wrap after the frame's
// last and the next frame's positions follow. The induction compares the position counted here
// with the raster counter's:
// formal-probe: probe_group dut.output_position.group
// formal-probe: probe_slot dut.output_position.slot
// formal-probe: probe_row dut.output_position.frame_row.row
// formal-probe: probe_last dut.output_position.frame_row.last
// formal-probe: probe_before_last dut.output_position.frame_row.before_last
module output_order_props #(
  parameter EXTRA_ROWS = 1
) (
  input wire       clk,
  input wire       restart,
  input wire       adv,
  input wire       out_on,
  input wire       overlap,
  input wire [2:0] frame_width,
  input wire [2:0] frame_height,
  input wire       active,
  input wire [2:0] x,
  input wire [1:0] slot,
  input wire       group,
  input wire [2:0] word
);
  localparam ROW_SLOTS = 5, G = 2, X_W = 3, Y_W = 3;
  wire           read_done, read_event;
  wire [X_W-1:0] read_x;
  wire [Y_W-1:0] read_y;
  wire [1:0]     read_slot_row;
  wire [2:0]     read_word;
  fpstereo_disparity_reorder #(.ROW_SLOTS(ROW_SLOTS), .G(G), .DISP_W(2), .OUT_ROWS(3), .OUT_ROW_W(2), .DISP_AW(4),
                               .EXTRA_ROWS(EXTRA_ROWS), .X_W(X_W), .Y_W(Y_W), .G_W(1)) dut (
    .clk(clk), .restart(restart), .adv(adv), .out_on(out_on), .overlap(overlap), .frame_width(frame_width),
    .frame_height(frame_height), .active(active), .x(x), .slot(slot), .group(group), .word(word),
    .read_done(read_done), .read_event(read_event), .read_x(read_x), .read_y(read_y),
    .read_slot_row(read_slot_row), .read_word(read_word));

`ifdef FORMAL
  (* keep *) wire           probe_group, probe_last;
  (* keep *) wire [X_W-1:0] probe_slot;
  (* keep *) wire [Y_W-1:0] probe_row, probe_before_last;

  wire past_valid, past_rst;
  formal_start run_start (.clk(clk), .rst(restart), .past_valid(past_valid), .past_rst(past_rst));
  // Registered past values: an assumption in a clocked block would bind one cycle late.
  reg       past_out_on, past_overlap;
  reg [2:0] past_width, past_height;
  always @(posedge clk) {past_out_on, past_overlap, past_width, past_height} <= {out_on, overlap, frame_width, frame_height};

  // ---- The environment.
  wire [7:0] width = {5'd0, frame_width}, event_rows = {5'd0, frame_height} + EXTRA_ROWS[7:0];
  wire [7:0] height = {5'd0, frame_height};
  always @* begin
    assume(frame_width >= 1 && frame_width <= ROW_SLOTS && frame_height >= 2);
    assume(event_rows < 8'd8);
    if (past_valid) begin
      assume(frame_width == past_width && frame_height == past_height && overlap == past_overlap);
      if (past_rst) assume(!out_on);
      else if (past_out_on) assume(out_on);
    end
    if (adv && out_on && probe_group && probe_slot == ROW_SLOTS - 1 && probe_row == {Y_W{1'b1}}) assume(restart);
  end

  // ---- The positions taken, counted: the next one expected (ex, ey) and its index in the frame;
  // after the frame's last (without overlap) the index stays at the end.
  reg [X_W-1:0] ex;
  reg [Y_W-1:0] ey;
  wire [7:0] rows = overlap ? height : event_rows;
  wire [7:0] expected = {5'd0, ey} * width + {5'd0, ex};
  always @(posedge clk)
    if (restart) begin
      ex <= 0;
      ey <= 0;
    end else if (adv && read_event) begin
      ex <= ex == frame_width - 1'b1 ? {X_W{1'b0}} : ex + 1'b1;
      if (ex == frame_width - 1'b1) ey <= overlap && {5'd0, ey} == height - 1'b1 ? {Y_W{1'b0}} : ey + 1'b1;
    end

  // The raster counter's next position that is an event, as an index: its slot if that is in the
  // row, else the next row's first (with overlap, the frame's end is the next frame's start).
  wire [7:0] at = {5'd0, probe_row} * width + (probe_slot < frame_width ? {5'd0, probe_slot} : width);
  wire [7:0] counter = overlap && at == rows * width ? 8'd0 : at;
  wire [7:0] taken = expected + {7'd0, read_event};
  always @*
    if (past_valid && !past_rst) begin
      // each event taken is the next position of the frame
      if (read_event) assert(read_x == ex && read_y == ey && read_x < frame_width && {5'd0, read_y} < rows);
      assert(ex < frame_width && ({5'd0, ey} < rows || (!overlap && {5'd0, ey} == rows && ex == 0)));
      // the counter is the events taken and the one pending ahead
      if (overlap) assert(counter == (taken == rows * width ? 8'd0 : taken));
      else assert((counter < rows * width ? counter : rows * width) == taken);
      if (!out_on) assert(probe_slot == 0 && probe_row == 0 && !probe_group && !read_event);
      assert(probe_slot < ROW_SLOTS && probe_before_last == frame_height - 2'd2);
      assert(probe_last == (probe_row == frame_height - 1'b1));
      if (overlap) assert({5'd0, probe_row} < height);
    end
`endif
endmodule
`resetall
