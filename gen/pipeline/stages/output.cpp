// Output: one register stage, so that what the sequencer's enable depends on (out_due,
// frame_done) comes from flip-flops; each pixel's word is pushed in the step after its stream
// event. The frame ends with its last pixel; the core is idle for one cycle, and the next frame's
// step 0 comes two cycles after its start (fpstereo_sequencer).
#include <fmt/core.h>

#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class OutputStage : public Stage {
 public:
  std::string title() const override { return "output"; }
  std::vector<std::string> knobs() const override { return {}; }
  Latency latency(const Geometry&) const override { return {0, 0, 1 + kStepsAfterPush}; }
  std::vector<StageMemory> memories(const Geometry& g) const override {
    if (!confidence_rows(g)) return {};
    return {{"core.confidence_rows.confidences.mem", int64_t(confidence_rows(g)) * (g.cfg.width / g.strips),
             int64_t(kConfidenceBits) * g.strips}};
  }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams& streams) const override {
    const PixelStream& s = streams.pixels;
    core.text("\n  // Output: registered, so that the sequencer's inputs are flip-flops.\n");
    output_register(core, "out", s, s.event, s.word, d.widths.output_word * d.strips);
    if (d.cfg.confidence) confidence_verilog(core, d, s);
    core.logic(fmt::format("  reg frame_done_q;\n"
                           "  always @(posedge clk)\n"
                           "    if (restart) frame_done_q <= 1'b0;\n"
                           "    else if (adv) frame_done_q <= {0} && {1} == frame_last_x && {2} == frame_last_y;\n"
                           "  assign frame_done = frame_done_q;\n"
                           "  assign frame_end  = adv && frame_done;\n",
                           s.event, s.x, s.y),
               {"frame_done", "frame_end"});
  }

  // ---- HLS: the words into the output video stream, with confidence each above its word.
  std::string hls_calls(const RtlDesign& d, HlsStreams& s) const override {
    if (d.cfg.confidence)
      return fmt::format("\n  // Output.\n  write_confident_words<C>({}, confidences, out, W, H);\n", s.base);
    return fmt::format("\n  // Output.\n  write_words<C>({}, out, W, H);\n", s.base);
  }

 private:
  // Rows of confidences between the disparity reorder RAM and the output: more than the rows the
  // speckle filter, the median and gap interpolation delay the stream; none when nothing but the
  // check lies between, or nothing at all (in strips the check comes before the read stream: its
  // confidences are read where they are written).
  static int confidence_rows(const Geometry& g) {
    const StereoConfig& c = g.cfg;
    const bool check_between = c.lr != LrCheck::None && g.strips == 1;
    if (!c.confidence || (c.speckle_size == 0 && c.median == 0 && !c.gap_interpolation && !check_between))
      return 0;
    return g.speckle_rows + c.median / 2 + (c.gap_interpolation ? 1 : 0) + 2;
  }
  // The pixel's confidence beside its word, registered with it (with strips, a slot's P).
  static void confidence_verilog(CoreBuilder& core, const RtlDesign& d, const PixelStream& s) {
    const int rows = confidence_rows(d);
    if (rows == 0) {
      core.logic(fmt::format("  reg [{}:0] out_confidence_q;\n"
                             "  always @(posedge clk)\n"
                             "    if (adv) out_confidence_q <= read_confidence;\n"
                             "  assign out_confidence = out_confidence_q;\n",
                             kConfidenceBits * d.strips - 1),
                 {"out_confidence"});
      return;
    }
    const int64_t slots = d.cfg.width / d.strips;  // a row's slots
    core.instance("fpstereo_confidence_rows", "confidence_rows",
                  {{"W", num(slots)},
                   {"P", num(d.strips)},
                   {"ROWS", num(rows)},
                   {"ROW_K_W", num(bits_for(uint64_t(rows - 1)))},
                   {"AW", num(bits_for(uint64_t(rows) * slots - 1))},
                   {"X_W", num(d.x_bits)}},
                  {{"in_event", "read_event"},
                   {"in_x", "read_x"},
                   {"in_confidence", "read_confidence"},
                   {"out_event", s.event},
                   {"out_x", s.x}});
  }
};

}  // namespace

StagePtr output_stage() { return std::make_shared<OutputStage>(); }

}  // namespace fpstereo::rtl
