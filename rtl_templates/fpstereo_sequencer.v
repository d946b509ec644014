`resetall
`default_nettype none
// Frame sequencing of the SGM core (docs/architecture.md, "Time base"): while idle, start begins
// a frame, whose step 0 is two cycles later (the pixel register slice in front of the core has its
// first pixel by then); from then on the step counter advances in every cycle where adv is high,
// and adv is the one enable of every stage, so the whole pipeline stalls together. adv is low
// while a stage is due to take an input pixel that is not there (in_due) or to push an output word
// that cannot leave (out_due). While a frame runs and the window stage can still take a following
// one (follow_open), start begins that frame instead (follow; docs/architecture.md, "Back-to-back
// frames"): next_frame, a register, from the next cycle until the window stage takes it. A frame ends in the step that pushes its
// last word (frame_done); unless the next frame follows on (continuing), restart clears the
// stages' valid flags then, as at reset, and a next frame begun too late to follow on (pending)
// starts as from idle.
module fpstereo_sequencer #(
  parameter STEP_W = 20
) (
  input  wire              clk,
  input  wire              rst,
  input  wire              start,
  output wire              idle,
  input  wire              follow_open,
  output wire              follow,
  output wire              next_frame,
  input  wire              next_taken,
  input  wire              continuing,
  input  wire              in_due,
  input  wire              in_valid,
  input  wire              out_due,
  input  wire              out_ready,
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
  assign adv = in_frame && !(in_due && !in_valid) && !(out_due && !out_ready);
  wire ends = adv && frame_done && !continuing;
  always @(posedge clk)
    if (rst) begin
      starting <= 1'b0;
      in_frame <= 1'b0;
    end else begin
      // A following frame that began as the window stage closed (pending, not taken) starts
      // when this frame ends, as from idle: the framing stage is already passing its pixels.
      starting <= (start && idle) || (ends && pending);
      if (!in_frame) in_frame <= starting;
      else if (ends) in_frame <= 1'b0;
    end
  assign idle = !in_frame && !starting;
  assign follow = in_frame && follow_open && !pending;
  assign next_frame = pending;
  always @(posedge clk)
    if (restart || next_taken) pending <= 1'b0;
    else if (start && follow) pending <= 1'b1;
  // With frames following on, the step counter wraps unnoticed: the start flags it sets stay set.
  always @(posedge clk)
    if (rst) step <= 0;
    else if (adv) step <= ends ? {STEP_W{1'b0}} : step + 1'b1;
  assign restart = rst || ends;
endmodule
`resetall
