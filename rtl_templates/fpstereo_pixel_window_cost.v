`resetall
`default_nettype none
// Cost stage for SAD and ZSAD: the zero-extended base window, and the match window's newest
// column, which enters the match ring (plus, for ZSAD, the base window's mean and the column's
// sum). The ring serves later centres too, so the column is zero-extended by its own position.
// history_x / history_y / history_slot are the centre whose costs the lanes compute in this slot.
module fpstereo_pixel_window_cost #(
  parameter N = 5,
  // ZSAD: subtract the windows' means
  parameter ZERO_MEAN = 0,
  parameter DMAX = 32,
  parameter UF = 8,
  parameter COST_W = 13,
  parameter COST_MAX = 6375,
  // width of a window column's pixel sum; ZSAD: mean = (sum * MEAN_MUL) >> MEAN_SHIFT
  parameter COLSUM_W = 11,
  parameter MEAN_MUL = 1,
  parameter MEAN_SHIFT = 0,
  parameter COST_K_W = 1,
  parameter X_W = 7,
  parameter YS_W = 8,
  parameter G_W = 2,
  // the cost lanes' latency the stage plans with (fpstereo_window_cost_lanes checks it)
  parameter LAT = 3
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
  input  wire signed [YS_W-1:0] transform_y,
  input  wire [COST_K_W-1:0]    transform_slot,
  output reg  [X_W-1:0]         history_x,
  output reg  signed [YS_W-1:0] history_y,
  output reg  [COST_K_W-1:0]    history_slot,
  output wire [UF*COST_W-1:0]   costs
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 3 || N % 2 == 0) begin : invalid_N
      fpstereo_invalid_parameters_pixel_window_cost_N_is_not_odd_and_at_least_3 failed ();
    end
    if (255 * N >= (1 << COLSUM_W)) begin : invalid_COLSUM_W
      fpstereo_invalid_parameters_pixel_window_cost_COLSUM_W_does_not_hold_255_N failed ();
    end
    if (UF < 1 || DMAX % (UF > 0 ? UF : 1) != 0 || DMAX / (UF > 0 ? UF : 1) - 1 >= (1 << G_W)) begin : invalid_G_W
      fpstereo_invalid_parameters_pixel_window_cost_needs_DMAX_a_multiple_of_UF_and_G_W_holding_the_group failed ();
    end
  endgenerate
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
  // ZSAD: the base window's sum is registered with the window, its mean (a constant multiply)
  // with the next shift.
  reg [N*N*8-1:0]    base_t, base_h;
  reg [N*8-1:0]      column_t;
  reg [COLSUM_W-1:0] column_sum_t;
  reg [COLSUM_W+7:0] base_sum_t;
  reg [7:0]          base_mean_h;
  /* verilator lint_off WIDTH */  // constant multiply and shift, cut to the 8-bit mean
  wire [7:0] base_mean = (base_sum_t * MEAN_MUL) >> MEAN_SHIFT;
  /* verilator lint_on WIDTH */
  always @(posedge clk)
    if (shift) begin
      history_slot <= transform_slot;
      base_t       <= base_masked;
      column_t     <= newest_column;
      column_sum_t <= newest_sum;
      base_sum_t   <= base_sum;
      base_h       <= base_t;
      base_mean_h  <= base_mean;
      history_x    <= transform_x;
      history_y    <= transform_y;
    end
  wire [(UF+N-1)*N*8-1:0]      view;
  wire [(UF+N-1)*COLSUM_W-1:0] view_sums;
  fpstereo_match_ring #(.COLUMN_W(N*8), .SPAN(N), .DMAX(DMAX), .UF(UF)) match_history (
    .clk(clk), .en(adv), .slot_end(slot_end), .column_in(column_t), .view(view));
  fpstereo_match_ring #(.COLUMN_W(COLSUM_W), .SPAN(N), .DMAX(DMAX), .UF(UF)) match_sums (
    .clk(clk), .en(adv), .slot_end(slot_end), .column_in(column_sum_t), .view(view_sums));
  fpstereo_window_cost_lanes #(.ZERO_MEAN(ZERO_MEAN), .HAMMING(0), .ELEM_W(8), .SPAN(N), .UF(UF),
                               .COST_W(COST_W), .COST_MAX(COST_MAX), .GROUP_W(G_W), .X_W(X_W),
                               .COLSUM_W(COLSUM_W), .MEAN_MUL(MEAN_MUL), .MEAN_SHIFT(MEAN_SHIFT), .LAT(LAT)) lanes (
    .clk(clk), .en(adv), .base(base_h), .base_mean(base_mean_h), .view(view), .view_sums(view_sums),
    .group(group), .x(history_x), .width(frame_width), .costs(costs));
endmodule
`resetall
