`resetall
`default_nettype none
// Input framing (docs/architecture.md, "Robust video input"): pairs the left and right pixels for
// the core and holds them to the Xilinx video convention, tuser on a frame's first pixel and
// tlast on each row's last.
// The core needs frames of at least 2 x 2 (the control block's MIN_WIDTH and MIN_HEIGHT are
// larger): the position flags are registers, set for the next pixel as one is taken.
// With several pixels per beat (ppc > 1), a "pixel" here is a beat of DATA_W bits and
// frame_width counts beats.
//   SEEK: beats that do not start a frame are skipped. When both streams offer a start of frame
//         and the core accepts a frame, the frame begins (or, while disabled, is skipped as dropped).
//         If one stream skipped at least half a frame's rows more than the other, the other's
//         frame is the counterpart of what was skipped (a start of frame missing or repeated on
//         one stream only) and is skipped as well, so that the streams pair up again.
//   RUN:  each pair goes to the core while its flags match its position. A pair whose flags do
//         not ends the frame early: it is left for SEEK (it may start the next frame).
//   PAD:  the core gets zero pixels for the rest of the truncated frame, so that its output
//         frame is complete and well-formed and nothing waits for input that will not come.
//   After the frame's last pixel the unit takes nothing for a cycle, then seeks again.
// Every event is a one-cycle pulse for the status counters. Skipped data counts as one
// protocol error per stretch, unless it follows an error already counted or a dropped frame.
module fpstereo_video_in #(
  // bits of a beat's pixels (8 per pixel)
  parameter DATA_W = 8,
  parameter X_W = 7,
  parameter Y_W = 6
) (
  input  wire           clk,
  input  wire           rst,
  // new frames are taken while high, skipped (and counted as dropped) while low
  input  wire           enable,
  // the streams after their register slices: {tuser, tlast, tdata}
  input  wire [DATA_W+1:0] left,
  input  wire           left_valid,
  output wire           left_ready,
  input  wire [DATA_W+1:0] right,
  input  wire           right_valid,
  output wire           right_ready,
  // the core: a frame begins with core_start while the core accepts one (idle, or able to take
  // a following frame); its size holds from the next cycle until the frame is done
  input  wire           core_accepting,
  output wire           core_start,
  input  wire [X_W-1:0] frame_width,
  input  wire [Y_W-1:0] frame_height,
  output wire           in_valid,
  output wire [DATA_W-1:0] in_left,
  output wire [DATA_W-1:0] in_right,
  // the core's pixel register slice takes a pixel while high (taken: in_valid && in_ready,
  // inside this module, so that the take's logic is mapped with the flags it depends on)
  input  wire           in_ready,
  // events
  output wire           frame_dropped,
  output wire           frame_truncated,
  output wire           protocol_error
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (X_W < 2 || Y_W < 2 || DATA_W < 8) begin : invalid
      fpstereo_invalid_parameters_video_in_X_W_or_Y_W_below_2_or_DATA_W_below_8 failed ();
    end
  endgenerate
  localparam [1:0] SEEK = 2'd0, RUN = 2'd1, PAD = 2'd2;
  reg [1:0]     state;
  reg           quiet;  // skipped data is already accounted for
  reg [X_W-1:0] x;
  reg [Y_W-1:0] y;

  wire left_user = left[DATA_W+1], left_last = left[DATA_W];
  wire right_user = right[DATA_W+1], right_last = right[DATA_W];
  wire both = left_valid && right_valid;
  // Flags of the pixel at (x, y), kept as registers so that no compare with the frame size lies
  // on the path from the streams to the core (frame_end too: row_end && last_row, registered).
  reg  first, row_end, last_row, frame_end;
  localparam [X_W-1:0] TWO_X = 2;
  localparam [Y_W-1:0] TWO_Y = 2;
  wire flags_match = left_user == first && right_user == first && left_last == row_end && right_last == row_end;

  // SEEK: a stream's beat that starts no frame is skipped; a frame starts on both streams at once.
  wire starts = state == SEEK && both && left_user && right_user;
  wire skip_left = state == SEEK && left_valid && !left_user;
  wire skip_right = state == SEEK && right_valid && !right_user;
  // Rows skipped on each stream since the last frame began (saturating below 2^Y_W).
  // The comparison is a register, made with the counts it will see (the frame height changes
  // only in the cycle after a start, when both counts are 0 and neither stream is stale).
  reg  [Y_W:0] left_rows, right_rows;
  wire [Y_W:0] left_rows_next, right_rows_next;
  wire [Y_W:0] half = {2'b00, frame_height[Y_W-1:1]};
  reg  left_stale, right_stale;
  wire aligned = !left_stale && !right_stale;
  assign core_start = starts && aligned && core_accepting && enable;
  wire drop = starts && aligned && core_accepting && !enable;

  // RUN and PAD: the core's pixel stream, until the frame's last pixel is taken (done: the state
  // returns to SEEK in the next cycle, so that the state does not wait for the take).
  reg  done;
  wire fault = state == RUN && !done && both && !flags_match;
  wire passing = state == RUN && !done && both && flags_match;
  assign in_valid = passing || (state == PAD && !done);
  assign in_left = passing ? left[DATA_W-1:0] : {DATA_W{1'b0}};
  assign in_right = passing ? right[DATA_W-1:0] : {DATA_W{1'b0}};
  wire in_take = in_valid && in_ready;
  wire pass_take = passing && in_take;
  assign left_ready = skip_left || drop || (starts && left_stale) || pass_take;
  assign right_ready = skip_right || drop || (starts && right_stale) || pass_take;

  assign frame_dropped = drop;
  assign frame_truncated = fault;
  assign protocol_error = ((skip_left || skip_right) && !quiet) || fault;

  always @(posedge clk)
    if (rst) begin
      state <= SEEK;
      quiet <= 1'b0;
    end else begin
      case (state)
        SEEK:
          if (core_start) begin
            state <= RUN;
            quiet <= 1'b0;
          end else if (drop || skip_left || skip_right) quiet <= 1'b1;
        RUN:
          if (done) state <= SEEK;
          else if (fault) begin
            state <= PAD;
            quiet <= 1'b1;
          end
        default:  // PAD
          if (done) state <= SEEK;
      endcase
    end
  always @(posedge clk)
    if (rst || done) done <= 1'b0;
    else done <= in_take && frame_end;

  localparam [Y_W:0] ROWS_MAX = {1'b0, {Y_W{1'b1}}};
  wire restart_rows = rst || core_start || drop;
  wire left_inc = skip_left && left_last && left_rows != ROWS_MAX;
  wire right_inc = skip_right && right_last && right_rows != ROWS_MAX;
  assign left_rows_next = restart_rows ? {(Y_W+1){1'b0}} : left_rows + {{Y_W{1'b0}}, left_inc};
  assign right_rows_next = restart_rows ? {(Y_W+1){1'b0}} : right_rows + {{Y_W{1'b0}}, right_inc};
  // Stale after this cycle's skips: rows + half + (own skip) - (other's skip) <= other's rows,
  // the three cases compared in parallel from the registers and then chosen.
  wire [Y_W+1:0] left_reach = {1'b0, left_rows} + {1'b0, half};
  wire [Y_W+1:0] right_reach = {1'b0, right_rows} + {1'b0, half};
  wire [Y_W+1:0] left_wide = {1'b0, left_rows}, right_wide = {1'b0, right_rows};
  always @(posedge clk) begin
    left_rows <= left_rows_next;
    right_rows <= right_rows_next;
    if (restart_rows) begin
      left_stale <= !rst && half == 0;
      right_stale <= !rst && half == 0;
    end else begin
      left_stale <= left_inc == right_inc ? left_reach <= right_wide
                  : left_inc ? left_reach < right_wide : left_reach <= right_wide + 1'b1;
      right_stale <= left_inc == right_inc ? right_reach <= left_wide
                   : right_inc ? right_reach < left_wide : right_reach <= left_wide + 1'b1;
    end
  end

  // Whether the next pixel ends its row (in the last row, the frame).
  wire next_row_end = !row_end && x == frame_width - TWO_X;
  always @(posedge clk)
    if (rst || core_start) begin
      x <= 0;
      y <= 0;
      first <= 1'b1;
      row_end <= 1'b0;
      last_row <= 1'b0;
      frame_end <= 1'b0;
    end else if (in_take) begin
      x <= row_end ? {X_W{1'b0}} : x + 1'b1;
      first <= 1'b0;
      row_end <= next_row_end;
      frame_end <= next_row_end && last_row;
      if (row_end) begin
        y <= y + 1'b1;
        last_row <= y == frame_height - TWO_Y;
      end
    end
endmodule
`resetall
