`resetall
`default_nettype none
// A stage's row-time counter (docs/architecture.md, "Back-to-back frames"): it advances by one at
// each `next` and, while `wrap` is high, returns to 0 after the frame's last row (height - 1),
// so that the next frame's rows follow this frame's without a restart. Without wrap it counts on
// past the frame (the rows a lone frame drains through). `last` says the row is the frame's last,
// as a register (frames are at least 2 rows high). A counter that lags its stage's row-times
// starts at START < 0 (two's complement: rows above the first frame).
module fpstereo_frame_row #(
  parameter Y_W = 6,
  parameter START = 0
) (
  input  wire           clk,
  input  wire           restart,
  input  wire           next,
  input  wire           wrap,
  input  wire [Y_W-1:0] height,
  output reg  [Y_W-1:0] row,
  output reg            last
);
  localparam [Y_W-1:0] TWO = 2;
  reg [Y_W-1:0] before_last;
  always @(posedge clk) before_last <= height - TWO;
  wire wraps = wrap && last;
  localparam integer START_I = START;
  localparam [Y_W-1:0] FIRST = START_I[Y_W-1:0];
  always @(posedge clk)
    if (restart) begin
      row <= FIRST;
      last <= 1'b0;
    end else if (next) begin
      row <= wraps ? {Y_W{1'b0}} : row + 1'b1;
      last <= !wraps && row == before_last;
    end
endmodule
`resetall
