`resetall
`default_nettype none
// Line buffer and N x N window of one image. The N-1 previous rows of each column live in one
// block RAM word (registered read, read one slot ahead); the window is a register array that
// shifts in one column per slot. window[(i*N + j)*8 +: 8] is row i (0 = oldest) and column j
// (0 = leftmost).
module fpstereo_window #(
  // window side
  parameter N = 7,
  // columns per row-time (line buffer depth)
  parameter ROW_SLOTS = 64,
  // column address bits
  parameter ADDR_W = 6
) (
  input  wire              clk,
  // high in the step where this slot's pixel enters
  input  wire              shift,
  // column of the entering pixel, and the column of the next slot (below ROW_SLOTS)
  /* verilator lint_off UNUSEDSIGNAL */  // wider than the line buffer address when ROW_SLOTS is a power of two
  input  wire [ADDR_W-1:0] col,
  input  wire [ADDR_W-1:0] next_col,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [7:0]        pixel,
  output wire [N*N*8-1:0]  window
);
  localparam STORED_W = (N - 1) * 8;
  localparam LB_AW = $clog2(ROW_SLOTS);

  // stored[i*8 +: 8] is the pixel i + 1 rows above the entering one.
  wire [STORED_W-1:0] stored;
  // The column moves down one row: the entering pixel on top, the oldest row dropped (N >= 3).
  wire [STORED_W-1:0] updated = {stored[STORED_W-9:0], pixel};

  fpstereo_ram_sdp #(.WIDTH(STORED_W), .DEPTH(ROW_SLOTS), .ADDR_W(LB_AW)) line_buffer (
    .clk(clk), .we(shift), .waddr(col[LB_AW-1:0]), .wdata(updated),
    .re(shift), .raddr(next_col[LB_AW-1:0]), .rdata(stored));

  reg [N*N*8-1:0] window_q;
  assign window = window_q;

  integer i, j;
  always @(posedge clk)
    if (shift)
      for (i = 0; i < N; i = i + 1) begin
        for (j = 0; j < N - 1; j = j + 1) window_q[(i*N + j)*8 +: 8] <= window_q[(i*N + j + 1)*8 +: 8];
        window_q[(i*N + N - 1)*8 +: 8] <= (i == N - 1) ? pixel : stored[(N - 2 - i)*8 +: 8];
      end
endmodule
`resetall
