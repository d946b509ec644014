`resetall
`default_nettype none
// Pipelined minimum (and its index) over N values: fpstereo_reduction_tree over {value, index}
// summaries, ties keeping the lower index. Latency LAT: max(1, ceil(clog2(N) / LEVELS_PER_STAGE)).
module fpstereo_min_tree #(
  // number of values
  parameter N = 8,
  // value width
  parameter W = 8,
  // index width, at least clog2(N) (at least 1)
  parameter IDX_W = 3,
  // compare-select levels between registers
  parameter LEVELS_PER_STAGE = 3,
  // the latency the caller plans with (fpstereo_reduction_tree checks it)
  parameter LAT = 1
) (
  input  wire             clk,
  input  wire             en,
  input  wire [N*W-1:0]   values,
  output wire [W-1:0]     min_value,
  output wire [IDX_W-1:0] min_index
);
  localparam S_W = W + IDX_W;
  wire [N*S_W-1:0] leaves;
  genvar i;
  generate
    for (i = 0; i < N; i = i + 1) begin : leaf
      wire [IDX_W-1:0] at = i;
      assign leaves[i*S_W +: S_W] = {values[i*W +: W], at};
    end
  endgenerate
  fpstereo_reduction_tree #(.N(N), .W(W), .IDX_W(IDX_W), .UNIQUE(0), .S_W(S_W),
                            .LEVELS_PER_STAGE(LEVELS_PER_STAGE), .LAT(LAT)) tree (
    .clk(clk), .en(en), .leaves(leaves), .root({min_value, min_index}));
endmodule
`resetall
