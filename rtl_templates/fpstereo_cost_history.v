`resetall
`default_nettype none
// What the cost lanes read, common to every cost stage: the base (its data and its centre's
// position) held one slot, and the match image's last columns in the match ring. A disparity
// offset MIN_DISP (docs/semantics.md, section 2: base pixel x against match pixel x - MIN_DISP - d)
// delays one side first: the ring serves d = 0 .. DMAX - 1 from its newest column back, so with
// MIN_DISP > 0 the match columns enter it MIN_DISP slots late; with MIN_DISP < 0 the base waits
// -MIN_DISP slots instead, so that the ring already holds the match columns right of it.
module fpstereo_cost_history #(
  // bits of the base's data (a code or a window) and of its centre's position
  parameter BASE_W = 8,
  parameter POSITION_W = 8,
  // bits of one match column, and the window side the lanes need (1: one code per disparity)
  parameter COLUMN_W = 8,
  parameter SPAN = 1,
  parameter DMAX = 32,
  parameter UF = 8,
  // bits of the lanes' group index (checked to hold DMAX / UF groups)
  parameter G_W = 2,
  parameter MIN_DISP = 0
) (
  input  wire                            clk,
  input  wire                            adv,
  input  wire                            slot_end,
  input  wire                            shift,
  input  wire [BASE_W-1:0]               base,
  input  wire [POSITION_W-1:0]           position,
  input  wire [COLUMN_W-1:0]             column,
  output reg  [BASE_W-1:0]               base_held,
  output reg  [POSITION_W-1:0]           position_held,
  output wire [(UF+SPAN-1)*COLUMN_W-1:0] view
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (UF < 1 || DMAX % (UF > 0 ? UF : 1) != 0 || DMAX / (UF > 0 ? UF : 1) - 1 >= (1 << G_W)) begin : invalid
      fpstereo_invalid_parameters_cost_history_needs_DMAX_a_multiple_of_UF_and_G_W_holding_the_group failed ();
    end
  endgenerate
  // The offset's delays: shift registers advanced once per slot, none at MIN_DISP = 0.
  wire [BASE_W+POSITION_W-1:0] base_now;
  wire [COLUMN_W-1:0]          column_now;
  generate
    if (MIN_DISP > 0) begin : match_late
      fpstereo_delay #(.WIDTH(COLUMN_W), .DEPTH(MIN_DISP)) match_wait (
        .clk(clk), .rst(1'b0), .en(shift), .in(column), .out(column_now));
    end else begin : match_in_time
      assign column_now = column;
    end
    if (MIN_DISP < 0) begin : base_late
      fpstereo_delay #(.WIDTH(BASE_W + POSITION_W), .DEPTH(-MIN_DISP)) base_wait (
        .clk(clk), .rst(1'b0), .en(shift), .in({base, position}), .out(base_now));
    end else begin : base_in_time
      assign base_now = {base, position};
    end
  endgenerate
  always @(posedge clk)
    if (shift) {base_held, position_held} <= base_now;
  fpstereo_match_ring #(.COLUMN_W(COLUMN_W), .SPAN(SPAN), .DMAX(DMAX), .UF(UF)) match_history (
    .clk(clk), .en(adv), .slot_end(slot_end), .column_in(column_now), .view(view));
endmodule
`resetall
