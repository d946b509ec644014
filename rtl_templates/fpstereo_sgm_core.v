`resetall
`default_nettype none
// The SGM pipeline between the input and output skid buffers (docs/architecture.md): front end
// in raster order, cost reorder RAM, aggregation in K interleaved chains, winner-take-all (with
// uniqueness), disparity reorder RAM, left-right check (LR1 or LR2), median, gap interpolation
// and output. Every register advances only in steps where adv is high, so the whole pipeline
// stalls together; the stages find their pixel from step counters.
module fpstereo_sgm_core #(
  // largest image width W and time base: ROW_SLOTS = K * SLEN slots per row-time, G steps per slot
  parameter W = 64,
  parameter ROW_SLOTS = 64,
  parameter K = 2,
  parameter SLEN = 32,
  parameter G = 4,
  // disparities: DMAX = G * UF
  parameter UF = 8,
  parameter DMAX = 32,
  // cost function: 0 = census, 1 = rank, 2 = SAD, 3 = ZSAD, 4 = SHD; window side N; census code
  // or rank width; SHD summation window; cost lanes' latency
  parameter COST_KIND = 0,
  parameter N = 5,
  parameter CODE_W = 24,
  parameter SHD_K = 3,
  parameter COST_W = 5,
  parameter COST_MAX = 24,
  parameter COST_LAT = 1,
  // SAD/ZSAD: width of a window column's pixel sum; ZSAD: mean = (sum * MEAN_MUL) >> MEAN_SHIFT
  parameter COLSUM_W = 11,
  parameter MEAN_MUL = 1,
  parameter MEAN_SHIFT = 0,
  // path cost, sum and disparity widths (docs/semantics.md, "Bit widths")
  parameter PATH_W = 7,
  parameter SUM_W = 9,
  parameter DISP_W = 5,
  // left-right check (0 = none, 1 = LR1, 2 = LR2); uniqueness check present (its ratio is a
  // setting); median filter window (0 = off, 3, 5 or 7)
  parameter LR = 0,
  parameter UNIQUENESS = 0,
  parameter MEDIAN = 0,
  // gap interpolation (0 = off, 1 = on)
  parameter GAP = 0,
  // enabled paths: bit 0 = 0 degrees, 1 = 45, 2 = 90, 3 = 135
  parameter PATHS = 15,
  // compare-select levels per register stage in the minimum trees, and the trees' latencies
  parameter LEVELS_PER_STAGE = 3,
  parameter PATH_TREE_LAT = 1,
  parameter WTA_TREE_LAT = 1,
  // steps after the frame's first step at which aggregation, LR2's match-side aggregation and
  // output begin
  parameter AGG_START = 100,
  parameter MATCH_START = 200,
  parameter OUT_START = 200,
  // counter widths
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter G_W = 2,
  parameter K_W = 1,
  parameter LANE_W = 3,
  parameter STEP_W = 20
) (
  input  wire              clk,
  input  wire              rst,
  // Frames: while idle, start begins one. The settings are the frame's and must hold until the
  // core is idle again (fpstereo_control latches them); the frame is at most W pixels wide.
  input  wire              start,
  output wire              idle,
  input  wire [X_W-1:0]    frame_width,
  input  wire [Y_W-1:0]    frame_height,
  input  wire [PATH_W-1:0] p1,
  input  wire [PATH_W-1:0] p2,
  /* verilator lint_off UNUSEDSIGNAL */  // used where the design has the uniqueness or LR check
  input  wire [6:0]        uniqueness,
  input  wire [3:0]        lr_threshold,
  /* verilator lint_on UNUSEDSIGNAL */
  // one pixel of each image, taken when in_take is high
  input  wire              in_valid,
  input  wire [7:0]        in_left,
  input  wire [7:0]        in_right,
  output wire              in_take,
  // output word (invalid flag above the disparity), pushed when out_push is high
  input  wire              out_ready,
  output wire              out_push,
  output wire [DISP_W:0]   out_word,
  output wire              out_first,
  output wire              out_last,
  // high in the cycle that pushes the frame's last pixel
  output wire              frame_end
);
  localparam R = N / 2;
  // Rows of the cost reorder RAM: K, one more with LR2, whose match side reads a row longer.
  localparam COST_ROWS = K + (LR == 2 ? 1 : 0);
  localparam COST_K_W = $clog2(COST_ROWS);
  localparam COST_DEPTH = COST_ROWS * ROW_SLOTS * G;
  localparam COST_AW = $clog2(COST_DEPTH);
  localparam STATE_DEPTH = K * G;
  localparam STATE_AW = STATE_DEPTH > 1 ? $clog2(STATE_DEPTH) : 1;
  // Rows of the disparity (and match disparity) RAMs: K, one more for the output's lag, and one
  // (LR1) or two (LR2) more, as long as the output waits for the match side to finish a row.
  localparam OUT_ROWS = K + 1 + LR;
  localparam OUT_K_W = $clog2(OUT_ROWS);
  localparam DISP_DEPTH = OUT_ROWS * ROW_SLOTS;
  localparam DISP_AW = $clog2(DISP_DEPTH);
  localparam [DISP_W:0] INVALID_WORD = {1'b1, {DISP_W{1'b0}}};
  // Sized copies of the constants the counters are compared with (keeps widths exact).
  localparam integer LAST_GROUP_I = G - 1;
  localparam [G_W-1:0] LAST_GROUP = LAST_GROUP_I[G_W-1:0];
  localparam [X_W-1:0] LAST_SLOT = ROW_SLOTS - 1;
  wire [X_W:0] width_x = {1'b0, frame_width};
  localparam YS_W = Y_W + 2;  // signed row coordinates: a window centre may lie above the image
  localparam signed [YS_W-1:0] R_Y = R;
  wire signed [YS_W-1:0] height_y = $signed({2'b00, frame_height});

  // ------------------------------------------------------------------------------------------
  // Global advance and frame sequencing.
  wire in_due, out_due, frame_done;
  reg  in_frame;
  wire adv = in_frame && !(in_due && !in_valid) && !(out_due && !out_ready);
  always @(posedge clk)
    if (rst) in_frame <= 1'b0;
    else if (!in_frame) in_frame <= start;
    else if (adv && frame_done) in_frame <= 1'b0;
  assign idle = !in_frame;
  reg  [STEP_W-1:0] step;
  always @(posedge clk)
    if (rst) step <= 0;
    else if (adv) step <= frame_done ? {STEP_W{1'b0}} : step + 1'b1;
  wire restart = rst || (adv && frame_done);

  // ------------------------------------------------------------------------------------------
  // Front end: input counters (group, slot, row-time).
  wire [G_W-1:0] gi;
  wire [X_W-1:0] si;
  wire [Y_W-1:0] ti;
  wire [COST_K_W-1:0] ti_slot;  // ti mod COST_ROWS: which row of the cost reorder RAM the row uses
  wire slot_end;
  fpstereo_raster_counter #(.G(G), .ROW_SLOTS(ROW_SLOTS), .K(COST_ROWS), .G_W(G_W), .X_W(X_W), .Y_W(Y_W),
                            .K_W(COST_K_W))
    input_position (.clk(clk), .restart(restart), .en(adv), .group(gi), .slot(si), .row(ti), .row_slot(ti_slot),
                    .slot_end(slot_end));
  assign in_due  = slot_end && si < frame_width && ti < frame_height;
  assign in_take = adv && in_due;
  wire shift = adv && slot_end;
  wire [X_W-1:0] next_col = (si == LAST_SLOT) ? {X_W{1'b0}} : si + 1'b1;

  wire [N*N*8-1:0] window_left, window_right;
  fpstereo_window #(.N(N), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) left_window (
    .clk(clk), .shift(shift), .col(si), .next_col(next_col),
    .word(in_due ? in_left : 8'd0), .window(window_left));
  fpstereo_window #(.N(N), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) right_window (
    .clk(clk), .shift(shift), .col(si), .next_col(next_col),
    .word(in_due ? in_right : 8'd0), .window(window_right));

  // Centre of the window that forms in this shift, and its row's slot in the cost reorder RAM.
  wire [X_W-1:0] centre_x;
  wire signed [YS_W-1:0] centre_y;
  wire [COST_K_W-1:0] centre_slot;
  fpstereo_window_centre #(.LAG(R), .ROW_SLOTS(ROW_SLOTS), .X_W(X_W), .YS_W(YS_W), .ROWS(COST_ROWS),
                           .SLOT_W(COST_K_W)) centre (
    .x(si), .y($signed({2'b00, ti})), .slot(ti_slot), .centre_x(centre_x), .centre_y(centre_y),
    .centre_slot(centre_slot));
  reg  [X_W-1:0] window_x;
  reg  signed [YS_W-1:0] window_y;
  reg  [COST_K_W-1:0] window_slot;
  // The window's newest column is the input column itself: in the image if the input column is,
  // and its rows centred on the input row - R (no borrow, unlike the centre at a row's start).
  reg  newest_in_row;
  reg  signed [YS_W-1:0] newest_y;
  always @(posedge clk)
    if (shift) begin
      window_x <= centre_x;
      window_y <= centre_y;
      window_slot <= centre_slot;
      newest_in_row <= {1'b0, si} < width_x;
      newest_y <= $signed({2'b00, ti}) - R_Y;
    end

  // Window positions inside the image (semantics section 1), for the window and for its newest
  // column on its own row.
  wire [N-1:0] row_valid, col_valid;
  fpstereo_window_bounds #(.SIDE(N), .X_W(X_W), .YS_W(YS_W)) window_bounds (
    .x(window_x), .y(window_y), .width(width_x), .height(height_y), .row_valid(row_valid), .col_valid(col_valid));
  /* verilator lint_off UNUSEDSIGNAL */  // only the window costs (SAD, ZSAD) use them
  wire [N-1:0] newest_rows, newest_unused_columns;
  wire [N-1:0] newest_row_valid = newest_in_row ? newest_rows : {N{1'b0}};
  /* verilator lint_on UNUSEDSIGNAL */
  fpstereo_window_bounds #(.SIDE(N), .X_W(X_W), .YS_W(YS_W)) newest_bounds (
    .x(window_x), .y(newest_y), .width(width_x), .height(height_y), .row_valid(newest_rows), .col_valid(newest_unused_columns));

  // Transform stage, once per slot: the window centre's position and, for census, rank and SHD,
  // the base and match codes (SAD and ZSAD keep their windows; their branch registers them).
  reg  [X_W-1:0] transform_x;
  reg  signed [YS_W-1:0] transform_y;
  reg  [COST_K_W-1:0] transform_slot;
  always @(posedge clk)
    if (shift) begin
      transform_x    <= window_x;
      transform_y    <= window_y;
      transform_slot <= window_slot;
    end
  /* verilator lint_off UNUSEDSIGNAL */  // SAD and ZSAD use no codes
  reg  [CODE_W-1:0] code_base_t, code_match_t;
  /* verilator lint_on UNUSEDSIGNAL */
  generate
    if (COST_KIND == 0 || COST_KIND == 1 || COST_KIND == 4) begin : codes
      wire [CODE_W-1:0] code_left, code_right;
      if (COST_KIND == 1) begin : rank
        fpstereo_rank #(.N(N), .RANK_W(CODE_W)) base (.window(window_left), .row_valid(row_valid), .col_valid(col_valid), .rank(code_left));
        fpstereo_rank #(.N(N), .RANK_W(CODE_W)) match (.window(window_right), .row_valid(row_valid), .col_valid(col_valid), .rank(code_right));
      end else begin : census
        fpstereo_census #(.N(N)) base (.window(window_left), .row_valid(row_valid), .col_valid(col_valid), .code(code_left));
        fpstereo_census #(.N(N)) match (.window(window_right), .row_valid(row_valid), .col_valid(col_valid), .code(code_right));
      end
      always @(posedge clk)
        if (shift) begin
          code_base_t  <= code_left;
          code_match_t <= code_right;
        end
    end
  endgenerate

  // Match history and cost lanes of the chosen cost function. Each branch sets history_x /
  // history_y: the centre whose costs the lanes compute in this slot.
  reg  [X_W-1:0] history_x;
  reg  signed [YS_W-1:0] history_y;
  reg  [COST_K_W-1:0] history_slot;
  wire [UF*COST_W-1:0] costs;
  generate
    if (COST_KIND <= 1) begin : point_cost
      // Census or rank: one code per pixel.
      reg [CODE_W-1:0] code_base_h;
      always @(posedge clk)
        if (shift) begin
          code_base_h    <= code_base_t;
          history_x      <= transform_x;
          history_y      <= transform_y;
          history_slot   <= transform_slot;
        end
      wire [UF*CODE_W-1:0] match_lanes;
      fpstereo_match_ring #(.COLUMN_W(CODE_W), .SPAN(1), .DMAX(DMAX), .UF(UF)) match_history (
        .clk(clk), .en(adv), .slot_end(slot_end), .column_in(code_match_t), .view(match_lanes));
      fpstereo_cost_lanes #(.KIND(COST_KIND), .CODE_W(CODE_W), .UF(UF), .COST_W(COST_W), .COST_MAX(COST_MAX),
                            .GROUP_W(G_W), .X_W(X_W)) lanes (
        .clk(clk), .en(adv), .base_code(code_base_h), .match_codes(match_lanes), .group(gi),
        .x(history_x), .costs(costs));

    end else if (COST_KIND <= 3) begin : pixel_window_cost
      // SAD or ZSAD: the zero-extended base window, and the match window's newest column, which
      // enters the match ring (plus, for ZSAD, the base window's mean and the column's sum). The
      // ring serves later centres too, so the column is zero-extended by its own position.
      wire [N*N*8-1:0] base_masked;
      fpstereo_window_mask #(.N(N), .WORD_W(8)) base_mask (
        .window(window_left), .row_valid(row_valid), .col_valid(col_valid), .masked(base_masked));
      reg [N*8-1:0]      newest_column;
      reg [COLSUM_W-1:0] newest_sum;
      reg [COLSUM_W+7:0] base_sum;
      integer e;
      always @* begin
        newest_sum = 0;
        base_sum = 0;
        for (e = 0; e < N; e = e + 1) begin
          newest_column[e*8 +: 8] = newest_row_valid[e] ? window_right[(e*N + N - 1)*8 +: 8] : 8'd0;
          newest_sum = newest_sum + {{(COLSUM_W-8){1'b0}}, newest_column[e*8 +: 8]};
        end
        for (e = 0; e < N * N; e = e + 1) base_sum = base_sum + {{COLSUM_W{1'b0}}, base_masked[e*8 +: 8]};
      end
      /* verilator lint_off WIDTH */  // constant multiply and shift, cut to the 8-bit mean
      wire [7:0] base_mean = (base_sum * MEAN_MUL) >> MEAN_SHIFT;
      /* verilator lint_on WIDTH */
      reg [N*N*8-1:0]    base_t, base_h;
      reg [N*8-1:0]      column_t;
      reg [COLSUM_W-1:0] column_sum_t;
      reg [7:0]          base_mean_t, base_mean_h;
      always @(posedge clk)
        if (shift) begin
          history_slot <= transform_slot;
          base_t       <= base_masked;
          column_t     <= newest_column;
          column_sum_t <= newest_sum;
          base_mean_t  <= base_mean;
          base_h       <= base_t;
          base_mean_h  <= base_mean_t;
          history_x    <= transform_x;
          history_y    <= transform_y;
        end
      wire [(UF+N-1)*N*8-1:0]    view;
      wire [(UF+N-1)*COLSUM_W-1:0] view_sums;
      fpstereo_match_ring #(.COLUMN_W(N*8), .SPAN(N), .DMAX(DMAX), .UF(UF)) match_history (
        .clk(clk), .en(adv), .slot_end(slot_end), .column_in(column_t), .view(view));
      fpstereo_match_ring #(.COLUMN_W(COLSUM_W), .SPAN(N), .DMAX(DMAX), .UF(UF)) match_sums (
        .clk(clk), .en(adv), .slot_end(slot_end), .column_in(column_sum_t), .view(view_sums));
      fpstereo_window_cost_lanes #(.KIND(COST_KIND - 2), .ELEM_W(8), .SPAN(N), .UF(UF), .COST_W(COST_W),
                                   .COST_MAX(COST_MAX), .GROUP_W(G_W), .X_W(X_W), .COLSUM_W(COLSUM_W),
                                   .MEAN_MUL(MEAN_MUL), .MEAN_SHIFT(MEAN_SHIFT)) lanes (
        .clk(clk), .en(adv), .base(base_h), .base_mean(base_mean_h), .view(view), .view_sums(view_sums),
        .group(gi), .x(history_x), .width(frame_width), .costs(costs));

    end else begin : code_window_cost
      // SHD: census codes, then a SHD_K x SHD_K window of codes (zero outside the image) whose
      // newest match column enters the match ring.
      localparam RS = SHD_K / 2;
      localparam signed [YS_W-1:0] RS_Y = RS;
      // The code windows take in code_base_t / code_match_t, at column transform_x.
      wire [X_W-1:0] code_next_col = (transform_x == LAST_SLOT) ? {X_W{1'b0}} : transform_x + 1'b1;
      wire [SHD_K*SHD_K*CODE_W-1:0] codes_left, codes_right;
      fpstereo_window #(.N(SHD_K), .WORD_W(CODE_W), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) base_codes (
        .clk(clk), .shift(shift), .col(transform_x), .next_col(code_next_col), .word(code_base_t), .window(codes_left));
      fpstereo_window #(.N(SHD_K), .WORD_W(CODE_W), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) match_codes (
        .clk(clk), .shift(shift), .col(transform_x), .next_col(code_next_col), .word(code_match_t), .window(codes_right));
      // Centre of the code window: RS rows and RS slots behind the entering code; the newest
      // column is the entering code's own column (zero outside the image, as for SAD).
      wire [X_W-1:0] codes_centre_x;
      wire signed [YS_W-1:0] codes_centre_y;
      wire [COST_K_W-1:0] codes_slot_next;
      fpstereo_window_centre #(.LAG(RS), .ROW_SLOTS(ROW_SLOTS), .X_W(X_W), .YS_W(YS_W), .ROWS(COST_ROWS),
                               .SLOT_W(COST_K_W)) codes_centre (
        .x(transform_x), .y(transform_y), .slot(transform_slot), .centre_x(codes_centre_x),
        .centre_y(codes_centre_y), .centre_slot(codes_slot_next));
      reg [X_W-1:0] codes_x;
      reg signed [YS_W-1:0] codes_y;
      reg [COST_K_W-1:0] codes_slot;
      reg code_newest_in_row;
      reg signed [YS_W-1:0] code_newest_y;
      always @(posedge clk)
        if (shift) begin
          code_newest_in_row <= {1'b0, transform_x} < width_x;
          code_newest_y <= transform_y - RS_Y;
          codes_x <= codes_centre_x;
          codes_y <= codes_centre_y;
          codes_slot <= codes_slot_next;
        end
      wire [SHD_K-1:0] code_row_valid, code_col_valid, code_newest_rows;
      /* verilator lint_off UNUSEDSIGNAL */  // the newest column's own column bound is code_newest_in_row
      wire [SHD_K-1:0] code_newest_unused_columns;
      /* verilator lint_on UNUSEDSIGNAL */
      fpstereo_window_bounds #(.SIDE(SHD_K), .X_W(X_W), .YS_W(YS_W)) code_bounds (
        .x(codes_x), .y(codes_y), .width(width_x), .height(height_y), .row_valid(code_row_valid), .col_valid(code_col_valid));
      fpstereo_window_bounds #(.SIDE(SHD_K), .X_W(X_W), .YS_W(YS_W)) code_newest_bounds (
        .x(codes_x), .y(code_newest_y), .width(width_x), .height(height_y), .row_valid(code_newest_rows), .col_valid(code_newest_unused_columns));
      wire [SHD_K-1:0] code_newest_row_valid = code_newest_in_row ? code_newest_rows : {SHD_K{1'b0}};
      wire [SHD_K*SHD_K*CODE_W-1:0] base_masked;
      fpstereo_window_mask #(.N(SHD_K), .WORD_W(CODE_W)) base_mask (
        .window(codes_left), .row_valid(code_row_valid), .col_valid(code_col_valid), .masked(base_masked));
      reg [SHD_K*CODE_W-1:0] newest_column;
      integer e;
      always @*
        for (e = 0; e < SHD_K; e = e + 1)
          newest_column[e*CODE_W +: CODE_W] = code_newest_row_valid[e] ? codes_right[(e*SHD_K + SHD_K - 1)*CODE_W +: CODE_W]
                                                                        : {CODE_W{1'b0}};
      reg [SHD_K*SHD_K*CODE_W-1:0] base_h;
      always @(posedge clk)
        if (shift) begin
          base_h       <= base_masked;
          history_x    <= codes_x;
          history_y    <= codes_y;
          history_slot <= codes_slot;
        end
      wire [(UF+SHD_K-1)*SHD_K*CODE_W-1:0] view;
      fpstereo_match_ring #(.COLUMN_W(SHD_K*CODE_W), .SPAN(SHD_K), .DMAX(DMAX), .UF(UF)) match_history (
        .clk(clk), .en(adv), .slot_end(slot_end), .column_in(newest_column), .view(view));
      fpstereo_window_cost_lanes #(.KIND(2), .ELEM_W(CODE_W), .SPAN(SHD_K), .UF(UF), .COST_W(COST_W),
                                   .COST_MAX(COST_MAX), .GROUP_W(G_W), .X_W(X_W), .COLSUM_W(COLSUM_W)) lanes (
        .clk(clk), .en(adv), .base(base_h), .base_mean(8'd0), .view(view), .view_sums({(UF+SHD_K-1)*COLSUM_W{1'b0}}),
        .group(gi), .x(history_x), .width(frame_width), .costs(costs));
    end
  endgenerate
  wire history_valid = {1'b0, history_x} < width_x && history_y >= 0 && history_y < height_y;

  // ------------------------------------------------------------------------------------------
  // From here on, RAM addresses are products of narrow unsigned counters and constants; they
  // zero-extend and are cut to the address widths (sized from the RAM depths), which Verilator's
  // WIDTH lint reports. The bit-exact test benches check every address path.
  // verilator lint_off WIDTH

  // The cost word's position, delayed as long as the cost lanes take. Rows outside the image
  // are never written, so only valid rows' slots (row mod K) matter.
  wire [X_W-1:0] history_x_cut = history_x;
  wire           cost_valid;
  wire [X_W-1:0] cost_x;
  wire [COST_K_W-1:0] cost_row_slot;
  wire [G_W-1:0] cost_group;
  fpstereo_delay #(.WIDTH(1 + X_W + COST_K_W + G_W), .DEPTH(COST_LAT)) cost_tag (
    .clk(clk), .rst(restart), .en(adv), .in({history_valid, history_x_cut, history_slot, gi}),
    .out({cost_valid, cost_x, cost_row_slot, cost_group}));

  // Cost reorder RAM: K rows, written in raster order, read in chain order.
  wire [COST_AW-1:0] cost_waddr = (cost_row_slot * ROW_SLOTS + cost_x) * G + cost_group;
  wire [COST_AW-1:0] cost_raddr;
  wire [UF*COST_W-1:0] cost_q;
  fpstereo_ram_sdp #(.WIDTH(UF*COST_W), .DEPTH(COST_DEPTH), .ADDR_W(COST_AW)) cost_ram (
    .clk(clk), .we(adv && cost_valid), .waddr(cost_waddr), .wdata(costs),
    .re(adv), .raddr(cost_raddr), .rdata(cost_q));

  // ------------------------------------------------------------------------------------------
  // Aggregation in K interleaved chains (fpstereo_aggregator), from step AGG_START.
  wire agg_on = step >= AGG_START;
  wire [UF*SUM_W-1:0] sum4;
  wire                active4;
  wire [X_W-1:0]      x4;
  wire [G_W-1:0]      group4;
  wire [K_W-1:0]      chain4;
  wire [OUT_K_W-1:0]  slot4;
  fpstereo_aggregator #(.W(W), .ROW_SLOTS(ROW_SLOTS), .K(K), .SLEN(SLEN), .G(G), .UF(UF), .COST_W(COST_W),
                        .COST_MAX(COST_MAX), .PATH_W(PATH_W), .SUM_W(SUM_W), .PATHS(PATHS),
                        .MATCH_SIDE(0), .LEVELS_PER_STAGE(LEVELS_PER_STAGE), .PATH_TREE_LAT(PATH_TREE_LAT),
                        .OUT_ROWS(OUT_ROWS), .OUT_K_W(OUT_K_W), .COST_AW(COST_AW), .X_W(X_W), .Y_W(Y_W), .G_W(G_W),
                        .K_W(K_W), .COST_ROWS(COST_ROWS), .COST_K_W(COST_K_W)) aggregation (
    .clk(clk), .restart(restart), .adv(adv), .width(frame_width), .height(frame_height), .p1(p1), .p2(p2),
    .agg_on(agg_on), .cost_raddr(cost_raddr), .cost_q(cost_q),
    .sum4(sum4), .active4(active4), .x4(x4), .group4(group4), .chain4(chain4), .slot4(slot4));
  // What the stages after the sums need of a pixel's position.
  localparam TAG_W = 1 + X_W + G_W + K_W + OUT_K_W;
  wire [TAG_W-1:0] tag4 = {active4, x4, group4, chain4, slot4};
  `define FPS_TAG_ACTIVE(t) t[TAG_W-1]
  `define FPS_TAG_X(t)      t[TAG_W-2 -: X_W]
  `define FPS_TAG_GROUP(t)  t[G_W+K_W+OUT_K_W-1 -: G_W]
  `define FPS_TAG_CHAIN(t)  t[K_W+OUT_K_W-1 -: K_W]
  `define FPS_TAG_SLOT(t)   t[OUT_K_W-1:0]

  // ------------------------------------------------------------------------------------------
  // Winner-take-all: minimum over the lanes, then over the groups (the earlier group wins ties);
  // with uniqueness, the summaries of fpstereo_unique_tree instead (semantics section 4).
  wire [TAG_W-1:0] tag_w;
  fpstereo_delay #(.WIDTH(TAG_W), .DEPTH(WTA_TREE_LAT)) tag_to_wta (.clk(clk), .rst(restart), .en(adv), .in(tag4), .out(tag_w));
  wire [G_W-1:0] g_w = `FPS_TAG_GROUP(tag_w);
  wire [DISP_W:0] word_w;  // the pixel's word, invalid flag on top, in its last group's step
  generate
    if (UNIQUENESS == 0) begin : plain_wta
      wire [SUM_W-1:0]  group_min;
      wire [LANE_W-1:0] group_lane;
      fpstereo_min_tree #(.N(UF), .W(SUM_W), .IDX_W(LANE_W), .LEVELS_PER_STAGE(LEVELS_PER_STAGE)) tree (
        .clk(clk), .en(adv), .values(sum4), .min_value(group_min), .min_index(group_lane));
      wire [DISP_W-1:0] group_disparity = g_w * UF + group_lane;
      reg  [SUM_W-1:0]  best_sum;
      reg  [DISP_W-1:0] best_disparity;
      wire take_group = g_w == 0 || group_min < best_sum;
      always @(posedge clk)
        if (adv && take_group) begin
          best_sum <= group_min;
          best_disparity <= group_disparity;
        end
      assign word_w = {1'b0, take_group ? group_disparity : best_disparity};
    end else begin : unique_wta
      localparam S_W = 5 * SUM_W + DISP_W + 2;
      wire [SUM_W-1:0]  best, all, but_first, but_last, second;
      wire [LANE_W-1:0] lane;
      wire              first, last;
      fpstereo_unique_tree #(.N(UF), .W(SUM_W), .IDX_W(LANE_W), .LEVELS_PER_STAGE(LEVELS_PER_STAGE)) tree (
        .clk(clk), .en(adv), .values(sum4), .best(best), .index(lane), .first(first), .last(last), .all(all),
        .but_first(but_first), .but_last(but_last), .second(second));
      wire [DISP_W-1:0] group_disparity = g_w * UF + lane;
      wire [S_W-1:0] group_summary = {best, all, but_first, but_last, second, group_disparity, first, last};
      reg  [S_W-1:0] running;  // groups 0 .. g_w - 1
      wire [S_W-1:0] joined;
      fpstereo_unique_join #(.W(SUM_W), .IDX_W(DISP_W)) join_groups (.a(running), .b(group_summary), .joined(joined));
      wire [S_W-1:0] total = g_w == 0 ? group_summary : joined;
      always @(posedge clk)
        if (adv) running <= total;
      wire [SUM_W-1:0]  s1 = total[S_W-1 -: SUM_W];
      wire [SUM_W-1:0]  s2 = total[S_W-4*SUM_W-1 -: SUM_W];
      wire [DISP_W-1:0] winner = total[DISP_W+1:2];
      // Invalid iff S2 * (100 - u) < S1 * 100: one integer comparison, no division (u = 0 never
      // invalidates: S2 >= S1).
      wire [7:0] keep = 8'd100 - {1'b0, uniqueness};
      wire [SUM_W+7:0] scaled_second = s2 * keep;
      wire [SUM_W+7:0] scaled_best = s1 * 8'd100;
      assign word_w = (scaled_second < scaled_best) ? INVALID_WORD : {1'b0, winner};
    end
  endgenerate

  // ------------------------------------------------------------------------------------------
  // Disparity reorder RAM (K rows) and output in raster order.
  wire [DISP_AW-1:0] disp_waddr = `FPS_TAG_SLOT(tag_w) * ROW_SLOTS + `FPS_TAG_X(tag_w);
  wire disp_write = adv && `FPS_TAG_ACTIVE(tag_w) && g_w == LAST_GROUP;

  wire out_on = step >= OUT_START;
  /* verilator lint_off UNUSEDSIGNAL */  // out_slot_end says what the output needs of the group
  wire [G_W-1:0] go;
  /* verilator lint_on UNUSEDSIGNAL */
  wire [X_W-1:0] so;
  wire [Y_W-1:0] to;
  wire [OUT_K_W-1:0] to_slot;  // to mod OUT_ROWS
  wire out_slot_end;
  fpstereo_raster_counter #(.G(G), .ROW_SLOTS(ROW_SLOTS), .K(OUT_ROWS), .G_W(G_W), .X_W(X_W), .Y_W(Y_W),
                            .K_W(OUT_K_W))
    output_position (.clk(clk), .restart(restart), .en(adv && out_on), .group(go), .slot(so), .row(to),
                     .row_slot(to_slot), .slot_end(out_slot_end));
  // One read per slot, in raster order; rows below the image (the median's last rows need
  // them) and bubble slots read as invalid words. Gap interpolation, one row behind, needs one
  // more row of events.
  wire [Y_W-1:0] event_rows = frame_height + GAP;
  wire read_slot = out_on && out_slot_end;
  wire read_event = read_slot && so < frame_width && to < event_rows;
  wire read_valid = read_event && to < frame_height;
  wire [DISP_W:0] disparity_q;
  fpstereo_ram_sdp #(.WIDTH(DISP_W + 1), .DEPTH(DISP_DEPTH), .ADDR_W(DISP_AW)) disp_ram (
    .clk(clk), .we(disp_write), .waddr(disp_waddr), .wdata(word_w),
    .re(adv && read_valid), .raddr(to_slot * ROW_SLOTS + so), .rdata(disparity_q));
  reg               read_done, read_was_event, read_was_valid;
  reg [X_W-1:0]     read_x;
  reg [Y_W-1:0]     read_y;
  /* verilator lint_off UNUSEDSIGNAL */  // the left-right check reads with it
  reg [OUT_K_W-1:0] read_slot_row;
  /* verilator lint_on UNUSEDSIGNAL */
  always @(posedge clk)
    if (restart) begin
      read_done <= 1'b0;
      read_was_event <= 1'b0;
      read_was_valid <= 1'b0;
    end else if (adv) begin
      read_done <= read_slot;
      read_was_event <= read_event;
      read_was_valid <= read_valid;
      read_x <= so;
      read_y <= to;
      read_slot_row <= to_slot;
    end
  wire [DISP_W:0] read_word = read_was_valid ? disparity_q : INVALID_WORD;

  // Left-right check (semantics section 5): the stream after it, one step later with LR1.
  /* verilator lint_off UNUSEDSIGNAL */  // the median uses the slot steps, the plain output the events
  wire            checked_done, checked_event;
  /* verilator lint_on UNUSEDSIGNAL */
  wire [X_W-1:0]  checked_x;
  wire [Y_W-1:0]  checked_y;
  wire [DISP_W:0] checked_word;
  generate
    if (LR == 0) begin : no_lr
      assign checked_done = read_done;
      assign checked_event = read_was_event;
      assign checked_x = read_x;
      assign checked_y = read_y;
      assign checked_word = read_word;
    end else begin : lr
      // The match side writes Dm(x') into the completed RAM (and, for LR1, the row-end RAM).
      localparam END_AW = $clog2(OUT_ROWS * G);
      wire                 completed_we, end_we;
      wire [DISP_AW-1:0]   completed_waddr;
      wire [DISP_W-1:0]    completed_wdata;
      wire [END_AW-1:0]    end_waddr;
      wire [UF*DISP_W-1:0] end_wdata;
      if (LR == 1) begin : lr1
        // Dm(x') = argmin_d S(x' + d, d) from the base side's sums. Each chain keeps, for the
        // match pixels x - e (e < DMAX) of its current pixel x, the best (sum, disparity) over
        // d <= e so far; the next pixel shifts them by one and offers its own S(x + 1, e + 1),
        // smaller d winning ties. At e = DMAX - 1 a match pixel is complete; at the row's end the
        // rest are (row-end RAM). The state follows the chains like the path costs do.
        localparam E_W = SUM_W + DISP_W;
        wire [STATE_AW-1:0] entry_addr = chain4 * G + group4;
        wire [UF*E_W-1:0]   previous, updated;
        /* verilator lint_off UNUSEDSIGNAL */  // one read port is enough here
        wire [UF*E_W-1:0]   previous_unused;
        /* verilator lint_on UNUSEDSIGNAL */
        fpstereo_ram_async #(.WIDTH(UF*E_W), .DEPTH(STATE_DEPTH), .ADDR_W(STATE_AW)) entries (
          .clk(clk), .we(adv && active4), .waddr(entry_addr), .wdata(updated),
          .raddr_a(entry_addr), .rdata_a(previous), .raddr_b(entry_addr), .rdata_b(previous_unused));
        reg [E_W-1:0] below_q;  // the previous group's last entry, before this pixel overwrote it
        always @(posedge clk)
          if (adv) below_q <= previous[UF*E_W-1 -: E_W];
        genvar l2;
        for (l2 = 0; l2 < UF; l2 = l2 + 1) begin : lane
          wire [DISP_W-1:0] disparity = group4 * UF + l2;
          wire [E_W-1:0]    earlier = (l2 == 0) ? below_q : previous[(l2-1)*E_W +: E_W];
          wire [SUM_W-1:0]  offered = sum4[l2*SUM_W +: SUM_W];
          wire              take = disparity == 0 || offered < earlier[E_W-1 -: SUM_W];
          assign updated[l2*E_W +: E_W] = take ? {offered, disparity} : earlier;
          assign end_wdata[l2*DISP_W +: DISP_W] = updated[l2*E_W +: DISP_W];
        end
        assign completed_we = adv && active4 && group4 == LAST_GROUP && x4 >= DMAX - 1;
        assign completed_waddr = slot4 * ROW_SLOTS + (x4 - (DMAX - 1));
        assign completed_wdata = updated[(UF-1)*E_W +: DISP_W];
        assign end_we = adv && active4 && x4 == frame_width - 1;
        assign end_waddr = slot4 * G + group4;
      end else begin : lr2
        // A second cost volume and aggregation with the images' roles swapped. Every cost is
        // symmetric, so the match side's C(x', d) is the base side's C(x' + d, d): lane l of each
        // base cost word goes to its own RAM bank at match pixel x - d, and a word of the match
        // side reads all banks at one address.
        wire [UF*COST_W-1:0] match_costs;
        wire [COST_AW-1:0]   match_raddr;
        genvar l3;
        for (l3 = 0; l3 < UF; l3 = l3 + 1) begin : bank
          wire [DISP_W-1:0] disparity = cost_group * UF + l3;
          fpstereo_ram_sdp #(.WIDTH(COST_W), .DEPTH(COST_DEPTH), .ADDR_W(COST_AW)) costs_of_lane (
            .clk(clk), .we(adv && cost_valid && cost_x >= disparity),
            .waddr((cost_row_slot * ROW_SLOTS + (cost_x - disparity)) * G + cost_group),
            .wdata(costs[l3*COST_W +: COST_W]), .re(adv), .raddr(match_raddr),
            .rdata(match_costs[l3*COST_W +: COST_W]));
        end
        wire [UF*SUM_W-1:0] match_sum4;
        wire                match_active4;
        wire [X_W-1:0]      match_x4;
        wire [G_W-1:0]      match_group4;
        /* verilator lint_off UNUSEDSIGNAL */  // the match side needs no chain state after the sums
        wire [K_W-1:0]      match_chain4;
        /* verilator lint_on UNUSEDSIGNAL */
        wire [OUT_K_W-1:0]  match_slot4;
        fpstereo_aggregator #(.W(W), .ROW_SLOTS(ROW_SLOTS), .K(K), .SLEN(SLEN), .G(G), .UF(UF),
                              .COST_W(COST_W), .COST_MAX(COST_MAX), .PATH_W(PATH_W), .SUM_W(SUM_W),
                              .PATHS(PATHS), .MATCH_SIDE(1), .LEVELS_PER_STAGE(LEVELS_PER_STAGE),
                              .PATH_TREE_LAT(PATH_TREE_LAT), .OUT_ROWS(OUT_ROWS), .OUT_K_W(OUT_K_W),
                              .COST_AW(COST_AW), .X_W(X_W), .Y_W(Y_W), .G_W(G_W), .K_W(K_W),
                              .COST_ROWS(COST_ROWS), .COST_K_W(COST_K_W)) match_aggregation (
          .clk(clk), .restart(restart), .adv(adv), .width(frame_width), .height(frame_height), .p1(p1),
          .p2(p2), .agg_on(step >= MATCH_START), .cost_raddr(match_raddr),
          .cost_q(match_costs), .sum4(match_sum4), .active4(match_active4), .x4(match_x4),
          .group4(match_group4), .chain4(match_chain4), .slot4(match_slot4));
        // Winner-take-all of the match side (no uniqueness).
        wire [SUM_W-1:0]  group_min;
        wire [LANE_W-1:0] group_lane;
        fpstereo_min_tree #(.N(UF), .W(SUM_W), .IDX_W(LANE_W), .LEVELS_PER_STAGE(LEVELS_PER_STAGE)) tree (
          .clk(clk), .en(adv), .values(match_sum4), .min_value(group_min), .min_index(group_lane));
        wire              active_w;
        wire [X_W-1:0]    x_w;
        wire [G_W-1:0]    group_w;
        wire [OUT_K_W-1:0] slot_w;
        fpstereo_delay #(.WIDTH(1 + X_W + G_W + OUT_K_W), .DEPTH(WTA_TREE_LAT)) tag_to_wta (
          .clk(clk), .rst(restart), .en(adv), .in({match_active4, match_x4, match_group4, match_slot4}),
          .out({active_w, x_w, group_w, slot_w}));
        wire [DISP_W-1:0] group_disparity = group_w * UF + group_lane;
        reg  [SUM_W-1:0]  best_sum;
        reg  [DISP_W-1:0] best_disparity;
        wire take_group = group_w == 0 || group_min < best_sum;
        always @(posedge clk)
          if (adv && take_group) begin
            best_sum <= group_min;
            best_disparity <= group_disparity;
          end
        assign completed_we = adv && active_w && group_w == LAST_GROUP;
        assign completed_waddr = slot_w * ROW_SLOTS + x_w;
        assign completed_wdata = take_group ? group_disparity : best_disparity;
        assign end_we = 1'b0;
        assign end_waddr = {END_AW{1'b0}};
        assign end_wdata = {UF*DISP_W{1'b0}};
      end

      // Dm(x') of x' = x - D, from the completed match pixels or, for LR1's last DMAX - 1 of the
      // row, from the row-end RAM; then the check.
      wire [DISP_W-1:0] d = read_word[DISP_W-1:0];
      wire outside = read_word[DISP_W] || read_x < d;
      wire [X_W-1:0] xm = read_x - d;
      wire from_row_end = LR == 1 && xm > frame_width - DMAX;
      wire [DISP_W-1:0] from_end = frame_width - 1 - xm;  // the row-end entry of x'
      wire [DISP_W-1:0] match_q;
      wire [UF*DISP_W-1:0] end_q;
      fpstereo_ram_sdp #(.WIDTH(DISP_W), .DEPTH(DISP_DEPTH), .ADDR_W(DISP_AW)) completed (
        .clk(clk), .we(completed_we), .waddr(completed_waddr), .wdata(completed_wdata),
        .re(adv), .raddr(read_slot_row * ROW_SLOTS + xm), .rdata(match_q));
      fpstereo_ram_sdp #(.WIDTH(UF*DISP_W), .DEPTH(OUT_ROWS * G), .ADDR_W(END_AW)) row_end (
        .clk(clk), .we(end_we), .waddr(end_waddr), .wdata(end_wdata),
        .re(adv), .raddr(read_slot_row * G + from_end / UF), .rdata(end_q));
      reg               done_c, event_c, outside_c, from_row_end_c;
      reg [X_W-1:0]     x_c;
      reg [Y_W-1:0]     y_c;
      reg [DISP_W:0]    word_c;
      reg [LANE_W-1:0]  lane_c;
      always @(posedge clk)
        if (restart) begin
          done_c <= 1'b0;
          event_c <= 1'b0;
        end else if (adv) begin
          done_c <= read_done;
          event_c <= read_was_event;
          x_c <= read_x;
          y_c <= read_y;
          word_c <= read_word;
          outside_c <= outside;
          from_row_end_c <= from_row_end;
          lane_c <= from_end % UF;
        end
      wire [DISP_W-1:0] dm = from_row_end_c ? end_q[lane_c * DISP_W +: DISP_W] : match_q;
      wire [DISP_W-1:0] db = word_c[DISP_W-1:0];
      wire [DISP_W-1:0] difference = db > dm ? db - dm : dm - db;
      assign checked_done = done_c;
      assign checked_event = event_c;
      assign checked_x = x_c;
      assign checked_y = y_c;
      assign checked_word = (outside_c || difference > lr_threshold) ? INVALID_WORD : word_c;
    end
  endgenerate

  // Optional median filter (semantics section 6): the stream of words before gap interpolation.
  wire            pre_pending;  // a register in both branches
  wire [X_W-1:0]  pre_x;
  wire [Y_W-1:0]  pre_y;
  wire [DISP_W:0] final_word;
  generate
    if (MEDIAN == 0) begin : no_median
      assign pre_pending = checked_event;
      assign pre_x = checked_x;
      assign pre_y = checked_y;
      assign final_word = checked_word;
    end else begin : median
      // The word read in the previous slot enters an M x M window; its centre is RM rows and
      // RM slots behind.
      localparam RM = MEDIAN / 2;
      wire median_shift = adv && checked_done;  // a slot's word (or the invalid word outside the image)
      wire [X_W-1:0] median_next_col = (checked_x == LAST_SLOT) ? {X_W{1'b0}} : checked_x + 1'b1;
      wire [MEDIAN*MEDIAN*(DISP_W+1)-1:0] window;
      fpstereo_window #(.N(MEDIAN), .WORD_W(DISP_W + 1), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) line_window (
        .clk(clk), .shift(median_shift), .col(checked_x), .next_col(median_next_col), .word(checked_word),
        .window(window));
      wire [X_W-1:0] centre_x_m;
      wire signed [YS_W-1:0] centre_y_m;
      /* verilator lint_off UNUSEDSIGNAL */  // the median needs no RAM slot
      wire centre_slot_m;
      /* verilator lint_on UNUSEDSIGNAL */
      fpstereo_window_centre #(.LAG(RM), .ROW_SLOTS(ROW_SLOTS), .X_W(X_W), .YS_W(YS_W), .ROWS(1), .SLOT_W(1)) centre_m (
        .x(checked_x), .y($signed({2'b00, checked_y})), .slot(1'b0), .centre_x(centre_x_m), .centre_y(centre_y_m),
        .centre_slot(centre_slot_m));
      reg [X_W-1:0] median_x;
      reg signed [YS_W-1:0] median_y;
      reg           fresh;     // high in the step after a shift: one result per slot
      always @(posedge clk)
        if (restart) fresh <= 1'b0;
        else if (adv) fresh <= checked_done;
      always @(posedge clk)
        if (median_shift) begin
          median_x <= centre_x_m;
          median_y <= centre_y_m;
        end
      wire [MEDIAN-1:0] row_valid_m, col_valid_m;
      fpstereo_window_bounds #(.SIDE(MEDIAN), .X_W(X_W), .YS_W(YS_W)) bounds_m (
        .x(median_x), .y(median_y), .width(width_x), .height(height_y), .row_valid(row_valid_m), .col_valid(col_valid_m));
      fpstereo_median_select #(.M(MEDIAN), .WORD_W(DISP_W + 1)) select (
        .clk(clk), .en(adv), .window(window), .row_valid(row_valid_m), .col_valid(col_valid_m),
        .median(final_word));
      // The centre's coordinates travel as long as the selection takes.
      wire signed [YS_W-1:0] event_rows_y = height_y + GAP;
      wire in_image = {1'b0, median_x} < width_x && median_y >= 0 && median_y < event_rows_y;
      /* verilator lint_off UNUSEDSIGNAL */  // the top bits are 0 whenever in_image
      wire [YS_W-1:0] median_row = median_y;
      /* verilator lint_on UNUSEDSIGNAL */
      wire          done_m;
      wire [X_W-1:0] x_m;
      wire [Y_W-1:0] y_m;
      fpstereo_delay #(.WIDTH(1 + X_W + Y_W), .DEPTH(DISP_W + 1)) median_delay (
        .clk(clk), .rst(restart), .en(adv), .in({fresh && in_image, median_x, median_row[Y_W-1:0]}), .out({done_m, x_m, y_m}));
      reg           pending_q;
      reg [X_W-1:0] x_q;
      reg [Y_W-1:0] y_q;
      always @(posedge clk)
        if (restart) pending_q <= 1'b0;
        else if (adv) begin
          pending_q <= done_m;
          x_q <= x_m;
          y_q <= y_m;
        end
      assign pre_pending = pending_q;
      assign pre_x = x_q;
      assign pre_y = y_q;
    end
  endgenerate
  // After the median, one more register holds the word of the pixel in pre_x / pre_y.
  reg [DISP_W:0] median_word_q;
  always @(posedge clk)
    if (adv) median_word_q <= final_word;
  wire [DISP_W:0] pre_word = MEDIAN == 0 ? checked_word : median_word_q;

  // Optional gap interpolation (semantics section 7), then the output.
  wire            out_pending;  // a register in both branches
  wire [X_W-1:0]  out_x;
  wire [Y_W-1:0]  out_y;
  generate
    if (GAP == 0) begin : no_gap
      assign out_pending = pre_pending;
      assign out_x = pre_x;
      assign out_y = pre_y;
      assign out_word = pre_word;
    end else begin : gap
      fpstereo_gap_fill #(.W(W), .WORD_W(DISP_W + 1), .X_W(X_W), .Y_W(Y_W)) stage (
        .clk(clk), .rst(restart), .en(adv), .width(frame_width), .height(frame_height), .in_event(pre_pending), .in_x(pre_x), .in_y(pre_y), .in_word(pre_word),
        .out_event(out_pending), .out_x(out_x), .out_y(out_y), .out_word(out_word));
    end
  endgenerate
  assign out_due    = out_pending;
  assign out_push   = adv && out_pending;
  assign out_first  = out_x == 0 && out_y == 0;
  assign out_last   = out_x == frame_width - 1;
  assign frame_done = out_pending && out_last && out_y == frame_height - 1;
  assign frame_end  = adv && frame_done;
  // verilator lint_on WIDTH

  `undef FPS_TAG_ACTIVE
  `undef FPS_TAG_X
  `undef FPS_TAG_GROUP
  `undef FPS_TAG_CHAIN
  `undef FPS_TAG_SLOT
endmodule
`resetall
