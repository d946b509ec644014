`resetall
`default_nettype none
// Speckle filter stage (docs/semantics.md section 5a, docs/speckle-hardware.md): the pixel stream's
// word of every slot (the invalid word outside the image) enters fpstereo_speckle, ROW_SLOTS words
// a row, and the word of the same slot ROWS rows earlier leaves filtered. The filter takes a word
// once in 4 clocks; a slot is G >= 4 steps, so it is ready for each slot's word, and its exit word
// for a slot is there by the next slot's word, which is when it is taken: the stream leaves ROWS
// rows, one slot and one step behind. The first word of each frame (row 0, also after a wrap)
// tells the filter that nothing above it connects.
module fpstereo_speckle_stage #(
  parameter ROW_SLOTS = 64,
  // steps a slot: the filter needs 4 clocks a word
  parameter G = 4,
  // the speckle size S and range R (in word units: r << sub-pixel bits)
  parameter S = 8,
  parameter R = 2,
  // rows the filter holds: its latency in rows
  parameter ROWS = S + 2 + (S + 3) / 4,
  parameter DISP_W = 5,
  // events for the frame's rows and EXTRA_ROWS more (gap interpolation's row below the image)
  parameter EXTRA_ROWS = 0,
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter SIGNED_Y_W = 8
) (
  input  wire             clk,
  input  wire             restart,
  input  wire             adv,
  input  wire [X_W-1:0]   frame_width,
  input  wire [Y_W-1:0]   frame_height,
  // back-to-back frames: once wrapped, the rows above row 0 are the previous frame's
  input  wire             wrapped,
  input  wire             in_done,
  input  wire [X_W-1:0]   in_x,
  input  wire [Y_W-1:0]   in_y,
  input  wire [DISP_W:0]  in_word,
  output reg              out_done,
  output reg              out_event,
  output reg  [X_W-1:0]   out_x,
  output reg  [Y_W-1:0]   out_y,
  output reg  [DISP_W:0]  out_word
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (G < 4) begin : invalid_G
      fpstereo_invalid_parameters_speckle_stage_G_below_4 failed ();
    end
    if (SIGNED_Y_W < Y_W + 2) begin : invalid_SIGNED_Y_W
      fpstereo_invalid_parameters_speckle_stage_SIGNED_Y_W_below_Y_W_plus_2 failed ();
    end
  endgenerate
  localparam [DISP_W:0] INVALID_WORD = {1'b1, {DISP_W{1'b0}}};
  localparam integer ROWS_I = ROWS;
  localparam signed [SIGNED_Y_W-1:0] LAG_Y = ROWS_I[SIGNED_Y_W-1:0];
  wire take = adv && in_done;
  // Slots outside the frame (bubbles, the rows below it in a lone frame's drain) enter as the
  // invalid word: the stages before leave whatever word there.
  wire in_frame = in_x < frame_width && in_y < frame_height;
  wire [DISP_W:0] filtered;
  /* verilator lint_off UNUSEDSIGNAL */  // slots come G >= 4 steps apart: always ready, and the
  wire ready, exit_valid;                 // exit word is there by the next slot's word
  /* verilator lint_on UNUSEDSIGNAL */
  fpstereo_speckle #(.W(ROW_SLOTS), .S(S), .R(R), .WORD_W(DISP_W + 1), .INVALID(INVALID_WORD),
                     .ROWS(ROWS)) filter (
    .clk(clk), .rst(restart), .in_valid(take), .in_ready(ready), .in_first(in_x == 0 && in_y == 0),
    .in_word(in_frame ? in_word : INVALID_WORD), .out_valid(exit_valid), .out_word(filtered));
  // The position of the word that leaves: ROWS rows above the entering one, the previous frame's
  // row once wrapped.
  wire signed [SIGNED_Y_W-1:0] height_y = $signed({2'b00, frame_height});
  wire signed [SIGNED_Y_W-1:0] lagged = $signed({2'b00, in_y}) - LAG_Y;
  wire signed [SIGNED_Y_W-1:0] exit_y = wrapped && lagged < 0 ? lagged + height_y : lagged;
  wire exit_event = in_x < frame_width && exit_y >= 0 && exit_y < height_y + EXTRA_ROWS;
  // The slot taken last, whose exit word the filter holds when the next slot's word comes. The
  // stream out starts with the first slot whose exit row is not above the frame (as the disparity
  // reorder RAM's starts with row 0), so that every slot it passes has a position.
  reg           prev_event, prev_started;
  reg [X_W-1:0] prev_x;
  /* verilator lint_off UNUSEDSIGNAL */  // the top bits are 0 once started
  reg signed [SIGNED_Y_W-1:0] prev_y;
  /* verilator lint_on UNUSEDSIGNAL */
  always @(posedge clk)
    if (restart) begin
      prev_event <= 1'b0;
      prev_started <= 1'b0;
    end else if (take) begin
      prev_event <= exit_event;
      if (exit_y >= 0) prev_started <= 1'b1;
    end
  always @(posedge clk)
    if (take) begin
      prev_x <= in_x;
      prev_y <= exit_y;
    end
  always @(posedge clk)
    if (restart) begin
      out_done <= 1'b0;
      out_event <= 1'b0;
    end else if (adv) begin
      out_done <= in_done && prev_started;
      out_event <= in_done && prev_event;
    end
  always @(posedge clk)
    if (take) begin
      out_x <= prev_x;
      out_y <= prev_y[Y_W-1:0];
      out_word <= filtered;
    end
endmodule
`resetall
