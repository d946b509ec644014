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
// Where the match centre lies left of the image (x < d) the cost is COST_MAX. Register steps
// (LAT): the column masks and the border flag; ZSAD: the match window's sum, then its mean, then
// the difference of the means; the row sums of the elements' terms; the total.
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
  parameter COLSUM_W = 11,
  parameter MEAN_MUL = 1,
  parameter MEAN_SHIFT = 0,
  // the latency the instantiating stage plans with (checked: 3, ZSAD 6)
  parameter LAT = 3
) (
  input  wire                                clk,
  input  wire                                en,
  input  wire [SPAN*SPAN*ELEM_W-1:0]         base,
  /* verilator lint_off UNUSEDSIGNAL */  // the means serve ZSAD only
  input  wire [7:0]                          base_mean,
  input  wire [(UF+SPAN-1)*COLSUM_W-1:0]     view_sums,
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
    if (LAT != (ZERO_MEAN != 0 ? 6 : 3)) begin : invalid_LAT
      fpstereo_invalid_parameters_window_cost_lanes_LAT_is_not_the_latency failed ();
    end
  endgenerate
  localparam R = SPAN / 2;
  localparam COLUMN_W = SPAN * ELEM_W;
  // wide enough for x + SPAN and for any disparity plus R
  localparam D_W = (X_W > GROUP_W + 9 ? X_W : GROUP_W + 9) + 2;
  localparam WINSUM_W = COLSUM_W + 4;  // a window's pixel sum (SPAN <= 11 columns)
  localparam TERM_W = 11;              // |(b - m) - delta| < 2^11 for 8-bit pixels
  wire [D_W-1:0] x_wide = {{(D_W-X_W){1'b0}}, x};
  wire [D_W-1:0] group_base = {{(D_W-GROUP_W){1'b0}}, group} * UF[D_W-1:0];

  // The elements' terms: |(b - m) - delta| of pixels, or the Hamming distance of codes.
  localparam MAG_W = HAMMING != 0 ? $clog2(ELEM_W + 1) : TERM_W;
  localparam MEAN_STEPS = ZERO_MEAN != 0 ? 3 : 0;

  // The windows wait for the masks (and the ZSAD means): 1 + MEAN_STEPS steps; the base
  // window's mean meets the match window's after three.
  wire [SPAN*SPAN*ELEM_W-1:0]        base_d;
  wire [(UF+SPAN-1)*SPAN*ELEM_W-1:0] view_d;
  /* verilator lint_off UNUSEDSIGNAL */  // ZSAD only
  wire [7:0]                         base_mean_d;
  /* verilator lint_on UNUSEDSIGNAL */
  fpstereo_delay #(.WIDTH(SPAN*SPAN*ELEM_W + (UF+SPAN-1)*SPAN*ELEM_W), .DEPTH(1 + MEAN_STEPS)) windows_wait (
    .clk(clk), .rst(1'b0), .en(en), .in({base, view}), .out({base_d, view_d}));
  fpstereo_delay #(.WIDTH(8), .DEPTH(3)) base_mean_wait (
    .clk(clk), .rst(1'b0), .en(en), .in(base_mean), .out(base_mean_d));
  /* verilator lint_off UNUSEDSIGNAL */  // ZSAD only
  reg [(UF+SPAN-1)*COLSUM_W-1:0] view_sums_q;
  /* verilator lint_on UNUSEDSIGNAL */
  always @(posedge clk)
    if (en) view_sums_q <= view_sums;

  genvar l, i, j;
  generate
    for (l = 0; l < UF; l = l + 1) begin : lane
      wire [D_W-1:0] d = group_base + l[D_W-1:0];
      // Window column j (left to right) is view column l + SPAN - 1 - j; it lies inside the
      // image where 0 <= x - d + (j - R) < width.
      wire [SPAN-1:0] column_valid;
      for (j = 0; j < SPAN; j = j + 1) begin : column
        wire [D_W-1:0] position = x_wide + j[D_W-1:0];  // x - d + (j - R) + d + R
        assign column_valid[j] = position >= d + R[D_W-1:0] && position < d + R[D_W-1:0] + {{(D_W-X_W){1'b0}}, width};
      end

      // Step 1: the masks and the border flag, which wait with the windows.
      reg  [SPAN-1:0] column_valid_q;
      reg             outside_q;
      always @(posedge clk)
        if (en) begin
          column_valid_q <= column_valid;
          outside_q <= x_wide < d;
        end
      wire [SPAN-1:0] valid_d;
      wire            outside_d;
      if (MEAN_STEPS > 0) begin : valid_wait
        fpstereo_delay #(.WIDTH(SPAN), .DEPTH(MEAN_STEPS)) masks (
          .clk(clk), .rst(1'b0), .en(en), .in(column_valid_q), .out(valid_d));
      end else begin : valid_now
        assign valid_d = column_valid_q;
      end
      fpstereo_delay #(.WIDTH(1), .DEPTH(LAT - 2)) outside_wait (
        .clk(clk), .rst(1'b0), .en(en), .in(outside_q), .out(outside_d));

      // ZSAD, steps 2 to 4: the match window's sum from its column sums, its mean, and the
      // difference of the means.
      wire signed [9:0] delta;
      if (ZERO_MEAN) begin : zero_mean
        reg [WINSUM_W-1:0] match_sum;
        integer c;
        always @* begin
          match_sum = 0;
          for (c = 0; c < SPAN; c = c + 1)
            if (column_valid_q[c])
              match_sum = match_sum + {{(WINSUM_W-COLSUM_W){1'b0}}, view_sums_q[(l + SPAN - 1 - c)*COLSUM_W +: COLSUM_W]};
        end
        reg [WINSUM_W-1:0] match_sum_q;
        reg [7:0]          match_mean_q;
        reg signed [9:0]   delta_q;
        always @(posedge clk)
          if (en) begin
            match_sum_q <= match_sum;
            /* verilator lint_off WIDTH */  // constant multiply and shift, cut to the 8-bit mean
            match_mean_q <= (match_sum_q * MEAN_MUL) >> MEAN_SHIFT;
            /* verilator lint_on WIDTH */
            delta_q <= $signed({2'b00, base_mean_d}) - $signed({2'b00, match_mean_q});
          end
        assign delta = delta_q;
      end else begin : no_mean
        assign delta = 10'sd0;
      end

      // The per-row sums of the elements' terms.
      wire [SPAN*COST_W-1:0] row_sums;
      for (i = 0; i < SPAN; i = i + 1) begin : row
        reg [SPAN*MAG_W-1:0] terms;
        integer k, b2;
        reg [ELEM_W-1:0] bv, mv;
        reg signed [TERM_W-1:0] diff;
        reg [MAG_W-1:0] magnitude;  // its own assignment: in the sum, -diff would widen first
        always @* begin
          for (k = 0; k < SPAN; k = k + 1) begin
            bv = base_d[(i*SPAN + k)*ELEM_W +: ELEM_W];
            mv = valid_d[k] ? view_d[(l + SPAN - 1 - k)*COLUMN_W + i*ELEM_W +: ELEM_W] : {ELEM_W{1'b0}};
            magnitude = 0;
            if (HAMMING) begin
              for (b2 = 0; b2 < ELEM_W; b2 = b2 + 1) magnitude = magnitude + {{(MAG_W-1){1'b0}}, bv[b2] ^ mv[b2]};
            end else begin
              /* verilator lint_off WIDTH */  // 8-bit pixels widened into the signed difference
              diff = $signed({3'b000, bv}) - $signed({3'b000, mv}) - delta;
              magnitude = diff < 0 ? -diff : diff;
              /* verilator lint_on WIDTH */
            end
            terms[k*MAG_W +: MAG_W] = magnitude;
          end
        end
        reg [COST_W-1:0] row_sum;
        integer t;
        always @* begin
          row_sum = 0;
          for (t = 0; t < SPAN; t = t + 1) row_sum = row_sum + {{(COST_W-MAG_W){1'b0}}, terms[t*MAG_W +: MAG_W]};
        end
        reg [COST_W-1:0] row_sum_q;
        always @(posedge clk)
          if (en) row_sum_q <= row_sum;
        assign row_sums[i*COST_W +: COST_W] = row_sum_q;
      end

      // The total.
      reg [COST_W-1:0] total;
      integer t;
      always @* begin
        total = 0;
        for (t = 0; t < SPAN; t = t + 1) total = total + row_sums[t*COST_W +: COST_W];
      end
      always @(posedge clk)
        if (en) costs[l*COST_W +: COST_W] <= outside_d ? COST_MAX[COST_W-1:0] : total;
    end
  endgenerate
endmodule
`resetall
