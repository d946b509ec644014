`resetall
`default_nettype none
// Frame sequencing of the SGM core (docs/architecture.md, "Time base"): while idle, start begins
// a frame, whose step 0 is two cycles later (the pixel register slice in front of the core has
// its first pixel by then); from then on the step counter advances in every cycle where adv is high, and adv is
// the one enable of every stage, so the whole pipeline stalls together. adv is low while a stage
// is due to take an input pixel that is not there (in_due) or to push an output word that cannot
// leave (out_due). The frame ends in the step that pushes its last word (frame_done); restart
// clears the stages' valid flags then and at reset.
module fpstereo_sequencer #(
  parameter STEP_W = 20
) (
  input  wire              clk,
  input  wire              rst,
  input  wire              start,
  output wire              idle,
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
  reg starting, in_frame;
  assign adv = in_frame && !(in_due && !in_valid) && !(out_due && !out_ready);
  always @(posedge clk)
    if (rst) begin
      starting <= 1'b0;
      in_frame <= 1'b0;
    end else begin
      starting <= start && idle;
      if (!in_frame) in_frame <= starting;
      else if (adv && frame_done) in_frame <= 1'b0;
    end
  assign idle = !in_frame && !starting;
  always @(posedge clk)
    if (rst) step <= 0;
    else if (adv) step <= frame_done ? {STEP_W{1'b0}} : step + 1'b1;
  assign restart = rst || (adv && frame_done);
endmodule
`resetall
