`resetall
`default_nettype none
// Line buffer and M x M window of the disparity words that feed the median filter
// (docs/semantics.md, sections 6 and 8). Built like fpstereo_window, only with WORD_W-bit words
// instead of 8-bit pixels: the M-1 previous rows of each column live in one block RAM word
// (registered read, read one slot ahead so the word is ready when the slot's word enters); the
// window is a register array that shifts in one column per slot.
// window[(i*M + j)*WORD_W +: WORD_W] is row i (0 = oldest) and column j (0 = leftmost). Words are
// stored as they arrive, invalid flag included; which of them lie inside the image is the
// median's business (row_valid / col_valid), as for the cost windows.
module fpstereo_median_window #(
  // window side (3, 5 or 7; at least 3)
  parameter M = 5,
  // word width: disparity bits plus the invalid flag on top
  parameter WORD_W = 8,
  // columns per row-time (line buffer depth)
  parameter ROW_SLOTS = 64,
  // column address bits
  parameter ADDR_W = 6
) (
  input  wire                  clk,
  // high in the step where this slot's word enters
  input  wire                  shift,
  // column of the entering word, and the column of the next slot (below ROW_SLOTS)
  /* verilator lint_off UNUSEDSIGNAL */  // wider than the line buffer address when ROW_SLOTS is a power of two
  input  wire [ADDR_W-1:0]     col,
  input  wire [ADDR_W-1:0]     next_col,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [WORD_W-1:0]     word,
  output wire [M*M*WORD_W-1:0] window
);
  localparam STORED_W = (M - 1) * WORD_W;
  localparam LB_AW = $clog2(ROW_SLOTS);

  // stored[i*WORD_W +: WORD_W] is the word i + 1 rows above the entering one.
  wire [STORED_W-1:0] stored;
  // The column moves down one row: the entering word on top, the oldest row dropped (M >= 3).
  wire [STORED_W-1:0] updated = {stored[STORED_W-WORD_W-1:0], word};

  fpstereo_ram_sdp #(.WIDTH(STORED_W), .DEPTH(ROW_SLOTS), .ADDR_W(LB_AW)) line_buffer (
    .clk(clk), .we(shift), .waddr(col[LB_AW-1:0]), .wdata(updated),
    .re(shift), .raddr(next_col[LB_AW-1:0]), .rdata(stored));

  reg [M*M*WORD_W-1:0] window_q;
  assign window = window_q;

  integer i, j;
  always @(posedge clk)
    if (shift)
      for (i = 0; i < M; i = i + 1) begin
        for (j = 0; j < M - 1; j = j + 1)
          window_q[(i*M + j)*WORD_W +: WORD_W] <= window_q[(i*M + j + 1)*WORD_W +: WORD_W];
        window_q[(i*M + M - 1)*WORD_W +: WORD_W] <= (i == M - 1) ? word : stored[(M - 2 - i)*WORD_W +: WORD_W];
      end
endmodule
`resetall
