`resetall
`default_nettype none
// The fused cost's pixel-wise feature (docs/semantics.md, section 2, "Fused cost") of the base and
// match windows' centres, registered once per slot like the transform's codes and SLOTS shifts
// after its window as they are (fpstereo_front_end's TRANSFORM_SLOTS), so that each feature
// travels with its pixel's code. Intensity: the centre pixel. Gradient: I(x+1) - I(x-1) on
// the centre row, neighbours outside the image (col_valid low) reading 0, as two's complement.
module fpstereo_fused_features #(
  parameter N = 5,
  // 1: the horizontal gradient (9 bits, signed); 0: the intensity (8 bits)
  parameter GRADIENT = 0,
  parameter FEATURE_W = 8,
  parameter SLOTS = 1
) (
  input  wire                 clk,
  input  wire                 shift,
  /* verilator lint_off UNUSEDSIGNAL */  // the centre row's centre (and its neighbours) only
  input  wire [N*N*8-1:0]     window_left,
  input  wire [N*N*8-1:0]     window_right,
  input  wire [N-1:0]         col_valid,
  /* verilator lint_on UNUSEDSIGNAL */
  output reg  [FEATURE_W-1:0] feature_base,
  output reg  [FEATURE_W-1:0] feature_match
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (N < 3 || N % 2 == 0 || FEATURE_W != (GRADIENT != 0 ? 9 : 8) || SLOTS < 1 || SLOTS > 2) begin : invalid
      fpstereo_invalid_parameters_fused_features_needs_odd_N_3_up_FEATURE_W_8_or_9_for_the_gradient_SLOTS_1_or_2 failed ();
    end
  endgenerate
  localparam R = N / 2;
  // Window position (row, column): (i*N + j), row 0 the oldest, column 0 the leftmost.
  localparam CENTRE = R * N + R;
  wire [FEATURE_W-1:0] base_now, match_now;
  generate
    if (GRADIENT != 0) begin : gradient
      wire [7:0] base_right  = col_valid[R+1] ? window_left[(CENTRE+1)*8 +: 8] : 8'd0;
      wire [7:0] base_left   = col_valid[R-1] ? window_left[(CENTRE-1)*8 +: 8] : 8'd0;
      wire [7:0] match_right = col_valid[R+1] ? window_right[(CENTRE+1)*8 +: 8] : 8'd0;
      wire [7:0] match_left  = col_valid[R-1] ? window_right[(CENTRE-1)*8 +: 8] : 8'd0;
      assign base_now  = {1'b0, base_right} - {1'b0, base_left};
      assign match_now = {1'b0, match_right} - {1'b0, match_left};
    end else begin : intensity
      assign base_now  = window_left[CENTRE*8 +: 8];
      assign match_now = window_right[CENTRE*8 +: 8];
    end
  endgenerate
  wire [FEATURE_W-1:0] base_before, match_before;  // a shift before the output
  generate
    if (SLOTS == 2) begin : counted
      reg [FEATURE_W-1:0] base_q, match_q;
      always @(posedge clk)
        if (shift) begin
          base_q  <= base_now;
          match_q <= match_now;
        end
      assign base_before = base_q;
      assign match_before = match_q;
    end else begin : direct
      assign base_before = base_now;
      assign match_before = match_now;
    end
  endgenerate
  always @(posedge clk)
    if (shift) begin
      feature_base  <= base_before;
      feature_match <= match_before;
    end
endmodule
`resetall
