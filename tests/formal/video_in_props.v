`default_nettype none
// Formal properties of rtl_templates/fpstereo_video_in.v (tests/formal/run_proof.sh), frames up
// to 7 x 3 (X_W 3, Y_W 2). The environment (assumed): both input streams obey AXI4-Stream (no
// TVALID in reset or in the cycle after it, held until TREADY with {tuser, tlast, tdata} stable),
// with any tuser/tlast (framing faults included); the core's ready is free (a pixel is taken
// when offered and ready), and its frame size (at least 2 x 2, as the unit requires) holds from
// the cycle after core_start until the frame's last pixel is taken. The unit (asserted):
//   - an input beat is taken only while its TVALID is high;
//   - during a frame the streams are taken only in pairs, each pair as the pixel the core takes;
//   - the core gets exactly width x height pixels per frame (core_start only between frames,
//     in_valid only within one), offered until taken with the pixel stable;
//   - every pair passed on has tuser on the frame's first pixel and tlast on each row's last,
//     on both streams (the documented positions), and its data unchanged; a pixel taken
//     without a pair (padding of a truncated frame) is 0.
// The induction compares the frame position counted here with the unit's:
// formal-probe: probe_state dut.state
// formal-probe: probe_x dut.x
// formal-probe: probe_y dut.y
// formal-probe: probe_first dut.first
// formal-probe: probe_row_end dut.row_end
// formal-probe: probe_last_row dut.last_row
// formal-probe: probe_frame_end dut.frame_end
// formal-probe: probe_done dut.done
module video_in_props (
  input wire       clk,
  input wire       rst,
  input wire       enable,
  input wire [9:0] left,
  input wire       left_valid,
  input wire [9:0] right,
  input wire       right_valid,
  input wire       core_accepting,
  input wire [2:0] frame_width,
  input wire [1:0] frame_height,
  input wire       in_ready
);
  localparam X_W = 3, Y_W = 2;
  wire       left_ready, right_ready, core_start, in_valid;
  wire [7:0] in_left, in_right;
  wire       frame_dropped, frame_truncated, protocol_error;
  fpstereo_video_in #(.X_W(X_W), .Y_W(Y_W)) dut (
    .clk(clk), .rst(rst), .enable(enable),
    .left(left), .left_valid(left_valid), .left_ready(left_ready),
    .right(right), .right_valid(right_valid), .right_ready(right_ready),
    .core_accepting(core_accepting), .core_start(core_start), .frame_width(frame_width),
    .frame_height(frame_height), .in_valid(in_valid), .in_left(in_left), .in_right(in_right),
    .in_ready(in_ready), .frame_dropped(frame_dropped), .frame_truncated(frame_truncated),
    .protocol_error(protocol_error));

`ifdef FORMAL
  (* keep *) wire [1:0] probe_state;
  (* keep *) wire [X_W-1:0] probe_x;
  (* keep *) wire [Y_W-1:0] probe_y;
  (* keep *) wire           probe_first, probe_row_end, probe_last_row, probe_frame_end, probe_done;

  wire in_take = in_valid && in_ready;  // the core's take
  wire past_valid, past_rst;
  formal_start run_start (.clk(clk), .rst(rst), .past_valid(past_valid), .past_rst(past_rst));

  // ---- The frame as the core sees it: started by core_start, width x height pixels taken.
  reg           in_frame;
  reg [X_W-1:0] x, w;
  reg [Y_W-1:0] y, h;
  wire row_last = x == w - 1'b1;
  wire frame_last = row_last && y == h - 1'b1;
  always @(posedge clk)
    if (rst) in_frame <= 1'b0;
    else if (core_start) begin
      in_frame <= 1'b1;
      x <= 0;
      y <= 0;
      w <= frame_width;
      h <= frame_height;
    end else if (in_frame && in_take) begin
      x <= row_last ? {X_W{1'b0}} : x + 1'b1;
      if (row_last) y <= y + 1'b1;
      if (frame_last) in_frame <= 1'b0;
    end

  // ---- The environment.
  always @* begin
    assume(frame_width >= 2 && frame_height >= 2);
    if (in_frame) assume(frame_width == w && frame_height == h);
  end
  formal_axis_in #(.W(10)) left_stream (.clk(clk), .rst(rst), .valid(left_valid), .ready(left_ready), .payload(left));
  formal_axis_in #(.W(10)) right_stream (.clk(clk), .rst(rst), .valid(right_valid), .ready(right_ready), .payload(right));

  // ---- The unit.
  wire pair = left_ready && right_ready;
  always @*
    if (past_valid && !past_rst) begin
      // no beat taken without TVALID
      assert(!left_ready || left_valid);
      assert(!right_ready || right_valid);
      // frames: one at a time, pixels only within one
      if (core_start) assert(!in_frame);
      if (in_valid) assert(in_frame);
      if (in_frame) begin
        // the streams are taken in pairs, each pair as the pixel the core takes
        assert(left_ready == right_ready);
        if (pair) begin
          assert(in_take && in_valid);
          assert(left[9] == (x == 0 && y == 0) && right[9] == (x == 0 && y == 0));
          assert(left[8] == row_last && right[8] == row_last);
          assert(in_left == left[7:0] && in_right == right[7:0]);
        end else if (in_take) begin
          // a pixel taken that takes no pair is padding
          assert(in_left == 8'd0 && in_right == 8'd0);
        end
        // the unit's position is the frame's
        assert(probe_x == x && probe_y == y && x < w && y < h);
        assert(probe_first == (x == 0 && y == 0) && probe_row_end == row_last && probe_last_row == (y == h - 1'b1));
        assert(probe_frame_end == frame_last);
      end
      assert(in_frame == (probe_state != 2'd0 && !probe_done) && probe_state != 2'd3);
    end
  // offered until taken (or reset), unchanged
  always @(posedge clk)
    if (past_valid && !past_rst && !rst && $past(in_valid && !in_take))
      assert(in_valid && in_left == $past(in_left) && in_right == $past(in_right));
`endif
endmodule
`resetall
