`resetall
`default_nettype none
// Cost stage for SAD and ZSAD: the zero-extended base window, and the match window's newest
// column, which enters the match ring (plus, for ZSAD, the base window's mean and the column's
// sum). The ring serves later centres too, so the column is zero-extended by its own position.
// history_x / history_y / history_slot are the centre whose costs the lanes compute in this slot.
// ZSAD spreads the base window's mean over three shifts after the window's register (its row
// sums, their total, the constant multiply), so the window, its position and the match column
// wait two shifts longer than for SAD. fpstereo_cost_history holds the window and its centre,
// and the match columns, with the disparity offset's delays.
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
  endgenerate
  wire [N*N*8-1:0] base_masked;
  fpstereo_window_mask #(.N(N), .WORD_W(8)) base_mask (
    .window(window_left), .row_valid(row_valid), .col_valid(col_valid), .masked(base_masked));
  localparam POSITION_W = X_W + SIGNED_Y_W + COST_ROW_W;
  localparam COLUMN_W = N*8 + COLUMN_SUM_W;
  // The match window's newest column, zero outside the image, and its sum.
  reg [N*8-1:0] newest_column;
  integer e;
  always @*
    for (e = 0; e < N; e = e + 1)
      newest_column[e*8 +: 8] = newest_row_valid[e] ? window_right[(e*N + N - 1)*8 +: 8] : 8'd0;
  wire [COLUMN_SUM_W-1:0] newest_sum;
  fpstereo_sum_tree #(.N(N), .IN_W(8), .SUM_W(COLUMN_SUM_W)) newest_total (.clk(clk), .en(shift), .values(newest_column), .sum(newest_sum));
  // Registered with the window (shift k): the match column and its sum. The base window is held
  // with its position (transform_* lags the window by one, so the position is a shift later)
  // and registered once more.
  reg  [COLUMN_W-1:0]   column_t;
  wire [COLUMN_W-1:0]   column_l;
  wire [N*N*8-1:0]      base_t;
  reg  [N*N*8-1:0]      base_h;
  wire [POSITION_W-1:0] position_h;
  always @(posedge clk)
    if (shift) begin
      column_t <= {newest_column, newest_sum};
      base_h   <= base_t;
    end
  wire [(UF+N-1)*COLUMN_W-1:0] view_columns;
  fpstereo_cost_history #(.BASE_W(N*N*8), .POSITION_W(POSITION_W), .COLUMN_W(COLUMN_W), .SPAN(N), .DMAX(DMAX),
                          .UF(UF), .G_W(G_W), .MIN_DISP(MIN_DISP)) cost_history (
    .clk(clk), .adv(adv), .slot_end(slot_end), .shift(shift), .base(base_masked),
    .position({transform_x, transform_y, transform_slot}), .column(column_l), .base_held(base_t),
    .position_held(position_h), .view(view_columns));
  // The ring's columns, split into the pixels and their sums the lanes read.
  wire [(UF+N-1)*N*8-1:0]          view;
  wire [(UF+N-1)*COLUMN_SUM_W-1:0] view_sums;
  genvar c;
  generate
    for (c = 0; c < UF + N - 1; c = c + 1) begin : split
      assign {view[c*N*8 +: N*8], view_sums[c*COLUMN_SUM_W +: COLUMN_SUM_W]} = view_columns[c*COLUMN_W +: COLUMN_W];
    end
  endgenerate
  // ZSAD: the match column, and the base window with its position, wait two shifts more for the
  // base window's mean (the column before the ring, the window after it).
  wire [N*N*8-1:0] base_l;
  /* verilator lint_off UNUSEDSIGNAL */  // ZSAD only
  wire [7:0]          base_mean;
  /* verilator lint_on UNUSEDSIGNAL */
  generate
    if (ZERO_MEAN != 0) begin : mean_wait
      fpstereo_delay #(.WIDTH(COLUMN_W), .DEPTH(2)) column_wait (
        .clk(clk), .rst(1'b0), .en(shift), .in(column_t), .out(column_l));
      fpstereo_delay #(.WIDTH(N*N*8 + POSITION_W), .DEPTH(2)) base_wait (
        .clk(clk), .rst(1'b0), .en(shift), .in({base_h, position_h}),
        .out({base_l, history_x, history_y, history_slot}));
      // The base window's mean over three shifts from the held window (its row sums at shift
      // k + 1, their total at k + 2, the mean at k + 3).
      fpstereo_window_mean #(.N(N), .COLUMN_SUM_W(COLUMN_SUM_W), .MEAN_MUL(MEAN_MUL), .MEAN_SHIFT(MEAN_SHIFT)) base_mean_of (
        .clk(clk), .en(shift), .window(base_t), .mean(base_mean));
    end else begin : no_wait
      assign column_l = column_t;
      assign {base_l, history_x, history_y, history_slot} = {base_h, position_h};
      assign base_mean = 8'd0;
    end
  endgenerate
  fpstereo_window_cost_lanes #(.ZERO_MEAN(ZERO_MEAN), .HAMMING(0), .ELEM_W(8), .SPAN(N), .UF(UF),
                               .COST_W(COST_W), .COST_MAX(COST_MAX), .GROUP_W(G_W), .X_W(X_W),
                               .COLUMN_SUM_W(COLUMN_SUM_W), .MEAN_MUL(MEAN_MUL), .MEAN_SHIFT(MEAN_SHIFT), .MIN_DISP(MIN_DISP),
                               .LAT(LAT)) lanes (
    .clk(clk), .en(adv), .base(base_l), .base_mean(base_mean), .view(view), .view_sums(view_sums),
    .group(group), .x(history_x), .width(frame_width), .costs(costs));
endmodule
`resetall
