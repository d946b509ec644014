`resetall
`default_nettype none
// Frame sequencing of the SGM core (docs/architecture.md, "Time base"): while idle, start begins
// a frame, whose step 0 is two cycles later (the pixel register slice in front of the core has its
// first pixel by then); from then on the step counter advances in every cycle where adv is high,
// and adv is the one enable of every stage, so the whole pipeline stalls together. adv is low
// while a stage is due to take an input pixel that is not there (in_due) or to push an output word
// that cannot leave (out_due, and view_due for the right view's stream), and while the window
// stage holds a frame's end for the next frame (hold, a few cycles a frame). A start while a frame
// runs begins the next frame (docs/architecture.md, "Back-to-back frames"): next_frame (pending),
// a register, from the next cycle until the window stage takes it, which it can while
// follow_open is high. A frame ends in the step that pushes its last word (frame_done); unless
// the next frame follows on (continuing), restart clears the stages' valid flags then, as at
// reset, and a next frame that was not taken starts as from idle.
// accepting tells the framing stage that it may start a frame: while idle, or while the window
// stage can take a following frame with the same settings (settings_held). It is a register, so
// that no path runs from this block's state through the framing checks into the input slices:
// exact for idle (made from the next state) and after a start or an end, one cycle late for
// following on otherwise. A start in that late cycle, after follow_open fell, is pending like
// any other and begins when the frame ends; the settings cannot have changed (settings_held
// falls in the cycle after a write is taken, and the write is applied a cycle later). So no
// start taken while accepting is lost (tests/formal/sequencer_props.v).
module fpstereo_sequencer #(
  parameter STEP_W = 20
) (
  input  wire              clk,
  input  wire              rst,
  input  wire              start,
  output wire              idle,
  // the written settings equal the running frame's (a register, fpstereo_control)
  input  wire              settings_held,
  output reg               accepting,
  input  wire              follow_open,
  output wire              next_frame,
  input  wire              next_taken,
  input  wire              continuing,
  input  wire              in_due,
  input  wire              in_valid,
  input  wire              out_due,
  input  wire              out_ready,
  input  wire              view_due,
  input  wire              view_ready,
  input  wire              hold,
  input  wire              frame_done,
  output wire              adv,
  output reg  [STEP_W-1:0] step,
  output wire              restart
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (STEP_W < 1) begin : invalid
      fpstereo_invalid_parameters_sequencer_STEP_W_below_1 failed ();
    end
  endgenerate
  reg starting, in_frame, pending;
  wire follow = in_frame && follow_open && !pending;
  assign adv = in_frame && !(in_due && !in_valid) && !(out_due && !out_ready) && !(view_due && !view_ready) && !hold;
  wire ends = adv && frame_done && !continuing;
  // A next frame not taken (pending, or begun in this very step) starts when this frame ends,
  // as from idle: the framing stage is already passing its pixels.
  wire starting_next = (start && idle) || (ends && (pending || start));
  wire in_frame_next = in_frame ? !ends : starting;
  always @(posedge clk)
    if (rst) begin
      starting <= 1'b0;
      in_frame <= 1'b0;
      accepting <= 1'b1;
    end else begin
      starting <= starting_next;
      in_frame <= in_frame_next;
      accepting <= (!in_frame_next && !starting_next) || (follow && settings_held && !start && !ends);
    end
  assign idle = !in_frame && !starting;
  assign next_frame = pending;
  always @(posedge clk)
    if (restart || next_taken) pending <= 1'b0;
    else if (start && in_frame) pending <= 1'b1;
  // With frames following on, the step counter wraps unnoticed: the start flags it sets stay set.
  always @(posedge clk)
    if (rst) step <= 0;
    else if (adv) step <= ends ? {STEP_W{1'b0}} : step + 1'b1;
  assign restart = rst || ends;
endmodule
`resetall
