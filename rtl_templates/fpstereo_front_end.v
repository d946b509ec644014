`resetall
`default_nettype none
// Window stage (docs/architecture.md, "Front end"): takes P left and P right pixels per slot (a
// beat: columns slot * P + q, q = 0 .. P - 1) in raster order, keeps N - 1 rows of each image in
// line buffers and forms the N x N windows, with the positions of their centres and which window
// rows and columns lie inside the image (semantics section 1). Outside the frame (bubble slots,
// rows below the image) the windows take zeros. The P windows of a shift are centred on the P
// columns of one slot, CENTRE_LAG slots behind the input: window q is columns q .. q + N - 1 of
// the COLS-wide arrays, whose column bounds are col_valid[q + N - 1 : q].
// transform_x / transform_y / transform_slot are the centres' slot, row and cost RAM row of the
// windows TRANSFORM_SLOTS shifts back: the position of what the transform (or the SAD/ZSAD window
// registers) holds.
// Back-to-back frames (docs/architecture.md): while `overlap` is high the row-times wrap after
// the frame's last row. If the next frame has begun by the step that would take its first pixel
// (next_frame), its rows follow at once (next_taken, and `continuing` until the next frame's own
// rows end); otherwise the input stays closed and the frame drains as a lone one. With G = 1 that
// step is the frame's last slot, which comes sooner than a following frame's first pixel can:
// `hold` stops the pipeline for FOLLOW_WAIT cycles there (only in the last row of a frame that
// may be followed), so that a frame sent on time is taken. `wrapped`: the rows have wrapped since
// the restart, so the rows above row 0 are the previous frame's.
module fpstereo_front_end #(
  parameter N = 5,
  parameter ROW_SLOTS = 64,
  parameter G = 4,
  // rows of the cost reorder RAM: the centre row's slot there is its row mod COST_ROWS
  parameter COST_ROWS = 2,
  parameter COST_ROW_W = 1,
  parameter X_W = 7,
  parameter Y_W = 6,
  // signed row coordinates (Y_W + 2): a window centre may lie above the image
  parameter SIGNED_Y_W = 8,
  parameter G_W = 2,
  // cycles the frame's last step waits for a following frame (0 when G > 1)
  parameter FOLLOW_WAIT = 0,
  // pixels per slot (1, 2 or 4); frame_width counts pixels, a multiple of P, and X_W holds it
  parameter P = 1,
  // the slots the windows' centres lag the input, and the window arrays' columns
  parameter CENTRE_LAG = (N / 2 + P - 1) / P,
  parameter COLS = P * (1 + CENTRE_LAG) + N / 2,
  // shifts from a window to the transform's result: 1 (census; SAD and ZSAD's window registers),
  // 2 (rank, whose count is registered halfway)
  parameter TRANSFORM_SLOTS = 1
) (
  input  wire                   clk,
  input  wire                   restart,
  input  wire                   adv,
  input  wire [X_W-1:0]         frame_width,
  input  wire [Y_W-1:0]         frame_height,
  input  wire                   overlap,
  input  wire                   next_frame,
  output wire                   next_taken,
  output wire                   follow_open,
  output wire                   hold,
  output reg                    continuing,
  output reg                    wrapped,
  // the pixel pair, taken in a step where in_due is high (in_take = adv && in_due)
  output wire                   in_due,
  output wire                   in_take,
  input  wire [P*8-1:0]         in_left,
  input  wire [P*8-1:0]         in_right,
  // the step's group and the slot's last step; shift = adv in a slot's last step
  output wire [G_W-1:0]         group,
  output wire                   slot_end,
  output wire                   shift,
  output wire [N*COLS*8-1:0]    window_left,
  output wire [N*COLS*8-1:0]    window_right,
  output wire [N-1:0]           row_valid,
  output wire [N+P-2:0]         col_valid,
  // window rows inside the image for the newest column (zero when that column is outside)
  output wire [N-1:0]           newest_row_valid,
  output reg  [X_W-1:0]         transform_x,
  output reg  signed [SIGNED_Y_W-1:0] transform_y,
  output reg  [COST_ROW_W-1:0]    transform_slot,
  // whether that position lies in the frame (its slot's first pixel and its row)
  output reg                    transform_in_frame
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 3 || N % 2 == 0) begin : invalid_N
      fpstereo_invalid_parameters_front_end_N_is_not_odd_and_at_least_3 failed ();
    end
    if (SIGNED_Y_W < Y_W + 2) begin : invalid_SIGNED_Y_W
      fpstereo_invalid_parameters_front_end_SIGNED_Y_W_below_Y_W_plus_2 failed ();
    end
    if (FOLLOW_WAIT < 0 || FOLLOW_WAIT > 3 || (FOLLOW_WAIT != 0 && G != 1)) begin : invalid_FOLLOW_WAIT
      fpstereo_invalid_parameters_front_end_FOLLOW_WAIT_outside_0_to_3_or_with_G_above_1 failed ();
    end
    if (TRANSFORM_SLOTS != 1 && TRANSFORM_SLOTS != 2) begin : invalid_TRANSFORM_SLOTS
      fpstereo_invalid_parameters_front_end_TRANSFORM_SLOTS_not_1_or_2 failed ();
    end
    if ((P != 1 && P != 2 && P != 4) || (P != 1 && G != 1) || ROW_SLOTS * P > (1 << X_W) ||
        CENTRE_LAG * P < N / 2 || COLS != P * (1 + CENTRE_LAG) + N / 2) begin : invalid_P
      fpstereo_invalid_parameters_front_end_P_not_1_2_4_with_G_1_or_X_W_CENTRE_LAG_COLS_wrong failed ();
    end
  endgenerate
  localparam R = N / 2;
  localparam LOG_P = $clog2(P);
  localparam integer LAST_SLOT_I = ROW_SLOTS - 1;
  localparam [X_W-1:0] LAST_SLOT = LAST_SLOT_I[X_W-1:0];
  wire [X_W:0] width_x = {1'b0, frame_width};
  wire signed [SIGNED_Y_W-1:0] height_y = $signed({2'b00, frame_height});

  wire [X_W-1:0] si;
  wire [Y_W-1:0] ti;
  /* verilator lint_off PINCONNECTEMPTY */  // the centre's RAM slot has a counter of its own
  fpstereo_raster_counter #(.G(G), .ROW_SLOTS(ROW_SLOTS), .K(1), .G_W(G_W), .X_W(X_W), .Y_W(Y_W), .K_W(1))
    input_position (.clk(clk), .restart(restart), .en(adv), .wrap(overlap), .height(frame_height), .group(group),
                    .slot(si), .row(ti), .row_slot(), .slot_end(slot_end));
  /* verilator lint_on PINCONNECTEMPTY */
  // in_due is a register, set for the next step (the sequencer's enable depends on it), with
  // flags for whether the slot's column and the row lie inside the frame. Step 0 is group 0 of
  // column 0 of row 0, inside every frame.
  localparam integer BEFORE_LAST_I = G > 1 ? G - 2 : 0;
  localparam [G_W-1:0] GROUP_BEFORE_LAST = BEFORE_LAST_I[G_W-1:0];
  // Whether the slot is the row-time's last, the frame's last column and last row, as registers
  // set when the counter moves (frames are at least 2 x 2); the frame size holds from the cycle
  // before step 0 (fpstereo_sequencer) to the frame's end.
  localparam integer SLOT_BEFORE_LAST_I = ROW_SLOTS - 2;
  localparam [X_W-1:0] SLOT_BEFORE_LAST = SLOT_BEFORE_LAST_I[X_W-1:0];
  localparam [X_W-1:0] TWO_X = 2;
  localparam [Y_W-1:0] TWO_Y = 2;
  reg  [X_W-1:0] col_before_last;
  reg  [Y_W-1:0] row_before_last;
  always @(posedge clk) begin
    col_before_last <= (frame_width >> LOG_P) - TWO_X;
    row_before_last <= frame_height - TWO_Y;
  end
  reg  at_last_slot, at_last_col, at_last_row;
  always @(posedge clk)
    if (restart) begin
      at_last_slot <= 1'b0;
      at_last_col <= 1'b0;
      at_last_row <= 1'b0;
    end else if (shift) begin
      at_last_slot <= si == SLOT_BEFORE_LAST;
      at_last_col <= !at_last_slot && si == col_before_last;
      if (at_last_slot) at_last_row <= ti == row_before_last;
    end
  reg  col_in, row_in, in_due_q;
  wire col_in_next = slot_end ? at_last_slot || (col_in && !at_last_col) : col_in;
  wire slot_end_next = G == 1 || group == GROUP_BEFORE_LAST;
  // After the frame's last row, the next frame may begin (open) until the step that predicts
  // whether its first pixel is due (deadline); `closed` once it did not.
  reg  awaiting, closed;
  wire rows_end = slot_end && at_last_slot && at_last_row;
  wire open = !closed && (awaiting || (rows_end && overlap && row_in));
  wire deadline = slot_end_next && col_in_next;
  wire row_in_next = open ? next_frame : slot_end && at_last_slot ? row_in && !at_last_row : row_in;
  assign next_taken = adv && open && next_frame;
  assign follow_open = overlap && !closed;
  always @(posedge clk)
    if (restart) begin
      col_in <= 1'b1;
      row_in <= 1'b1;
      in_due_q <= G == 1;
      awaiting <= 1'b0;
      closed <= 1'b0;
      continuing <= 1'b0;
      wrapped <= 1'b0;
    end else if (adv) begin
      col_in <= col_in_next;
      row_in <= row_in_next;
      in_due_q <= slot_end_next && col_in_next && row_in_next;
      if (open) begin
        continuing <= next_frame;
        awaiting <= !next_frame && !deadline;
        closed <= !next_frame && deadline;
      end
      if (rows_end && overlap) wrapped <= 1'b1;
    end
  // The hold: armed in the step before the last row's last slot (G = 1: every step is a slot),
  // while the frame may be followed; it lasts FOLLOW_WAIT cycles, whether the frame comes or not,
  // so that every frame takes the same time. hold is itself a register, as adv and through it the
  // restart depend on it (logic depth): it is set where armed is (never while armed, so once a
  // slot) and clears after FOLLOW_WAIT cycles, which waited counts.
  reg armed, hold_q;
  reg [1:0] waited;
  localparam [1:0] WAIT_LAST = FOLLOW_WAIT - 1;
  wire arm = FOLLOW_WAIT != 0 && si == SLOT_BEFORE_LAST && at_last_row && overlap && row_in && !closed;
  always @(posedge clk)
    if (restart) begin
      armed <= 1'b0;
      hold_q <= 1'b0;
    end else if (adv) begin
      armed <= arm;
      hold_q <= arm && !armed;
    end else begin
      hold_q <= hold_q && waited != WAIT_LAST;
    end
  assign hold = hold_q;
  always @(posedge clk)
    if (restart || !armed) waited <= 2'd0;
    else if (hold) waited <= waited + 1'b1;
  assign in_due  = in_due_q;
  assign in_take = adv && in_due;
  assign shift = adv && slot_end;
  wire [X_W-1:0] next_col = (si == LAST_SLOT) ? {X_W{1'b0}} : si + 1'b1;

  fpstereo_window #(.N(N), .P(P), .COLS(COLS), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) left_window (
    .clk(clk), .shift(shift), .col(si), .next_col(next_col),
    .word(in_due ? in_left : {(P*8){1'b0}}), .window(window_left));
  fpstereo_window #(.N(N), .P(P), .COLS(COLS), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) right_window (
    .clk(clk), .shift(shift), .col(si), .next_col(next_col),
    .word(in_due ? in_right : {(P*8){1'b0}}), .window(window_right));

  // Centre of the windows that form in this shift, CENTRE_LAG slots (R pixels at P = 1) and R rows
  // behind the input, and its row's slot in the cost reorder RAM, all counters, so that the
  // bounds compare registers. The windows' newest columns are the input slot's own: in the image
  // if the input slot is, and their rows centred on the input row - R (newest_y: no borrow, unlike
  // the centre at a row's start, which lies in the previous row-time, newest_prev_y).
  localparam integer CENTRE_START_I = ROW_SLOTS - CENTRE_LAG;
  localparam integer SLOT_BIAS = COST_ROWS * ((R + 1 + COST_ROWS) / COST_ROWS);  // a multiple above R + 1
  localparam integer NEWEST_SLOT_I = (SLOT_BIAS - R) % COST_ROWS;
  localparam integer PREV_SLOT_I = (SLOT_BIAS - R - 1) % COST_ROWS;
  localparam integer LAST_COST_ROW_I = COST_ROWS - 1;
  localparam integer PREV_START_I = -R - 1;
  localparam [X_W-1:0] CENTRE_START = CENTRE_START_I[X_W-1:0];
  localparam [COST_ROW_W-1:0] NEWEST_SLOT = NEWEST_SLOT_I[COST_ROW_W-1:0];
  localparam [COST_ROW_W-1:0] PREV_SLOT = PREV_SLOT_I[COST_ROW_W-1:0];
  localparam [COST_ROW_W-1:0] LAST_COST_ROW = LAST_COST_ROW_I[COST_ROW_W-1:0];
  localparam [SIGNED_Y_W-1:0] PREV_START = PREV_START_I[SIGNED_Y_W-1:0];
  localparam integer LAG_I = CENTRE_LAG;
  localparam [X_W-1:0] LAG_X = LAG_I[X_W-1:0];
  reg  [X_W-1:0] centre_x;
  always @(posedge clk)
    if (restart) centre_x <= CENTRE_START;
    else if (shift) centre_x <= centre_x == LAST_SLOT ? {X_W{1'b0}} : centre_x + 1'b1;
  wire input_row_ends = shift && at_last_slot;
  wire signed [SIGNED_Y_W-1:0] newest_y;
  reg  signed [SIGNED_Y_W-1:0] newest_prev_y;
  reg  [COST_ROW_W-1:0] newest_slot, newest_prev_slot;
  /* verilator lint_off PINCONNECTEMPTY */
  fpstereo_frame_row #(.Y_W(SIGNED_Y_W), .START(-R)) newest_row (
    .clk(clk), .restart(restart), .next(input_row_ends), .wrap(overlap), .height(height_y), .row(newest_y), .last());
  /* verilator lint_on PINCONNECTEMPTY */
  always @(posedge clk)
    if (restart) begin
      newest_prev_y <= PREV_START;
      newest_slot <= NEWEST_SLOT;
      newest_prev_slot <= PREV_SLOT;
    end else if (input_row_ends) begin
      newest_prev_y <= newest_y;
      newest_slot <= newest_slot == LAST_COST_ROW ? {COST_ROW_W{1'b0}} : newest_slot + 1'b1;
      newest_prev_slot <= newest_slot;
    end
  // The centre lies in the previous row-time while the input slot is below CENTRE_LAG: a register
  // that moves with the slot counter (slot 0 after a restart), so the rows' mux starts from it.
  reg borrow;
  always @(posedge clk)
    if (restart) borrow <= 1'b1;
    else if (shift) borrow <= si == LAST_SLOT || si + 1'b1 < LAG_X;
  wire signed [SIGNED_Y_W-1:0] centre_y = borrow ? newest_prev_y : newest_y;
  wire [COST_ROW_W-1:0] centre_slot = borrow ? newest_prev_slot : newest_slot;
  reg  [X_W-1:0] window_x;
  reg  signed [SIGNED_Y_W-1:0] window_y;
  reg  [COST_ROW_W-1:0] window_slot;
  // The position a shift before the transform's result (the window's with one slot of transform).
  wire [X_W-1:0] before_x;
  wire signed [SIGNED_Y_W-1:0] before_y;
  wire [COST_ROW_W-1:0] before_slot;
  always @(posedge clk)
    if (shift) begin
      window_x <= centre_x;
      window_y <= centre_y;
      window_slot <= centre_slot;
      transform_x <= before_x;
      transform_y <= before_y;
      transform_slot <= before_slot;
    end

  // The bounds of the window that forms in this shift are registered with its position, so that
  // the compares with the frame size and the transform lie in different steps. Its rows' bounds
  // are those of one of the two counted rows.
  wire [N-1:0] newest_rows, prev_rows;
  /* verilator lint_off UNUSEDSIGNAL */  // the columns' bounds come from fpstereo_slot_columns below
  wire [N-1:0] newest_unused_columns, prev_unused_columns;
  /* verilator lint_on UNUSEDSIGNAL */
  fpstereo_window_bounds #(.SIDE(N), .X_W(X_W), .SIGNED_Y_W(SIGNED_Y_W)) window_bounds (
    .clk(clk), .x(centre_x), .y(newest_y), .width(width_x), .height(height_y), .row_valid(newest_rows),
    .col_valid(newest_unused_columns));
  fpstereo_window_bounds #(.SIDE(N), .X_W(X_W), .SIGNED_Y_W(SIGNED_Y_W)) prev_bounds (
    .clk(clk), .x(centre_x), .y(newest_prev_y), .width(width_x), .height(height_y), .row_valid(prev_rows),
    .col_valid(prev_unused_columns));
  // The columns' bounds: those of the P windows side by side, centred on the slot's first pixel
  // x = centre_x * P and the P - 1 after it, from a counter of the slots left in the width.
  wire [N+P-2:0] centre_columns;
  fpstereo_slot_columns #(.COLS(N + P - 1), .LAG(R), .P(P), .X_W(X_W), .START(CENTRE_START_I)) columns (
    .clk(clk), .restart(restart), .shift(shift), .to_first(centre_x == LAST_SLOT), .frame_width(frame_width),
    .x(centre_x), .col_valid(centre_columns));
  wire [N-1:0] centre_rows = borrow ? prev_rows : newest_rows;
  reg [N-1:0] row_valid_q, newest_row_valid_q;
  reg [N+P-2:0] col_valid_q;
  always @(posedge clk)
    if (shift) begin
      row_valid_q <= centre_rows;
      col_valid_q <= centre_columns;
      // (col_in: the input slot lies inside the width, a register)
      newest_row_valid_q <= col_in ? newest_rows : {N{1'b0}};
    end
  // Whether the transform's position lies in the frame: its window's centre row and its slot's
  // first column are inside, which the window's registered bounds already say (row and column R),
  // so the code writes' enable starts from registers (logic depth, docs/timing.md). A restart
  // clears it for two shifts: the first one's bounds are not yet its window's, and the windows of
  // the first shifts lie above the image anyway.
  reg window_fresh;
  wire before_in_frame;
  always @(posedge clk)
    if (restart) begin
      window_fresh <= 1'b1;
      transform_in_frame <= 1'b0;
    end else if (shift) begin
      window_fresh <= 1'b0;
      transform_in_frame <= before_in_frame;
    end
  wire window_in_frame = !window_fresh && row_valid_q[R] && col_valid_q[R];
  generate
    if (TRANSFORM_SLOTS == 2) begin : counted
      reg [X_W-1:0] counted_x;
      reg signed [SIGNED_Y_W-1:0] counted_y;
      reg [COST_ROW_W-1:0] counted_slot;
      reg counted_in_frame;
      always @(posedge clk)
        if (shift) begin
          counted_x <= window_x;
          counted_y <= window_y;
          counted_slot <= window_slot;
        end
      always @(posedge clk)
        if (restart) counted_in_frame <= 1'b0;
        else if (shift) counted_in_frame <= window_in_frame;
      assign {before_x, before_y, before_slot, before_in_frame} = {counted_x, counted_y, counted_slot, counted_in_frame};
    end else begin : direct
      assign {before_x, before_y, before_slot, before_in_frame} = {window_x, window_y, window_slot, window_in_frame};
    end
  endgenerate
  assign row_valid = row_valid_q;
  assign col_valid = col_valid_q;
  assign newest_row_valid = newest_row_valid_q;
endmodule
`resetall
