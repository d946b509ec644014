`resetall
`default_nettype none
// The code reorder RAM over P strips of a row (docs/ppc-hardware.md, "Memories";
// fpstereo_strip_aggregation places it): the front end writes a slot's P entries (P consecutive
// pixels, {match, base} each) at once in raster order, and strip s's aggregator reads one entry a
// step in its chain order. A slot lies in one strip (STRIP_PIXELS is a multiple of P), so strip s
// has a RAM of its own whose word is a slot's entries, and the read picks the entry by the address'
// low bits, registered with the word. Strip s reads a row during the K row-times that follow the
// strip's lag of s * K, so its RAM holds (s + 1) * K rows: row r takes row slot r mod (s + 1) * K.
// The write's row slot counts modulo SLOT_ROWS, a multiple of every strip's rows, so each strip's
// is a constant modulus of it. A write reaches its RAM a clock after its inputs: each strip
// registers whether it is its own, its row's first word and the slot's word within the row, so
// that neither the frame's bounds (in we) nor the modulus lie on a path with the address' sum.
// With EXTRA_W, each pixel's word holds EXTRA_W more bits above its entry (adaptive P2's
// penalties, which leave fpstereo_adaptive_p2 a slot and EXTRA_LAT steps after the entries): the
// writes wait as long, so that each word holds its own pixel's (uf = dmax: every step is a slot's).
// With BASE_WAIT (min-disp below 0, where a pixel's match pixel lies right of it) a slot's base
// entries (each pixel's low ENTRY_W / 2 bits), whether and where they are written and their
// penalties wait BASE_WAIT slots for the slots of their match pixels, whose entries come on time
// (the generator turns them to meet the base entries).
module fpstereo_strip_code_reorder #(
  parameter P = 2,
  parameter K = 5,
  // pixels of a strip (K * SEGMENT, a multiple of P)
  parameter STRIP_PIXELS = 20,
  parameter ENTRY_W = 24,
  parameter EXTRA_W = 0,
  parameter EXTRA_LAT = 1,
  // slots the base entries wait (ceil(-min-disp / P) below min-disp 0, else 0)
  parameter BASE_WAIT = 0,
  parameter SLOT_ROWS = 10,
  parameter SLOT_W = 4,
  // width of the write's slot (pixel / P) and of each strip's read address
  parameter X_W = 6,
  parameter AW = 9
) (
  input  wire               clk,
  input  wire               adv,
  input  wire               we,
  input  wire [X_W-1:0]     wslot,
  input  wire [SLOT_W-1:0]  wrow,
  input  wire [P*ENTRY_W-1:0] wdata,
  /* verilator lint_off UNUSEDSIGNAL */  // without EXTRA_W
  input  wire [P*(EXTRA_W > 0 ? EXTRA_W : 1)-1:0] extra,
  /* verilator lint_on UNUSEDSIGNAL */
  // strip s: its row slot * STRIP_PIXELS + its pixel within the strip
  input  wire [P*AW-1:0]    raddr,
  output wire [P*(ENTRY_W+EXTRA_W)-1:0] q
);
  localparam WORDS = STRIP_PIXELS / P;  // a strip's words per row
  localparam PIXEL_W = ENTRY_W + EXTRA_W;  // a pixel's part of a word
  localparam LOG_P = $clog2(P);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if ((P != 2 && P != 4) || STRIP_PIXELS % P != 0 || P * WORDS > (1 << X_W) || SLOT_ROWS > (1 << SLOT_W) ||
        (1 << AW) < P * K * STRIP_PIXELS || (EXTRA_W > 0 && EXTRA_LAT < 1) || BASE_WAIT < 0 ||
        (BASE_WAIT > 0 && ENTRY_W % 2 != 0)) begin : invalid
      fpstereo_invalid_parameters_strip_code_reorder_P_STRIP_PIXELS_widths_EXTRA_LAT_or_BASE_WAIT failed ();
    end
  endgenerate
  // The write with its base entries as they meet their match entries: at once, or BASE_WAIT slots
  // later. No reset: the wait carries a frame's last slots into the next frame's first.
  wire              we_met;
  wire [X_W-1:0]    wslot_met;
  wire [SLOT_W-1:0] wrow_met;
  wire [P*ENTRY_W-1:0] wdata_met;
  /* verilator lint_off UNUSEDSIGNAL */  // without EXTRA_W
  wire [P*(EXTRA_W > 0 ? EXTRA_W : 1)-1:0] extra_met;
  /* verilator lint_on UNUSEDSIGNAL */
  genvar s, i;
  generate
    if (BASE_WAIT > 0) begin : base_late
      localparam BASE_W = ENTRY_W / 2;
      localparam LATE_W = 1 + X_W + SLOT_W + P * BASE_W;
      wire [P*BASE_W-1:0] bases, bases_late;
      wire [LATE_W-1:0] late;
      for (i = 0; i < P; i = i + 1) begin : pixel
        assign bases[i*BASE_W +: BASE_W] = wdata[i*ENTRY_W +: BASE_W];
        assign wdata_met[i*ENTRY_W +: ENTRY_W] = {wdata[i*ENTRY_W+BASE_W +: BASE_W], bases_late[i*BASE_W +: BASE_W]};
      end
      fpstereo_delay #(.WIDTH(LATE_W), .DEPTH(BASE_WAIT), .RESET(0)) base_wait (
        .clk(clk), .rst(1'b0), .en(adv), .in({we, wslot, wrow, bases}), .out(late));
      assign we_met = adv && late[LATE_W-1];
      assign {wslot_met, wrow_met, bases_late} = late[LATE_W-2:0];
      if (EXTRA_W > 0) begin : penalties_late
        fpstereo_delay #(.WIDTH(P * EXTRA_W), .DEPTH(BASE_WAIT), .RESET(0)) penalty_wait (
          .clk(clk), .rst(1'b0), .en(adv), .in(extra), .out(extra_met));
      end else begin : no_penalties
        assign extra_met = extra;
      end
    end else begin : base_in_time
      assign we_met = we;
      assign wslot_met = wslot;
      assign wrow_met = wrow;
      assign wdata_met = wdata;
      assign extra_met = extra;
    end
  endgenerate
  // The write as it reaches the strips' registers: at once, or with EXTRA_W after the penalties.
  wire              we_in;
  wire [X_W-1:0]    wslot_in;
  wire [SLOT_W-1:0] wrow_in;
  wire [P*PIXEL_W-1:0] wdata_in;
  generate
    if (EXTRA_W > 0) begin : wait_for_extra
      localparam HELD_W = 1 + X_W + SLOT_W + P * ENTRY_W;
      reg  [HELD_W-1:0] held;
      wire [HELD_W-1:0] later;
      always @(posedge clk)
        if (adv) held <= {we_met, wslot_met, wrow_met, wdata_met};
      fpstereo_delay #(.WIDTH(HELD_W), .DEPTH(EXTRA_LAT)) extra_wait (
        .clk(clk), .rst(1'b0), .en(adv), .in(held), .out(later));
      assign we_in = adv && later[HELD_W-1];
      assign {wslot_in, wrow_in} = later[HELD_W-2 -: X_W+SLOT_W];
      for (i = 0; i < P; i = i + 1) begin : pixel
        assign wdata_in[i*PIXEL_W +: PIXEL_W] = {extra_met[i*EXTRA_W +: EXTRA_W], later[i*ENTRY_W +: ENTRY_W]};
      end
    end else begin : at_once
      assign we_in = we_met;
      assign wslot_in = wslot_met;
      assign wrow_in = wrow_met;
      assign wdata_in = wdata_met;
    end
  endgenerate
  reg [P*PIXEL_W-1:0] write_data;  // the strips' writes a clock later (below)
  always @(posedge clk) write_data <= wdata_in;
  generate
    for (s = 0; s < P; s = s + 1) begin : strip
      localparam ROWS = (s + 1) * K;
      localparam DEPTH = ROWS * WORDS;
      localparam RAM_AW = $clog2(DEPTH);
      if (SLOT_ROWS % ROWS != 0) begin : invalid_rows
        fpstereo_invalid_parameters_strip_code_reorder_SLOT_ROWS_not_a_multiple_of_a_strips_rows failed ();
      end
      localparam integer FIRST_I = s * WORDS, AFTER_I = (s + 1) * WORDS;
      localparam [X_W:0] FIRST = FIRST_I[X_W:0], AFTER = AFTER_I[X_W:0];
      wire mine;
      if (s == 0) begin : first_strip
        assign mine = {1'b0, wslot_in} < AFTER;
      end else begin : later_strip
        assign mine = {1'b0, wslot_in} >= FIRST && {1'b0, wslot_in} < AFTER;
      end
      // The row's first word, (wrow mod ROWS) * WORDS, read from a ROM by the row slot: a modulus
      // and a product of the slot were 7 LUTs deep where ROWS is not a power of two (1080p, four
      // strips of six chains), and a chain of compares over the slots, which the mapper left 9
      // deep in the whole design where other paths set its delay target. A ROM is a mux tree on
      // the slot's bits. The other addresses are narrow values and constants, cut to the RAM's
      // address width.
      /* verilator lint_off WIDTH */
      reg [RAM_AW-1:0] first_words [0:(1<<SLOT_W)-1];
      integer r;
      initial
        for (r = 0; r < (1 << SLOT_W); r = r + 1)
          first_words[r] = (r % ROWS) * WORDS;
      wire [RAM_AW-1:0] row_first = first_words[wrow_in];
      wire [RAM_AW-1:0] word_in_row = wslot_in - FIRST;
      wire [AW-1:0] at = raddr[s*AW +: AW];
      wire [RAM_AW-1:0] word_addr = at >> LOG_P;
      /* verilator lint_on WIDTH */
      reg write = 1'b0;
      reg [RAM_AW-1:0] write_first, write_word;
      always @(posedge clk) begin
        write <= we_in && mine;
        write_first <= row_first;
        write_word <= word_in_row;
      end
      wire [P*PIXEL_W-1:0] word;
      fpstereo_ram_sdp #(.WIDTH(P*PIXEL_W), .DEPTH(DEPTH), .ADDR_W(RAM_AW)) ram (
        .clk(clk), .we(write), .waddr(write_first + write_word), .wdata(write_data), .re(adv), .raddr(word_addr),
        .rdata(word));
      reg [LOG_P-1:0] pick;
      always @(posedge clk)
        if (adv) pick <= at[LOG_P-1:0];
      assign q[s*PIXEL_W +: PIXEL_W] = word[pick*PIXEL_W +: PIXEL_W];
    end
  endgenerate
endmodule
`resetall
