`resetall
`default_nettype none
// Cost stage for SHD: the census codes enter SHD_K x SHD_K code windows (zero outside the
// image); the base window waits a slot, the match window's newest column enters the match ring,
// and the lanes sum the Hamming distances over the window (docs/semantics.md, section 2).
// history_x / history_y / history_slot are the centre whose costs the lanes compute in this slot;
// fpstereo_cost_history holds them, with the disparity offset's delays. With the fused cost (WEIGHT
// above 0) the pixels' features (fpstereo_fused_features) enter windows of their own beside the
// codes: the base window's centre and the match window's newest column at the centre row travel
// with the codes through the history, and fpstereo_fused_term adds the pixel-wise term of the
// centres.
module fpstereo_code_window_cost #(
  // the summation window's side
  parameter SHD_K = 3,
  parameter CODE_W = 24,
  parameter ROW_SLOTS = 64,
  parameter DMAX = 32,
  parameter UF = 8,
  parameter COST_W = 8,
  parameter COST_MAX = 216,
  parameter COLUMN_SUM_W = 11,
  parameter COST_ROWS = 2,
  parameter COST_ROW_W = 1,
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter SIGNED_Y_W = 8,
  parameter G_W = 2,
  parameter MIN_DISP = 0,
  // the fused cost: WEIGHT in eighths (0: off), TRUNC, the features' width and signedness
  parameter WEIGHT = 0,
  parameter TRUNC = 20,
  parameter FEATURE_W = 8,
  parameter GRADIENT = 0,
  // the cost lanes' latency, and the stage's (the lanes' plus the fused term's step, or the same);
  // fpstereo_window_cost_lanes and fpstereo_fused_term check them
  parameter LANES_LAT = 4,
  parameter LAT = 4
) (
  input  wire                   clk,
  input  wire                   adv,
  input  wire                   slot_end,
  input  wire                   shift,
  input  wire [G_W-1:0]         group,
  input  wire [X_W-1:0]         frame_width,
  input  wire [Y_W-1:0]         frame_height,
  // back-to-back frames: once wrapped, the rows above row 0 are the previous frame's
  input  wire                   wrapped,
  input  wire [CODE_W-1:0]      code_base,
  input  wire [CODE_W-1:0]      code_match,
  /* verilator lint_off UNUSEDSIGNAL */  // the fused cost's only
  input  wire [FEATURE_W-1:0]   feature_base,
  input  wire [FEATURE_W-1:0]   feature_match,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [X_W-1:0]         transform_x,
  input  wire signed [SIGNED_Y_W-1:0] transform_y,
  input  wire [COST_ROW_W-1:0]    transform_slot,
  output wire [X_W-1:0]         history_x,
  output wire signed [SIGNED_Y_W-1:0] history_y,
  output wire [COST_ROW_W-1:0]    history_slot,
  output wire [UF*COST_W-1:0]   costs
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (SHD_K < 3 || SHD_K % 2 == 0) begin : invalid_SHD_K
      fpstereo_invalid_parameters_code_window_cost_SHD_K_is_not_odd_and_at_least_3 failed ();
    end
    if (SIGNED_Y_W < Y_W + 2) begin : invalid_SIGNED_Y_W
      fpstereo_invalid_parameters_code_window_cost_SIGNED_Y_W_below_Y_W_plus_2 failed ();
    end
  endgenerate
  localparam RS = SHD_K / 2;
  localparam [X_W-1:0] LAST_SLOT = ROW_SLOTS - 1;
  wire [X_W:0] width_x = {1'b0, frame_width};
  wire signed [SIGNED_Y_W-1:0] height_y = $signed({2'b00, frame_height});
  // The code windows take in the codes at column transform_x.
  wire [X_W-1:0] code_next_col = (transform_x == LAST_SLOT) ? {X_W{1'b0}} : transform_x + 1'b1;
  wire [SHD_K*SHD_K*CODE_W-1:0] codes_left, codes_right;
  fpstereo_window #(.N(SHD_K), .WORD_W(CODE_W), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) base_codes (
    .clk(clk), .shift(shift), .col(transform_x), .next_col(code_next_col), .word(code_base), .window(codes_left));
  fpstereo_window #(.N(SHD_K), .WORD_W(CODE_W), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) match_codes (
    .clk(clk), .shift(shift), .col(transform_x), .next_col(code_next_col), .word(code_match), .window(codes_right));
  // Centre of the code window: RS rows and RS slots behind the entering code; the newest
  // column is the entering code's own column (zero outside the image, as for SAD).
  wire [X_W-1:0] codes_centre_x;
  wire signed [SIGNED_Y_W-1:0] codes_centre_y;
  wire [COST_ROW_W-1:0] codes_slot_next;
  wire signed [SIGNED_Y_W-1:0] code_newest_y_next;
  fpstereo_window_centre #(.LAG(RS), .ROW_SLOTS(ROW_SLOTS), .X_W(X_W), .SIGNED_Y_W(SIGNED_Y_W), .ROWS(COST_ROWS),
                           .SLOT_W(COST_ROW_W)) codes_centre (
    .x(transform_x), .y(transform_y), .slot(transform_slot), .wrapped(wrapped), .height(height_y),
    .centre_x(codes_centre_x), .centre_y(codes_centre_y), .centre_slot(codes_slot_next), .row_y(code_newest_y_next));
  reg [X_W-1:0] codes_x;
  reg signed [SIGNED_Y_W-1:0] codes_y;
  reg [COST_ROW_W-1:0] codes_slot;
  reg code_newest_in_row;
  reg signed [SIGNED_Y_W-1:0] code_newest_y;
  always @(posedge clk)
    if (shift) begin
      code_newest_in_row <= {1'b0, transform_x} < width_x;
      code_newest_y <= code_newest_y_next;
      codes_x <= codes_centre_x;
      codes_y <= codes_centre_y;
      codes_slot <= codes_slot_next;
    end
  wire [SHD_K-1:0] code_row_valid, code_col_valid, code_newest_rows;
  /* verilator lint_off UNUSEDSIGNAL */  // the newest column's own column bound is code_newest_in_row
  wire [SHD_K-1:0] code_newest_unused_columns;
  /* verilator lint_on UNUSEDSIGNAL */
  fpstereo_window_bounds #(.SIDE(SHD_K), .X_W(X_W), .SIGNED_Y_W(SIGNED_Y_W)) code_bounds (
    .clk(clk), .x(codes_x), .y(codes_y), .width(width_x), .height(height_y), .row_valid(code_row_valid),
    .col_valid(code_col_valid));
  fpstereo_window_bounds #(.SIDE(SHD_K), .X_W(X_W), .SIGNED_Y_W(SIGNED_Y_W)) code_newest_bounds (
    .clk(clk), .x(codes_x), .y(code_newest_y), .width(width_x), .height(height_y), .row_valid(code_newest_rows),
    .col_valid(code_newest_unused_columns));
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
  localparam POSITION_W = X_W + SIGNED_Y_W + COST_ROW_W;
  // A history entry: the base window (or a match column), with the fused cost the centre's feature
  // (or the column's at the centre row) above it.
  localparam FUSED = WEIGHT != 0;
  localparam BASE_W = SHD_K*SHD_K*CODE_W;
  localparam COLUMN_W = SHD_K*CODE_W;
  localparam FEATURE_ENTRY_W = FUSED ? FEATURE_W : 0;
  localparam VIEW_COLS = UF + SHD_K - 1;
  wire [BASE_W+FEATURE_ENTRY_W-1:0]             base_entry, base_entry_h;
  wire [COLUMN_W+FEATURE_ENTRY_W-1:0]           match_entry;
  wire [VIEW_COLS*(COLUMN_W+FEATURE_ENTRY_W)-1:0] entry_view;
  wire [POSITION_W-1:0]                         history;
  generate
    if (FUSED) begin : with_features
      // The feature windows delay the features as the code windows delay the codes; only the
      // centre row is read.
      /* verilator lint_off UNUSEDSIGNAL */
      wire [SHD_K*SHD_K*FEATURE_W-1:0] features_left, features_right;
      /* verilator lint_on UNUSEDSIGNAL */
      fpstereo_window #(.N(SHD_K), .WORD_W(FEATURE_W), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) base_features (
        .clk(clk), .shift(shift), .col(transform_x), .next_col(code_next_col), .word(feature_base),
        .window(features_left));
      fpstereo_window #(.N(SHD_K), .WORD_W(FEATURE_W), .ROW_SLOTS(ROW_SLOTS), .ADDR_W(X_W)) match_features (
        .clk(clk), .shift(shift), .col(transform_x), .next_col(code_next_col), .word(feature_match),
        .window(features_right));
      assign base_entry = {features_left[(RS*SHD_K + RS)*FEATURE_W +: FEATURE_W], base_masked};
      assign match_entry = {features_right[(RS*SHD_K + SHD_K - 1)*FEATURE_W +: FEATURE_W], newest_column};
    end else begin : codes_only
      assign base_entry = base_masked;
      assign match_entry = newest_column;
    end
  endgenerate
  fpstereo_cost_history #(.BASE_W(BASE_W + FEATURE_ENTRY_W), .POSITION_W(POSITION_W),
                          .COLUMN_W(COLUMN_W + FEATURE_ENTRY_W), .SPAN(SHD_K), .DMAX(DMAX), .UF(UF), .G_W(G_W),
                          .MIN_DISP(MIN_DISP)) cost_history (
    .clk(clk), .adv(adv), .slot_end(slot_end), .shift(shift), .base(base_entry),
    .position({codes_x, codes_y, codes_slot}), .column(match_entry), .base_held(base_entry_h),
    .position_held(history), .view(entry_view));
  assign {history_x, history_y, history_slot} = history;
  // The lanes' view: each entry's code column.
  reg [VIEW_COLS*COLUMN_W-1:0] view;
  integer c;
  always @*
    for (c = 0; c < VIEW_COLS; c = c + 1)
      view[c*COLUMN_W +: COLUMN_W] = entry_view[c*(COLUMN_W+FEATURE_ENTRY_W) +: COLUMN_W];
  wire [UF*COST_W-1:0] lane_costs;
  fpstereo_window_cost_lanes #(.ZERO_MEAN(0), .HAMMING(1), .ELEM_W(CODE_W), .SPAN(SHD_K), .UF(UF),
                               .COST_W(COST_W), .COST_MAX(COST_MAX), .GROUP_W(G_W), .X_W(X_W),
                               .COLUMN_SUM_W(COLUMN_SUM_W), .MIN_DISP(MIN_DISP), .LAT(LANES_LAT)) lanes (
    .clk(clk), .en(adv), .base(base_entry_h[BASE_W-1:0]), .base_mean(8'd0), .view(view),
    .view_sums({VIEW_COLS*COLUMN_SUM_W{1'b0}}), .group(group), .x(history_x), .width(frame_width),
    .costs(lane_costs));
  generate
    if (FUSED) begin : fused
      // Lane l's match window is centred on view column l + RS.
      reg [UF*FEATURE_W-1:0] match_centres;
      integer l;
      always @*
        for (l = 0; l < UF; l = l + 1)
          match_centres[l*FEATURE_W +: FEATURE_W] = entry_view[(l + RS)*(COLUMN_W+FEATURE_W) + COLUMN_W +: FEATURE_W];
      fpstereo_fused_term #(.UF(UF), .COST_W(COST_W), .COST_MAX(COST_MAX), .GRADIENT(GRADIENT), .FEATURE_W(FEATURE_W),
                            .WEIGHT(WEIGHT), .TRUNC(TRUNC), .LANES_LAT(LANES_LAT), .LAT(LAT)) term (
        .clk(clk), .en(adv), .base_feature(base_entry_h[BASE_W +: FEATURE_W]), .match_features(match_centres),
        .plain_costs(lane_costs), .costs(costs));
    end else begin : plain
      if (LAT != LANES_LAT) begin : invalid_LAT
        fpstereo_invalid_parameters_code_window_cost_LAT_is_not_LANES_LAT_without_the_fused_cost failed ();
      end
      assign costs = lane_costs;
    end
  endgenerate
endmodule
`resetall
