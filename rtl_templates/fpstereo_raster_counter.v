`resetall
`default_nettype none
// Position of a stage on the time base (docs/architecture.md): step `group` of slot `slot` of
// row-time `row`, and which row of a K-row reorder RAM the row uses. While `wrap` is high the
// row-time returns to 0 after the frame's last (fpstereo_frame_row); the RAM row counts on modulo
// K regardless, so that the next frame's rows take the RAM rows that follow.
module fpstereo_raster_counter #(
  parameter G = 4,
  parameter ROW_SLOTS = 64,
  parameter K = 2,
  parameter G_W = 2,
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter K_W = 1
) (
  input  wire           clk,
  input  wire           restart,
  input  wire           en,
  input  wire           wrap,
  input  wire [Y_W-1:0] height,
  output reg  [G_W-1:0] group,
  output reg  [X_W-1:0] slot,
  output wire [Y_W-1:0] row,
  output reg  [K_W-1:0] row_slot,
  output wire           slot_end
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (G < 1 || ROW_SLOTS < 1 || K < 1) begin : invalid_counts
      fpstereo_invalid_parameters_raster_counter_G_ROW_SLOTS_or_K_below_1 failed ();
    end
    if (G - 1 >= (1 << G_W) || ROW_SLOTS - 1 >= (1 << X_W) || K - 1 >= (1 << K_W)) begin : invalid_widths
      fpstereo_invalid_parameters_raster_counter_G_W_X_W_or_K_W_too_narrow failed ();
    end
  endgenerate
  localparam integer LAST_GROUP_I = G - 1;
  localparam integer LAST_CHAIN_I = K - 1;
  localparam [G_W-1:0] LAST_GROUP = LAST_GROUP_I[G_W-1:0];
  localparam [K_W-1:0] LAST_ROW_SLOT = LAST_CHAIN_I[K_W-1:0];
  localparam integer LAST_SLOT_I = ROW_SLOTS - 1;
  localparam [X_W-1:0] LAST_SLOT = LAST_SLOT_I[X_W-1:0];

  assign slot_end = group == LAST_GROUP;
  always @(posedge clk)
    if (restart) begin
      group <= 0;
      slot <= 0;
      row_slot <= 0;
    end else if (en) begin
      group <= slot_end ? {G_W{1'b0}} : group + 1'b1;
      if (slot_end) begin
        slot <= (slot == LAST_SLOT) ? {X_W{1'b0}} : slot + 1'b1;
        if (slot == LAST_SLOT)
          row_slot <= (row_slot == LAST_ROW_SLOT) ? {K_W{1'b0}} : row_slot + 1'b1;
      end
    end
  /* verilator lint_off PINCONNECTEMPTY */
  fpstereo_frame_row #(.Y_W(Y_W)) frame_row (
    .clk(clk), .restart(restart), .next(en && slot_end && slot == LAST_SLOT), .wrap(wrap), .height(height),
    .row(row), .last());
  /* verilator lint_on PINCONNECTEMPTY */
endmodule
`resetall
