`resetall
`default_nettype none
// Line buffer and window over a raster stream of WORD_W-bit words (pixels, or transform codes),
// P words a slot (a beat of P consecutive columns, the leftmost in the lowest bits). The N-1
// previous rows of a beat's columns live in one block RAM word (registered read, read one slot
// ahead); the window is a register array N rows high and COLS columns wide that shifts in P
// columns per slot. With COLS = N + P - 1 it holds the P windows of N x N whose newest columns
// just entered (window p: columns p .. p + N - 1); wider, it holds older ones too, so that a
// front end can take windows whose centres are a whole slot (P columns starting at a multiple of P).
// window[(i*COLS + j)*WORD_W +: WORD_W] is row i (0 = oldest) and column j (0 = leftmost).
module fpstereo_window #(
  // window side
  parameter N = 7,
  // bits per word
  parameter WORD_W = 8,
  // words (columns) per slot
  parameter P = 1,
  // columns of the register array
  parameter COLS = N + P - 1,
  // slots per row-time (line buffer depth)
  parameter ROW_SLOTS = 64,
  // slot address bits
  parameter ADDR_W = 6
) (
  input  wire              clk,
  // high in the step where this slot's words enter
  input  wire              shift,
  // slot of the entering words, and the slot after it (below ROW_SLOTS)
  /* verilator lint_off UNUSEDSIGNAL */  // wider than the line buffer address when ROW_SLOTS is a power of two
  input  wire [ADDR_W-1:0] col,
  input  wire [ADDR_W-1:0] next_col,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [P*WORD_W-1:0] word,
  output wire [N*COLS*WORD_W-1:0] window
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 3) begin : invalid_N
      fpstereo_invalid_parameters_window_N_below_3 failed ();
    end
    if (P < 1 || COLS < N + P - 1) begin : invalid_P
      fpstereo_invalid_parameters_window_P_below_1_or_COLS_below_N_plus_P_minus_1 failed ();
    end
    if (ROW_SLOTS < 2 || ADDR_W < $clog2(ROW_SLOTS)) begin : invalid_ADDR_W
      fpstereo_invalid_parameters_window_ADDR_W_below_clog2_ROW_SLOTS failed ();
    end
  endgenerate
  localparam C = COLS;
  localparam BEAT_W = P * WORD_W;
  localparam STORED_W = (N - 1) * BEAT_W;
  localparam LB_AW = $clog2(ROW_SLOTS);

  // stored[i*BEAT_W +: BEAT_W] is the slot's words i + 1 rows above the entering ones.
  wire [STORED_W-1:0] stored;
  // The columns move down one row: the entering words on top, the oldest row dropped (N >= 3).
  wire [STORED_W-1:0] updated = {stored[STORED_W-BEAT_W-1:0], word};

  fpstereo_ram_sdp #(.WIDTH(STORED_W), .DEPTH(ROW_SLOTS), .ADDR_W(LB_AW)) line_buffer (
    .clk(clk), .we(shift), .waddr(col[LB_AW-1:0]), .wdata(updated),
    .re(shift), .raddr(next_col[LB_AW-1:0]), .rdata(stored));

  reg [N*C*WORD_W-1:0] window_q;
  assign window = window_q;

  integer i, j, q;
  always @(posedge clk)
    if (shift)
      for (i = 0; i < N; i = i + 1) begin
        for (j = 0; j < C - P; j = j + 1) window_q[(i*C + j)*WORD_W +: WORD_W] <= window_q[(i*C + j + P)*WORD_W +: WORD_W];
        for (q = 0; q < P; q = q + 1)
          window_q[(i*C + C - P + q)*WORD_W +: WORD_W] <=
              (i == N - 1) ? word[q*WORD_W +: WORD_W] : stored[(N - 2 - i)*BEAT_W + q*WORD_W +: WORD_W];
      end
endmodule
`resetall
