// Confidence (fpstereo_confidence): each pixel's 255 (S2 - S1) / S2 from the winner-take-all's two
// best sums, divided in kConfidenceSteps while its word waits beside; it then travels above the
// word through the disparity reorder RAM and, rows later, to the output (output.cpp).
#include <fmt/core.h>

#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class ConfidenceStage : public Stage {
 public:
  std::string title() const override { return "confidence"; }
  std::vector<std::string> knobs() const override { return {"confidence"}; }
  Latency latency(const Geometry&) const override { return {0, 0, kConfidenceSteps}; }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams& streams) const override {
    if (d.strips > 1) return;  // a divider per strip, in fpstereo_strip_aggregation
    const bool whole = d.carries_whole;
    const int data_bits = 1 + d.x_bits + d.out_row_bits + d.group_bits + d.widths.output_word +
                          (whole ? d.widths.disparity : 0);
    auto data = [&](const std::string& words) {
      std::vector<std::string> fields{words + "_word"};
      if (whole) fields.push_back(words + "_whole");
      return word_tag(words, true, fields);
    };
    const std::string in = streams.words, out = "rated";
    core.text("\n  // Confidence: the word waits beside the division.\n");
    word_wires(core, d, out, d.widths.output_word, whole);
    core.wire(out + "_confidence", kConfidenceBits);
    // The sub-pixel fit, when there, holds the words its latency after the sums.
    core.instance("fpstereo_confidence", "confidence_divider",
                  {{"SUM_W", num(d.widths.aggregated)},
                   {"DATA_W", num(data_bits)},
                   {"IN_DELAY", num(d.subpixel_steps)},
                   {"LAT", num(kConfidenceSteps)}},
                  {{"best", "winner_best"},
                   {"second", "winner_second"},
                   {"data_in", data(in)},
                   {"data_out", data(out)},
                   {"confidence", out + "_confidence"}});
    streams.words = out;
  }
  // ---- HLS: select_base computes it (Winner::confidence).
  std::string hls_calls(const RtlDesign&, HlsStreams&) const override {
    return "\n  // Confidence: none, select_base computes it.\n";
  }
};

}  // namespace

StagePtr confidence_stage() { return std::make_shared<ConfidenceStage>(); }

}  // namespace fpstereo::rtl
