`resetall
`default_nettype none
// Cost stage in the aggregation's chain order (docs/architecture.md, "Code reorder"): the code
// reorder RAM gives one entry per slot, the pixel's base entry and the match entry that enters
// its row's match history; the costs are computed here, after the reorder, as the aggregator
// reads them. Each row in flight keeps its own match history: the last DMAX match entries of its
// row, a ring that turns by UF each step as fpstereo_match_ring does. The K rings take turns at
// the head, whose UF entries the lanes read: chain k continues in row-time t + 1 the row chain
// k - 1 left in row-time t, so the rings serve the chains in a fixed cycle, and the head keeps its
// ring only into a row-time's first slot, where the ring of the row just finished begins a new
// row (its old entries lie left of the row and are never read: the lanes mask x - MIN_DISP - d <
// 0). Timing: the aggregator's schedule names a pixel's group in step S0, where it reads the
// pixel's entry; the entry is in the RAM's register in S1, where the head takes it in the first
// group, so the lanes take group g in step S2 + g and the costs leave LAT steps later.
// In a strip of several (FROM_LEFT, docs/ppc-hardware.md; uf = dmax), a row-time's first slot
// continues the row the strip to the left has just finished: the head takes that strip's ring
// (ring_in) instead of keeping its own, and hands its own to the strip to the right (ring_out,
// captured at the same slot, which comes K steps earlier there).
// Below MIN_DISP 0 a pixel's match entry is pixel x - MIN_DISP's, right of it, and a row's first
// pixel needs the match pixels left of that one too: the head that begins the row (without
// FROM_LEFT: the only strip or the first) takes them from prefix (PREFIX = min(-MIN_DISP,
// DMAX - 1) entries, match pixel -MIN_DISP - p at entry p - 1); the lanes mask x - MIN_DISP - d
// >= the width as well.
module fpstereo_chain_cost #(
  parameter HAMMING = 1,
  parameter CODE_W = 24,
  parameter DMAX = 32,
  parameter UF = 8,
  parameter K = 2,
  parameter COST_W = 5,
  parameter COST_MAX = 24,
  parameter X_W = 7,
  parameter G_W = 2,
  parameter MIN_DISP = 0,
  parameter WEIGHT = 0,
  parameter TRUNC = 20,
  parameter FEATURE_W = 8,
  parameter GRADIENT = 0,
  parameter LANES_LAT = 2,
  parameter LAT = 2,
  parameter ENTRY_W = CODE_W,
  // bits read beside the entry (adaptive P2's penalties), which leave with the pixel's costs
  parameter EXTRA_W = 0,
  // 1: a strip with one to its left, whose ring continues its rows
  parameter FROM_LEFT = 0,
  // the match entries a row begins with below MIN_DISP 0 (the first strip's; else 0)
  parameter PREFIX = 0
) (
  input  wire                  clk,
  input  wire                  adv,
  // the schedule in S0: the group, the pixel's x, and whether the slot opens a row-time
  input  wire [G_W-1:0]        group,
  input  wire [X_W-1:0]        x,
  input  wire                  row_time_first,
  input  wire [X_W-1:0]        frame_width,
  // the pixel's entry, in S1
  input  wire [2*ENTRY_W-1:0]  entry,
  // below MIN_DISP 0, the row's first match entries (PREFIX), with the row's first entry
  /* verilator lint_off UNUSEDSIGNAL */  // without PREFIX
  input  wire [(PREFIX > 0 ? PREFIX : 1)*ENTRY_W-1:0] prefix,
  /* verilator lint_on UNUSEDSIGNAL */
  /* verilator lint_off UNUSEDSIGNAL */  // without EXTRA_W
  input  wire [(EXTRA_W > 0 ? EXTRA_W : 1)-1:0] extra,
  /* verilator lint_on UNUSEDSIGNAL */
  output wire [UF*COST_W-1:0]  costs,
  output wire [(EXTRA_W > 0 ? EXTRA_W : 1)-1:0] extra_out,
  // strips: the ring of the row the strip to the left has finished, and this strip's
  /* verilator lint_off UNUSEDSIGNAL */  // unused in the first strip and without strips
  input  wire [DMAX*ENTRY_W-1:0] ring_in,
  /* verilator lint_on UNUSEDSIGNAL */
  output reg  [DMAX*ENTRY_W-1:0] ring_out
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (K < 2 || UF < 1 || DMAX % (UF > 0 ? UF : 1) != 0) begin : invalid
      fpstereo_invalid_parameters_chain_cost_needs_K_2_or_more_and_DMAX_a_multiple_of_UF failed ();
    end
    // below MIN_DISP 0 the first strip's rows begin with a prefix, which the others continue
    if (PREFIX != (FROM_LEFT != 0 || MIN_DISP >= 0 ? 0 : -MIN_DISP < DMAX - 1 ? -MIN_DISP : DMAX - 1))
    begin : invalid_prefix
      fpstereo_invalid_parameters_chain_cost_PREFIX_is_not_the_first_strips_min_of_minus_MIN_DISP_and_DMAX_1 failed ();
    end
    if (FROM_LEFT != 0 && UF != DMAX) begin : invalid_strip
      fpstereo_invalid_parameters_chain_cost_strips_need_UF_equal_to_DMAX failed ();
    end
  endgenerate
  // Turns as in fpstereo_match_ring (SPAN 1): by UF in a slot's steps; at the load, the turn that
  // completes the slot plus the shift by one entry.
  localparam TURN = UF % DMAX;
  localparam SHIFT = (UF - 1) % DMAX;
  localparam RING_W = DMAX * ENTRY_W;
  localparam PREFIX_N = PREFIX > 0 ? PREFIX : 1;  // the prefix port's entries
  reg [RING_W-1:0] head;
  // the rings waiting for their chain, the next one at index 0, each with its turn completed
  reg [(K-1)*RING_W-1:0] waiting;
  reg [ENTRY_W-1:0] base_held;
  // The schedule in S1 (the head takes the entry in a first group) and S2 (the lanes).
  reg [G_W-1:0] group1, group2;
  reg [X_W-1:0] x1, x2;
  reg first1;
  always @(posedge clk)
    if (adv) begin
      {group1, x1, first1} <= {group, x, row_time_first};
      {group2, x2} <= {group1, x1};
    end
  wire load = group1 == 0;
  wire [ENTRY_W-1:0] base_in = entry[ENTRY_W-1:0];
  wire [ENTRY_W-1:0] match_in = entry[2*ENTRY_W-1 -: ENTRY_W];
  wire [RING_W-1:0] next_ring = waiting[RING_W-1:0];
  // the ring a row-time's first slot continues: the head's own, or in a strip the left one's
  wire [RING_W-1:0] kept = FROM_LEFT != 0 ? ring_in : head;
  reg [RING_W-1:0] head_turned;
  integer p;
  always @*
    for (p = 0; p < DMAX; p = p + 1) head_turned[p*ENTRY_W +: ENTRY_W] = head[((p + TURN) % DMAX)*ENTRY_W +: ENTRY_W];
  always @(posedge clk)
    if (adv) begin
      if (!load) head <= head_turned;
      else begin
        head[0 +: ENTRY_W] <= match_in;
        for (p = 1; p < DMAX; p = p + 1)
          head[p*ENTRY_W +: ENTRY_W] <= !first1 ? next_ring[(p-1)*ENTRY_W +: ENTRY_W]
                                      : p <= PREFIX ? prefix[((p-1) % PREFIX_N)*ENTRY_W +: ENTRY_W]
                                      : kept[((p + SHIFT) % DMAX)*ENTRY_W +: ENTRY_W];
        base_held <= base_in;
      end
    end
  always @(posedge clk)
    if (adv && load && first1) ring_out <= head;
  // The head's ring joins the end of the queue as the next one leaves it.
  wire rotate = adv && load && !first1;
  generate
    if (K > 2) begin : queue
      always @(posedge clk)
        if (rotate) waiting <= {head_turned, waiting[(K-1)*RING_W-1:RING_W]};
    end else begin : one
      always @(posedge clk)
        if (rotate) waiting <= head_turned;
    end
  endgenerate
  generate
    if (EXTRA_W > 0) begin : extras
      fpstereo_delay #(.WIDTH(EXTRA_W), .DEPTH(LAT + 1)) extra_wait (
        .clk(clk), .rst(1'b0), .en(adv), .in(extra), .out(extra_out));
    end else begin : no_extras
      assign extra_out = 1'b0;
    end
  endgenerate
  fpstereo_point_lanes #(.HAMMING(HAMMING), .CODE_W(CODE_W), .UF(UF), .COST_W(COST_W), .COST_MAX(COST_MAX), .X_W(X_W),
                         .G_W(G_W), .MIN_DISP(MIN_DISP), .WEIGHT(WEIGHT), .TRUNC(TRUNC), .FEATURE_W(FEATURE_W),
                         .GRADIENT(GRADIENT), .LANES_LAT(LANES_LAT), .LAT(LAT), .ENTRY_W(ENTRY_W)) lanes (
    .clk(clk), .en(adv), .group(group2), .x(x2), .frame_width(frame_width), .base_entry(base_held),
    .match_entries(head[UF*ENTRY_W-1:0]), .costs(costs));
endmodule
`resetall
