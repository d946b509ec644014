`resetall
`default_nettype none
// The aggregation over P strips of a row (docs/ppc-hardware.md), the core's middle when it takes
// P pixels a step (the aggregation stage places it with CODES, RAM and OUTPUT; the module tests
// drive it without them too): P aggregators side by side, each
// with K chains over its strip of ROW_SLOTS = K * SEGMENT pixels, strip p starting at pixel
// p * ROW_SLOTS. Strip p runs p * K steps behind strip 0 (its start and wrap flags wait that long)
// and its chain k works on row t - p * K - k of its row-time t, so the chain that continues a row
// in the next strip starts its first pixel K + 1 steps after the previous strip's last, as the
// chains of one aggregator do. The edges carry the 0 and 45-degree predecessors of a strip's
// first pixel from the strip to its left and the 135-degree one of its last pixel from the strip
// to its right. uf = dmax (G = 1). Each strip has its own cost read port and sums; the ports are
// the aggregator's, strip p's in bits p * width. With CODES each strip reads code entries
// ({match, base}, HAMMING: census codes, else ranks) and its own fpstereo_chain_cost computes
// the costs, the strips handing their match rings on as their rows move right. With RAM (and
// CODES) the entries come from fpstereo_strip_code_reorder instead, written in raster order a
// slot of P pixels a step (code_we, code_slot, code_row: the row modulo SLOT_ROWS; code_extra:
// adaptive P2's penalties, a slot and EXTRA_LAT steps later; below MIN_DISP 0, code_prefix: the
// first match entries of the row whose first pixel strip 0 reads next, fpstereo_chain_cost's
// prefix), and each strip's RAM holds
// (p + 1) * K rows (COST_ROWS is then unused). With RAM and no CODES (SAD and ZSAD) the RAMs hold
// cost words, adaptive P2's penalties above each (code_data: a slot's P words, written as the
// window costs leave; no BASE_WAIT, no prefix). With OUTPUT each strip's sums
// go on to a winner-take-all (fpstereo_wta, with UNIQUE fpstereo_wta_unique and its uniqueness
// check), with SUBPIXEL_BITS a sub-pixel fit (fpstereo_subpixel), with CONFIDENCE the confidence
// (fpstereo_confidence, from fpstereo_wta_unique's two best sums: UNIQUE must be set), and its
// words to fpstereo_strip_disparity_reorder, read from out_on on in raster order a slot of P pixels
// a step, each word with its confidence above it (the strips' OUT_ROWS are then (P - p) * K + 1
// and the parameter is unused). With LR1 each strip's LR1 match side writes the Dm it completes
// (dm_*); with MATCH_SIDE the module is LR2's match side instead (below), and with LR2 the check
// takes that instance's writes (match_dm_*).
module fpstereo_strip_aggregation #(
  parameter P = 2,
  parameter W = 64,
  parameter ROW_SLOTS = 32,
  parameter K = 2,
  parameter SEGMENT = 16,
  parameter UF = 8,
  parameter COST_W = 5,
  parameter COST_MAX = 24,
  parameter PATH_W = 7,
  parameter SUM_W = 9,
  parameter PATHS = 15,
  parameter LEVELS_PER_STAGE = 2,
  parameter PATH_TREE_LAT = 2,
  parameter OUT_ROWS = 3,
  parameter OUT_ROW_W = 2,
  parameter COST_AW = 10,
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter K_W = 1,
  parameter COST_ROWS = 2,
  parameter COST_ROW_W = 1,
  parameter CODES = 0,
  /* verilator lint_off UNUSEDPARAM */  // with CODES
  parameter HAMMING = 1,
  parameter CODE_W = 8,
  // the cost lanes' latency with CODES (2, or 3 for census codes above 48 bits)
  parameter LANES_LAT = 2,
  // with CODES: the entries' match codes are pixel x - MIN_DISP's (fpstereo_chain_cost)
  parameter MIN_DISP = 0,
  // with CODES: an entry's bits (the code, with the fused cost its feature above) and the fused
  // cost's term (fpstereo_chain_cost's WEIGHT, TRUNC, FEATURE_W, GRADIENT; WEIGHT 0: none), and
  // the chain costs' latency (LANES_LAT, or the fused term's)
  parameter ENTRY_W = CODE_W,
  parameter WEIGHT = 0,
  parameter TRUNC = 20,
  parameter FEATURE_W = 8,
  parameter GRADIENT = 0,
  parameter CHAIN_LAT = LANES_LAT,
  // with CODES: 0, or adaptive P2's penalties above each entry (a P2 field of PATH_W bits per
  // enabled path), which leave with the pixel's costs to the aggregator (its PENALTIES)
  parameter EXTRA_W = 0,
  /* verilator lint_on UNUSEDPARAM */
  // steps from cost_raddr to the aggregator's cost word: 1 (the RAM), or with CODES 2 + LANES_LAT
  parameter COST_LEAD = 1,
  /* verilator lint_off UNUSEDPARAM */  // with RAM
  parameter RAM = 0,
  parameter SLOT_ROWS = 10,
  parameter SLOT_W = 4,
  // with RAM and EXTRA_W: the steps adaptive P2's penalties come after their slot's entries (the
  // code writes wait as long, fpstereo_strip_code_reorder)
  parameter EXTRA_LAT = 1,
  // with RAM: the slots a slot's base entries wait for their match pixels below MIN_DISP 0
  // (fpstereo_strip_code_reorder)
  parameter BASE_WAIT = 0,
  parameter OUTPUT = 0,
  // the output words' disparity width; the winner's (whole pixels) is WTA_DISP_W
  parameter DISP_W = 4,
  parameter WTA_DISP_W = DISP_W,
  parameter WTA_TREE_LAT = 2,
  parameter WTA_LEVELS_PER_STAGE = LEVELS_PER_STAGE,
  parameter UNIQUE = 0,
  // fpstereo_subpixel's fraction bits (0: none), its fit and the winner's word lag behind the sums
  parameter SUBPIXEL_BITS = 0,
  parameter EQUIANGULAR = 1,
  parameter WTA_WORD_LAG = 1,
  // fpstereo_subpixel's latency (0 without it): the confidence waits as long for the words
  parameter SUBPIXEL_LAT = 0,
  // 1: each word leaves with its pixel's 8-bit confidence above it
  parameter CONFIDENCE = 0,
  // with OUTPUT: rows read after the frame's (gap interpolation's, fpstereo_strip_disparity_reorder)
  parameter EXTRA_ROWS = 0,
  // 1: LR1's match side per strip (fpstereo_lr1_match, its state handed from strip to strip), its
  // completed pixels and row ends out per strip; LR1_AW the completed writes' address width
  parameter LR1 = 0,
  parameter LR1_AW = 8,
  // with OUTPUT: the steps LR1's writes wait, to land with the strips' disparity words (the
  // winner's, the fit's and the confidence's latencies)
  parameter LR1_LAG = 0,
  // with LR1 and OUTPUT: the right view's Dm(x) beside each read word (right_word), the check
  // VIEW_WAIT steps later (fpstereo_strip_lr_check)
  parameter RIGHT_VIEW = 0,
  parameter VIEW_WAIT = 0,
  // 1: LR2's match side (docs/ppc-hardware.md, "LR2 in strips"), without OUTPUT: the entries are
  // the match image's ({base entry, match entry} swapped, MIN_DISP = -(min-disp + UF - 1); without
  // CODES the cost words of the window costs with the images swapped, at that MIN_DISP), so lane l
  // holds the match side's index UF - 1 - l; each strip's winner over the lanes turned
  // back (no uniqueness) is Dm(x') of its pixel x', written on dm_* at slot * ROW_SLOTS + x' -
  // p * ROW_SLOTS DM_LAG (3 or more) steps after the winner, the row slots those of the base
  // side's strip ((P - p) * K + 1 rows)
  parameter MATCH_SIDE = 0,
  parameter DM_LAG = 3,
  // 1, with OUTPUT: LR2, whose check reads the match side's writes (match_dm_*) as LR1's
  parameter LR2 = 0
  /* verilator lint_on UNUSEDPARAM */
) (
  input  wire                  clk,
  input  wire                  restart,
  input  wire                  adv,
  input  wire [X_W-1:0]        frame_width,
  input  wire [Y_W-1:0]        frame_height,
  input  wire [PATH_W-1:0]     p1,
  input  wire [PATH_W-1:0]     p2,
  input  wire                  agg_on,
  input  wire                  overlap,
  input  wire                  wrapped,
  output wire [P*COST_AW-1:0]  cost_raddr,
  // each strip's cost word, or with CODES its entry, a step after its address
  /* verilator lint_off UNUSEDSIGNAL */  // cost_q with RAM, the code ports without
  input  wire [P*((CODES != 0 ? 2*ENTRY_W : UF*COST_W) + EXTRA_W)-1:0] cost_q,
  input  wire                  code_we,
  input  wire [X_W-1:0]        code_slot,
  input  wire [SLOT_W-1:0]     code_row,
  input  wire [P*(CODES != 0 ? 2*ENTRY_W : UF*COST_W+EXTRA_W)-1:0] code_data,
  input  wire [P*(EXTRA_W > 0 ? EXTRA_W : 1)-1:0] code_extra,
  // (PREFIX entries, below; at least one)
  input  wire [(CODES != 0 && MIN_DISP < 0 ? (-MIN_DISP < UF - 1 ? -MIN_DISP : UF - 1) : 1)*ENTRY_W-1:0] code_prefix,
  /* verilator lint_on UNUSEDSIGNAL */
  output wire [P*UF*SUM_W-1:0] sums,
  output wire [P-1:0]          sums_active,
  output wire [P*X_W-1:0]      sums_x,
  output wire [P*K_W-1:0]      sums_chain,
  output wire [P*OUT_ROW_W-1:0] sums_slot,
  // with OUTPUT: the raster order's stream (fpstereo_strip_disparity_reorder)
  /* verilator lint_off UNUSEDSIGNAL */  // without OUTPUT
  input  wire                  out_on,
  input  wire [6:0]            uniqueness,
  input  wire [3:0]            lr_threshold,
  /* verilator lint_on UNUSEDSIGNAL */
  output wire                  read_done,
  output wire                  read_event,
  output wire [X_W-1:0]        read_x,
  output wire [Y_W-1:0]        read_y,
  output wire [P*(DISP_W+1+8*CONFIDENCE)-1:0] read_word,
  output wire [P*WTA_DISP_W-1:0] right_word,
  // with LR1, strip p's: Dm of the match pixel x - MIN_DISP - (UF - 1) of its pixel x, written at
  // slot * ROW_SLOTS + x - p * ROW_SLOTS; and at the row's last pixel the row end's UF words
  // (with MATCH_SIDE: Dm of its own pixels, no row end)
  output wire [P-1:0]          dm_we,
  output wire [P*LR1_AW-1:0]   dm_waddr,
  output wire [P*WTA_DISP_W-1:0] dm_wdata,
  output wire [P-1:0]          dm_end_we,
  output wire [P*OUT_ROW_W-1:0] dm_end_waddr,
  output wire [P*UF*WTA_DISP_W-1:0] dm_end_wdata,
  // with LR2: the match side's dm_* writes
  /* verilator lint_off UNUSEDSIGNAL */  // without LR2
  input  wire [P-1:0]          match_dm_we,
  input  wire [P*LR1_AW-1:0]   match_dm_waddr,
  input  wire [P*WTA_DISP_W-1:0] match_dm_wdata
  /* verilator lint_on UNUSEDSIGNAL */
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (P < 2 || (P - 1) * ROW_SLOTS >= W || P * ROW_SLOTS < W) begin : invalid_P
      fpstereo_invalid_parameters_strip_aggregation_P_strips_of_ROW_SLOTS_do_not_cover_W failed ();
    end
    if (EXTRA_W != 0 && ((CODES == 0 && RAM == 0) || EXTRA_W != NP * PATH_W)) begin : invalid_EXTRA_W
      fpstereo_invalid_parameters_strip_aggregation_EXTRA_W_is_not_a_P2_per_path_with_CODES_or_RAM failed ();
    end
    if (CONFIDENCE != 0 && (UNIQUE == 0 || CONFIDENCE != 1)) begin : invalid_CONFIDENCE
      fpstereo_invalid_parameters_strip_aggregation_CONFIDENCE_needs_UNIQUE failed ();
    end
    if (RIGHT_VIEW != 0 && (LR1 + LR2 != 1 || OUTPUT == 0)) begin : invalid_RIGHT_VIEW
      fpstereo_invalid_parameters_strip_aggregation_RIGHT_VIEW_needs_LR1_or_LR2_and_OUTPUT failed ();
    end
    if ((MATCH_SIDE != 0 && (OUTPUT != 0 || LR1 != 0 || LR2 != 0 || (CODES == 0 && RAM == 0) || EXTRA_W != 0 ||
                             DM_LAG < 3)) ||
        (LR2 != 0 && (OUTPUT == 0 || LR1 != 0))) begin : invalid_LR2
      fpstereo_invalid_parameters_strip_aggregation_MATCH_SIDE_is_alone_with_CODES_or_RAM_LR2_needs_OUTPUT failed ();
    end
  endgenerate
  localparam EDGE_W = (UF + 1) * PATH_W;
  localparam Q_W = (CODES != 0 ? 2 * ENTRY_W : UF * COST_W) + EXTRA_W;
  localparam NP = PATHS % 2 + (PATHS / 2) % 2 + (PATHS / 4) % 2 + (PATHS / 8) % 2;
  localparam PENALTIES = EXTRA_W != 0 ? NP : 0;
  localparam RING_W = UF * ENTRY_W;
  // below MIN_DISP 0 a row's first pixel needs the match pixels left of its own match pixel
  /* verilator lint_off UNUSEDPARAM */  // without CODES
  localparam PREFIX = CODES == 0 || MIN_DISP >= 0 ? 0 : -MIN_DISP < UF - 1 ? -MIN_DISP : UF - 1;
  localparam PREFIX_N = PREFIX > 0 ? PREFIX : 1;  // code_prefix's entries
  /* verilator lint_on UNUSEDPARAM */
  // With RAM, the strips' code entries from their RAMs (a step after each address); else cost_q.
  /* verilator lint_off UNUSEDSIGNAL */  // cost_q with RAM
  wire [P*Q_W-1:0] entries;
  /* verilator lint_on UNUSEDSIGNAL */
  generate
    if (RAM != 0) begin : code_ram
      // Without CODES a pixel's entry is its cost word with adaptive P2's penalties above, which
      // come together (the cost stage's writes wait for both).
      localparam RAM_EXTRA_W = CODES != 0 ? EXTRA_W : 0;
      fpstereo_strip_code_reorder #(.P(P), .K(K), .STRIP_PIXELS(ROW_SLOTS), .ENTRY_W(CODES != 0 ? 2 * ENTRY_W : Q_W),
                                    .EXTRA_W(RAM_EXTRA_W), .EXTRA_LAT(EXTRA_LAT),
                                    .BASE_WAIT(CODES != 0 ? BASE_WAIT : 0),
                                    .SLOT_ROWS(SLOT_ROWS),
                                    .SLOT_W(SLOT_W), .X_W(X_W), .AW(COST_AW)) codes (
        .clk(clk), .adv(adv), .we(code_we), .wslot(code_slot), .wrow(code_row), .wdata(code_data),
        .extra(code_extra[P*(RAM_EXTRA_W > 0 ? RAM_EXTRA_W : 1)-1:0]), .raddr(cost_raddr), .q(entries));
    end else begin : from_port
      assign entries = cost_q;
    end
  endgenerate
  /* verilator lint_off UNUSEDSIGNAL */  // with CODES
  wire [(P+1)*RING_W-1:0] rings;  // rings[p]: from strip p - 1's chain costs to strip p's
  /* verilator lint_on UNUSEDSIGNAL */
  assign rings[0 +: RING_W] = 0;
  wire [(P+1)*2*EDGE_W-1:0] edge_right;  // edge_right[p]: from strip p - 1 to strip p
  wire [(P+1)*EDGE_W-1:0]   edge_left;   // edge_left[p]: from strip p + 1 to strip p
  assign edge_right[0 +: 2*EDGE_W] = 0;
  assign edge_left[P*EDGE_W +: EDGE_W] = 0;
  genvar p, l;
  generate
    for (p = 0; p < P; p = p + 1) begin : strip
      wire on, wrapped_p;
      if (p == 0) begin : first
        assign on = agg_on;
        assign wrapped_p = wrapped;
      end else begin : lagged
        fpstereo_delay #(.WIDTH(2), .DEPTH(p * K), .RESET(1)) lag (
          .clk(clk), .rst(restart), .en(adv), .in({agg_on, wrapped}), .out({on, wrapped_p}));
      end
      wire [UF*COST_W+PENALTIES*PATH_W-1:0] costs;
      /* verilator lint_off UNUSEDSIGNAL */  // the chain-order costs' schedule
      wire [X_W+1:0] schedule;
      /* verilator lint_on UNUSEDSIGNAL */
      if (CODES != 0) begin : chain_costs
        /* verilator lint_off PINCONNECTEMPTY */
        // adaptive P2's penalties: read above the entry, out above the costs
        wire [(EXTRA_W > 0 ? EXTRA_W : 1)-1:0] penalties_in;
        /* verilator lint_off UNUSEDSIGNAL */  // without EXTRA_W
        wire [(EXTRA_W > 0 ? EXTRA_W : 1)-1:0] penalties;
        /* verilator lint_on UNUSEDSIGNAL */
        if (EXTRA_W > 0) begin : with_penalties
          assign penalties_in = entries[p*Q_W + 2*ENTRY_W +: (EXTRA_W > 0 ? EXTRA_W : 1)];
          assign costs[UF*COST_W +: (EXTRA_W > 0 ? EXTRA_W : 1)] = penalties;
        end else begin : without_penalties
          assign penalties_in = 1'b0;
        end
        fpstereo_chain_cost #(.HAMMING(HAMMING), .CODE_W(CODE_W), .DMAX(UF), .UF(UF), .K(K), .COST_W(COST_W),
                              .COST_MAX(COST_MAX), .X_W(X_W), .G_W(1), .MIN_DISP(MIN_DISP), .WEIGHT(WEIGHT),
                              .TRUNC(TRUNC), .FEATURE_W(FEATURE_W), .GRADIENT(GRADIENT), .LANES_LAT(LANES_LAT),
                              .LAT(CHAIN_LAT), .ENTRY_W(ENTRY_W), .EXTRA_W(EXTRA_W), .FROM_LEFT(p > 0 ? 1 : 0),
                              .PREFIX(p == 0 ? PREFIX : 0)) chain_cost (
          .clk(clk), .adv(adv), .group(schedule[0]), .x(schedule[X_W:1]), .row_time_first(schedule[X_W+1]),
          .frame_width(frame_width), .entry(entries[p*Q_W +: 2*ENTRY_W]),
          .prefix(code_prefix[(p == 0 ? PREFIX_N : 1)*ENTRY_W-1:0]),
          .extra(penalties_in), .costs(costs[UF*COST_W-1:0]), .extra_out(penalties),
          .ring_in(rings[p*RING_W +: RING_W]), .ring_out(rings[(p+1)*RING_W +: RING_W]));
        /* verilator lint_on PINCONNECTEMPTY */
      end else begin : cost_words
        assign costs = entries[p*Q_W +: Q_W];
        assign rings[(p+1)*RING_W +: RING_W] = 0;
      end
      /* verilator lint_off PINCONNECTEMPTY */
      fpstereo_aggregator #(.W(W), .ROW_SLOTS(ROW_SLOTS), .K(K), .SEGMENT(SEGMENT), .G(1), .UF(UF),
                            .COST_W(COST_W), .COST_MAX(COST_MAX), .PATH_W(PATH_W), .SUM_W(SUM_W), .PATHS(PATHS),
                            .MATCH_SIDE(0), .PENALTIES(PENALTIES), .LEVELS_PER_STAGE(LEVELS_PER_STAGE),
                            .PATH_TREE_LAT(PATH_TREE_LAT),
                            .OUT_ROWS(OUTPUT != 0 || MATCH_SIDE != 0 ? (P - p) * K + 1 : OUT_ROWS),
                            .OUT_ROW_W(OUT_ROW_W),
                            .COST_AW(COST_AW), .X_W(X_W), .Y_W(Y_W), .G_W(1), .K_W(K_W),
                            .COST_ROWS(RAM != 0 ? (p + 1) * K : COST_ROWS), .COST_ROW_W(COST_ROW_W),
                            .MIN_DISP(0), .CODES(CODES),
                            .COST_LEAD(COST_LEAD), .STRIPS(1), .X_BASE(p * ROW_SLOTS), .CHAIN_BASE(p * K))
        aggregation (
          .clk(clk), .restart(restart), .adv(adv), .frame_width(frame_width), .frame_height(frame_height),
          .p1(p1), .p2(p2), .agg_on(on), .overlap(overlap), .wrapped(wrapped_p),
          .cost_raddr(cost_raddr[p*COST_AW +: COST_AW]), .cost_schedule(schedule), .cost_q(costs),
          .sums(sums[p*UF*SUM_W +: UF*SUM_W]), .sums_active(sums_active[p]), .sums_x(sums_x[p*X_W +: X_W]),
          .sums_group(), .sums_chain(sums_chain[p*K_W +: K_W]), .sums_slot(sums_slot[p*OUT_ROW_W +: OUT_ROW_W]),
          .edge_in(edge_right[p*2*EDGE_W +: 2*EDGE_W]), .edge135_in(edge_left[(p+1)*EDGE_W +: EDGE_W]),
          .edge_out(edge_right[(p+1)*2*EDGE_W +: 2*EDGE_W]), .edge135_out(edge_left[p*EDGE_W +: EDGE_W]));
      /* verilator lint_on PINCONNECTEMPTY */
    end
  endgenerate
  generate
    if (LR1 != 0) begin : lr1_match_side
      localparam LR1_EDGE_W = UF * (SUM_W + WTA_DISP_W);
      /* verilator lint_off UNUSEDSIGNAL */  // the last strip's edge goes nowhere
      wire [(P+1)*LR1_EDGE_W-1:0] lr1_edges;  // lr1_edges[p]: from strip p - 1 to strip p
      /* verilator lint_on UNUSEDSIGNAL */
      assign lr1_edges[0 +: LR1_EDGE_W] = 0;
      for (p = 0; p < P; p = p + 1) begin : lr1_of_strip
        localparam DATA_W = LR1_AW + WTA_DISP_W + OUT_ROW_W + UF * WTA_DISP_W;
        wire                       we, end_we;
        wire [LR1_AW-1:0]          waddr;
        wire [WTA_DISP_W-1:0]      wdata;
        wire [OUT_ROW_W-1:0]       end_waddr;
        wire [UF*WTA_DISP_W-1:0]   end_wdata;
        fpstereo_lr1_match #(.K(K), .G(1), .UF(UF), .DMAX(UF), .ROW_SLOTS(ROW_SLOTS), .SUM_W(SUM_W),
                             .DISP_W(WTA_DISP_W), .OUT_ROW_W(OUT_ROW_W), .DISP_AW(LR1_AW), .END_AW(OUT_ROW_W),
                             .X_W(X_W), .G_W(1), .K_W(K_W), .MIN_DISP(MIN_DISP), .STRIPS(1),
                             .X_BASE(p * ROW_SLOTS)) lr1_match (
          .clk(clk), .adv(adv), .frame_width(frame_width), .sums(sums[p*UF*SUM_W +: UF*SUM_W]),
          .active(sums_active[p]), .x(sums_x[p*X_W +: X_W]), .group(1'b0), .chain(sums_chain[p*K_W +: K_W]),
          .slot(sums_slot[p*OUT_ROW_W +: OUT_ROW_W]), .completed_we(we), .completed_waddr(waddr),
          .completed_wdata(wdata), .row_end_we(end_we), .row_end_waddr(end_waddr), .row_end_wdata(end_wdata),
          .edge_in(lr1_edges[p*LR1_EDGE_W +: LR1_EDGE_W]), .edge_out(lr1_edges[(p+1)*LR1_EDGE_W +: LR1_EDGE_W]));
        if (LR1_LAG > 0) begin : lagged
          wire [1:0] flags;
          fpstereo_delay #(.WIDTH(2), .DEPTH(LR1_LAG), .RESET(1)) flag_lag (
            .clk(clk), .rst(restart), .en(adv), .in({we, end_we}), .out(flags));
          fpstereo_delay #(.WIDTH(DATA_W), .DEPTH(LR1_LAG)) data_lag (
            .clk(clk), .rst(1'b0), .en(adv), .in({waddr, wdata, end_waddr, end_wdata}),
            .out({dm_waddr[p*LR1_AW +: LR1_AW], dm_wdata[p*WTA_DISP_W +: WTA_DISP_W],
                  dm_end_waddr[p*OUT_ROW_W +: OUT_ROW_W], dm_end_wdata[p*UF*WTA_DISP_W +: UF*WTA_DISP_W]}));
          assign dm_we[p] = adv && flags[1];
          assign dm_end_we[p] = adv && flags[0];
        end else begin : at_once
          assign dm_we[p] = we;
          assign dm_end_we[p] = end_we;
          assign {dm_waddr[p*LR1_AW +: LR1_AW], dm_wdata[p*WTA_DISP_W +: WTA_DISP_W],
                  dm_end_waddr[p*OUT_ROW_W +: OUT_ROW_W], dm_end_wdata[p*UF*WTA_DISP_W +: UF*WTA_DISP_W]} =
                 {waddr, wdata, end_waddr, end_wdata};
        end
      end
    end else if (MATCH_SIDE != 0) begin : lr2_match_side
      // Each strip's winner over its lanes turned back (lane l: index UF - 1 - l), its write's
      // address in two steps (the row's first word, then the sum), and DM_LAG - 2 steps more.
      localparam TAG_W = 1 + X_W + OUT_ROW_W;
      localparam DATA_W = LR1_AW + WTA_DISP_W;
      for (p = 0; p < P; p = p + 1) begin : winner_of_strip
        wire [UF*SUM_W-1:0] turned;
        for (l = 0; l < UF; l = l + 1) begin : lane
          assign turned[l*SUM_W +: SUM_W] = sums[(p*UF + UF - 1 - l)*SUM_W +: SUM_W];
        end
        wire won;
        wire [X_W-1:0] won_x;
        wire [OUT_ROW_W-1:0] won_slot;
        /* verilator lint_off UNUSEDSIGNAL */  // the never-set invalid flag
        wire [WTA_DISP_W:0] won_word;
        /* verilator lint_on UNUSEDSIGNAL */
        /* verilator lint_off PINCONNECTEMPTY */
        fpstereo_wta #(.UF(UF), .SUM_W(SUM_W), .DISP_W(WTA_DISP_W), .LANE_W(WTA_DISP_W), .G_W(1), .TAG_W(TAG_W),
                       .LEVELS_PER_STAGE(WTA_LEVELS_PER_STAGE), .TREE_LAT(WTA_TREE_LAT)) wta (
          .clk(clk), .restart(restart), .adv(adv), .sums(turned), .group(1'b0),
          .tag({sums_active[p], sums_x[p*X_W +: X_W], sums_slot[p*OUT_ROW_W +: OUT_ROW_W]}), .group_out(),
          .tag_out({won, won_x, won_slot}), .word(won_word));
        /* verilator lint_on PINCONNECTEMPTY */
        localparam integer X_BASE = p * ROW_SLOTS;
        reg                  won_q = 1'b0, at_q = 1'b0;
        reg [LR1_AW-1:0]     row_first_q, column_q, at_addr_q;
        reg [WTA_DISP_W-1:0] dm_q, at_dm_q;
        always @(posedge clk)
          if (restart) begin
            won_q <= 1'b0;
            at_q <= 1'b0;
          end else if (adv) begin
            won_q <= won;
            at_q <= won_q;
          end
        // The address is a product of narrow values and constants, cut to the address width.
        /* verilator lint_off WIDTH */
        always @(posedge clk)
          if (adv) begin
            row_first_q <= won_slot * ROW_SLOTS;
            column_q <= won_x - X_BASE;
            dm_q <= won_word[WTA_DISP_W-1:0];
            at_addr_q <= row_first_q + column_q;
            at_dm_q <= dm_q;
          end
        /* verilator lint_on WIDTH */
        wire lagged_we;
        fpstereo_delay #(.WIDTH(1), .DEPTH(DM_LAG - 2), .RESET(1)) flag_lag (
          .clk(clk), .rst(restart), .en(adv), .in(at_q), .out(lagged_we));
        fpstereo_delay #(.WIDTH(DATA_W), .DEPTH(DM_LAG - 2)) data_lag (
          .clk(clk), .rst(1'b0), .en(adv), .in({at_addr_q, at_dm_q}),
          .out({dm_waddr[p*LR1_AW +: LR1_AW], dm_wdata[p*WTA_DISP_W +: WTA_DISP_W]}));
        assign dm_we[p] = adv && lagged_we;
      end
      assign dm_end_we = 0;
      assign dm_end_waddr = 0;
      assign dm_end_wdata = 0;
    end else begin : no_lr1
      assign dm_we = 0;
      assign dm_waddr = 0;
      assign dm_wdata = 0;
      assign dm_end_we = 0;
      assign dm_end_waddr = 0;
      assign dm_end_wdata = 0;
    end
  endgenerate
  generate
    if (OUTPUT != 0) begin : output_order
      localparam TAG_W = 1 + X_W + OUT_ROW_W;
      wire [P-1:0] wta_active;
      wire [P*X_W-1:0] wta_x;
      wire [P*OUT_ROW_W-1:0] wta_slot;
      wire [P*(WTA_DISP_W+1)-1:0] wta_word;
      /* verilator lint_off UNUSEDSIGNAL */  // without CONFIDENCE
      wire [P*SUM_W-1:0] wta_best, wta_second;
      /* verilator lint_on UNUSEDSIGNAL */
      for (p = 0; p < P; p = p + 1) begin : wta_of_strip
        /* verilator lint_off PINCONNECTEMPTY */
        if (UNIQUE != 0) begin : with_uniqueness
          fpstereo_wta_unique #(.UF(UF), .SUM_W(SUM_W), .DISP_W(WTA_DISP_W), .LANE_W(WTA_DISP_W), .G_W(1),
                                .TAG_W(TAG_W),
                                .LEVELS_PER_STAGE(WTA_LEVELS_PER_STAGE), .TREE_LAT(WTA_TREE_LAT)) wta (
            .clk(clk), .restart(restart), .adv(adv), .sums(sums[p*UF*SUM_W +: UF*SUM_W]), .group(1'b0),
            .tag({sums_active[p], sums_x[p*X_W +: X_W], sums_slot[p*OUT_ROW_W +: OUT_ROW_W]}),
            .uniqueness(uniqueness), .group_out(),
            .tag_out({wta_active[p], wta_x[p*X_W +: X_W], wta_slot[p*OUT_ROW_W +: OUT_ROW_W]}),
            .word(wta_word[p*(WTA_DISP_W+1) +: WTA_DISP_W+1]), .best_sum(wta_best[p*SUM_W +: SUM_W]),
            .second_sum(wta_second[p*SUM_W +: SUM_W]));
        end else begin : plain
          fpstereo_wta #(.UF(UF), .SUM_W(SUM_W), .DISP_W(WTA_DISP_W), .LANE_W(WTA_DISP_W), .G_W(1),
                         .TAG_W(TAG_W),
                         .LEVELS_PER_STAGE(WTA_LEVELS_PER_STAGE), .TREE_LAT(WTA_TREE_LAT)) wta (
            .clk(clk), .restart(restart), .adv(adv), .sums(sums[p*UF*SUM_W +: UF*SUM_W]), .group(1'b0),
            .tag({sums_active[p], sums_x[p*X_W +: X_W], sums_slot[p*OUT_ROW_W +: OUT_ROW_W]}), .group_out(),
            .tag_out({wta_active[p], wta_x[p*X_W +: X_W], wta_slot[p*OUT_ROW_W +: OUT_ROW_W]}),
            .word(wta_word[p*(WTA_DISP_W+1) +: WTA_DISP_W+1]));
          assign wta_best[p*SUM_W +: SUM_W] = {SUM_W{1'b0}};
          assign wta_second[p*SUM_W +: SUM_W] = {SUM_W{1'b0}};
        end
        /* verilator lint_on PINCONNECTEMPTY */
      end
      // The words the disparity RAMs take: the winner's, or refined by the sub-pixel fit; with
      // LR1 or LR2 the refined word carries the whole D below it for the check, {invalid, refined, D}.
      localparam WHOLE_W = (LR1 != 0 || LR2 != 0) && SUBPIXEL_BITS != 0 ? WTA_DISP_W : 0;
      localparam FIT_W = DISP_W + 1 + WHOLE_W;
      wire [P-1:0] out_active;
      wire [P*X_W-1:0] out_x;
      wire [P*OUT_ROW_W-1:0] out_slot;
      wire [P*FIT_W-1:0] out_word;
      // ... and with CONFIDENCE after the division, with their confidences above them.
      localparam WORD_W = FIT_W + 8 * CONFIDENCE;
      wire [P-1:0] rated_active;
      wire [P*X_W-1:0] rated_x;
      wire [P*OUT_ROW_W-1:0] rated_slot;
      wire [P*WORD_W-1:0] rated_word;
      for (p = 0; p < P; p = p + 1) begin : confidence_of_strip
        if (CONFIDENCE != 0) begin : divided
          localparam DATA_W = 1 + X_W + OUT_ROW_W + FIT_W;
          wire [7:0] confidence;
          wire [FIT_W-1:0] word;
          // The sub-pixel fit, when there, holds the words its latency after the winner's sums.
          fpstereo_confidence #(.SUM_W(SUM_W), .DATA_W(DATA_W),
                                .IN_DELAY(SUBPIXEL_LAT), .LAT(10)) divider (
            .clk(clk), .restart(restart), .adv(adv), .best(wta_best[p*SUM_W +: SUM_W]),
            .second(wta_second[p*SUM_W +: SUM_W]),
            .data_in({out_active[p], out_x[p*X_W +: X_W], out_slot[p*OUT_ROW_W +: OUT_ROW_W],
                      out_word[p*FIT_W +: FIT_W]}),
            .data_out({rated_active[p], rated_x[p*X_W +: X_W], rated_slot[p*OUT_ROW_W +: OUT_ROW_W], word}),
            .confidence(confidence));
          assign rated_word[p*WORD_W +: WORD_W] = {confidence, word};
        end else begin : passed
          assign rated_active[p] = out_active[p];
          assign rated_x[p*X_W +: X_W] = out_x[p*X_W +: X_W];
          assign rated_slot[p*OUT_ROW_W +: OUT_ROW_W] = out_slot[p*OUT_ROW_W +: OUT_ROW_W];
          assign rated_word[p*WORD_W +: WORD_W] = out_word[p*FIT_W +: FIT_W];
        end
      end
      if (SUBPIXEL_BITS != 0) begin : refined
        for (p = 0; p < P; p = p + 1) begin : fit_of_strip
          // with LR1 the whole D travels in the fit's tag, below the tag's fields
          wire [TAG_W-1:0] tag = {wta_active[p], wta_x[p*X_W +: X_W], wta_slot[p*OUT_ROW_W +: OUT_ROW_W]};
          wire [TAG_W+WHOLE_W-1:0] tag_in, tag_out;
          if (WHOLE_W > 0) begin : carried
            assign tag_in = {tag, wta_word[p*(WTA_DISP_W+1) +: WHOLE_W]};
            assign out_word[p*FIT_W +: WHOLE_W] = tag_out[0 +: WHOLE_W];
          end else begin : alone
            assign tag_in = tag;
          end
          fpstereo_subpixel #(.UF(UF), .G(1), .SUM_W(SUM_W), .DMAX(UF), .DISP_W(WTA_DISP_W),
                              .K(SUBPIXEL_BITS), .EQUIANGULAR(EQUIANGULAR), .OUT_W(DISP_W),
                              .WTA_WORD_LAG(WTA_WORD_LAG), .TAG_W(TAG_W + WHOLE_W)) fit (
            .clk(clk), .restart(restart), .adv(adv), .sums(sums[p*UF*SUM_W +: UF*SUM_W]),
            .tag(tag_in),
            .word(wta_word[p*(WTA_DISP_W+1) +: WTA_DISP_W+1]),
            .tag_out(tag_out),
            .word_out(out_word[p*FIT_W + WHOLE_W +: DISP_W+1]));
          assign {out_active[p], out_x[p*X_W +: X_W], out_slot[p*OUT_ROW_W +: OUT_ROW_W]} = tag_out[WHOLE_W +: TAG_W];
        end
      end else begin : whole
        if (WTA_DISP_W != DISP_W) begin : invalid_widths
          fpstereo_invalid_parameters_strip_aggregation_DISP_W_differs_without_SUBPIXEL_BITS failed ();
        end
        assign out_active = wta_active;
        assign out_x = wta_x;
        assign out_slot = wta_slot;
        assign out_word = wta_word;
      end
      wire raster_done, raster_event;
      wire [X_W-1:0] raster_x;
      wire [Y_W-1:0] raster_y;
      wire [P*WORD_W-1:0] raster_word;
      /* verilator lint_off UNUSEDSIGNAL */  // without LR1
      wire [P*OUT_ROW_W-1:0] raster_slots;
      /* verilator lint_on UNUSEDSIGNAL */
      fpstereo_strip_disparity_reorder #(.P(P), .K(K), .STRIP_PIXELS(ROW_SLOTS), .DISP_W(WORD_W - 1), .X_W(X_W),
                                         .Y_W(Y_W), .SLOT_W(OUT_ROW_W), .EXTRA_ROWS(EXTRA_ROWS)) disparities (
        .clk(clk), .restart(restart), .adv(adv), .out_on(out_on), .overlap(overlap), .frame_width(frame_width),
        .frame_height(frame_height), .active(rated_active), .x(rated_x), .slot(rated_slot), .word(rated_word),
        .read_done(raster_done), .read_event(raster_event), .read_x(raster_x), .read_y(raster_y),
        .read_word(raster_word), .read_slots(raster_slots));
      if (LR1 != 0 || LR2 != 0) begin : checked
        // LR2: the match side's writes, every match pixel's, no row ends
        wire [P-1:0]            check_we = LR2 != 0 ? match_dm_we : dm_we;
        wire [P*LR1_AW-1:0]     check_waddr = LR2 != 0 ? match_dm_waddr : dm_waddr;
        wire [P*WTA_DISP_W-1:0] check_wdata = LR2 != 0 ? match_dm_wdata : dm_wdata;
        fpstereo_strip_lr_check #(.P(P), .K(K), .STRIP_PIXELS(ROW_SLOTS), .DMAX(UF), .DISP_W(WTA_DISP_W), .LR2(LR2),
                                  .REFINED_W(SUBPIXEL_BITS != 0 ? DISP_W : 0), .CARRY_W(8 * CONFIDENCE), .CAW(LR1_AW),
                                  .RIGHT_VIEW(RIGHT_VIEW), .VIEW_WAIT(VIEW_WAIT),
                                  .SLOT_W(OUT_ROW_W), .X_W(X_W), .Y_W(Y_W), .MIN_DISP(MIN_DISP)) check (
          .clk(clk), .restart(restart), .adv(adv), .frame_width(frame_width), .lr_threshold(lr_threshold),
          .completed_we(check_we), .completed_waddr(check_waddr), .completed_wdata(check_wdata),
          .row_end_we(dm_end_we), .row_end_waddr(dm_end_waddr), .row_end_wdata(dm_end_wdata),
          .read_done(raster_done), .read_event(raster_event), .read_x(raster_x), .read_y(raster_y),
          .read_slots(raster_slots), .read_word(raster_word), .checked_done(read_done), .checked_event(read_event),
          .checked_x(read_x), .checked_y(read_y), .checked_word(read_word), .right_word(right_word));
      end else begin : unchecked
        assign read_done = raster_done;
        assign read_event = raster_event;
        assign read_x = raster_x;
        assign read_y = raster_y;
        assign read_word = raster_word;
        assign right_word = {(P*WTA_DISP_W){1'b0}};
      end
    end else begin : no_output
      assign read_done = 1'b0;
      assign read_event = 1'b0;
      assign read_x = {X_W{1'b0}};
      assign read_y = {Y_W{1'b0}};
      assign read_word = {(P*(DISP_W+1+8*CONFIDENCE)){1'b0}};
      assign right_word = {(P*WTA_DISP_W){1'b0}};
    end
  endgenerate
  /* verilator lint_off UNUSEDSIGNAL */  // the last strip's edge to the right, the first's to the left
  wire unused_edges = ^{edge_right[P*2*EDGE_W +: 2*EDGE_W], edge_left[0 +: EDGE_W], rings[P*RING_W +: RING_W]};
  /* verilator lint_on UNUSEDSIGNAL */
endmodule
`resetall
