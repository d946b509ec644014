// Framing: the input register slices, the pairing and framing checks (fpstereo_video_in), with
// several pixels per beat the beats' split into pixels (fpstereo_beat_split), and the control
// interface, in the top; the core starts its time base with the frame
// (fpstereo_sequencer), and adv, every stage's enable, stalls the pipeline as one.
#include <fmt/core.h>

#include "hls_text.hpp"
#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class FramingStage : public Stage {
 public:
  std::string title() const override { return "framing"; }
  std::vector<std::string> knobs() const override { return {"width", "height", "ppc"}; }
  Latency latency(const Geometry&) const override { return {}; }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams&) const override {
    core.text("  // Frame sequencing: adv is every stage's enable.\n");
    for (const char* net : {"adv", "restart", "in_due", "out_due"}) core.wire(net, 1);
    if (d.cfg.right_view) core.wire("view_due", 1);
    core.wire("frame_done", 1);
    core.wire("step", d.step_bits);
    for (const char* net : {"follow_open", "hold", "next_frame", "next_taken", "continuing", "wrapped"}) core.wire(net, 1);
    core.logic(fmt::format("  // Frames follow on (docs/architecture.md, \"Back-to-back frames\") when they are taller\n"
                           "  // than the pipeline's drain.\n"
                           "  localparam OVERLAP_HEIGHT = {};\n"
                           "  reg overlap;\n"
                           "  always @(posedge clk) overlap <= frame_height >= OVERLAP_HEIGHT;\n"
                           "  // The frame's last column (with strips, slot) and row, registered (the settings hold\n"
                           "  // while a frame runs), so that the stages' end-of-row and end-of-frame compares take no\n"
                           "  // subtraction.\n"
                           "  reg [{}:0] frame_last_x;\n"
                           "  reg [{}:0] frame_last_y;\n"
                           "  always @(posedge clk) begin\n"
                           "    frame_last_x <= {};\n"
                           "    frame_last_y <= frame_height - 1'b1;\n"
                           "  end\n",
                           d.overlap_height, d.x_bits - 1, d.y_bits - 1,
                           // with strips a slot holds P pixels: the last slot's
                           d.strips > 1 ? fmt::format("(frame_width >> {}) - 1'b1", clog2(d.strips))
                                        : std::string("frame_width - 1'b1")),
               {}, {{"overlap", 1}, {"frame_last_x", d.x_bits}, {"frame_last_y", d.y_bits}});
    // Without the right view nothing waits for its stream.
    Connections view;
    if (!d.cfg.right_view) view = {{"view_due", "1'b0"}, {"view_ready", "1'b1"}};
    core.instance("fpstereo_sequencer", "sequencer", {{"STEP_W", num(d.step_bits)}}, view);
  }

  // ---- HLS: the pixel pairs of the two video streams.
  std::string hls_calls(const RtlDesign& d, HlsStreams& s) const override {
    s = {"left", "right"};
    std::string text =
        "\n  // Framing: the left and right pixels.\n" + hls::stream_declarations("Pixel", {s.base, s.match});
    if (d.cfg.p2_adapt == 0) return text + "  read_pair<C>(left_in, right_in, left, right, W, H);\n";
    // Adaptive P2's penalties read the left pixels too (the cost stage).
    return text + hls::stream_declarations("Pixel", {"left_read", "guide_pixels"}) +
           "  read_pair<C>(left_in, right_in, left_read, right, W, H);\n"
           "  fork_pixels<C>(left_read, left, guide_pixels, W, H);\n";
  }
};

}  // namespace

StagePtr framing_stage() { return std::make_shared<FramingStage>(); }

}  // namespace fpstereo::rtl
