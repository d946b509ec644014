`resetall
`default_nettype none
// Cost aggregation (docs/architecture.md, docs/semantics.md section 3): reads the cost reorder
// RAM in chain order, runs the enabled paths in K interleaved chains and delivers, per step, the
// path sums of one group of one pixel with the pixel's position. Every register advances when
// adv is high. With MATCH_SIDE the pixels are match-image pixels x' and lanes whose base pixel
// x' + MIN_DISP + d lies outside the row get COST_MAX (docs/semantics.md section 5, LR2). With
// PENALTIES (adaptive P2, the base side), each cost word carries above its costs one P2 per
// enabled path (fpstereo_adaptive_p2), which replaces the p2 input for that path.
// With several pixels per clock (docs/ppc-hardware.md) the row is cut into strips, one
// aggregator each (fpstereo_strip_aggregation wires them): this one's pixels are X_BASE + k * SEGMENT + j, its
// chain k works on row ta - CHAIN_BASE - k, and the edges carry what the strips' first and last
// pixels need from the neighbouring strips (STRIPS != 0, uf = dmax only). With MIRROR it runs the
// 180-degree path (docs/path180-hardware.md): the 0-degree lanes on each row from its end.
module fpstereo_aggregator #(
  // the largest image width (the path rows hold one row of it)
  parameter W = 64,
  parameter ROW_SLOTS = 64,
  parameter K = 2,
  parameter SEGMENT = 32,
  parameter G = 4,
  parameter UF = 8,
  parameter COST_W = 5,
  parameter COST_MAX = 24,
  parameter PATH_W = 7,
  parameter SUM_W = 9,
  // enabled paths: bit 0 = 0 degrees, 1 = 45, 2 = 90, 3 = 135
  parameter PATHS = 15,
  parameter MATCH_SIDE = 0,
  // 0, or the enabled paths: P2 fields of PATH_W bits above the costs of each word
  parameter PENALTIES = 0,
  parameter LEVELS_PER_STAGE = 3,
  parameter PATH_TREE_LAT = 1,
  // rows of the output RAMs (the slot output is the row modulo OUT_ROWS)
  parameter OUT_ROWS = 3,
  parameter OUT_ROW_W = 2,
  parameter COST_AW = 10,
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter G_W = 2,
  parameter K_W = 1,
  // rows of the cost reorder RAM (K, or more) and the bits of a row slot
  parameter COST_ROWS = 2,
  parameter COST_ROW_W = 1,
  // the match side's disparity offset
  parameter MIN_DISP = 0,
  // 1: the RAM holds a pixel's entries, not its cost words (fpstereo_code_reorder): a word per
  // pixel, which fpstereo_chain_cost turns into the cost words
  parameter CODES = 0,
  // steps from cost_raddr to its word on cost_q (1: the RAM's read register; with CODES, the
  // chain cost stage's)
  parameter COST_LEAD = 1,
  // 1: one strip of several; X_BASE its first pixel, CHAIN_BASE the strips' chains to its left
  parameter STRIPS = 0,
  parameter X_BASE = 0,
  parameter CHAIN_BASE = 0,
  // 1: the 180-degree path, PATHS = 1 (the 0-degree lanes), cost words, no strips: chain k's pixel
  // is frame_width - 1 - (k * SEGMENT + j), the path starts at the row's last pixel. With
  // PENALTIES (the number of P2 fields in the word, the base side's, the 0-degree one first) the
  // lanes take the 0-degree P2 of the chain's previous pixel x + 1: the same two intensities.
  parameter MIRROR = 0,
  // 1: each cost word carries, above its P2 fields, the 180-degree path's uf costs of its pixel
  // (the mirrored aggregator's, read beside it), which the sums add.
  parameter RIGHT_TO_LEFT = 0
) (
  input  wire                 clk,
  input  wire                 restart,
  input  wire                 adv,
  // the frame's size and penalties
  input  wire [X_W-1:0]       frame_width,
  input  wire [Y_W-1:0]       frame_height,
  input  wire [PATH_W-1:0]    p1,
  /* verilator lint_off UNUSEDSIGNAL */  // unused where every path's P2 adapts
  input  wire [PATH_W-1:0]    p2,
  /* verilator lint_on UNUSEDSIGNAL */
  // high from the frame's step at which aggregation starts
  input  wire                 agg_on,
  // back-to-back frames (fpstereo_front_end): the row-times wrap after the frame's last row, and
  // once wrapped, the rows above row 0 are the previous frame's
  input  wire                 overlap,
  input  wire                 wrapped,
  output wire [COST_AW-1:0]   cost_raddr,
  // the schedule where cost_raddr is read: {the slot opens a row-time, the pixel's x, the group}
  output wire [X_W+G_W:0]     cost_schedule,
  input  wire [UF*COST_W+PENALTIES*PATH_W+RIGHT_TO_LEFT*UF*PATH_W-1:0] cost_q,
  // the sums of one group of one pixel (S5), and where they belong
  output reg  [UF*SUM_W-1:0]  sums,
  output wire                 sums_active,
  output wire [X_W-1:0]       sums_x,
  output wire [G_W-1:0]       sums_group,
  output wire [K_W-1:0]       sums_chain,
  output wire [OUT_ROW_W-1:0]   sums_slot,
  // With STRIPS: from the strip to the left, what its last pixel leaves for this strip's first
  // {0-degree path costs, their minimum, the 45-degree row above at x - 1, its minimum}, and the
  // same to the right; from the strip to the right, its first pixel's 135-degree path costs and
  // minimum in the row above, and this strip's to the left.
  /* verilator lint_off UNUSEDSIGNAL */  // unused in the first strip and without STRIPS
  input  wire [2*(UF+1)*PATH_W-1:0] edge_in,
  input  wire [(UF+1)*PATH_W-1:0]   edge135_in,
  /* verilator lint_on UNUSEDSIGNAL */
  output wire [2*(UF+1)*PATH_W-1:0] edge_out,
  output wire [(UF+1)*PATH_W-1:0]   edge135_out
);
  localparam LANES_LAT = 2;  // steps of fpstereo_path_lanes
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (K < 1 || SEGMENT < 1 || SEGMENT * K != ROW_SLOTS || (STRIPS == 0 && ROW_SLOTS < W)) begin : invalid_segments
      fpstereo_invalid_parameters_aggregator_ROW_SLOTS_is_not_K_segments_of_SEGMENT_covering_W failed ();
    end
    if ((K - 1) * G < PATH_TREE_LAT + LANES_LAT) begin : invalid_chains
      fpstereo_invalid_parameters_aggregator_K_chains_too_few_for_the_path_minimum_latency failed ();
    end
    if (COST_LEAD < 1 || (CODES != 0 && MATCH_SIDE != 0)) begin : invalid_CODES
      fpstereo_invalid_parameters_aggregator_CODES_only_on_the_base_side failed ();
    end
    if (COST_ROWS < K || OUT_ROWS < K) begin : invalid_rows
      fpstereo_invalid_parameters_aggregator_COST_ROWS_or_OUT_ROWS_below_K failed ();
    end
    if (G - 1 >= (1 << G_W) || K - 1 >= (1 << K_W) || ROW_SLOTS - 1 >= (1 << X_W) || W >= (1 << X_W) || COST_ROWS > (1 << COST_ROW_W) || OUT_ROWS > (1 << OUT_ROW_W) || COST_AW < $clog2(COST_ROWS * ROW_SLOTS * (CODES != 0 ? 1 : G))) begin : invalid_widths
      fpstereo_invalid_parameters_aggregator_counter_or_address_widths_too_narrow failed ();
    end
    if (COST_MAX >= (1 << COST_W) || PATH_W < COST_W || SUM_W < PATH_W) begin : invalid_costs
      fpstereo_invalid_parameters_aggregator_needs_COST_MAX_within_COST_W_and_COST_W_at_most_PATH_W_at_most_SUM_W failed ();
    end
    if (PATHS < 1 || PATHS > 15) begin : invalid_PATHS
      fpstereo_invalid_parameters_aggregator_PATHS_is_not_a_nonempty_subset_of_4 failed ();
    end
    if (PENALTIES != 0 && (MATCH_SIDE != 0 || (MIRROR == 0 && PENALTIES != PATHS % 2 + (PATHS / 2) % 2 + (PATHS / 4) % 2 + (PATHS / 8) % 2))) begin : invalid_PENALTIES
      fpstereo_invalid_parameters_aggregator_PENALTIES_is_not_the_base_sides_number_of_PATHS failed ();
    end
    if (X_BASE < 0 || X_BASE >= W || CHAIN_BASE < 0 || (STRIPS == 0 && X_BASE != 0) || (STRIPS != 0 && G != 1)) begin : invalid_strip
      fpstereo_invalid_parameters_aggregator_strips_need_G_1_and_X_BASE_within_W failed ();
    end
    if (MIRROR != 0 && (PATHS != 1 || STRIPS != 0 || CODES != 0)) begin : invalid_MIRROR
      fpstereo_invalid_parameters_aggregator_MIRROR_needs_PATHS_1_cost_words_and_no_strips failed ();
    end
    if (RIGHT_TO_LEFT != 0 && (MIRROR != 0 || STRIPS != 0 || CODES != 0)) begin : invalid_RIGHT_TO_LEFT
      fpstereo_invalid_parameters_aggregator_RIGHT_TO_LEFT_needs_cost_words_no_strips_and_no_MIRROR failed ();
    end
  endgenerate
  localparam ONES = {PATH_W{1'b1}};
  // the strip's pixels: all W of the row without STRIPS
  localparam STRIP_W = W - X_BASE < ROW_SLOTS ? W - X_BASE : ROW_SLOTS;
  localparam integer X_FIRST_I = X_BASE, X_LAST_I = X_BASE + STRIP_W - 1;
  localparam [X_W-1:0] X_FIRST = X_FIRST_I[X_W-1:0], X_LAST = X_LAST_I[X_W-1:0];
  // the pixel after the strip's last, which the strip to the right has
  localparam integer X_AFTER_I = X_BASE + STRIP_W;
  localparam [X_W-1:0] X_AFTER = X_AFTER_I[X_W-1:0];
  localparam FROM_LEFT = STRIPS != 0 && X_BASE != 0;
  localparam FROM_RIGHT = STRIPS != 0 && X_BASE + STRIP_W < W;
  localparam ROW_DEPTH = (STRIP_W + 1) * G;
  localparam ROW_AW = $clog2(ROW_DEPTH);
  localparam MIN_AW = $clog2(STRIP_W + 1);
  localparam STATE_DEPTH = K * G;
  localparam STATE_AW = STATE_DEPTH > 1 ? $clog2(STATE_DEPTH) : 1;
  localparam LANES_W = UF * PATH_W;
  localparam integer LAST_GROUP_I = G - 1;
  localparam integer LAST_CHAIN_I = K - 1;
  localparam [G_W-1:0] LAST_GROUP = LAST_GROUP_I[G_W-1:0];
  localparam [K_W-1:0] LAST_CHAIN = LAST_CHAIN_I[K_W-1:0];
  localparam integer LAST_SEGMENT_SLOT_I = SEGMENT - 1;
  localparam [X_W-1:0] LAST_SEGMENT_SLOT = LAST_SEGMENT_SLOT_I[X_W-1:0];

  // RAM addresses are products of narrow unsigned counters and constants; they zero-extend and
  // are cut to the address widths (sized from the RAM depths), which Verilator's WIDTH lint
  // reports. The bit-exact test benches check every address path.
  // verilator lint_off WIDTH

  // ------------------------------------------------------------------------------------------
  // Aggregation schedule (S0): row-time ta, slot ja * K + ka, group ga. Chain ka works on row
  // ta - ka, pixel x = ka * SEGMENT + ja; its state lives in slot (ka + base) mod K.
  // The cost RAM's read address is a register (logic depth, docs/timing.md): counters a step
  // ahead (the _a registers, what ga, ka, ja and the row slot become at the next step) feed it,
  // and ga, ka and ja follow them.
  reg [G_W-1:0] ga, ga_a;
  reg [K_W-1:0] ka, ka_a, base;
  reg [OUT_ROW_W-1:0] ta_out_slot;    // ta mod OUT_ROWS
  reg [X_W-1:0] ja, ja_a;
  // the ahead step's (ta - CHAIN_BASE) mod COST_ROWS, and its chain's row slot
  reg [COST_ROW_W-1:0] first_slot_a, row_slot_a;
  wire [Y_W-1:0] ta;
  wire step = adv && agg_on;
  wire row_time_ends = step && ga == LAST_GROUP && ka == LAST_CHAIN && ja == LAST_SEGMENT_SLOT;
  /* verilator lint_off PINCONNECTEMPTY */
  fpstereo_frame_row #(.Y_W(Y_W)) row_time (
    .clk(clk), .restart(restart), .next(row_time_ends), .wrap(overlap), .height(frame_height), .row(ta), .last());
  /* verilator lint_on PINCONNECTEMPTY */
  // The schedule's first two steps (K >= 2): group 0 of chain 0 of slot 0, then group 1 or chain 1.
  localparam integer FIRST_SLOT_I = (COST_ROWS - CHAIN_BASE % COST_ROWS) % COST_ROWS;
  localparam integer SECOND_SLOT_I = G == 1 ? (FIRST_SLOT_I + COST_ROWS - 1) % COST_ROWS : FIRST_SLOT_I;
  localparam [COST_ROW_W-1:0] FIRST_SLOT = FIRST_SLOT_I[COST_ROW_W-1:0];
  localparam [COST_ROW_W-1:0] SECOND_SLOT = SECOND_SLOT_I[COST_ROW_W-1:0];
  localparam [G_W-1:0] SECOND_GROUP = G == 1 ? 0 : 1;
  localparam [K_W-1:0] SECOND_CHAIN = G == 1 ? 1 : 0;
  always @(posedge clk)
    if (restart) begin
      ga <= 0;
      ka <= 0;
      ja <= 0;
      base <= 0;
      ta_out_slot <= 0;
    end else if (step) begin
      ga <= ga_a;
      ka <= ka_a;
      ja <= ja_a;
      if (row_time_ends) begin
        ta_out_slot <= (ta_out_slot == OUT_ROWS - 1) ? {OUT_ROW_W{1'b0}} : ta_out_slot + 1'b1;
        base <= (base == 0) ? LAST_CHAIN : base - 1'b1;
      end
    end
  wire [COST_ROW_W-1:0] next_first_slot_a = first_slot_a == COST_ROWS - 1 ? {COST_ROW_W{1'b0}} : first_slot_a + 1'b1;
  always @(posedge clk)
    if (restart) begin
      ga_a <= SECOND_GROUP;
      ka_a <= SECOND_CHAIN;
      ja_a <= 0;
      first_slot_a <= FIRST_SLOT;
      row_slot_a <= SECOND_SLOT;
    end else if (step) begin
      ga_a <= (ga_a == LAST_GROUP) ? {G_W{1'b0}} : ga_a + 1'b1;
      if (ga_a == LAST_GROUP) begin
        ka_a <= (ka_a == LAST_CHAIN) ? {K_W{1'b0}} : ka_a + 1'b1;
        if (ka_a != LAST_CHAIN) begin
          row_slot_a <= row_slot_a == 0 ? COST_ROWS - 1 : row_slot_a - 1'b1;
        end else begin
          ja_a <= (ja_a == LAST_SEGMENT_SLOT) ? {X_W{1'b0}} : ja_a + 1'b1;
          if (ja_a == LAST_SEGMENT_SLOT) begin
            first_slot_a <= next_first_slot_a;
            row_slot_a <= next_first_slot_a;
          end else begin
            row_slot_a <= first_slot_a;
          end
        end
      end
    end
  // The step's pixel, a register fed like the read address: the chain's slot k * SEGMENT + j from
  // the strip's first pixel, or with MIRROR from the row's last (beyond the frame when the slot
  // is: the difference wraps to frame_width or more, since slots stay below 2^X_W).
  reg [X_W-1:0] x0;
  wire [X_W-1:0] slot_a = ka_a * SEGMENT + ja_a;
  wire [X_W-1:0] last_x = frame_width - 1'b1;
  wire [X_W-1:0] x_a = MIRROR != 0 ? last_x - slot_a : X_FIRST + slot_a;
  always @(posedge clk)
    if (restart) x0 <= MIRROR != 0 ? last_x : X_FIRST;
    else if (step) x0 <= x_a;
  // Chain ka's row is ta - CHAIN_BASE - ka: negative before the first frame's row 0, the previous
  // frame's once wrapped (the difference plus the frame's height).
  wire [Y_W:0]   lagged0 = {1'b0, ta} - CHAIN_BASE - {{(Y_W+1-K_W){1'b0}}, ka};
  // (row-time - CHAIN_BASE - ka) modulo the output RAMs' rows, kept non-negative
  localparam integer OUT_ROWS_UP = CHAIN_BASE == 0 ? OUT_ROWS : ((CHAIN_BASE + K) / OUT_ROWS + 1) * OUT_ROWS;
  wire [OUT_ROW_W-1:0] out_slot0 = (ta_out_slot + OUT_ROWS_UP - CHAIN_BASE - ka) % OUT_ROWS;
  wire [K_W-1:0] chain_slot0 = (ka + base) % K;
  // The RAM's column: the slot, or with MIRROR the pixel (0 where the slot is beyond the frame).
  wire [X_W-1:0] column_a = MIRROR == 0 ? slot_a : slot_a < frame_width ? x_a : {X_W{1'b0}};
  wire [COST_AW-1:0] raddr_a = CODES != 0 ? row_slot_a * ROW_SLOTS + column_a
                                            : (row_slot_a * ROW_SLOTS + column_a) * G + ga_a;
  localparam integer FIRST_RADDR_I = FIRST_SLOT_I * ROW_SLOTS * (CODES != 0 ? 1 : G);
  localparam [COST_AW-1:0] FIRST_RADDR = FIRST_RADDR_I[COST_AW-1:0];
  wire [COST_AW-1:0] first_raddr = MIRROR != 0 ? FIRST_RADDR + last_x * G : FIRST_RADDR;
  reg [COST_AW-1:0] raddr;
  always @(posedge clk)
    if (restart) raddr <= first_raddr;
    else if (step) raddr <= raddr_a;
  assign cost_raddr = raddr;
  assign cost_schedule = {ka == 0 && ja == 0, x0, ga};

  // Tags travel with the data: S0 -> S1 -> S2 (the lanes' inputs) -> S3 -> S4 (path costs)
  // -> S5 (sums). Where the cost word takes COST_LEAD > 1 steps, the tag waits as long before S1.
  localparam TAG_W = 1 + X_W + (Y_W + 1) + G_W + K_W + OUT_ROW_W;
  // With a cost lead the tag is finished in the lead's first step: S0 registers the row's
  // difference with what decides it (the frame's height, whether the rows have wrapped, whether
  // the pixel's column is in the frame), so that no path runs from the counters through the
  // difference, the wrap's sum and the height's compare (logic depth, docs/timing.md).
  localparam ROW_IN_W = 1 + (Y_W + 1) + 1 + Y_W;
  localparam REST_W = X_W + G_W + K_W + OUT_ROW_W;
  wire [ROW_IN_W+REST_W-1:0] tag_parts0 = {agg_on && x0 < frame_width, lagged0, wrapped, frame_height,
                                           x0, ga, chain_slot0, out_slot0};
  wire [ROW_IN_W+REST_W-1:0] tag_parts;
  reg  [TAG_W-1:0] tag1, tag2, tag3, tag4, tag5;
  wire [TAG_W-1:0] tag_first, tag_led;
  generate
    if (COST_LEAD > 1) begin : lead
      fpstereo_delay #(.WIDTH(ROW_IN_W + REST_W), .DEPTH(1), .RESET(1)) tag_start (
        .clk(clk), .rst(restart), .en(adv), .in(tag_parts0), .out(tag_parts));
    end else begin : no_lead
      assign tag_parts = tag_parts0;
    end
  endgenerate
  wire         column_in = tag_parts[ROW_IN_W+REST_W-1];
  wire [Y_W:0] lagged = tag_parts[ROW_IN_W+REST_W-2 -: Y_W+1];
  wire         rows_wrapped = tag_parts[REST_W+Y_W];
  wire [Y_W-1:0] height = tag_parts[REST_W+Y_W-1 -: Y_W];
  // The row, and whether it lies in the frame: a negative difference is the previous frame's row
  // (its sum with the height, always below it) once wrapped, a non-negative one is below the height.
  wire [Y_W:0] wrapped_row = lagged + {1'b0, height};
  wire [Y_W:0] row = rows_wrapped && lagged[Y_W] ? wrapped_row : lagged;
  wire active = column_in && (lagged[Y_W] ? rows_wrapped && !wrapped_row[Y_W] : lagged[Y_W-1:0] < height);
  assign tag_first = {active, tag_parts[REST_W-1 -: X_W], row, tag_parts[G_W+K_W+OUT_ROW_W-1:0]};
  generate
    if (COST_LEAD > 2) begin : lead_rest
      fpstereo_delay #(.WIDTH(TAG_W), .DEPTH(COST_LEAD - 2), .RESET(1)) tag_lead (
        .clk(clk), .rst(restart), .en(adv), .in(tag_first), .out(tag_led));
    end else begin : no_lead_rest
      assign tag_led = tag_first;
    end
  endgenerate
  always @(posedge clk)
    if (restart) begin
      tag1 <= {TAG_W{1'b0}};
      tag2 <= {TAG_W{1'b0}};
      tag3 <= {TAG_W{1'b0}};
      tag4 <= {TAG_W{1'b0}};
      tag5 <= {TAG_W{1'b0}};
    end else if (adv) begin
      tag1 <= tag_led;
      tag2 <= tag1;
      tag3 <= tag2;
      tag4 <= tag3;
      tag5 <= tag4;
    end
  `define FPS_TAG_ACTIVE(t) t[TAG_W-1]
  `define FPS_TAG_X(t)      t[TAG_W-2 -: X_W]
  `define FPS_TAG_ROW(t)    t[G_W+K_W+OUT_ROW_W+Y_W -: Y_W+1]
  `define FPS_TAG_GROUP(t)  t[G_W+K_W+OUT_ROW_W-1 -: G_W]
  `define FPS_TAG_CHAIN(t)  t[K_W+OUT_ROW_W-1 -: K_W]
  `define FPS_TAG_SLOT(t)   t[OUT_ROW_W-1:0]

  // The row RAMs are read in the step before S1 (S0 without a cost lead).
  /* verilator lint_off UNUSEDSIGNAL */  // the 45, 90 and 135 degree paths' row RAMs read them
  wire [X_W-1:0]   x_read = `FPS_TAG_X(tag_led);
  wire [G_W-1:0]   g_read = `FPS_TAG_GROUP(tag_led);
  /* verilator lint_on UNUSEDSIGNAL */
  wire [X_W-1:0]   x2 = `FPS_TAG_X(tag2);
  wire [G_W-1:0]   g2 = `FPS_TAG_GROUP(tag2);
  /* verilator lint_off UNUSEDSIGNAL */  // the 45-degree path's kept minima
  wire [K_W-1:0]   chain2 = `FPS_TAG_CHAIN(tag2);
  /* verilator lint_on UNUSEDSIGNAL */
  // Whether S2's step is its pixel's first or last group, the strip's first pixel, and which of
  // its predecessors lie in the frame: registered from S1's tag, so that the lanes' neighbour
  // selection starts from a register (logic depth, docs/timing.md).
  wire [G_W-1:0]   g1 = `FPS_TAG_GROUP(tag1);
  wire [X_W-1:0]   x1 = `FPS_TAG_X(tag1);
  wire [Y_W:0]     row1 = `FPS_TAG_ROW(tag1);
  reg              first_group2;
  /* verilator lint_off UNUSEDSIGNAL */  // those of the enabled paths
  reg              last_group2;      // the 0 and 45-degree paths' and the mirror's
  reg              first2;           // the strip's first pixel, whose 0 and 45-degree predecessors come from edge_in
  reg              left_in2;         // x2 has a 0-degree predecessor: x2 != 0, with MIRROR x2 != frame_width - 1
  reg              above_in2;        // row2 != 0
  reg  [1:0]       column_in2;       // x2 + dx < frame_width, dx = 0, 1
  /* verilator lint_on UNUSEDSIGNAL */
  always @(posedge clk)
    if (restart) begin
      first_group2 <= 1'b0;
      last_group2 <= 1'b0;
      first2 <= 1'b0;
      left_in2 <= 1'b0;
      above_in2 <= 1'b0;
      column_in2 <= 2'b00;
    end else if (adv) begin
      first_group2 <= g1 == 0;
      last_group2 <= g1 == G - 1;
      first2 <= FROM_LEFT && x1 == X_FIRST;
      left_in2 <= MIRROR != 0 ? x1 != last_x : x1 != 0;
      above_in2 <= row1 != 0;
      column_in2 <= {{1'b0, x1} + 1'b1 < {1'b0, frame_width}, x1 < frame_width};
    end
  /* verilator lint_off UNUSEDSIGNAL */  // the state RAMs of the 0 and 45 degree paths use these
  // The state RAMs' addresses of S2 (the chain's slot, its group and the next group's), registered
  // from S1's tag like the flags above.
  wire [K_W-1:0] chain1 = `FPS_TAG_CHAIN(tag1);
  wire [STATE_AW-1:0] state_addr1 = chain1 * G + g1;
  reg  [STATE_AW-1:0] state_addr2, state_next_addr2;
  always @(posedge clk)
    if (restart) begin
      state_addr2 <= {STATE_AW{1'b0}};
      state_next_addr2 <= G == 1 ? {STATE_AW{1'b0}} : {{(STATE_AW-1){1'b0}}, 1'b1};
    end else if (adv) begin
      state_addr2 <= state_addr1;
      state_next_addr2 <= g1 == G - 1 ? state_addr1 : state_addr1 + 1'b1;
    end
  /* verilator lint_on UNUSEDSIGNAL */

  wire [X_W-1:0]   x4 = `FPS_TAG_X(tag4);
  wire [G_W-1:0]   g4 = `FPS_TAG_GROUP(tag4);
  wire             active4 = `FPS_TAG_ACTIVE(tag4);
  /* verilator lint_off UNUSEDSIGNAL */  // the row RAMs of the 45, 90 and 135 degree paths use it
  wire [ROW_AW-1:0] row_waddr4 = (x4 - X_FIRST) * G + g4;
  /* verilator lint_on UNUSEDSIGNAL */

  // The cost word of the pixel in S2 (read in S0, COST_LEAD steps to cost_q, one here). On the
  // match side, lanes whose base pixel x' + d lies beyond the image cost COST_MAX.
  /* verilator lint_off UNUSEDSIGNAL */  // with MIRROR, the P2 fields but the 0-degree one
  reg  [UF*COST_W+PENALTIES*PATH_W+RIGHT_TO_LEFT*UF*PATH_W-1:0] cost_read2;
  /* verilator lint_on UNUSEDSIGNAL */
  wire [UF*COST_W-1:0] cost2;
  always @(posedge clk)
    if (adv) cost_read2 <= cost_q;
  // Each path's P2 for the pixel in S2: the word's field (paths in order 0, 45, 90, 135), or p2.
  /* verilator lint_off UNUSEDSIGNAL */  // those of the enabled paths
  wire [4*PATH_W-1:0] p2_of;
  /* verilator lint_on UNUSEDSIGNAL */
  genvar f;
  generate
    for (f = 0; f < 4; f = f + 1) begin : penalty
      localparam integer FIELD = (f > 0 ? PATHS % 2 : 0) + (f > 1 ? (PATHS / 2) % 2 : 0) + (f > 2 ? (PATHS / 4) % 2 : 0);
      if (MIRROR != 0 && PENALTIES != 0 && f == 0) begin : of_previous_pixel
        // The 0-degree field of the chain's previous pixel, kept by chain slot at its last group
        // and read in S1 for S2 (the chain's next pixel comes K * G >= 2 steps later).
        reg [PATH_W-1:0] kept [0:K-1];
        reg [PATH_W-1:0] p2_2;
        always @(posedge clk)
          if (adv && last_group2) kept[chain2] <= cost_read2[UF*COST_W +: PATH_W];
        always @(posedge clk)
          if (adv) p2_2 <= kept[chain1];
        assign p2_of[0 +: PATH_W] = p2_2;
      end else if (PENALTIES != 0 && MIRROR == 0 && (PATHS >> f) % 2 != 0) begin : adaptive
        assign p2_of[f*PATH_W +: PATH_W] = cost_read2[UF*COST_W + FIELD*PATH_W +: PATH_W];
      end else begin : constant
        assign p2_of[f*PATH_W +: PATH_W] = p2;
      end
    end
  endgenerate
  /* verilator lint_off UNUSEDSIGNAL */  // those of the enabled paths
  wire [PATH_W-1:0] p2_0 = p2_of[0 +: PATH_W], p2_45 = p2_of[PATH_W +: PATH_W];
  wire [PATH_W-1:0] p2_90 = p2_of[2*PATH_W +: PATH_W], p2_135 = p2_of[3*PATH_W +: PATH_W];
  /* verilator lint_on UNUSEDSIGNAL */
  // base pixel x' + m + d compared as x' + d + BEHIND against the row shifted by AHEAD
  localparam integer BEHIND = MIN_DISP > 0 ? MIN_DISP : 0;
  localparam integer AHEAD = MIN_DISP < 0 ? -MIN_DISP : 0;
  genvar c;
  generate
    for (c = 0; c < UF; c = c + 1) begin : match_border
      wire beyond = MATCH_SIDE != 0 && (x2 + g2 * UF + c + BEHIND > frame_width - 1 + AHEAD ||
                                        (MIN_DISP < 0 && x2 + g2 * UF + c < AHEAD));
      assign cost2[c*COST_W +: COST_W] = beyond ? COST_MAX[COST_W-1:0] : cost_read2[c*COST_W +: COST_W];
    end
  endgenerate

  // Path tag delayed by the path minimum trees' latency, for the running minimum.
  wire [TAG_W-1:0] tag_m;
  fpstereo_delay #(.WIDTH(TAG_W), .DEPTH(PATH_TREE_LAT), .RESET(1)) tag_to_min (.clk(clk), .rst(restart), .en(adv), .in(tag4), .out(tag_m));
  wire             pixel_done_m = `FPS_TAG_ACTIVE(tag_m) && `FPS_TAG_GROUP(tag_m) == G - 1;

  wire [LANES_W-1:0] path_0, path_45, path_90, path_135;

  // ---- Strip edges (STRIPS; G = 1, so a word is a pixel). The strip's first pixel takes its
  // 0 and 45-degree predecessors from edge_in, which the strip to the left captured at its last
  // pixel K + 1 clocks before; the last pixel's 135-degree predecessor comes from edge135_in,
  // captured by the strip to the right at its first pixel of the row above.
  localparam EDGE_W = (UF + 1) * PATH_W;
  /* verilator lint_off UNUSEDSIGNAL */  // those of the enabled paths
  wire [LANES_W-1:0] edge_l0 = edge_in[0 +: LANES_W], edge_a45 = edge_in[EDGE_W +: LANES_W];
  wire [PATH_W-1:0]  edge_min0 = edge_in[LANES_W +: PATH_W], edge_a45_min = edge_in[EDGE_W + LANES_W +: PATH_W];
  /* verilator lint_on UNUSEDSIGNAL */
  /* verilator lint_off UNUSEDSIGNAL */  // the edges' captures read it
  wire [X_W-1:0]     x_m = `FPS_TAG_X(tag_m);
  /* verilator lint_on UNUSEDSIGNAL */

  // ---- 0 degrees: the predecessor is the chain's previous pixel (state RAM by chain slot).
  generate
    if ((PATHS & 1) != 0) begin : path0
      wire [LANES_W-1:0] cur;
      /* verilator lint_off UNUSEDSIGNAL */
      wire [LANES_W-1:0] nxt;  // only its first lane (d + 1 of this group's last lane) is used
      /* verilator lint_on UNUSEDSIGNAL */
      wire [PATH_W-1:0] min_0;  // finished minimum of the pixel in tag_m
      wire [STATE_AW-1:0] state_waddr = `FPS_TAG_CHAIN(tag4) * G + g4;
      fpstereo_ram_async #(.WIDTH(LANES_W), .DEPTH(STATE_DEPTH), .ADDR_W(STATE_AW)) state (
        .clk(clk), .we(adv && active4), .waddr(state_waddr), .wdata(path_0),
        .raddr_a(state_addr2), .rdata_a(cur), .raddr_b(state_next_addr2), .rdata_b(nxt));
      reg [PATH_W-1:0] below_q;
      always @(posedge clk)
        if (adv) below_q <= cur[LANES_W-1 -: PATH_W];
      reg [PATH_W-1:0] minimum [0:K-1];
      // The chain's previous minimum for S2, read in S1 (with the write of that step passed on).
      reg [PATH_W-1:0] min2;
      fpstereo_path_lanes #(.UF(UF), .COST_W(COST_W), .PATH_W(PATH_W)) lanes (
        .clk(clk), .en(adv), .p1(p1), .p2(p2_0), .cost(cost2), .has_pred(left_in2), .prev(first2 ? edge_l0 : cur),
        .prev_below(first_group2 ? ONES : below_q), .prev_above(last_group2 ? ONES : nxt[PATH_W-1:0]),
        .prev_min(first2 ? edge_min0 : min2), .path(path_0));
      fpstereo_path_minimum #(.UF(UF), .PATH_W(PATH_W), .G_W(G_W), .LEVELS_PER_STAGE(LEVELS_PER_STAGE),
                              .TREE_LAT(PATH_TREE_LAT))
        reduce (.clk(clk), .en(adv), .path(path_0), .group(`FPS_TAG_GROUP(tag_m)), .minimum(min_0));
      always @(posedge clk)
        if (adv && pixel_done_m) minimum[`FPS_TAG_CHAIN(tag_m)] <= min_0;
      always @(posedge clk)
        if (adv) min2 <= pixel_done_m && `FPS_TAG_CHAIN(tag_m) == chain1 ? min_0 : minimum[chain1];
      if (STRIPS != 0) begin : strip_edge
        reg [LANES_W-1:0] last_q;
        reg [PATH_W-1:0]  last_min_q;
        always @(posedge clk) begin
          if (adv && active4 && x4 == X_LAST) last_q <= path_0;
          if (adv && pixel_done_m && x_m == X_LAST) last_min_q <= min_0;
        end
        assign edge_out[0 +: EDGE_W] = {last_min_q, last_q};
      end else begin : no_strip_edge
        assign edge_out[0 +: EDGE_W] = 0;
      end
    end else begin : no_path0
      assign path_0 = 0;
      assign edge_out[0 +: EDGE_W] = 0;
    end
  endgenerate

  // ---- 45 degrees: the predecessor is (x-1, row-1). The chain reads the row above at x and
  // keeps it (state RAM) for its next pixel, before its own write overwrites it.
  generate
    if ((PATHS & 2) != 0) begin : path45
      wire [LANES_W-1:0] above_q, cur;
      /* verilator lint_off UNUSEDSIGNAL */
      wire [LANES_W-1:0] nxt;  // only its first lane (d + 1 of this group's last lane) is used
      /* verilator lint_on UNUSEDSIGNAL */
      wire [PATH_W-1:0] above_min_q, min_45;
      reg  [LANES_W-1:0] above2;
      reg  [PATH_W-1:0] above_min2;
      wire [ROW_AW-1:0] row_raddr = (x_read - X_FIRST) * G + g_read;
      wire [MIN_AW-1:0] min_waddr = `FPS_TAG_X(tag_m) - X_FIRST, min_raddr = x_read - X_FIRST;
      fpstereo_ram_sdp #(.WIDTH(LANES_W), .DEPTH(ROW_DEPTH), .ADDR_W(ROW_AW)) row (
        .clk(clk), .we(adv && active4), .waddr(row_waddr4), .wdata(path_45),
        .re(adv), .raddr(row_raddr), .rdata(above_q));
      fpstereo_ram_sdp #(.WIDTH(PATH_W), .DEPTH(STRIP_W + 1), .ADDR_W(MIN_AW)) row_min (
        .clk(clk), .we(adv && pixel_done_m), .waddr(min_waddr), .wdata(min_45),
        .re(adv), .raddr(min_raddr), .rdata(above_min_q));
      always @(posedge clk)
        if (adv) begin
          above2 <= above_q;
          above_min2 <= above_min_q;
        end
      fpstereo_ram_async #(.WIDTH(LANES_W), .DEPTH(STATE_DEPTH), .ADDR_W(STATE_AW)) state (
        .clk(clk), .we(adv), .waddr(state_addr2), .wdata(above2),
        .raddr_a(state_addr2), .rdata_a(cur), .raddr_b(state_next_addr2), .rdata_b(nxt));
      reg [PATH_W-1:0] below_q;
      always @(posedge clk)
        if (adv) below_q <= cur[LANES_W-1 -: PATH_W];
      reg [PATH_W-1:0] minimum [0:K-1];
      always @(posedge clk)
        if (adv && last_group2) minimum[chain2] <= above_min2;
      // The chain's kept minimum for S2, read in S1 (with the write of that step passed on).
      reg [PATH_W-1:0] min2;
      always @(posedge clk)
        if (adv) min2 <= last_group2 && chain2 == chain1 ? above_min2 : minimum[chain1];
      fpstereo_path_lanes #(.UF(UF), .COST_W(COST_W), .PATH_W(PATH_W)) lanes (
        .clk(clk), .en(adv), .p1(p1), .p2(p2_45), .cost(cost2), .has_pred(left_in2 && above_in2),
        .prev(first2 ? edge_a45 : cur), .prev_below(first_group2 ? ONES : below_q),
        .prev_above(last_group2 ? ONES : nxt[PATH_W-1:0]), .prev_min(first2 ? edge_a45_min : min2),
        .path(path_45));
      fpstereo_path_minimum #(.UF(UF), .PATH_W(PATH_W), .G_W(G_W), .LEVELS_PER_STAGE(LEVELS_PER_STAGE),
                              .TREE_LAT(PATH_TREE_LAT))
        reduce (.clk(clk), .en(adv), .path(path_45), .group(`FPS_TAG_GROUP(tag_m)), .minimum(min_45));
      // The row above at the strip's last pixel, which the next strip's first pixel follows.
      if (STRIPS != 0) begin : strip_edge
        reg [LANES_W-1:0] last_q;
        reg [PATH_W-1:0]  last_min_q;
        always @(posedge clk)
          if (adv && `FPS_TAG_ACTIVE(tag2) && x2 == X_LAST) begin
            last_q <= above2;
            last_min_q <= above_min2;
          end
        assign edge_out[EDGE_W +: EDGE_W] = {last_min_q, last_q};
      end else begin : no_strip_edge
        assign edge_out[EDGE_W +: EDGE_W] = 0;
      end
    end else begin : no_path45
      assign path_45 = 0;
      assign edge_out[EDGE_W +: EDGE_W] = 0;
    end
  endgenerate

  // ---- 90 and 135 degrees: the predecessor is (x, row-1) or (x+1, row-1), read from the row
  // RAM. With G > 1 each row word carries, above its lanes, lane 0 of the pixel's next group
  // (all ones in the last group's word): the d+1 neighbour of the group's last lane is read with
  // the group's own word and reaches the lanes from a register (logic depth, docs/timing.md).
  // The word is written one step late, when that lane is known.
  generate
    genvar p;
    for (p = 0; p < 2; p = p + 1) begin : vertical
      localparam ENABLED = p == 0 ? (PATHS & 4) != 0 : (PATHS & 8) != 0;
      localparam DX = p;  // predecessor column offset
      if (ENABLED) begin : path
        localparam ROW_W = LANES_W + (G > 1 ? PATH_W : 0);
        wire [ROW_W-1:0]   above_read_q, row_wdata;
        wire [LANES_W-1:0] above_q, path_out;
        wire [PATH_W-1:0]  above_min_read_q, above_min_q, min_out;
        wire               row_we;
        wire [ROW_AW-1:0]  row_waddr;
        reg  [LANES_W-1:0] cur;
        reg  [PATH_W-1:0]  below_q, above_min2;
        wire [ROW_AW-1:0]  row_raddr = (x_read + DX - X_FIRST) * G + g_read;
        wire [MIN_AW-1:0]  min_waddr = `FPS_TAG_X(tag_m) - X_FIRST, min_raddr = x_read + DX - X_FIRST;
        fpstereo_ram_sdp #(.WIDTH(ROW_W), .DEPTH(ROW_DEPTH), .ADDR_W(ROW_AW)) row (
          .clk(clk), .we(row_we), .waddr(row_waddr), .wdata(row_wdata),
          .re(adv), .raddr(row_raddr), .rdata(above_read_q));
        fpstereo_ram_sdp #(.WIDTH(PATH_W), .DEPTH(STRIP_W + 1), .ADDR_W(MIN_AW)) row_min (
          .clk(clk), .we(adv && pixel_done_m), .waddr(min_waddr), .wdata(min_out),
          .re(adv), .raddr(min_raddr), .rdata(above_min_read_q));
        // 135 degrees in a strip with one to its right: the pixel after the strip's last is that
        // strip's, from edge135_in; and this strip's first pixel goes to the strip to the left.
        if (DX == 1 && FROM_RIGHT) begin : after_strip
          reg after_q;
          always @(posedge clk)
            if (adv) after_q <= x_read + DX == X_AFTER;
          assign above_q = after_q ? edge135_in[0 +: LANES_W] : above_read_q[LANES_W-1:0];
          assign above_min_q = after_q ? edge135_in[LANES_W +: PATH_W] : above_min_read_q;
        end else begin : within_strip
          assign above_q = above_read_q[LANES_W-1:0];
          assign above_min_q = above_min_read_q;
        end
        if (DX == 1 && FROM_LEFT) begin : strip_edge
          reg [LANES_W-1:0] first_q;
          reg [PATH_W-1:0]  first_min_q;
          always @(posedge clk) begin
            if (adv && active4 && x4 == X_FIRST) first_q <= path_out;
            if (adv && pixel_done_m && x_m == X_FIRST) first_min_q <= min_out;
          end
          assign edge135_out = {first_min_q, first_q};
        end
        always @(posedge clk)
          if (adv) begin
            cur <= above_q;
            below_q <= cur[LANES_W-1 -: PATH_W];
            above_min2 <= above_min_q;
          end
        // The d+1 neighbour of the last lane: the word's next-group lane, all ones with G = 1.
        wire [PATH_W-1:0] above_next2;
        if (G > 1) begin : next_lane
          // The previous step's word, written now with this step's lane 0 (a pixel's groups take
          // consecutive steps) or, after the pixel's last group, with all ones.
          reg               late_we, late_last;
          reg [ROW_AW-1:0]  late_waddr;
          reg [LANES_W-1:0] late_path;
          reg [PATH_W-1:0]  next2;
          always @(posedge clk)
            if (restart) late_we <= 1'b0;
            else if (adv) late_we <= active4;
          always @(posedge clk)
            if (adv) begin
              late_last <= g4 == G - 1;
              late_waddr <= row_waddr4;
              late_path <= path_out;
              next2 <= above_read_q[ROW_W-1 -: PATH_W];
            end
          assign row_we = adv && late_we;
          assign row_waddr = late_waddr;
          assign row_wdata = {late_last ? ONES : path_out[PATH_W-1:0], late_path};
          assign above_next2 = next2;
        end else begin : no_next_lane
          assign row_we = adv && active4;
          assign row_waddr = row_waddr4;
          assign row_wdata = path_out;
          assign above_next2 = ONES;
        end
        fpstereo_path_lanes #(.UF(UF), .COST_W(COST_W), .PATH_W(PATH_W)) lanes (
          .clk(clk), .en(adv), .p1(p1), .p2(p == 0 ? p2_90 : p2_135), .cost(cost2), .has_pred(above_in2 && column_in2[DX]), .prev(cur),
          .prev_below(first_group2 ? ONES : below_q), .prev_above(above_next2),
          .prev_min(above_min2), .path(path_out));
        fpstereo_path_minimum #(.UF(UF), .PATH_W(PATH_W), .G_W(G_W), .LEVELS_PER_STAGE(LEVELS_PER_STAGE),
                              .TREE_LAT(PATH_TREE_LAT))
          reduce (.clk(clk), .en(adv), .path(path_out), .group(`FPS_TAG_GROUP(tag_m)), .minimum(min_out));
      end
    end
    if ((PATHS & 4) != 0) begin : path90_out
      assign path_90 = vertical[0].path.path_out;
    end else begin : no_path90
      assign path_90 = 0;
    end
    if ((PATHS & 8) != 0) begin : path135_out
      assign path_135 = vertical[1].path.path_out;
    end else begin : no_path135
      assign path_135 = 0;
    end
    if ((PATHS & 8) == 0 || !FROM_LEFT) begin : no_edge135
      assign edge135_out = 0;
    end
  endgenerate

  // ---- The 180-degree path's costs, from the word at S2 to the sum at S4 (the lanes' two steps).
  wire [LANES_W-1:0] path_180;
  generate
    if (RIGHT_TO_LEFT != 0) begin : right_to_left
      reg [LANES_W-1:0] path3, path4;
      always @(posedge clk)
        if (adv) begin
          path3 <= cost_read2[UF*COST_W+PENALTIES*PATH_W +: LANES_W];
          path4 <= path3;
        end
      assign path_180 = path4;
    end else begin : no_right_to_left
      assign path_180 = 0;
    end
  endgenerate

  // ---- Sum over the paths (S4 -> S5).
  genvar l;
  generate
    for (l = 0; l < UF; l = l + 1) begin : lane_sum
      wire [SUM_W-1:0] s = {{(SUM_W-PATH_W){1'b0}}, path_0[l*PATH_W +: PATH_W]}
                         + {{(SUM_W-PATH_W){1'b0}}, path_45[l*PATH_W +: PATH_W]}
                         + {{(SUM_W-PATH_W){1'b0}}, path_90[l*PATH_W +: PATH_W]}
                         + {{(SUM_W-PATH_W){1'b0}}, path_135[l*PATH_W +: PATH_W]}
                         + {{(SUM_W-PATH_W){1'b0}}, path_180[l*PATH_W +: PATH_W]};
      always @(posedge clk)
        if (adv) sums[l*SUM_W +: SUM_W] <= s;
    end
  endgenerate

  assign sums_active = `FPS_TAG_ACTIVE(tag5);
  assign sums_x = `FPS_TAG_X(tag5);
  assign sums_group = `FPS_TAG_GROUP(tag5);
  assign sums_chain = `FPS_TAG_CHAIN(tag5);
  assign sums_slot = `FPS_TAG_SLOT(tag5);
  // verilator lint_on WIDTH

  `undef FPS_TAG_ACTIVE
  `undef FPS_TAG_X
  `undef FPS_TAG_ROW
  `undef FPS_TAG_GROUP
  `undef FPS_TAG_CHAIN
  `undef FPS_TAG_SLOT
endmodule
`resetall
