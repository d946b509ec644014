`resetall
`default_nettype none
// Disparity reorder RAM and the output's raster order (docs/architecture.md): the winner-take-all
// writes each pixel's word in its last group's step, in chain order; from out_on on, one word is
// read per slot in raster order. Rows below the image (the median's last rows need them, and
// EXTRA_ROWS more for gap interpolation, one row behind) and bubble slots read as invalid words.
// The read stream: read_done in the step after each slot's read, read_event where that slot is a
// pixel of the frame's output rows, its position and word.
module fpstereo_disparity_reorder #(
  parameter ROW_SLOTS = 64,
  parameter G = 4,
  parameter DISP_W = 5,
  // rows of the RAM (the slot is the row modulo OUT_ROWS)
  parameter OUT_ROWS = 3,
  parameter OUT_ROW_W = 2,
  // address width of the OUT_ROWS * ROW_SLOTS words
  parameter DISP_AW = 8,
  parameter EXTRA_ROWS = 0,
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter G_W = 2
) (
  input  wire               clk,
  input  wire               restart,
  input  wire               adv,
  input  wire               out_on,
  // back-to-back frames (fpstereo_front_end): the read rows wrap after the frame's last, and the
  // next frame's rows stand in for the rows below the image
  input  wire               overlap,
  input  wire [X_W-1:0]     frame_width,
  input  wire [Y_W-1:0]     frame_height,
  // the winner-take-all's pixel: written in its last group's step
  input  wire               active,
  input  wire [X_W-1:0]     x,
  input  wire [OUT_ROW_W-1:0] slot,
  input  wire [G_W-1:0]     group,
  input  wire [DISP_W:0]    word,
  output reg                read_done,
  output reg                read_event,
  output reg  [X_W-1:0]     read_x,
  output reg  [Y_W-1:0]     read_y,
  output reg  [OUT_ROW_W-1:0] read_slot_row,
  output wire [DISP_W:0]    read_word
);
  localparam DISP_DEPTH = OUT_ROWS * ROW_SLOTS;
  localparam [DISP_W:0] INVALID_WORD = {1'b1, {DISP_W{1'b0}}};
  localparam integer LAST_GROUP_I = G - 1;
  localparam [G_W-1:0] LAST_GROUP = LAST_GROUP_I[G_W-1:0];
  generate
    if (DISP_AW < $clog2(DISP_DEPTH) || (1 << OUT_ROW_W) < OUT_ROWS) begin : invalid
      fpstereo_invalid_parameters_reorder_addresses_too_narrow failed ();
    end
  endgenerate
  // Addresses are products of narrow counters and constants, cut to the RAM's address width.
  // verilator lint_off WIDTH
  wire [DISP_AW-1:0] waddr = slot * ROW_SLOTS + x;
  wire write = adv && active && group == LAST_GROUP;

  /* verilator lint_off UNUSEDSIGNAL */  // slot_end says what the output needs of the group
  wire [G_W-1:0] go;
  /* verilator lint_on UNUSEDSIGNAL */
  wire [X_W-1:0] so;
  wire [Y_W-1:0] to;
  wire [OUT_ROW_W-1:0] to_slot;  // to mod OUT_ROWS
  wire slot_end;
  fpstereo_raster_counter #(.G(G), .ROW_SLOTS(ROW_SLOTS), .K(OUT_ROWS), .G_W(G_W), .X_W(X_W), .Y_W(Y_W),
                            .K_W(OUT_ROW_W))
    output_position (.clk(clk), .restart(restart), .en(adv && out_on), .wrap(overlap), .height(frame_height),
                     .group(go), .slot(so), .row(to), .row_slot(to_slot), .slot_end(slot_end));
  wire [Y_W-1:0] event_rows = frame_height + EXTRA_ROWS;
  wire read_slot = out_on && slot_end;
  wire read_now = read_slot && so < frame_width && to < event_rows;
  wire read_valid = read_now && to < frame_height;
  wire [DISP_W:0] disparity_q;
  wire [DISP_AW-1:0] raddr = to_slot * ROW_SLOTS + so;
  fpstereo_ram_sdp #(.WIDTH(DISP_W + 1), .DEPTH(DISP_DEPTH), .ADDR_W(DISP_AW)) disp_ram (
    .clk(clk), .we(write), .waddr(waddr), .wdata(word),
    .re(adv && read_valid), .raddr(raddr), .rdata(disparity_q));
  // verilator lint_on WIDTH
  reg read_was_valid;
  always @(posedge clk)
    if (restart) begin
      read_done <= 1'b0;
      read_event <= 1'b0;
      read_was_valid <= 1'b0;
    end else if (adv) begin
      read_done <= read_slot;
      read_event <= read_now;
      read_was_valid <= read_valid;
      read_x <= so;
      read_y <= to;
      read_slot_row <= to_slot;
    end
  assign read_word = read_was_valid ? disparity_q : INVALID_WORD;
endmodule
`resetall
