`resetall
`default_nettype none
// SAD, ZSAD and SHD costs of a slot's P pixels a step, in raster order, for the strips
// (docs/ppc-hardware.md, "SAD and ZSAD in strips"); fpstereo_pixel_window_cost and
// fpstereo_code_window_cost are the one-pixel stages. uf = dmax, so a slot is a step. The arrays
// are of pixels (fpstereo_front_end's) or, for SHD (HAMMING, ELEM_W the codes' width), of census
// codes (fpstereo_strip_code_windows'). Pixel q of the slot (x = slot * P + q) takes its base
// window out of the arrays (columns q .. q + N - 1, zero outside the image) and
// its UF + N - 1 match columns from a ring that the slot's P input columns (the arrays' newest,
// zero in rows outside the image) enter each step: pixel q's lanes (fpstereo_window_cost_lanes)
// read the ring at a fixed offset, newest first, so no lane needs a multiplexer.
// The offsets: the ring's newest column lies T = COLS - P - N + 1 columns beyond the last window's,
// so pixel q reads from T + P - 1 - q + MIN_DISP on. A positive MIN_DISP delays the columns
// MIN_DISP / P slots before the ring (a shift register) and adds the rest; a negative one delays
// the base windows BASE_WAIT = ceil(-MIN_DISP / P) slots instead and adds BASE_WAIT * P +
// MIN_DISP, so every offset is at least T.
// Timing: the windows of a shift are masked and registered (their position is transform_* a shift
// later); the base with its position waits one shift (ZSAD three: the base window's mean takes
// three, row sums, their total and the constant multiply) and BASE_WAIT more; the columns enter
// the ring as the base reaches the lanes. The lanes' costs leave LAT steps after, with the slot
// they belong to (cost_we: a shift whose slot lies in the frame, cost_slot, cost_row).
// SHD's fused cost (WEIGHT): the features' arrays come beside the codes'; each base window's
// centre feature waits with it, the newest columns' centre-row features enter a ring beside the
// codes' ring, and fpstereo_fused_term adds each pixel's term (LAT = its step after LANES_LAT).
module fpstereo_strip_window_cost #(
  parameter P = 2,
  parameter N = 5,
  // the arrays' columns: P * (1 + CENTRE_LAG) + N / 2
  parameter COLS = 6,
  // ZSAD: subtract the windows' means (of pixels)
  parameter ZERO_MEAN = 0,
  // SHD: the elements are census codes of ELEM_W bits, their distance a Hamming distance
  parameter HAMMING = 0,
  parameter ELEM_W = 8,
  parameter UF = 32,
  parameter COST_W = 13,
  parameter COST_MAX = 6375,
  // width of a window column's pixel sum; ZSAD: mean = (sum * MEAN_MUL) >> MEAN_SHIFT
  parameter COLUMN_SUM_W = 11,
  parameter MEAN_MUL = 1,
  parameter MEAN_SHIFT = 0,
  parameter ROW_W = 1,
  parameter X_W = 7,
  parameter MIN_DISP = 0,
  // SHD's fused cost (WEIGHT in eighths, 0: off; fpstereo_fused_term): the features' arrays beside
  // the codes', the base window's centre and the match columns' centre row
  parameter WEIGHT = 0,
  parameter TRUNC = 20,
  parameter FEATURE_W = 8,
  parameter GRADIENT = 0,
  // the lanes' latency (fpstereo_window_cost_lanes checks it) and the stage's (the fused term's
  // step more, fpstereo_fused_term checks it)
  parameter LANES_LAT = 4,
  parameter LAT = 4
) (
  input  wire                  clk,
  input  wire                  shift,
  input  wire [X_W-1:0]        frame_width,
  input  wire [N*COLS*ELEM_W-1:0] window_left,
  /* verilator lint_off UNUSEDSIGNAL */  // the newest P columns only; the features' centre row only
  input  wire [N*COLS*ELEM_W-1:0] window_right,
  input  wire [N*COLS*FEATURE_W-1:0] features_left,
  input  wire [N*COLS*FEATURE_W-1:0] features_right,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [N-1:0]          row_valid,
  input  wire [N+P-2:0]        col_valid,
  input  wire [N-1:0]          newest_row_valid,
  input  wire                  transform_in_frame,
  input  wire [X_W-1:0]        transform_x,
  input  wire [ROW_W-1:0]      transform_slot,
  output wire                  cost_we,
  output wire [X_W-1:0]        cost_slot,
  output wire [ROW_W-1:0]      cost_row,
  output wire [P*UF*COST_W-1:0] costs
);
  localparam LOG_P = $clog2(P);
  localparam T = COLS - P - N + 1;
  localparam MATCH_WAIT = MIN_DISP > 0 ? MIN_DISP / P : 0;
  localparam BASE_WAIT = MIN_DISP < 0 ? (-MIN_DISP + P - 1) / P : 0;
  localparam EXTRA = MIN_DISP > 0 ? MIN_DISP % P : BASE_WAIT * P + MIN_DISP;
  localparam MEAN_WAIT = ZERO_MEAN != 0 ? 2 : 0;
  localparam VIEW_COLS = UF + N - 1;
  localparam LENGTH = T + P - 1 + EXTRA + VIEW_COLS;  // the ring's columns
  localparam COLUMN_W = N * ELEM_W;
  localparam WINDOW_W = N * N * ELEM_W;
  localparam FUSED = WEIGHT != 0;
  localparam FW = FUSED ? FEATURE_W : 1;  // a feature's bits where they travel (none without)
  localparam RS = N / 2;
  localparam POSITION_W = 1 + X_W + ROW_W;
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if ((P != 2 && P != 4) || N < 3 || N % 2 == 0 || T < 0 || (COLS - N / 2) % P != 0) begin : invalid
      fpstereo_invalid_parameters_strip_window_cost_P_N_or_COLS_not_the_front_ends failed ();
    end
    if (ZERO_MEAN != 0 && 255 * N >= (1 << COLUMN_SUM_W)) begin : invalid_COLUMN_SUM_W
      fpstereo_invalid_parameters_strip_window_cost_COLUMN_SUM_W_does_not_hold_255_N failed ();
    end
    if ((ZERO_MEAN != 0 && (HAMMING != 0 || ELEM_W != 8)) || (HAMMING == 0 && ELEM_W != 8)) begin : invalid_elements
      fpstereo_invalid_parameters_strip_window_cost_pixels_are_8_bits_and_zero_mean_only_for_pixels failed ();
    end
    if ((FUSED && HAMMING == 0) || (!FUSED && LAT != LANES_LAT)) begin : invalid_fused
      fpstereo_invalid_parameters_strip_window_cost_fused_only_for_codes_or_LAT_is_not_LANES_LAT failed ();
    end
  endgenerate
  genvar q, e;

  // The base side: the P windows masked and registered, then with their position (the transform's,
  // a shift later) waiting 1 + MEAN_WAIT + BASE_WAIT shifts in all.
  wire [P*WINDOW_W-1:0] masked;
  generate
    for (q = 0; q < P; q = q + 1) begin : base_window
      wire [WINDOW_W-1:0] window;
      fpstereo_window_cut #(.N(N), .COLS(COLS), .WORD_W(ELEM_W), .Q(q)) cut (.array(window_left), .window(window));
      fpstereo_window_mask #(.N(N), .WORD_W(ELEM_W)) mask (
        .window(window), .row_valid(row_valid), .col_valid(col_valid[q +: N]), .masked(masked[q*WINDOW_W +: WINDOW_W]));
    end
  endgenerate
  // The fused cost's base features: each window's centre.
  wire [P*FW-1:0] base_features_now;
  generate
    for (q = 0; q < P; q = q + 1) begin : base_feature
      if (FUSED) begin : centre
        assign base_features_now[q*FW +: FW] = features_left[(RS*COLS + q + RS)*FEATURE_W +: FW];
      end else begin : none
        assign base_features_now[q*FW +: FW] = {FW{1'b0}};
      end
    end
  endgenerate
  reg [P*WINDOW_W-1:0] base_taken;
  reg [P*FW-1:0]       base_features_taken;
  always @(posedge clk)
    if (shift) begin
      base_taken <= masked;
      base_features_taken <= base_features_now;
    end
  // ZSAD: each window's mean from the taken window, over three shifts (row sums, total, mean).
  wire [P*8-1:0] means_now;
  generate
    if (ZERO_MEAN != 0) begin : means
      for (q = 0; q < P; q = q + 1) begin : pixel
        fpstereo_window_mean #(.N(N), .COLUMN_SUM_W(COLUMN_SUM_W), .MEAN_MUL(MEAN_MUL), .MEAN_SHIFT(MEAN_SHIFT)) base_mean_of (
          .clk(clk), .en(shift), .window(base_taken[q*WINDOW_W +: WINDOW_W]), .mean(means_now[q*8 +: 8]));
      end
    end else begin : no_means
      assign means_now = {(P*8){1'b0}};
    end
  endgenerate
  // The windows with their position as the means are done, then BASE_WAIT slots more.
  wire [P*WINDOW_W-1:0] base_meaned;
  wire [P*FW-1:0]       base_features_meaned;
  wire [POSITION_W-1:0] position_meaned;
  fpstereo_delay #(.WIDTH(P*WINDOW_W + P*FW + POSITION_W), .DEPTH(1 + MEAN_WAIT)) base_mean_wait (
    .clk(clk), .rst(1'b0), .en(shift),
    .in({base_taken, base_features_taken, transform_in_frame, transform_x, transform_slot}),
    .out({base_meaned, base_features_meaned, position_meaned}));
  wire [P*WINDOW_W-1:0] base;
  /* verilator lint_off UNUSEDSIGNAL */  // the fused cost's only
  wire [P*FW-1:0]       base_features;
  /* verilator lint_on UNUSEDSIGNAL */
  wire [POSITION_W-1:0] position;
  wire [P*8-1:0]        base_means;
  generate
    if (BASE_WAIT > 0) begin : base_late
      fpstereo_delay #(.WIDTH(P*WINDOW_W + P*FW + POSITION_W + P*8), .DEPTH(BASE_WAIT)) base_wait (
        .clk(clk), .rst(1'b0), .en(shift), .in({base_meaned, base_features_meaned, position_meaned, means_now}),
        .out({base, base_features, position, base_means}));
    end else begin : base_in_time
      assign {base, base_features, position, base_means} = {base_meaned, base_features_meaned, position_meaned, means_now};
    end
  endgenerate

  // The match side: the slot's P input columns, zero in rows outside the image, registered (ZSAD
  // with their sums), waiting MEAN_WAIT + MATCH_WAIT shifts, then into the ring (column j of the
  // slot at ring place P - 1 - j).
  wire [P*COLUMN_W-1:0]     columns_now;
  wire [P*COLUMN_SUM_W-1:0] sums_now;
  wire [P*FW-1:0]           features_now;  // the fused cost's: the columns' centre row
  generate
    for (q = 0; q < P; q = q + 1) begin : input_column
      if (FUSED) begin : centre_feature
        assign features_now[(P-1-q)*FW +: FW] = features_right[(RS*COLS + COLS - P + q)*FEATURE_W +: FW];
      end else begin : no_feature
        assign features_now[(P-1-q)*FW +: FW] = {FW{1'b0}};
      end
      for (e = 0; e < N; e = e + 1) begin : element
        assign columns_now[(P-1-q)*COLUMN_W + e*ELEM_W +: ELEM_W] =
            newest_row_valid[e] ? window_right[(e*COLS + COLS - P + q)*ELEM_W +: ELEM_W] : {ELEM_W{1'b0}};
      end
      if (ZERO_MEAN != 0) begin : column_sum
        fpstereo_sum_tree #(.N(N), .IN_W(8), .SUM_W(COLUMN_SUM_W)) total (
          .clk(clk), .en(shift), .values(columns_now[(P-1-q)*COLUMN_W +: COLUMN_W]),
          .sum(sums_now[(P-1-q)*COLUMN_SUM_W +: COLUMN_SUM_W]));
      end else begin : no_sum
        assign sums_now[(P-1-q)*COLUMN_SUM_W +: COLUMN_SUM_W] = {COLUMN_SUM_W{1'b0}};
      end
    end
  endgenerate
  reg [P*COLUMN_W-1:0]     columns_taken;
  reg [P*COLUMN_SUM_W-1:0] sums_taken;
  reg [P*FW-1:0]           features_taken;
  always @(posedge clk)
    if (shift) begin
      columns_taken <= columns_now;
      sums_taken <= sums_now;
      features_taken <= features_now;
    end
  wire [P*COLUMN_W-1:0]     columns_in;
  wire [P*COLUMN_SUM_W-1:0] sums_in;
  wire [P*FW-1:0]           features_in;
  generate
    if (MEAN_WAIT + MATCH_WAIT > 0) begin : match_late
      fpstereo_delay #(.WIDTH(P*(COLUMN_W + COLUMN_SUM_W + FW)), .DEPTH(MEAN_WAIT + MATCH_WAIT)) match_wait (
        .clk(clk), .rst(1'b0), .en(shift), .in({columns_taken, sums_taken, features_taken}),
        .out({columns_in, sums_in, features_in}));
    end else begin : match_in_time
      assign {columns_in, sums_in, features_in} = {columns_taken, sums_taken, features_taken};
    end
  endgenerate
  reg [LENGTH*COLUMN_W-1:0]     ring;
  reg [LENGTH*COLUMN_SUM_W-1:0] sum_ring;
  /* verilator lint_off UNUSEDSIGNAL */  // the fused cost's only, and the lanes' centres of it
  reg [LENGTH*FW-1:0]           feature_ring;
  /* verilator lint_on UNUSEDSIGNAL */
  always @(posedge clk)
    if (shift) begin
      ring <= {ring[(LENGTH-P)*COLUMN_W-1:0], columns_in};
      sum_ring <= {sum_ring[(LENGTH-P)*COLUMN_SUM_W-1:0], sums_in};
      feature_ring <= {feature_ring[(LENGTH-P)*FW-1:0], features_in};
    end

  // Pixel q's lanes, and the slot's position LAT steps later, with the costs.
  generate
    for (q = 0; q < P; q = q + 1) begin : pixel
      localparam FROM = T + P - 1 - q + EXTRA;
      /* verilator lint_off WIDTH */  // the slot's first pixel and q, in the pixel width
      wire [X_W-1:0] x = (position[X_W+ROW_W-1:ROW_W] << LOG_P) + q;
      /* verilator lint_on WIDTH */
      wire [UF*COST_W-1:0] lane_costs;
      fpstereo_window_cost_lanes #(.ZERO_MEAN(ZERO_MEAN), .HAMMING(HAMMING), .ELEM_W(ELEM_W), .SPAN(N), .UF(UF),
                                   .COST_W(COST_W), .COST_MAX(COST_MAX), .GROUP_W(1), .X_W(X_W),
                                   .COLUMN_SUM_W(COLUMN_SUM_W), .MEAN_MUL(MEAN_MUL), .MEAN_SHIFT(MEAN_SHIFT),
                                   .MIN_DISP(MIN_DISP), .LAT(LANES_LAT)) lanes (
        .clk(clk), .en(shift), .base(base[q*WINDOW_W +: WINDOW_W]), .base_mean(base_means[q*8 +: 8]),
        .view(ring[FROM*COLUMN_W +: VIEW_COLS*COLUMN_W]),
        .view_sums(sum_ring[FROM*COLUMN_SUM_W +: VIEW_COLS*COLUMN_SUM_W]), .group(1'b0), .x(x),
        .width(frame_width), .costs(lane_costs));
      if (FUSED) begin : fused
        // Lane l's match window is centred on its view's column l + RS.
        fpstereo_fused_term #(.UF(UF), .COST_W(COST_W), .COST_MAX(COST_MAX), .GRADIENT(GRADIENT), .FEATURE_W(FEATURE_W),
                              .WEIGHT(WEIGHT), .TRUNC(TRUNC), .LANES_LAT(LANES_LAT), .LAT(LAT)) term (
          .clk(clk), .en(shift), .base_feature(base_features[q*FW +: FW]),
          .match_features(feature_ring[(FROM + RS)*FW +: UF*FW]), .plain_costs(lane_costs),
          .costs(costs[q*UF*COST_W +: UF*COST_W]));
      end else begin : plain
        assign costs[q*UF*COST_W +: UF*COST_W] = lane_costs;
      end
    end
  endgenerate
  wire in_frame;
  fpstereo_delay #(.WIDTH(POSITION_W), .DEPTH(LAT)) position_wait (
    .clk(clk), .rst(1'b0), .en(shift), .in(position), .out({in_frame, cost_slot, cost_row}));
  assign cost_we = shift && in_frame;
endmodule
`resetall
