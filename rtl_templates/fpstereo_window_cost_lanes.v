`resetall
`default_nettype none
// UF window-based matching costs per step (docs/semantics.md, section 2), lane l = disparity
// d = group*UF + l: the sum over a SPAN x SPAN window of
//   SAD:  |b - m|                      over pixels
//   ZSAD: |(b - mean_b) - (m - mean_m)| over pixels, means floor(sum / SPAN^2) (ZERO_MEAN)
//   SHD:  popcount(b xor m)            over census codes (HAMMING)
// b is the (already zero-extended) base window; the match window of lane l is view columns
// l .. l + SPAN - 1 (fpstereo_match_ring), newest first; its columns outside the image read as 0
// (at the right border the ring already holds the next row's first columns).
// Lane l's disparity is MIN_DISP + d; where its match centre x - MIN_DISP - d lies outside the
// row the cost is COST_MAX. Register steps
// (LAT): the view's column masks, the windows and the border flag; ZSAD: the masked column sums,
// the match window's sum, its mean, the difference of the means (with the masked view); the
// magnitudes' pair sums; the row sums; the total. Sums are balanced adder trees
// (fpstereo_sum_tree).
module fpstereo_window_cost_lanes #(
  // pixels with their windows' means subtracted (ZSAD); census codes compared bit by bit (SHD)
  parameter ZERO_MEAN = 0,
  parameter HAMMING = 0,
  // bits per window element (8 for pixels, the code width for SHD)
  parameter ELEM_W = 8,
  parameter SPAN = 5,
  parameter UF = 32,
  parameter COST_W = 13,
  parameter COST_MAX = 6375,
  parameter GROUP_W = 2,
  parameter X_W = 11,
  // ZSAD: column sum width and floor(s / SPAN^2) = (s * MEAN_MUL) >> MEAN_SHIFT
  parameter COLUMN_SUM_W = 11,
  parameter MEAN_MUL = 1,
  parameter MEAN_SHIFT = 0,
  // the smallest disparity (docs/semantics.md, section 2)
  parameter MIN_DISP = 0,
  // the latency the instantiating stage plans with (checked: 4, ZSAD 8; 3 for SPAN 1)
  parameter LAT = 4
) (
  input  wire                                clk,
  input  wire                                en,
  input  wire [SPAN*SPAN*ELEM_W-1:0]         base,
  /* verilator lint_off UNUSEDSIGNAL */  // the means serve ZSAD only
  input  wire [7:0]                          base_mean,
  input  wire [(UF+SPAN-1)*COLUMN_SUM_W-1:0]     view_sums,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [(UF+SPAN-1)*SPAN*ELEM_W-1:0]  view,
  input  wire [GROUP_W-1:0]                  group,
  input  wire [X_W-1:0]                      x,
  input  wire [X_W-1:0]                      width,
  output reg  [UF*COST_W-1:0]                costs
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (SPAN < 1 || SPAN % 2 == 0 || (ZERO_MEAN != 0 && SPAN > 16)) begin : invalid_SPAN
      fpstereo_invalid_parameters_window_cost_lanes_SPAN_is_not_odd_or_too_large_for_the_window_sum failed ();
    end
    if (UF < 1 || UF > 512) begin : invalid_UF
      fpstereo_invalid_parameters_window_cost_lanes_UF_is_not_1_to_512 failed ();
    end
    if ((HAMMING == 0 && ELEM_W != 8) || ELEM_W < 1) begin : invalid_ELEM_W
      fpstereo_invalid_parameters_window_cost_lanes_pixels_need_ELEM_W_8 failed ();
    end
    if (COST_MAX >= (1 << COST_W)) begin : invalid_COST_W
      fpstereo_invalid_parameters_window_cost_lanes_COST_MAX_does_not_fit_COST_W failed ();
    end
    if (LAT != (ZERO_MEAN != 0 ? 4 : 0) + (SPAN > 1 ? 1 : 0) + 3) begin : invalid_LAT
      fpstereo_invalid_parameters_window_cost_lanes_LAT_is_not_the_latency failed ();
    end
  endgenerate
  localparam R = SPAN / 2;
  localparam COLUMN_W = SPAN * ELEM_W;
  localparam VIEW_COLS = UF + SPAN - 1;
  // wide enough for x + VIEW_COLS + 256 and for any index plus UF + R + 256 + width
  localparam D_W = (X_W > GROUP_W + 9 ? X_W : GROUP_W + 9) + 3;
  localparam WINSUM_W = COLUMN_SUM_W + 4;  // a window's pixel sum (SPAN <= 11 columns)
  // A pixel term is (b - m) - delta, in [-510, 510] (ZSAD) or [-255, 255] (SAD), signed.
  localparam TERM_W = ZERO_MEAN != 0 ? 10 : 9;
  // An element's magnitude: the Hamming distance of codes; of pixels, |term| - (term < 0).
  localparam MAG_W = HAMMING != 0 ? $clog2(ELEM_W + 1) : TERM_W - 1;
  localparam SIGNS_W = $clog2(SPAN + 1);
  localparam MEAN_STEPS = ZERO_MEAN != 0 ? 4 : 0;
  localparam PAIR_STEP = SPAN > 1 ? 1 : 0;
  wire [D_W-1:0] x_wide = {{(D_W-X_W){1'b0}}, x};
  wire [D_W-1:0] group_base = {{(D_W-GROUP_W){1'b0}}, group} * UF[D_W-1:0];
  wire [D_W-1:0] width_wide = {{(D_W-X_W){1'b0}}, width};
  // Match positions x - MIN_DISP - ..., compared as x + AHEAD against ... + BEHIND.
  localparam integer BEHIND = MIN_DISP > 0 ? MIN_DISP : 0;
  localparam integer AHEAD = MIN_DISP < 0 ? -MIN_DISP : 0;
  wire [D_W-1:0] x_ahead = x_wide + AHEAD[D_W-1:0];

  // View column c lies at x - MIN_DISP - group*UF + (SPAN - 1 - R - c) in the image for every
  // lane that reads it (lane l: window column j = l + SPAN - 1 - c, at x - MIN_DISP - d + j - R),
  // so one mask per view column serves all lanes. Inside: 0 <= that < width, here with
  // group*UF + UF + R + BEHIND added.
  wire [D_W-1:0] inside_low = group_base + UF[D_W-1:0] + R[D_W-1:0] + BEHIND[D_W-1:0];
  wire [D_W-1:0] inside_high = inside_low + width_wide;
  wire [VIEW_COLS-1:0] view_valid;
  genvar c;
  generate
    for (c = 0; c < VIEW_COLS; c = c + 1) begin : view_column
      localparam OFFSET = VIEW_COLS - c;
      wire [D_W-1:0] position = x_ahead + OFFSET[D_W-1:0];
      assign view_valid[c] = position >= inside_low && position < inside_high;
    end
  endgenerate

  // Step 1: the masks and the windows.
  reg  [VIEW_COLS-1:0]          view_valid_q;
  reg  [VIEW_COLS*COLUMN_W-1:0] view_q;
  always @(posedge clk)
    if (en) begin
      view_valid_q <= view_valid;
      view_q <= view;
    end
  // The view as the terms read it, its columns outside the image zeroed; ZSAD: the match
  // windows' column sums, masked the same way.
  wire [VIEW_COLS*COLUMN_W-1:0] view_d;
  /* verilator lint_off UNUSEDSIGNAL */  // ZSAD only
  wire [VIEW_COLS*COLUMN_SUM_W-1:0] view_sums_masked;
  wire [7:0]                    base_mean_d;
  /* verilator lint_on UNUSEDSIGNAL */
  generate
    if (ZERO_MEAN != 0) begin : late_mask
      // ZSAD: the column sums are masked at step 2 (the match sums start from flip-flops); the
      // view waits three steps more for the means, and is masked into the register of step 5
      // (the terms start from flip-flops, not from a shift register's read).
      reg  [VIEW_COLS*COLUMN_SUM_W-1:0] view_sums_q, view_sums_masked_q;
      wire [VIEW_COLS*COLUMN_W-1:0] view_late;
      wire [VIEW_COLS-1:0]          valid_late;
      reg  [VIEW_COLS*COLUMN_W-1:0] view_masked_q;
      fpstereo_delay #(.WIDTH(VIEW_COLS*COLUMN_W + VIEW_COLS), .DEPTH(MEAN_STEPS - 1)) view_wait (
        .clk(clk), .rst(1'b0), .en(en), .in({view_q, view_valid_q}), .out({view_late, valid_late}));
      integer n;
      always @(posedge clk)
        if (en) begin
          view_sums_q <= view_sums;
          for (n = 0; n < VIEW_COLS; n = n + 1) begin
            view_sums_masked_q[n*COLUMN_SUM_W +: COLUMN_SUM_W] <=
                view_valid_q[n] ? view_sums_q[n*COLUMN_SUM_W +: COLUMN_SUM_W] : {COLUMN_SUM_W{1'b0}};
            view_masked_q[n*COLUMN_W +: COLUMN_W] <= valid_late[n] ? view_late[n*COLUMN_W +: COLUMN_W] : {COLUMN_W{1'b0}};
          end
        end
      assign view_d = view_masked_q;
      assign view_sums_masked = view_sums_masked_q;
      // the base window's mean meets the match window's (step 4)
      fpstereo_delay #(.WIDTH(8), .DEPTH(MEAN_STEPS)) base_mean_wait (
        .clk(clk), .rst(1'b0), .en(en), .in(base_mean), .out(base_mean_d));
    end else begin : early_mask
      for (c = 0; c < VIEW_COLS; c = c + 1) begin : column
        assign view_d[c*COLUMN_W +: COLUMN_W] = view_valid_q[c] ? view_q[c*COLUMN_W +: COLUMN_W] : {COLUMN_W{1'b0}};
      end
      assign view_sums_masked = {VIEW_COLS*COLUMN_SUM_W{1'b0}};
      assign base_mean_d = 8'd0;
    end
  endgenerate
  wire [SPAN*SPAN*ELEM_W-1:0] base_d;
  fpstereo_delay #(.WIDTH(SPAN*SPAN*ELEM_W), .DEPTH(1 + MEAN_STEPS)) base_wait (
    .clk(clk), .rst(1'b0), .en(en), .in(base), .out(base_d));

  genvar l, i, k;
  generate
    for (l = 0; l < UF; l = l + 1) begin : lane
      wire [D_W-1:0] d = group_base + l[D_W-1:0] + BEHIND[D_W-1:0];
      // The border flag, registered at step 1, waits for the total.
      reg  outside_q;
      wire outside_d;
      always @(posedge clk)
        if (en) outside_q <= x_ahead < d || (MIN_DISP < 0 && x_ahead >= d + width_wide);
      fpstereo_delay #(.WIDTH(1), .DEPTH(LAT - 2)) outside_wait (
        .clk(clk), .rst(1'b0), .en(en), .in(outside_q), .out(outside_d));

      // ZSAD, steps 3 to 5: the match window's sum from its masked column sums, its mean, and
      // the difference of the means, negated: the terms are b - m + (mean_m - mean_b).
      /* verilator lint_off UNUSEDSIGNAL */  // ZSAD only
      wire signed [TERM_W-1:0] mean_offset;
      /* verilator lint_on UNUSEDSIGNAL */
      if (ZERO_MEAN != 0) begin : zero_mean
        wire [WINSUM_W-1:0] match_sum;
        fpstereo_sum_tree #(.N(SPAN), .IN_W(COLUMN_SUM_W), .SUM_W(WINSUM_W)) match_total (
          .clk(clk), .en(en), .values(view_sums_masked[l*COLUMN_SUM_W +: SPAN*COLUMN_SUM_W]), .sum(match_sum));
        reg [WINSUM_W-1:0] match_sum_q;
        reg [7:0]          match_mean_q;
        reg signed [TERM_W-1:0] mean_offset_q;
        always @(posedge clk)
          if (en) begin
            match_sum_q <= match_sum;
            /* verilator lint_off WIDTH */  // constant multiply and shift, cut to the 8-bit mean
            match_mean_q <= (match_sum_q * MEAN_MUL) >> MEAN_SHIFT;
            /* verilator lint_on WIDTH */
            mean_offset_q <= $signed({2'b00, match_mean_q}) - $signed({2'b00, base_mean_d});
          end
        assign mean_offset = mean_offset_q;
      end else begin : no_mean
        assign mean_offset = {TERM_W{1'b0}};
      end

      // Step 7 (ZSAD; SAD and SHD step 3): the row sums of the elements' magnitudes.
      wire [SPAN*COST_W-1:0] row_sums;
      for (i = 0; i < SPAN; i = i + 1) begin : row
        wire [SPAN*MAG_W-1:0] magnitudes;
        wire [SPAN-1:0]       negative;
        for (k = 0; k < SPAN; k = k + 1) begin : element
          // window column k (left to right) is view column l + SPAN - 1 - k
          wire [ELEM_W-1:0] b = base_d[(i*SPAN + k)*ELEM_W +: ELEM_W];
          wire [ELEM_W-1:0] m = view_d[(l + SPAN - 1 - k)*COLUMN_W + i*ELEM_W +: ELEM_W];
          if (HAMMING != 0) begin : code
            reg [MAG_W-1:0] distance;
            integer e;
            always @* begin
              distance = 0;
              for (e = 0; e < ELEM_W; e = e + 1)
                distance = distance + {{(MAG_W-1){1'b0}}, b[e] ^ m[e]};
            end
            assign magnitudes[k*MAG_W +: MAG_W] = distance;
            assign negative[k] = 1'b0;
          end else begin : pixel
            wire [TERM_W-1:0] term;
            if (ZERO_MEAN != 0) begin : zero_mean
              assign term = {{(TERM_W-ELEM_W){1'b0}}, b} - {{(TERM_W-ELEM_W){1'b0}}, m} + mean_offset;
            end else begin : plain
              assign term = {{(TERM_W-ELEM_W){1'b0}}, b} - {{(TERM_W-ELEM_W){1'b0}}, m};
            end
            // |term| = (term xor sign) + sign: the xor joins the row sum's first adders, and
            // the row's signs are counted and added once.
            assign negative[k] = term[TERM_W-1];
            assign magnitudes[k*MAG_W +: MAG_W] = term[MAG_W-1:0] ^ {MAG_W{negative[k]}};
          end
        end
        // The pairs' sums are registered (ZSAD step 6, otherwise step 2), so that the terms and
        // the row sum are not one path.
        wire [COST_W-1:0]  magnitude_sum;
        wire [SIGNS_W-1:0] sign_count;
        fpstereo_sum_tree #(.N(SPAN), .IN_W(MAG_W), .SUM_W(COST_W), .REGISTER_LEVEL(PAIR_STEP)) magnitude_total (
          .clk(clk), .en(en), .values(magnitudes), .sum(magnitude_sum));
        fpstereo_sum_tree #(.N(SPAN), .IN_W(1), .SUM_W(SIGNS_W), .REGISTER_LEVEL(PAIR_STEP)) sign_total (
          .clk(clk), .en(en), .values(negative), .sum(sign_count));
        reg [COST_W-1:0] row_sum_q;
        always @(posedge clk)
          if (en) row_sum_q <= magnitude_sum + {{(COST_W-SIGNS_W){1'b0}}, sign_count};
        assign row_sums[i*COST_W +: COST_W] = row_sum_q;
      end

      // The total.
      wire [COST_W-1:0] total;
      fpstereo_sum_tree #(.N(SPAN), .IN_W(COST_W), .SUM_W(COST_W)) row_total (
        .clk(clk), .en(en), .values(row_sums), .sum(total));
      always @(posedge clk)
        if (en) costs[l*COST_W +: COST_W] <= outside_d ? COST_MAX[COST_W-1:0] : total;
    end
  endgenerate
endmodule
`resetall
