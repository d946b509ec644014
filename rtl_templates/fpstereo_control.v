`resetall
`default_nettype none
// AXI4-Lite control and status (register map: the generated <prefix>_regs.h and docs/hardware.md).
// Settings are written any time and take effect when the next frame starts: frame_start copies
// them to the frame_* outputs, which hold for the whole frame. A write of a value out of range, of
// a read-only register or with partial byte strobes changes nothing, answers SLVERR and is
// counted. One transaction of each kind at a time; unmapped addresses read 0.
module fpstereo_control #(
  parameter X_W = 7,
  parameter Y_W = 6,
  parameter PATH_W = 8,
  // ranges and reset values of the settings
  parameter MIN_WIDTH = 16,
  parameter MAX_WIDTH = 64,
  // the width is a multiple of this (the pixels per beat: 1, 2 or 4)
  parameter WIDTH_STEP = 1,
  parameter MIN_HEIGHT = 4,
  parameter MAX_HEIGHT = 16,
  parameter P1_INIT = 7,
  parameter P2_INIT = 86,
  parameter P2_MAX = 86,
  // uniqueness and the LR threshold are settings only where the design has them
  parameter UNIQUENESS_SETTABLE = 0,
  parameter UNIQUENESS_INIT = 0,
  parameter LR_SETTABLE = 0,
  parameter LR_THRESHOLD_INIT = 1,
  // read-only words: version, configuration id, and 16 words of generated parameters at 0x40
  parameter [31:0] VERSION = 32'h0,
  parameter [31:0] CONFIG_ID = 32'h0,
  parameter [16*32-1:0] INFO = {16*32{1'b0}}
) (
  input  wire              clk,
  input  wire              rst,
  input  wire [7:0]        s_axi_awaddr,
  input  wire              s_axi_awvalid,
  output wire              s_axi_awready,
  input  wire [31:0]       s_axi_wdata,
  input  wire [3:0]        s_axi_wstrb,
  input  wire              s_axi_wvalid,
  output wire              s_axi_wready,
  output reg  [1:0]        s_axi_bresp,
  output reg               s_axi_bvalid,
  input  wire              s_axi_bready,
  input  wire [7:0]        s_axi_araddr,
  input  wire              s_axi_arvalid,
  output wire              s_axi_arready,
  output reg  [31:0]       s_axi_rdata,
  output wire [1:0]        s_axi_rresp,
  output reg               s_axi_rvalid,
  input  wire              s_axi_rready,
  // the core's side
  output wire              enable,
  input  wire              busy,
  input  wire              frame_start,
  output reg  [X_W-1:0]    frame_width,
  output reg  [Y_W-1:0]    frame_height,
  output reg  [PATH_W-1:0] frame_p1,
  output reg  [PATH_W-1:0] frame_p2,
  output reg  [6:0]        frame_uniqueness,
  output reg  [3:0]        frame_lr_threshold,
  // the settings written equal the frame's: a next frame may follow on with them (a register,
  // low from the cycle after a write is taken until the compare sees the written value)
  output reg               settings_held,
  // event pulses
  input  wire              frame_done,
  input  wire              frame_dropped,
  input  wire              frame_truncated,
  input  wire              protocol_error
);
  // Parameter invariants: a violation fails elaboration with the rule in the missing module's name.
  generate
    if (MIN_WIDTH < 1 || MIN_WIDTH > MAX_WIDTH || MAX_WIDTH >= (1 << X_W) ||
        (WIDTH_STEP != 1 && WIDTH_STEP != 2 && WIDTH_STEP != 4) || MIN_WIDTH % WIDTH_STEP != 0 ||
        MAX_WIDTH % WIDTH_STEP != 0) begin : invalid_width
      fpstereo_invalid_parameters_control_width_range_empty_or_too_wide_for_X_W_or_off_WIDTH_STEP failed ();
    end
    if (MIN_HEIGHT < 1 || MIN_HEIGHT > MAX_HEIGHT || MAX_HEIGHT >= (1 << Y_W)) begin : invalid_height
      fpstereo_invalid_parameters_control_height_range_empty_or_too_wide_for_Y_W failed ();
    end
    if (P1_INIT < 0 || P1_INIT > P2_INIT || P2_INIT > P2_MAX || P2_MAX >= (1 << PATH_W)) begin : invalid_penalties
      fpstereo_invalid_parameters_control_needs_P1_INIT_at_most_P2_INIT_at_most_P2_MAX_within_PATH_W failed ();
    end
    if (UNIQUENESS_INIT < 0 || UNIQUENESS_INIT > 99 || LR_THRESHOLD_INIT < 0 || LR_THRESHOLD_INIT > 15) begin : invalid_settings
      fpstereo_invalid_parameters_control_UNIQUENESS_INIT_or_LR_THRESHOLD_INIT_out_of_range failed ();
    end
  endgenerate
  localparam [7:0] A_CONTROL = 8'h00, A_STATUS = 8'h04, A_VERSION = 8'h08, A_CONFIG_ID = 8'h0C,
                   A_P1 = 8'h10, A_P2 = 8'h14, A_UNIQUENESS = 8'h18, A_LR_THRESHOLD = 8'h1C,
                   A_WIDTH = 8'h20, A_HEIGHT = 8'h24, A_REJECTED_WRITES = 8'h28, A_FRAMES_DONE = 8'h30,
                   A_FRAMES_DROPPED = 8'h34, A_FRAMES_TRUNCATED = 8'h38, A_PROTOCOL_ERRORS = 8'h3C,
                   A_INFO = 8'h40;
  localparam [31:0] MIN_WIDTH_V = MIN_WIDTH, MAX_WIDTH_V = MAX_WIDTH, MIN_HEIGHT_V = MIN_HEIGHT,
                    MAX_HEIGHT_V = MAX_HEIGHT, P1_MAX_V = P2_MAX < 255 ? P2_MAX : 255, P2_MAX_V = P2_MAX,
                    WIDTH_STEP_V = WIDTH_STEP;

  reg             enable_q;
  reg [X_W-1:0]   width_q;
  reg [Y_W-1:0]   height_q;
  reg [PATH_W-1:0] p1_q, p2_q;
  reg [6:0]       uniqueness_q;
  reg [3:0]       lr_threshold_q;
  reg [31:0]      rejected, frames_done, frames_dropped, frames_truncated, protocol_errors;
  assign enable = enable_q;

  // ---- Writes: address and data together, one response at a time. A write is registered as it
  // is taken (request), checked in the next cycle and applied in the one after (applying), its
  // response following it, so that the handshake, the range checks and the registers' enables lie
  // in different cycles (no other write comes between them).
  // the widest setting
  localparam V_W = X_W > Y_W ? (X_W > PATH_W ? (X_W > 7 ? X_W : 7) : (PATH_W > 7 ? PATH_W : 7))
                             : (Y_W > PATH_W ? (Y_W > 7 ? Y_W : 7) : (PATH_W > 7 ? PATH_W : 7));
  reg         request, applying, request_full, request_high_zero, accepted;
  reg [7:0]   request_addr;
  reg [V_W-1:0] v;
  // Whether the value is in each setting's range, compared as it is taken (the settings hold then:
  // no write is in flight), so the check selects one of them by the address (logic depth).
  reg         p1_fits, p2_fits, uniqueness_fits, lr_threshold_fits, width_fits, height_fits;
  wire write = s_axi_awvalid && s_axi_wvalid && !s_axi_bvalid && !request && !applying;
  assign s_axi_awready = write;
  assign s_axi_wready = write;
  always @(posedge clk)
    if (rst) begin
      request <= 1'b0;
      applying <= 1'b0;
    end else begin
      request <= write;
      applying <= request;
    end
  wire [31:0] p1_now = {{(32-PATH_W){1'b0}}, p1_q};
  wire [31:0] p2_now = {{(32-PATH_W){1'b0}}, p2_q};
  // Every range's upper bound fits in V_W bits, so a value is in range only if its bits above
  // V_W are zero, and then it is w.
  wire [31:0] w = {{(32-V_W){1'b0}}, s_axi_wdata[V_W-1:0]};
  always @(posedge clk)
    if (write) begin
      request_addr <= s_axi_awaddr;
      v <= s_axi_wdata[V_W-1:0];
      request_high_zero <= s_axi_wdata[31:V_W] == 0;
      request_full <= s_axi_wstrb == 4'hF;
      // p1 <= p2 at all times: raise p2 before p1, lower p1 before p2
      p1_fits <= w <= P1_MAX_V && w <= p2_now;
      p2_fits <= w <= P2_MAX_V && w >= p1_now;
      uniqueness_fits <= UNIQUENESS_SETTABLE != 0 && w <= 32'd99;
      lr_threshold_fits <= LR_SETTABLE != 0 && w <= 32'd15;
      width_fits <= w >= MIN_WIDTH_V && w <= MAX_WIDTH_V && (w & (WIDTH_STEP_V - 1)) == 0;
      height_fits <= w >= MIN_HEIGHT_V && w <= MAX_HEIGHT_V;
    end
  reg in_range;
  always @* begin
    case (request_addr)
      A_CONTROL:      in_range = 1'b1;
      A_P1:           in_range = request_high_zero && p1_fits;
      A_P2:           in_range = request_high_zero && p2_fits;
      A_UNIQUENESS:   in_range = request_high_zero && uniqueness_fits;
      A_LR_THRESHOLD: in_range = request_high_zero && lr_threshold_fits;
      A_WIDTH:        in_range = request_high_zero && width_fits;
      A_HEIGHT:       in_range = request_high_zero && height_fits;
      default:        in_range = 1'b0;
    endcase
  end
  always @(posedge clk)
    if (request) accepted <= request_full && in_range;

  always @(posedge clk)
    if (rst) begin
      s_axi_bvalid <= 1'b0;
      enable_q <= 1'b1;
      width_q <= MAX_WIDTH[X_W-1:0];
      height_q <= MAX_HEIGHT[Y_W-1:0];
      p1_q <= P1_INIT[PATH_W-1:0];
      p2_q <= P2_INIT[PATH_W-1:0];
      uniqueness_q <= UNIQUENESS_INIT[6:0];
      lr_threshold_q <= LR_THRESHOLD_INIT[3:0];
    end else if (applying) begin
      s_axi_bvalid <= 1'b1;
      s_axi_bresp <= accepted ? 2'b00 : 2'b10;  // OKAY or SLVERR
      if (accepted)
        case (request_addr)
          A_CONTROL:      enable_q <= v[0];
          A_P1:           p1_q <= v[PATH_W-1:0];
          A_P2:           p2_q <= v[PATH_W-1:0];
          A_UNIQUENESS:   uniqueness_q <= v[6:0];
          A_LR_THRESHOLD: lr_threshold_q <= v[3:0];
          A_WIDTH:        width_q <= v[X_W-1:0];
          A_HEIGHT:       height_q <= v[Y_W-1:0];
          default:        ;
        endcase
    end else if (s_axi_bready) s_axi_bvalid <= 1'b0;

  // ---- The frame's settings.
  always @(posedge clk)
    if (rst || frame_start) begin
      frame_width <= rst ? MAX_WIDTH[X_W-1:0] : width_q;
      frame_height <= rst ? MAX_HEIGHT[Y_W-1:0] : height_q;
      frame_p1 <= rst ? P1_INIT[PATH_W-1:0] : p1_q;
      frame_p2 <= rst ? P2_INIT[PATH_W-1:0] : p2_q;
      frame_uniqueness <= rst ? UNIQUENESS_INIT[6:0] : uniqueness_q;
      frame_lr_threshold <= rst ? LR_THRESHOLD_INIT[3:0] : lr_threshold_q;
    end

  // The compare of the written settings with the frame's is a register of its own (it lags them a
  // cycle, so a write keeps settings_held low a cycle longer: applied), so that the AXI4-Lite
  // handshake (write) meets only its result.
  reg settings_same, applied;
  always @(posedge clk) begin
    settings_same <= width_q == frame_width && height_q == frame_height && p1_q == frame_p1 && p2_q == frame_p2 &&
                     uniqueness_q == frame_uniqueness && lr_threshold_q == frame_lr_threshold;
    applied <= !rst && applying;
    settings_held <= !write && !request && !applying && !applied && settings_same;
  end

  // ---- Counters (wrap at 2^32).
  always @(posedge clk)
    if (rst) begin
      rejected <= 0;
      frames_done <= 0;
      frames_dropped <= 0;
      frames_truncated <= 0;
      protocol_errors <= 0;
    end else begin
      if (applying && !accepted) rejected <= rejected + 1'b1;
      if (frame_done) frames_done <= frames_done + 1'b1;
      if (frame_dropped) frames_dropped <= frames_dropped + 1'b1;
      if (frame_truncated) frames_truncated <= frames_truncated + 1'b1;
      if (protocol_error) protocol_errors <= protocol_errors + 1'b1;
    end

  // ---- Reads: one at a time, always OKAY. The address is registered as it is taken; the word
  // is then selected in two registered steps, within the registers (0x00 .. 0x3C) and within INFO
  // by the address's bits 5..2, then between the two by bits 7..6, so that no step is a deep mux.
  // RVALID comes two cycles after the address is taken; the word is the registers' values in the
  // cycle after.
  reg        read_pending, read_selecting;
  reg [7:0]  read_addr;
  reg [31:0] register_word, info_word;
  reg [1:0]  read_page;
  reg        read_aligned;
  wire read = s_axi_arvalid && !s_axi_rvalid && !read_pending && !read_selecting;
  assign s_axi_arready = read;
  assign s_axi_rresp = 2'b00;
  reg [31:0] register_at;
  always @* begin
    register_at = 32'd0;
    case ({2'b00, read_addr[5:2], 2'b00})
      A_CONTROL:          register_at = {31'd0, enable_q};
      A_STATUS:           register_at = {31'd0, busy};
      A_VERSION:          register_at = VERSION;
      A_CONFIG_ID:        register_at = CONFIG_ID;
      A_P1:               register_at = p1_now;
      A_P2:               register_at = p2_now;
      A_UNIQUENESS:       register_at = {25'd0, uniqueness_q};
      A_LR_THRESHOLD:     register_at = {28'd0, lr_threshold_q};
      A_WIDTH:            register_at = {{(32-X_W){1'b0}}, width_q};
      A_HEIGHT:           register_at = {{(32-Y_W){1'b0}}, height_q};
      A_REJECTED_WRITES:  register_at = rejected;
      A_FRAMES_DONE:      register_at = frames_done;
      A_FRAMES_DROPPED:   register_at = frames_dropped;
      A_FRAMES_TRUNCATED: register_at = frames_truncated;
      A_PROTOCOL_ERRORS:  register_at = protocol_errors;
      default:            register_at = 32'd0;
    endcase
  end
  always @(posedge clk)
    if (rst) begin
      read_pending <= 1'b0;
      read_selecting <= 1'b0;
      s_axi_rvalid <= 1'b0;
    end else if (read) begin
      read_pending <= 1'b1;
      read_addr <= s_axi_araddr;
    end else if (read_pending) begin
      read_pending <= 1'b0;
      read_selecting <= 1'b1;
      register_word <= register_at;
      info_word <= INFO[read_addr[5:2]*32 +: 32];
      read_page <= read_addr[7:6];
      read_aligned <= read_addr[1:0] == 2'b00;
    end else if (read_selecting) begin
      read_selecting <= 1'b0;
      s_axi_rvalid <= 1'b1;
      s_axi_rdata <= !read_aligned ? 32'd0 : read_page == A_INFO[7:6] ? info_word :
                     read_page == 2'b00 ? register_word : 32'd0;
    end else if (s_axi_rready) s_axi_rvalid <= 1'b0;
endmodule
`resetall
