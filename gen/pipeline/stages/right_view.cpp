// Right view (with right-view): the left-right check's Dm(x) at each pixel x of its stream, the
// right image's disparity, to a second output stream (m_axis_disp_right). Beside the stream: the
// main output is at least as late, so the frame ends with the main output's last push.
#include <fmt/core.h>

#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class RightViewStage : public Stage {
 public:
  std::string title() const override { return "right view"; }
  std::vector<std::string> knobs() const override { return {"right-view"}; }
  Latency latency(const Geometry&) const override { return {}; }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams& streams) const override {
    const PixelStream& s = streams.pixels;
    core.text("\n  // Right view: Dm(x) registered, pushed to its own output in the next step.\n");
    if (d.cfg.median == 0 && !d.cfg.gap_interpolation) {
      output_register(core, "view", s, s.event, "right_dm", d.widths.disparity * d.strips);
      return;
    }
    // With a median or gap interpolation the stream runs rows past the frame (their lookahead):
    // rows below the frame, or once the rows wrap (back-to-back frames) the next frame's rows,
    // which are real only if that frame follows on (continuing, known since the input passed
    // the frame's end, rows earlier).
    core.logic(fmt::format("  reg view_beyond;  // past the frame's last pixel, and no frame follows\n"
                           "  always @(posedge clk)\n"
                           "    if (restart) view_beyond <= 1'b0;\n"
                           "    else if (adv && {0} && {1} == frame_last_x && {2} == frame_last_y)\n"
                           "      view_beyond <= !continuing;\n",
                           s.event, s.x, s.y),
               {}, {{"view_beyond", 1}});
    output_register(core, "view", s, fmt::format("{} && {} < frame_height && !view_beyond", s.event, s.y), "right_dm",
                    d.widths.disparity * d.strips);
  }
  // ---- HLS: lr_check writes the right view's words; the pipeline's stream is named as the core's
  // output (output_streams).
  std::string hls_calls(const RtlDesign&, HlsStreams&) const override {
    return "\n  // Right view.\n  write_words<C>(right_view, view, W, H);\n";
  }
};

}  // namespace

StagePtr right_view_stage() { return std::make_shared<RightViewStage>(); }

}  // namespace fpstereo::rtl
