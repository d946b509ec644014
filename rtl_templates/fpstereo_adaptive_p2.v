`resetall
`default_nettype none
// Adaptive P2 (docs/semantics.md, section 3): for each enabled path r, the pixel's
//   P2_r = max(P1, P2 - (GAIN * |I(p) - I(p - r)|) >> 2)
// from the base window's centre and its predecessors, delivered beside the cost lanes' words
// (the same step as the costs of each group of the pixel). Timing: the pixels are taken from
// the window as the transform takes its codes (at shift), their steps |I(p) - I(p - r)| are
// registered at the next shift, as the cost stage takes the centre, after WAIT_ROWS row-times of
// ROW_SLOTS shifts in a block RAM ring (SHD's centre lags its code window's rows) and WAIT_SLOTS
// more shifts (ZSAD's base window waits two, SHD's code window RS + 1, a negative min-disp -m);
// then per step the product, the penalty, and LAT - 2 steps of delay, so that they leave with
// the costs the lanes compute LAT steps after the centre.
// Predecessors outside the image read whatever the window holds: the aggregation does not use
// P2 there. One field of PATH_W bits per enabled path, in path order (0, 45, 90, 135), the
// first at the least significant end.
module fpstereo_adaptive_p2 #(
  parameter N = 5,
  parameter PATHS = 15,
  parameter NP = 4,  // enabled paths
  // k, 1 .. 16
  parameter GAIN = 4,
  parameter PATH_W = 8,
  parameter WAIT_SLOTS = 0,
  parameter WAIT_ROWS = 0,
  parameter ROW_SLOTS = 64,
  parameter LAT = 2
) (
  input  wire               clk,
  input  wire               adv,
  input  wire               shift,
  /* verilator lint_off UNUSEDSIGNAL */  // the centre and its four predecessors only
  input  wire [N*N*8-1:0]   window,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [PATH_W-1:0]  p1,
  input  wire [PATH_W-1:0]  p2,
  output wire [NP*PATH_W-1:0] penalties
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 3 || N % 2 == 0 || GAIN < 1 || GAIN > 16 || LAT < 2 || WAIT_SLOTS < 0 || WAIT_ROWS < 0 ||
        WAIT_ROWS * ROW_SLOTS == 1) begin : invalid
      fpstereo_invalid_parameters_adaptive_p2_needs_odd_N_3_up_GAIN_1_to_16_and_LAT_2_up failed ();
    end
    if (NP != PATHS % 2 + (PATHS / 2) % 2 + (PATHS / 4) % 2 + (PATHS / 8) % 2) begin : invalid_NP
      fpstereo_invalid_parameters_adaptive_p2_NP_is_not_the_number_of_PATHS failed ();
    end
  endgenerate
  localparam R = N / 2;
  localparam CENTRE = R * N + R;
  // The window in raster order: (dy, dx) at (R + dy) * N + R + dx.
  localparam integer LEFT = CENTRE - 1, UP_LEFT = CENTRE - N - 1, UP = CENTRE - N, UP_RIGHT = CENTRE - N + 1;
  localparam PROD_W = 12;  // 16 * 255 < 2^12
  // cut = GAIN * step / 4 and P2 - P1 compared in CMP_W bits; a penalty is at most P2 (PATH_W bits).
  localparam CMP_W = PATH_W > PROD_W - 2 ? PATH_W : PROD_W - 2;

  // The centre and its predecessors, as the transform takes its codes.
  reg [7:0] centre;
  /* verilator lint_off UNUSEDSIGNAL */  // those of the enabled paths
  reg [8*4-1:0] predecessors;  // of the 0, 45, 90 and 135 degree paths
  /* verilator lint_on UNUSEDSIGNAL */
  always @(posedge clk)
    if (shift) begin
      centre <= window[CENTRE*8 +: 8];
      predecessors <= {window[UP_RIGHT*8 +: 8], window[UP*8 +: 8], window[UP_LEFT*8 +: 8], window[LEFT*8 +: 8]};
    end

  // |I(p) - I(p - r)| of the four paths from both differences in parallel (unused paths'
  // are dropped by synthesis).
  /* verilator lint_off UNUSEDSIGNAL */  // those of the enabled paths
  wire [4*8-1:0] steps_now, steps_rows;
  /* verilator lint_on UNUSEDSIGNAL */
  genvar r;
  generate
    for (r = 0; r < 4; r = r + 1) begin : difference
      wire [8:0] up = {1'b0, centre} - {1'b0, predecessors[r*8 +: 8]};
      wire [7:0] down = predecessors[r*8 +: 8] - centre;
      assign steps_now[r*8 +: 8] = up[8] ? down : up[7:0];
    end
    if (WAIT_ROWS > 0) begin : row_wait
      // A ring of DEPTH entries: each shift writes at `at` and reads at `at + 1`, the entry
      // written DEPTH - 1 shifts ago, whose read register holds it until the next shift.
      localparam DEPTH = WAIT_ROWS * ROW_SLOTS;
      localparam AW = $clog2(DEPTH);
      localparam [AW-1:0] LAST = DEPTH - 1;
      reg  [AW-1:0] at = {AW{1'b0}};
      wire [AW-1:0] next_at = at == LAST ? {AW{1'b0}} : at + 1'b1;
      always @(posedge clk)
        if (shift) at <= next_at;
      fpstereo_ram_sdp #(.WIDTH(4 * 8), .DEPTH(DEPTH), .ADDR_W(AW)) rows (
        .clk(clk), .we(shift), .waddr(at), .wdata(steps_now), .re(shift), .raddr(next_at), .rdata(steps_rows));
    end else begin : no_row_wait
      assign steps_rows = steps_now;
    end
    for (r = 0; r < 4; r = r + 1) begin : path
      if ((PATHS >> r) % 2 != 0) begin : enabled
        // Its field: the enabled paths below it.
        localparam integer FIELD = (r > 0 ? PATHS % 2 : 0) + (r > 1 ? (PATHS / 2) % 2 : 0) + (r > 2 ? (PATHS / 4) % 2 : 0);
        // The step, registered with the cost stage's centre.
        wire [7:0] step_now = steps_rows[r*8 +: 8];
        wire [7:0] step;
        if (WAIT_SLOTS == 0) begin : no_wait
          reg [7:0] step_q;
          always @(posedge clk)
            if (shift) step_q <= step_now;
          assign step = step_q;
        end else begin : wait_slots
          reg [8*(WAIT_SLOTS+1)-1:0] step_q;
          always @(posedge clk)
            if (shift) step_q <= {step_q[8*WAIT_SLOTS-1:0], step_now};
          assign step = step_q[8*(WAIT_SLOTS+1)-1 -: 8];
        end
        // Step 1: the reduction GAIN * step / 4 (shifts and adds: GAIN is a constant) and the
        // room P2 - P1; step 2: the penalty, P2 - cut where that stays above P1.
        wire [PROD_W-1:0] s = {4'd0, step};
        /* verilator lint_off UNUSEDSIGNAL */  // the two bits the division by 4 drops
        wire [PROD_W-1:0] product = (GAIN % 2 != 0 ? s : 0) + ((GAIN / 2) % 2 != 0 ? s << 1 : 0)
                                  + ((GAIN / 4) % 2 != 0 ? s << 2 : 0) + ((GAIN / 8) % 2 != 0 ? s << 3 : 0)
                                  + (GAIN / 16 != 0 ? s << 4 : 0);
        /* verilator lint_on UNUSEDSIGNAL */
        reg  [CMP_W-1:0]  cut, room;
        reg  [PATH_W-1:0] penalty;
        /* verilator lint_off WIDTH */  // cut and room zero-extend; P2 - cut fits when it is taken
        always @(posedge clk)
          if (adv) begin
            cut <= product[PROD_W-1:2];
            room <= p2 - p1;
            penalty <= room > cut ? p2 - cut : p1;
          end
        /* verilator lint_on WIDTH */
        if (LAT == 2) begin : aligned
          assign penalties[FIELD*PATH_W +: PATH_W] = penalty;
        end else begin : delayed
          fpstereo_delay #(.WIDTH(PATH_W), .DEPTH(LAT - 2)) to_costs (
            .clk(clk), .rst(1'b0), .en(adv), .in(penalty), .out(penalties[FIELD*PATH_W +: PATH_W]));
        end
      end
    end
  endgenerate
endmodule
`resetall
