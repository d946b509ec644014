`resetall
`default_nettype none
// Left-right check (docs/semantics.md, section 5), three steps: the match side writes Dm(x') of its
// completed pixels (and, with ROW_END, as LR1 does, the last DMAX - 1 of each row into the
// row-end RAM, one word of UF per group); for the read stream's pixel x with disparity D, Dm of
// x' = x - D is read, and the word becomes invalid where x' lies outside the image or
// |D - Dm(x')| > lr_threshold. The RAMs are read in the first step, Dm is registered in the
// second, the check's result in the third, and the stream leaves three steps later.
// With sub-pixel output (REFINED_W > 0) the read word carries the refined disparity above the
// whole D: the check uses D (semantics section 5), and the word that leaves is {invalid, refined}.
module fpstereo_lr_check #(
  parameter ROW_SLOTS = 64,
  parameter G = 4,
  parameter UF = 8,
  parameter DMAX = 32,
  parameter DISP_W = 5,
  // bits of the refined disparity carried above D in the read word, 0 without sub-pixel output
  parameter REFINED_W = 0,
  parameter OUT_ROWS = 3,
  parameter OUT_K_W = 2,
  parameter DISP_AW = 8,
  // LR1: the row ends come from the row-end RAM
  parameter ROW_END = 1,
  parameter END_AW = 4,
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter LANE_W = 3
) (
  input  wire                 clk,
  input  wire                 restart,
  input  wire                 adv,
  /* verilator lint_off UNUSEDSIGNAL */  // only LR1's row ends need the width
  input  wire [X_W-1:0]       frame_width,
  /* verilator lint_on UNUSEDSIGNAL */
  input  wire [3:0]           lr_threshold,
  input  wire                 completed_we,
  input  wire [DISP_AW-1:0]   completed_waddr,
  input  wire [DISP_W-1:0]    completed_wdata,
  /* verilator lint_off UNUSEDSIGNAL */  // LR2 has no row-end RAM
  input  wire                 row_end_we,
  input  wire [END_AW-1:0]    row_end_waddr,
  input  wire [UF*DISP_W-1:0] row_end_wdata,
  /* verilator lint_on UNUSEDSIGNAL */
  // the read stream (fpstereo_disparity_reorder)
  input  wire                 read_done,
  input  wire                 read_event,
  input  wire [X_W-1:0]       read_x,
  input  wire [Y_W-1:0]       read_y,
  input  wire [OUT_K_W-1:0]   read_slot_row,
  input  wire [REFINED_W+DISP_W:0] read_word,
  output reg                  checked_done,
  output reg                  checked_event,
  output reg  [X_W-1:0]       checked_x,
  output reg  [Y_W-1:0]       checked_y,
  output wire [(REFINED_W > 0 ? REFINED_W : DISP_W):0] checked_word
);
  localparam IN_W = REFINED_W + DISP_W;  // the read word's bits under its invalid flag
  localparam OUT_W = REFINED_W > 0 ? REFINED_W : DISP_W;
  localparam [OUT_W:0] INVALID_WORD = {1'b1, {OUT_W{1'b0}}};
  generate
    if (DISP_AW < $clog2(OUT_ROWS * ROW_SLOTS) || (ROW_END && END_AW < $clog2(OUT_ROWS * G))) begin : invalid
      fpstereo_invalid_parameters_lr_check_addresses_too_narrow failed ();
    end
  endgenerate
  // Addresses are products of narrow counters and constants, cut to the RAMs' address widths.
  // verilator lint_off WIDTH
  wire [DISP_W-1:0] d = read_word[DISP_W-1:0];
  wire outside = read_word[IN_W] || read_x < d;
  wire [X_W-1:0] xm = read_x - d;
  wire [DISP_W-1:0] match_q;
  fpstereo_ram_sdp #(.WIDTH(DISP_W), .DEPTH(OUT_ROWS * ROW_SLOTS), .ADDR_W(DISP_AW)) completed (
    .clk(clk), .we(completed_we), .waddr(completed_waddr), .wdata(completed_wdata),
    .re(adv), .raddr(read_slot_row * ROW_SLOTS + xm), .rdata(match_q));
  reg [IN_W:0]   word_c;
  reg            outside_c, done_c, event_c;
  reg [X_W-1:0]  x_c;
  reg [Y_W-1:0]  y_c;
  always @(posedge clk)
    if (restart) begin
      done_c <= 1'b0;
      event_c <= 1'b0;
    end else if (adv) begin
      done_c <= read_done;
      event_c <= read_event;
      x_c <= read_x;
      y_c <= read_y;
      word_c <= read_word;
      outside_c <= outside;
    end
  // Dm(x'): from the completed match pixels or, for LR1's last DMAX - 1 of the row, the row end.
  wire [DISP_W-1:0] dm;
  generate
    if (ROW_END) begin : row_end
      wire from_row_end = xm > frame_width - DMAX;
      wire [DISP_W-1:0] from_end = frame_width - 1 - xm;  // the row-end entry of x'
      wire [UF*DISP_W-1:0] end_q;
      fpstereo_ram_sdp #(.WIDTH(UF*DISP_W), .DEPTH(OUT_ROWS * G), .ADDR_W(END_AW)) row_end (
        .clk(clk), .we(row_end_we), .waddr(row_end_waddr), .wdata(row_end_wdata),
        .re(adv), .raddr(read_slot_row * G + from_end / UF), .rdata(end_q));
      reg              from_row_end_c;
      reg [LANE_W-1:0] lane_c;
      always @(posedge clk)
        if (adv) begin
          from_row_end_c <= from_row_end;
          lane_c <= from_end % UF;
        end
      assign dm = from_row_end_c ? end_q[lane_c * DISP_W +: DISP_W] : match_q;
    end else begin : completed_only
      assign dm = match_q;
    end
  endgenerate
  // Second step: Dm registered with the stream, so that the RAM reads and the check lie in
  // different steps; third: the check's result registered with the stream.
  reg              done_q, event_q;
  reg [X_W-1:0]    x_q;
  reg [Y_W-1:0]    y_q;
  reg [DISP_W-1:0] dm_q;
  reg [IN_W:0]     word_q;
  reg [OUT_W:0]    checked_word_q;
  reg              outside_q;
  wire [DISP_W-1:0] db = word_q[DISP_W-1:0];
  wire [DISP_W-1:0] difference = db > dm_q ? db - dm_q : dm_q - db;
  always @(posedge clk)
    if (restart) begin
      done_q <= 1'b0;
      event_q <= 1'b0;
      checked_done <= 1'b0;
      checked_event <= 1'b0;
    end else if (adv) begin
      done_q <= done_c;
      event_q <= event_c;
      x_q <= x_c;
      y_q <= y_c;
      word_q <= word_c;
      outside_q <= outside_c;
      dm_q <= dm;
      checked_done <= done_q;
      checked_event <= event_q;
      checked_x <= x_q;
      checked_y <= y_q;
      checked_word_q <= (outside_q || difference > lr_threshold) ? INVALID_WORD : {word_q[IN_W], word_q[IN_W-1 -: OUT_W]};
    end
  assign checked_word = checked_word_q;
  // verilator lint_on WIDTH
endmodule
`resetall
