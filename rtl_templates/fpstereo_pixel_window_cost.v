`resetall
`default_nettype none
// Cost stage for SAD and ZSAD: the zero-extended base window, and the match window's newest
// column, which enters the match ring (plus, for ZSAD, the base window's mean and the column's
// sum). The ring serves later centres too, so the column is zero-extended by its own position.
// history_x / history_y / history_slot are the centre whose costs the lanes compute in this slot.
// ZSAD spreads the base window's mean over three shifts after the window's register (its row
// sums, their total, the constant multiply), so the window, its position and the match column
// wait two shifts longer than for SAD. A disparity offset MIN_DISP delays the match columns by
// MIN_DISP slots before the rings or, when negative, the base window and its centre by -MIN_DISP
// slots (fpstereo_offset_delays).
module fpstereo_pixel_window_cost #(
  parameter N = 5,
  // ZSAD: subtract the windows' means
  parameter ZERO_MEAN = 0,
  parameter DMAX = 32,
  parameter UF = 8,
  parameter COST_W = 13,
  parameter COST_MAX = 6375,
  // width of a window column's pixel sum; ZSAD: mean = (sum * MEAN_MUL) >> MEAN_SHIFT
  parameter COLUMN_SUM_W = 11,
  parameter MEAN_MUL = 1,
  parameter MEAN_SHIFT = 0,
  parameter COST_ROW_W = 1,
  parameter X_W = 7,
  parameter SIGNED_Y_W = 8,
  parameter G_W = 2,
  parameter MIN_DISP = 0,
  // the cost lanes' latency the stage plans with (fpstereo_window_cost_lanes checks it)
  parameter LAT = 4
) (
  input  wire                   clk,
  input  wire                   adv,
  input  wire                   slot_end,
  input  wire                   shift,
  input  wire [G_W-1:0]         group,
  input  wire [X_W-1:0]         frame_width,
  input  wire [N*N*8-1:0]       window_left,
  input  wire [N*N*8-1:0]       window_right,
  input  wire [N-1:0]           row_valid,
  input  wire [N-1:0]           col_valid,
  input  wire [N-1:0]           newest_row_valid,
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
    if (N < 3 || N % 2 == 0) begin : invalid_N
      fpstereo_invalid_parameters_pixel_window_cost_N_is_not_odd_and_at_least_3 failed ();
    end
    if (255 * N >= (1 << COLUMN_SUM_W)) begin : invalid_COLUMN_SUM_W
      fpstereo_invalid_parameters_pixel_window_cost_COLUMN_SUM_W_does_not_hold_255_N failed ();
    end
    if (UF < 1 || DMAX % (UF > 0 ? UF : 1) != 0 || DMAX / (UF > 0 ? UF : 1) - 1 >= (1 << G_W)) begin : invalid_G_W
      fpstereo_invalid_parameters_pixel_window_cost_needs_DMAX_a_multiple_of_UF_and_G_W_holding_the_group failed ();
    end
  endgenerate
  wire [N*N*8-1:0] base_masked, base_o;
  fpstereo_window_mask #(.N(N), .WORD_W(8)) base_mask (
    .window(window_left), .row_valid(row_valid), .col_valid(col_valid), .masked(base_masked));
  wire [X_W-1:0]         transform_x_o;
  wire signed [SIGNED_Y_W-1:0] transform_y_o;
  wire [COST_ROW_W-1:0]    transform_slot_o;
  localparam WINSUM_W = COLUMN_SUM_W + 4;  // a window's pixel sum (N <= 11)
  // The match window's newest column, zero outside the image, and its sum.
  reg [N*8-1:0] newest_column;
  integer e;
  always @*
    for (e = 0; e < N; e = e + 1)
      newest_column[e*8 +: 8] = newest_row_valid[e] ? window_right[(e*N + N - 1)*8 +: 8] : 8'd0;
  wire [COLUMN_SUM_W-1:0] newest_sum;
  fpstereo_sum_tree #(.N(N), .IN_W(8), .SUM_W(COLUMN_SUM_W)) newest_total (.clk(clk), .en(shift), .values(newest_column), .sum(newest_sum));
  // Registered with the window (shift k): the window and the match column; the window's position
  // a shift later (transform_* lags the window by one), with the window again.
  reg [N*N*8-1:0]                base_t, base_h;
  reg [N*8-1:0]                  column_t;
  reg [COLUMN_SUM_W-1:0]             column_sum_t;
  reg [X_W+SIGNED_Y_W+COST_ROW_W-1:0]    position_h;
  always @(posedge clk)
    if (shift) begin
      base_t       <= base_o;
      column_t     <= newest_column;
      column_sum_t <= newest_sum;
      base_h       <= base_t;
      position_h   <= {transform_x_o, transform_y_o, transform_slot_o};
    end
  // ZSAD: all of it waits two shifts more for the base window's mean.
  wire [N*N*8-1:0]    base_l;
  wire [N*8-1:0]      column_l;
  wire [COLUMN_SUM_W-1:0] column_sum_l;
  /* verilator lint_off UNUSEDSIGNAL */  // ZSAD only
  wire [7:0]          base_mean;
  /* verilator lint_on UNUSEDSIGNAL */
  genvar r;
  generate
    if (ZERO_MEAN != 0) begin : mean_wait
      fpstereo_delay #(.WIDTH(N*N*8 + N*8 + COLUMN_SUM_W + X_W + SIGNED_Y_W + COST_ROW_W), .DEPTH(2)) shift_wait (
        .clk(clk), .rst(1'b0), .en(shift), .in({base_h, column_t, column_sum_t, position_h}),
        .out({base_l, column_l, column_sum_l, history_x, history_y, history_slot}));
      // The base window's mean over three shifts from the registered window: its row sums at
      // shift k + 1, their total at k + 2, the mean (a constant multiply) at k + 3.
      wire [N*COLUMN_SUM_W-1:0] row_sums;
      for (r = 0; r < N; r = r + 1) begin : row
        fpstereo_sum_tree #(.N(N), .IN_W(8), .SUM_W(COLUMN_SUM_W)) row_total (
          .clk(clk), .en(shift), .values(base_t[r*N*8 +: N*8]), .sum(row_sums[r*COLUMN_SUM_W +: COLUMN_SUM_W]));
      end
      reg  [N*COLUMN_SUM_W-1:0] row_sums_q;
      wire [WINSUM_W-1:0]   total;
      fpstereo_sum_tree #(.N(N), .IN_W(COLUMN_SUM_W), .SUM_W(WINSUM_W)) window_total (
        .clk(clk), .en(shift), .values(row_sums_q), .sum(total));
      reg  [WINSUM_W-1:0]   total_q;
      reg  [7:0]            mean_q;
      always @(posedge clk)
        if (shift) begin
          row_sums_q <= row_sums;
          total_q <= total;
          /* verilator lint_off WIDTH */  // constant multiply and shift, cut to the 8-bit mean
          mean_q <= (total_q * MEAN_MUL) >> MEAN_SHIFT;
          /* verilator lint_on WIDTH */
        end
      assign base_mean = mean_q;
    end else begin : no_wait
      assign {base_l, column_l, column_sum_l, history_x, history_y, history_slot} =
             {base_h, column_t, column_sum_t, position_h};
      assign base_mean = 8'd0;
    end
  endgenerate
  wire [N*8-1:0]      column_o;
  wire [COLUMN_SUM_W-1:0] column_sum_o;
  fpstereo_offset_delays #(.BASE_W(N*N*8 + X_W + SIGNED_Y_W + COST_ROW_W), .MATCH_W(N*8 + COLUMN_SUM_W), .MIN_DISP(MIN_DISP)) offset (
    .clk(clk), .shift(shift), .base({base_masked, transform_x, transform_y, transform_slot}),
    .match({column_l, column_sum_l}), .base_out({base_o, transform_x_o, transform_y_o, transform_slot_o}),
    .match_out({column_o, column_sum_o}));
  wire [(UF+N-1)*N*8-1:0]      view;
  wire [(UF+N-1)*COLUMN_SUM_W-1:0] view_sums;
  fpstereo_match_ring #(.COLUMN_W(N*8), .SPAN(N), .DMAX(DMAX), .UF(UF)) match_history (
    .clk(clk), .en(adv), .slot_end(slot_end), .column_in(column_o), .view(view));
  fpstereo_match_ring #(.COLUMN_W(COLUMN_SUM_W), .SPAN(N), .DMAX(DMAX), .UF(UF)) match_sums (
    .clk(clk), .en(adv), .slot_end(slot_end), .column_in(column_sum_o), .view(view_sums));
  fpstereo_window_cost_lanes #(.ZERO_MEAN(ZERO_MEAN), .HAMMING(0), .ELEM_W(8), .SPAN(N), .UF(UF),
                               .COST_W(COST_W), .COST_MAX(COST_MAX), .GROUP_W(G_W), .X_W(X_W),
                               .COLUMN_SUM_W(COLUMN_SUM_W), .MEAN_MUL(MEAN_MUL), .MEAN_SHIFT(MEAN_SHIFT), .MIN_DISP(MIN_DISP),
                               .LAT(LAT)) lanes (
    .clk(clk), .en(adv), .base(base_l), .base_mean(base_mean), .view(view), .view_sums(view_sums),
    .group(group), .x(history_x), .width(frame_width), .costs(costs));
endmodule
`resetall
