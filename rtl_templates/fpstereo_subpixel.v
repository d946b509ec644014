`resetall
`default_nettype none
// Sub-pixel stage (docs/semantics.md, section 4): the winner-take-all's word {invalid, D}
// refined to {invalid, D * 2^K + f} with the aggregated sums at D - 1, D and D + 1. The sums of
// the pixel's G groups wait in a history of WTA_WORD_LAG + G steps (the winner-take-all's word
// lags its sums by WTA_WORD_LAG): in the step after the pixel's word the high bits of D select a
// chunk of the sums (2^LO_W of them and one on each side), in the next its low bits pick the three sums (sums
// beyond the range read as 0; fpstereo_subpixel_fit keeps D whole there): two narrow
// multiplexers in two register steps instead of one dmax:1. Then the fit takes K + 3 steps.
// Latency K + 6 steps; the tag travels along. An invalid word stays the invalid word (the flag
// alone).
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
  parameter WTA_WORD_LAG = 1,
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
    if (UF < 1 || G < 1 || DMAX != UF * G || DMAX - 1 >= (1 << DISP_W) || DISP_W < 2) begin : invalid_DMAX
      fpstereo_invalid_parameters_subpixel_DMAX_is_not_UF_times_G_within_DISP_W failed ();
    end
    if (WTA_WORD_LAG < 1) begin : invalid_WTA_WORD_LAG
      fpstereo_invalid_parameters_subpixel_WTA_WORD_LAG_below_1 failed ();
    end
  endgenerate
  localparam DEPTH = WTA_WORD_LAG + G;
  localparam ROW_W = UF * SUM_W;
  localparam SLOTS = 1 << DISP_W;  // every value of D, those beyond DMAX reading 0

  wire invalid;
  fpstereo_delay #(.WIDTH(TAG_W + 1), .DEPTH(K + 6), .RESET(1)) tag_wait (
    .clk(clk), .rst(restart), .en(adv), .in({tag, word[DISP_W]}), .out({tag_out, invalid}));

  // The history: entry j holds the sums that came j + 1 steps ago.
  reg [DEPTH*ROW_W-1:0] history;
  always @(posedge clk)
    if (adv) history <= {history[(DEPTH-1)*ROW_W-1:0], sums};

  // In the first selection step, disparity g * UF + l is lane l of entry G + WTA_WORD_LAG - 1 - g.
  // padded S(v) for v = -1 .. SLOTS, 0 outside the range. Entries and chunks sit at strides that
  // are powers of two (SUM_P, WINDOW_P bits), so that each selection is a shift by D's bits: a
  // multiplexer tree of one level per two bits.
  localparam HI_W = DISP_W / 2;
  localparam LO_W = DISP_W - HI_W;
  localparam CHUNK = 1 << LO_W;
  localparam CHUNKS = 1 << HI_W;
  localparam WINDOW = CHUNK + 2;
  localparam SUM_P = 1 << $clog2(SUM_W);
  localparam WINDOW_P = 1 << $clog2(WINDOW * SUM_P);
  wire [(SLOTS+2)*SUM_P-1:0]   padded;
  wire [CHUNKS*WINDOW_P-1:0]   windows;  // chunk c: S(c * CHUNK - 1) .. S(c * CHUNK + CHUNK)
  genvar v, c;
  generate
    for (v = -1; v <= SLOTS; v = v + 1) begin : slot
      if (v >= 0 && v < DMAX) begin : in_range
        assign padded[(v+1)*SUM_P +: SUM_P] =
            {{(SUM_P-SUM_W){1'b0}}, history[((G + WTA_WORD_LAG - 1 - v / UF) * UF + v % UF) * SUM_W +: SUM_W]};
      end else begin : beyond
        assign padded[(v+1)*SUM_P +: SUM_P] = {SUM_P{1'b0}};
      end
    end
    for (c = 0; c < CHUNKS; c = c + 1) begin : chunk
      if (WINDOW_P > WINDOW * SUM_P) begin : pad
        assign windows[c*WINDOW_P + WINDOW*SUM_P +: WINDOW_P - WINDOW*SUM_P] = {(WINDOW_P - WINDOW*SUM_P){1'b0}};
      end
      assign windows[c*WINDOW_P +: WINDOW*SUM_P] = padded[c*CHUNK*SUM_P +: WINDOW*SUM_P];
    end
  endgenerate

  reg [DISP_W-1:0]       d_q, d_chunk, d_selected;
  /* verilator lint_off UNUSEDSIGNAL */  // the entries' and the window's padding
  reg [WINDOW_P-1:0]     window_q;
  /* verilator lint_on UNUSEDSIGNAL */
  reg [SUM_W-1:0]        left_q, best_q, right_q;
  // The chunk of D's high bits; then S(D - 1), S(D), S(D + 1): its window's entries lo .. lo + 2,
  // each a shift by lo of the window moved by 0, 1 or 2 entries.
  wire [HI_W-1:0] hi = d_q[DISP_W-1:LO_W];
  wire [LO_W-1:0] lo = d_chunk[LO_W-1:0];
  /* verilator lint_off UNUSEDSIGNAL */  // the chunks above the selected one
  wire [CHUNKS*WINDOW_P-1:0] chunks_from = windows >> (hi * WINDOW_P);
  /* verilator lint_on UNUSEDSIGNAL */
  wire [WINDOW_P-1:0] chunk_selected = chunks_from[WINDOW_P-1:0];
  wire [WINDOW_P-1:0] from_best = window_q >> SUM_P, from_right = window_q >> (2 * SUM_P);
  /* verilator lint_off UNUSEDSIGNAL */  // the bits above the selected entry
  wire [WINDOW_P-1:0] left_selected = window_q >> (lo * SUM_P);
  wire [WINDOW_P-1:0] best_selected = from_best >> (lo * SUM_P);
  wire [WINDOW_P-1:0] right_selected = from_right >> (lo * SUM_P);
  /* verilator lint_on UNUSEDSIGNAL */
  always @(posedge clk)
    if (adv) begin
      d_q <= word[DISP_W-1:0];
      d_chunk <= d_q;
      window_q <= chunk_selected;
      d_selected <= d_chunk;
      left_q <= left_selected[SUM_W-1:0];
      best_q <= best_selected[SUM_W-1:0];
      right_q <= right_selected[SUM_W-1:0];
    end

  wire [OUT_W-1:0] refined;
  fpstereo_subpixel_fit #(.DMAX(DMAX), .DISP_W(DISP_W), .SUM_W(SUM_W), .K(K), .EQUIANGULAR(EQUIANGULAR),
                          .OUT_W(OUT_W)) fit (
    .clk(clk), .en(adv), .d(d_selected), .left(left_q), .best(best_q), .right(right_q), .refined(refined));
  assign word_out = invalid ? {1'b1, {OUT_W{1'b0}}} : {1'b0, refined};
endmodule
`resetall
