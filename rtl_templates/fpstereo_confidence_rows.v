`resetall
`default_nettype none
// The confidences from the disparity reorder RAM's raster stream to the output stage, rows later
// (the median and gap interpolation between): written at (row slot, x) as the input stream
// passes, read a step before the output register takes the pixel's word, so that both leave in
// the same step. Row slots count the streams' row ends (ROWS of them, more than the rows the
// output lags), so frames that follow on continue them. With P > 1 (strips) x counts slots of
// P pixels, W is a row's slots and a slot's P confidences go together, pixel 0 lowest.
module fpstereo_confidence_rows #(
  parameter W = 64,
  parameter P = 1,
  parameter ROWS = 3,
  parameter ROW_K_W = 2,
  parameter AW = 8,
  parameter X_W = 7
) (
  input  wire           clk,
  input  wire           restart,
  input  wire           adv,
  input  wire [X_W-1:0] frame_width,
  input  wire           in_event,
  input  wire [X_W-1:0] in_x,
  input  wire [8*P-1:0] in_confidence,
  input  wire           out_event,
  input  wire [X_W-1:0] out_x,
  output wire [8*P-1:0] out_confidence
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (ROWS < 2 || ROWS > (1 << ROW_K_W) || AW < $clog2(ROWS * W) || W >= (1 << X_W) || (P != 1 && P != 2 && P != 4)) begin : invalid
      fpstereo_invalid_parameters_confidence_rows_widths_too_narrow failed ();
    end
  endgenerate
  localparam integer LAST_ROW_I = ROWS - 1;
  localparam [ROW_K_W-1:0] LAST_ROW = LAST_ROW_I[ROW_K_W-1:0];
  wire [X_W-1:0] last_x = (frame_width >> $clog2(P)) - 1'b1;
  reg  [ROW_K_W-1:0] in_row, out_row;
  always @(posedge clk)
    if (restart) begin
      in_row <= {ROW_K_W{1'b0}};
      out_row <= {ROW_K_W{1'b0}};
    end else if (adv) begin
      if (in_event && in_x == last_x) in_row <= in_row == LAST_ROW ? {ROW_K_W{1'b0}} : in_row + 1'b1;
      if (out_event && out_x == last_x) out_row <= out_row == LAST_ROW ? {ROW_K_W{1'b0}} : out_row + 1'b1;
    end
  // Addresses are products of narrow counters and a constant, cut to the RAM's address width.
  // verilator lint_off WIDTH
  wire [AW-1:0] waddr = in_row * W + in_x, raddr = out_row * W + out_x;
  fpstereo_ram_sdp #(.WIDTH(8 * P), .DEPTH(ROWS * W), .ADDR_W(AW)) confidences (
    .clk(clk), .we(adv && in_event), .waddr(waddr), .wdata(in_confidence),
    .re(adv), .raddr(raddr), .rdata(out_confidence));
  // verilator lint_on WIDTH
endmodule
`resetall
