`resetall
`default_nettype none
// Sub-pixel stage (docs/semantics.md, section 4): the winner-take-all's word {invalid, D}
// refined to {invalid, D * 2^K + f} with the aggregated sums at D - 1, D and D + 1. The sums of
// the pixel's G groups wait in a history of TREE_LAT + G steps (the winner-take-all's tree takes
// TREE_LAT): in the step after the pixel's word the three sums are selected by D, a register
// (sums beyond the range read as 0; fpstereo_subpixel_fit keeps D whole there), then the fit
// takes K + 3 steps. Latency K + 5 steps; the tag travels along. An invalid word stays the
// invalid word (the flag alone).
module fpstereo_subpixel #(
  parameter UF = 8,
  parameter G = 2,
  parameter SUM_W = 10,
  parameter DMAX = 16,
  parameter DISP_W = 4,
  parameter K = 4,
  parameter EQUIANGULAR = 1,
  // bits of the refined disparity: enough for (DMAX - 1) * 2^K
  parameter OUT_W = 8,
  parameter TREE_LAT = 1,
  parameter TAG_W = 8
) (
  input  wire                clk,
  input  wire                restart,
  input  wire                adv,
  input  wire [UF*SUM_W-1:0] sums,
  input  wire [TAG_W-1:0]    tag,
  input  wire [DISP_W:0]     word,
  output wire [TAG_W-1:0]    tag_out,
  output wire [OUT_W:0]      word_out
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (UF < 1 || G < 1 || DMAX != UF * G || DMAX - 1 >= (1 << DISP_W)) begin : invalid_DMAX
      fpstereo_invalid_parameters_subpixel_DMAX_is_not_UF_times_G_within_DISP_W failed ();
    end
    if (TREE_LAT < 1) begin : invalid_TREE_LAT
      fpstereo_invalid_parameters_subpixel_TREE_LAT_below_1 failed ();
    end
  endgenerate
  localparam DEPTH = TREE_LAT + G;
  localparam ROW_W = UF * SUM_W;
  localparam SLOTS = 1 << DISP_W;  // every value of D, those beyond DMAX reading 0

  wire invalid;
  fpstereo_delay #(.WIDTH(TAG_W + 1), .DEPTH(K + 5)) tag_wait (
    .clk(clk), .rst(restart), .en(adv), .in({tag, word[DISP_W]}), .out({tag_out, invalid}));

  // The history: entry j holds the sums that came j + 1 steps ago.
  reg [DEPTH*ROW_W-1:0] history;
  always @(posedge clk)
    if (adv) history <= {history[(DEPTH-1)*ROW_W-1:0], sums};

  // In the selection step, disparity g * UF + l is lane l of entry G + TREE_LAT - 1 - g.
  wire [SLOTS*SUM_W-1:0] below, at, above;  // S(D - 1), S(D), S(D + 1) at index D
  genvar v;
  generate
    for (v = 0; v < SLOTS; v = v + 1) begin : slot
      if (v < DMAX) begin : in_range
        assign at[v*SUM_W +: SUM_W] = history[((G + TREE_LAT - 1 - v / UF) * UF + v % UF) * SUM_W +: SUM_W];
      end else begin : beyond
        assign at[v*SUM_W +: SUM_W] = {SUM_W{1'b0}};
      end
      if (v > 0) begin : has_below
        assign below[v*SUM_W +: SUM_W] = at[(v-1)*SUM_W +: SUM_W];
      end else begin : no_below
        assign below[v*SUM_W +: SUM_W] = {SUM_W{1'b0}};
      end
      if (v < SLOTS - 1) begin : has_above
        assign above[v*SUM_W +: SUM_W] = at[(v+1)*SUM_W +: SUM_W];
      end else begin : no_above
        assign above[v*SUM_W +: SUM_W] = {SUM_W{1'b0}};
      end
    end
  endgenerate

  reg [DISP_W-1:0] d_q, d_selected;
  reg [SUM_W-1:0]  left_q, best_q, right_q;
  always @(posedge clk)
    if (adv) begin
      d_q <= word[DISP_W-1:0];
      d_selected <= d_q;
      left_q <= below[d_q*SUM_W +: SUM_W];
      best_q <= at[d_q*SUM_W +: SUM_W];
      right_q <= above[d_q*SUM_W +: SUM_W];
    end

  wire [OUT_W-1:0] refined;
  fpstereo_subpixel_fit #(.DMAX(DMAX), .DISP_W(DISP_W), .SUM_W(SUM_W), .K(K), .EQUIANGULAR(EQUIANGULAR),
                          .OUT_W(OUT_W)) fit (
    .clk(clk), .en(adv), .d(d_selected), .left(left_q), .best(best_q), .right(right_q), .refined(refined));
  assign word_out = invalid ? {1'b1, {OUT_W{1'b0}}} : {1'b0, refined};
endmodule
`resetall
