`default_nettype none
// Formal properties of rtl_templates/fpstereo_control.v (tests/formal/run_proof.sh), with a
// small parameter set: width 8..20, height 4..6, P2 at most 9, LR threshold settable, uniqueness
// not. The master is the environment: it obeys AXI4-Lite (assumed: no VALID in reset or in the
// cycle after it, VALID held until READY with address and data stable). The slave side is the
// unit's (asserted):
//   - BVALID/RVALID low after reset, held until BREADY/RREADY with BRESP/RDATA/RRESP stable;
//   - one response per request: a response only for a request accepted and not yet answered,
//     at most one outstanding of each kind, and each accepted request's response presented (a
//     write's two cycles after the one that takes it, when the write takes effect; a read's
//     two cycles after, with the registers' values of the cycle after the one that takes it);
//   - BRESP as the register map of docs/hardware.md says: OKAY for a full-strobe write in range to a
//     writable register, SLVERR out of range, to a read-only register (STATUS, VERSION,
//     CONFIG_ID, UNIQUENESS when not generated, the counters, INFO) or with partial strobes;
//   - RRESP OKAY, RDATA the register's value in the cycle after the address was taken (the
//     settings as written, the identity words, INFO), 0 for unmapped and unaligned addresses.
// The settings are modelled here from docs/hardware.md; the induction compares the model with the
// unit's registers:
// formal-probe: probe_enable dut.enable_q
// formal-probe: probe_width dut.width_q
// formal-probe: probe_height dut.height_q
// formal-probe: probe_p1 dut.p1_q
// formal-probe: probe_p2 dut.p2_q
// formal-probe: probe_lr dut.lr_threshold_q
// formal-probe: probe_uniqueness dut.uniqueness_q
module control_props (
  input wire        clk,
  input wire        rst,
  input wire [7:0]  awaddr,
  input wire        awvalid,
  input wire [31:0] wdata,
  input wire [3:0]  wstrb,
  input wire        wvalid,
  input wire        bready,
  input wire [7:0]  araddr,
  input wire        arvalid,
  input wire        rready,
  input wire        busy,
  input wire        frame_start,
  input wire        frame_done,
  input wire        frame_dropped,
  input wire        frame_truncated,
  input wire        protocol_error
);
  localparam X_W = 5, Y_W = 3, PATH_W = 4;
  localparam MIN_WIDTH = 8, MAX_WIDTH = 20, MIN_HEIGHT = 4, MAX_HEIGHT = 6;
  localparam P1_INIT = 2, P2_INIT = 5, P2_MAX = 9, LR_THRESHOLD_INIT = 1, UNIQUENESS_INIT = 3;
  localparam [31:0] VERSION = 32'h00010203, CONFIG_ID = 32'h00ABCDEF;
  localparam [16*32-1:0] INFO = {32'hC0DE000F, 32'hC0DE000E, 32'hC0DE000D, 32'hC0DE000C,
                                 32'hC0DE000B, 32'hC0DE000A, 32'hC0DE0009, 32'hC0DE0008,
                                 32'hC0DE0007, 32'hC0DE0006, 32'hC0DE0005, 32'hC0DE0004,
                                 32'hC0DE0003, 32'hC0DE0002, 32'hC0DE0001, 32'hC0DE0000};

  wire        awready, wready, bvalid, arready, rvalid;
  wire [1:0]  bresp, rresp;
  wire [31:0] rdata;
  wire        enable;
  wire [X_W-1:0] frame_width;
  wire [Y_W-1:0] frame_height;
  wire [PATH_W-1:0] frame_p1, frame_p2;
  wire [6:0] frame_uniqueness;
  wire [3:0] frame_lr_threshold;
  fpstereo_control #(
    .X_W(X_W), .Y_W(Y_W), .PATH_W(PATH_W), .MIN_WIDTH(MIN_WIDTH), .MAX_WIDTH(MAX_WIDTH),
    .MIN_HEIGHT(MIN_HEIGHT), .MAX_HEIGHT(MAX_HEIGHT), .P1_INIT(P1_INIT), .P2_INIT(P2_INIT),
    .P2_MAX(P2_MAX), .UNIQUENESS_SETTABLE(0), .UNIQUENESS_INIT(UNIQUENESS_INIT), .LR_SETTABLE(1),
    .LR_THRESHOLD_INIT(LR_THRESHOLD_INIT), .VERSION(VERSION), .CONFIG_ID(CONFIG_ID), .INFO(INFO)
  ) dut (
    .clk(clk), .rst(rst),
    .s_axi_awaddr(awaddr), .s_axi_awvalid(awvalid), .s_axi_awready(awready),
    .s_axi_wdata(wdata), .s_axi_wstrb(wstrb), .s_axi_wvalid(wvalid), .s_axi_wready(wready),
    .s_axi_bresp(bresp), .s_axi_bvalid(bvalid), .s_axi_bready(bready),
    .s_axi_araddr(araddr), .s_axi_arvalid(arvalid), .s_axi_arready(arready),
    .s_axi_rdata(rdata), .s_axi_rresp(rresp), .s_axi_rvalid(rvalid), .s_axi_rready(rready),
    .enable(enable), .busy(busy), .frame_start(frame_start), .frame_width(frame_width),
    .frame_height(frame_height), .frame_p1(frame_p1), .frame_p2(frame_p2),
    .frame_uniqueness(frame_uniqueness), .frame_lr_threshold(frame_lr_threshold),
    .frame_done(frame_done), .frame_dropped(frame_dropped), .frame_truncated(frame_truncated),
    .protocol_error(protocol_error));

`ifdef FORMAL
  (* keep *) wire probe_enable;
  (* keep *) wire [X_W-1:0] probe_width;
  (* keep *) wire [Y_W-1:0] probe_height;
  (* keep *) wire [PATH_W-1:0] probe_p1, probe_p2;
  (* keep *) wire [3:0] probe_lr;
  (* keep *) wire [6:0] probe_uniqueness;

  localparam [1:0] OKAY = 2'b00, SLVERR = 2'b10;
  wire past_valid, past_rst;
  formal_start run_start (.clk(clk), .rst(rst), .past_valid(past_valid), .past_rst(past_rst));

  // ---- The master (environment).
  always @(posedge clk)
    if (past_valid) begin
      if (rst || $past(rst)) assume(!awvalid && !wvalid && !arvalid);
      else begin
        if ($past(awvalid && !awready)) assume(awvalid && awaddr == $past(awaddr));
        if ($past(wvalid && !wready)) assume(wvalid && wdata == $past(wdata) && wstrb == $past(wstrb));
        if ($past(arvalid && !arready)) assume(arvalid && araddr == $past(araddr));
      end
    end

  // ---- Handshake rules on the slave's outputs.
  always @(posedge clk)
    if (past_valid) begin
      if ($past(rst)) assert(!bvalid && !rvalid);
      else begin
        if ($past(bvalid && !bready)) assert(bvalid && bresp == $past(bresp));
        if ($past(rvalid && !rready)) assert(rvalid && rdata == $past(rdata) && rresp == $past(rresp));
      end
    end

  // ---- Requests and responses: accepted minus answered.
  wire aw_take = awvalid && awready, w_take = wvalid && wready, b_take = bvalid && bready;
  wire ar_take = arvalid && arready, r_take = rvalid && rready;
  reg [1:0] aw_open, w_open, ar_open;
  // the write taken two cycles before, which takes effect now (its range checked in the cycle
  // between), and the one taken in the previous cycle
  reg        w_taken, w_taken2;
  reg [7:0]  w_addr;
  reg [31:0] w_data;
  reg [3:0]  w_strb;
  // the read address taken in the previous cycle, whose registers are read now, and in the one
  // before (the word is being selected)
  reg        ar_taken, ar_taken2;
  reg [7:0]  ar_addr;
  always @(posedge clk) begin
    ar_taken <= !rst && ar_take;
    ar_taken2 <= !rst && ar_taken;
    if (ar_take) ar_addr <= araddr;
    w_taken <= !rst && aw_take && w_take;
    w_taken2 <= !rst && w_taken;
    if (aw_take && w_take) begin
      w_addr <= awaddr;
      w_data <= wdata;
      w_strb <= wstrb;
    end
  end
  always @(posedge clk)
    if (rst) begin
      aw_open <= 2'd0;
      w_open <= 2'd0;
      ar_open <= 2'd0;
    end else begin
      aw_open <= aw_open + {1'b0, aw_take} - {1'b0, b_take};
      w_open <= w_open + {1'b0, w_take} - {1'b0, b_take};
      ar_open <= ar_open + {1'b0, ar_take} - {1'b0, r_take};
    end
  always @*
    if (past_valid && !past_rst) begin
      // address and data are taken together (the unit's documented write handshake)
      assert(awready == wready && aw_open == w_open);
      // one outstanding at a time, answered: a response exactly while a request is open
      assert(aw_open <= 2'd1 && w_open <= 2'd1 && ar_open <= 2'd1);
      assert(bvalid == (aw_open == 2'd1 && w_open == 2'd1 && !w_taken && !w_taken2));
      assert(rvalid == (ar_open == 2'd1 && !ar_taken && !ar_taken2));
      // a response is taken only when one was offered (no new one in the cycle it is taken)
      if (b_take) assert(!aw_take && !w_take);
      if (r_take) assert(!ar_take);
    end

  // ---- The register map (docs/hardware.md), modelled.
  reg        m_enable;
  reg [31:0] m_width, m_height, m_p1, m_p2, m_lr;
  reg        good;     // the write taking effect is accepted
  reg        writable; // its address is a writable register
  always @* begin
    writable = 1'b1;
    good = 1'b0;
    case (w_addr)
      8'h00: good = 1'b1;
      8'h10: good = w_data <= m_p2 && w_data <= 32'd255;
      8'h14: good = w_data >= m_p1 && w_data <= P2_MAX;
      8'h1C: good = w_data <= 32'd15;
      8'h20: good = w_data >= MIN_WIDTH && w_data <= MAX_WIDTH;
      8'h24: good = w_data >= MIN_HEIGHT && w_data <= MAX_HEIGHT;
      default: writable = 1'b0;
    endcase
    if (w_strb != 4'hF) good = 1'b0;
  end
  // read-only registers of the map (uniqueness: not generated here)
  wire read_only = w_addr == 8'h04 || w_addr == 8'h08 || w_addr == 8'h0C || w_addr == 8'h18 ||
                   w_addr == 8'h28 || (w_addr >= 8'h30 && w_addr <= 8'h7C && w_addr[1:0] == 2'b00);

  reg       b_check;  // the open write's response is classified
  reg [1:0] b_expect;
  always @(posedge clk)
    if (rst) begin
      m_enable <= 1'b1;
      m_width <= MAX_WIDTH;
      m_height <= MAX_HEIGHT;
      m_p1 <= P1_INIT;
      m_p2 <= P2_INIT;
      m_lr <= LR_THRESHOLD_INIT;
    end else if (w_taken2) begin
      b_check <= writable || read_only || w_strb != 4'hF;
      b_expect <= good ? OKAY : SLVERR;
      if (good)
        case (w_addr)
          8'h00: m_enable <= w_data[0];
          8'h10: m_p1 <= w_data;
          8'h14: m_p2 <= w_data;
          8'h1C: m_lr <= w_data;
          8'h20: m_width <= w_data;
          8'h24: m_height <= w_data;
          default: ;
        endcase
    end

  // the expected read word, in the cycle after the address was taken
  reg        r_check;
  reg [31:0] r_expect;
  always @(posedge clk)
    if (ar_taken) begin
      r_check <= 1'b1;
      case (ar_addr)
        8'h00: r_expect <= {31'd0, m_enable};
        8'h04: r_expect <= {31'd0, busy};
        8'h08: r_expect <= VERSION;
        8'h0C: r_expect <= CONFIG_ID;
        8'h10: r_expect <= m_p1;
        8'h14: r_expect <= m_p2;
        8'h18: r_expect <= UNIQUENESS_INIT;
        8'h1C: r_expect <= m_lr;
        8'h20: r_expect <= m_width;
        8'h24: r_expect <= m_height;
        8'h28, 8'h30, 8'h34, 8'h38, 8'h3C: r_check <= 1'b0;  // counters: not modelled
        default:
          if (ar_addr >= 8'h40 && ar_addr <= 8'h7C && ar_addr[1:0] == 2'b00)
            r_expect <= INFO[(ar_addr - 8'h40) * 8 +: 32];
          else r_expect <= 32'd0;  // unmapped
      endcase
    end

  always @*
    if (past_valid && !past_rst) begin
      if (bvalid && b_check) assert(bresp == b_expect);
      if (rvalid) assert(rresp == OKAY);
      if (rvalid && r_check) assert(rdata == r_expect);
      // the unit's settings are the model's
      assert(probe_enable == m_enable && enable == m_enable);
      assert({{(32-X_W){1'b0}}, probe_width} == m_width && {{(32-Y_W){1'b0}}, probe_height} == m_height);
      assert({{(32-PATH_W){1'b0}}, probe_p1} == m_p1 && {{(32-PATH_W){1'b0}}, probe_p2} == m_p2);
      assert({28'd0, probe_lr} == m_lr);
      assert(probe_uniqueness == UNIQUENESS_INIT);  // not settable here
      // the settings stay in their ranges, P1 <= P2 at all times
      assert(m_p1 <= m_p2 && m_p2 <= P2_MAX && m_lr <= 15);
      assert(m_width >= MIN_WIDTH && m_width <= MAX_WIDTH && m_height >= MIN_HEIGHT && m_height <= MAX_HEIGHT);
    end
`endif
endmodule
`resetall
