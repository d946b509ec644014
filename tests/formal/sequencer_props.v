`default_nettype none
// Formal properties of rtl_templates/fpstereo_sequencer.v (tests/formal/run_proof.sh): no frame
// start is lost or made up. The environment is free within the rules of the units around the
// sequencer: the framing stage starts a frame only while accepting is high, at most once per
// cycle; the window stage takes the next frame only while it is offered (next_frame) and the
// pipeline advances, and not in the frame's last step (it takes it after the frame's last row,
// at least two row-times before the last push); follow_open, continuing, settings_held, the
// stalls (hold among them) and frame_done are arbitrary. Asserted: every start is outstanding until the frame begins, either from idle
// (starting) or taken by the window stage (next_taken), and at most one is outstanding; while
// accepting, a start can be kept (the core is idle, or runs a frame with no next one waiting).
// The induction reads the sequencer's state:
// formal-probe: probe_starting dut.starting
// formal-probe: probe_in_frame dut.in_frame
module sequencer_props (
  input wire clk,
  input wire rst,
  input wire start,
  input wire settings_held,
  input wire follow_open,
  input wire next_taken,
  input wire continuing,
  input wire in_due,
  input wire in_valid,
  input wire out_due,
  input wire out_ready,
  input wire view_due,
  input wire view_ready,
  input wire hold,
  input wire frame_done
);
  localparam STEP_W = 4;
  wire              idle, accepting, next_frame, adv, restart;
  wire [STEP_W-1:0] step;
  fpstereo_sequencer #(.STEP_W(STEP_W)) dut (
    .clk(clk), .rst(rst), .start(start), .idle(idle), .settings_held(settings_held),
    .accepting(accepting), .follow_open(follow_open), .next_frame(next_frame), .next_taken(next_taken),
    .continuing(continuing), .in_due(in_due), .in_valid(in_valid), .out_due(out_due),
    .out_ready(out_ready), .view_due(view_due), .view_ready(view_ready), .hold(hold), .frame_done(frame_done),
    .adv(adv), .step(step), .restart(restart));

`ifdef FORMAL
  (* keep *) wire probe_starting, probe_in_frame;

  wire past_valid, past_rst;
  formal_start run_start (.clk(clk), .rst(rst), .past_valid(past_valid), .past_rst(past_rst));

  // ---- The environment.
  always @* begin
    if (rst || !accepting) assume(!start);
    if (!(adv && next_frame) || frame_done) assume(!next_taken);
  end

  // ---- Starts outstanding: taken by the framing stage, not yet begun by the core.
  wire begun = probe_starting || next_taken;
  reg [1:0] outstanding;
  always @(posedge clk)
    if (rst) outstanding <= 2'd0;
    else outstanding <= outstanding + {1'b0, start} - {1'b0, begun};
  always @*
    if (past_valid && !past_rst) begin
      assert(outstanding <= 2'd1);
      // what is outstanding is either about to begin from idle or offered to the window stage
      assert(outstanding == {1'b0, probe_starting || next_frame});
      assert(!(probe_starting && next_frame));
      // a next frame is offered only while a frame runs
      if (next_frame) assert(probe_in_frame);
      // while accepting, a start is kept: the core is idle, or no next frame is waiting
      if (accepting) assert(idle || (probe_in_frame && !next_frame));
      // idle and stepping exclude each other
      if (idle) assert(!adv && !next_frame);
    end
`endif
endmodule
`resetall
