`resetall
`default_nettype none
// Line buffer and N x N window over a raster stream of WORD_W-bit words (pixels, or transform
// codes). The N-1 previous rows of each column live in one block RAM word (registered read, read
// one slot ahead); the window is a register array that shifts in one column per slot.
// window[(i*N + j)*WORD_W +: WORD_W] is row i (0 = oldest) and column j (0 = leftmost).
module fpstereo_window #(
  // window side
  parameter N = 7,
  // bits per word
  parameter WORD_W = 8,
  // columns per row-time (line buffer depth)
  parameter ROW_SLOTS = 64,
  // column address bits
  parameter ADDR_W = 6
) (
  input  wire              clk,
  // high in the step where this slot's word enters
  input  wire              shift,
  // column of the entering word, and the column of the next slot (below ROW_SLOTS)
  /* verilator lint_off UNUSEDSIGNAL */  // wider than the line buffer address when ROW_SLOTS is a power of two
  input  wire [ADDR_W-1:0] col,
  input  wire [ADDR_W-1:0] next_col,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [WORD_W-1:0] word,
  output wire [N*N*WORD_W-1:0] window
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 3) begin : invalid_N
      fpstereo_invalid_parameters_window_N_below_3 failed ();
    end
    if (ROW_SLOTS < 2 || ADDR_W < $clog2(ROW_SLOTS)) begin : invalid_ADDR_W
      fpstereo_invalid_parameters_window_ADDR_W_below_clog2_ROW_SLOTS failed ();
    end
  endgenerate
  localparam STORED_W = (N - 1) * WORD_W;
  localparam LB_AW = $clog2(ROW_SLOTS);

  // stored[i*WORD_W +: WORD_W] is the word i + 1 rows above the entering one.
  wire [STORED_W-1:0] stored;
  // The column moves down one row: the entering word on top, the oldest row dropped (N >= 3).
  wire [STORED_W-1:0] updated = {stored[STORED_W-WORD_W-1:0], word};

  fpstereo_ram_sdp #(.WIDTH(STORED_W), .DEPTH(ROW_SLOTS), .ADDR_W(LB_AW)) line_buffer (
    .clk(clk), .we(shift), .waddr(col[LB_AW-1:0]), .wdata(updated),
    .re(shift), .raddr(next_col[LB_AW-1:0]), .rdata(stored));

  reg [N*N*WORD_W-1:0] window_q;
  assign window = window_q;

  integer i, j;
  always @(posedge clk)
    if (shift)
      for (i = 0; i < N; i = i + 1) begin
        for (j = 0; j < N - 1; j = j + 1) window_q[(i*N + j)*WORD_W +: WORD_W] <= window_q[(i*N + j + 1)*WORD_W +: WORD_W];
        window_q[(i*N + N - 1)*WORD_W +: WORD_W] <= (i == N - 1) ? word : stored[(N - 2 - i)*WORD_W +: WORD_W];
      end
endmodule
`resetall
