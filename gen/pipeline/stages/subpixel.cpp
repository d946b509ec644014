// Sub-pixel refinement of the winner-take-all's words (fpstereo_subpixel): the sums at D - 1, D
// and D + 1 selected in the two steps after the word, then the fit's subpixel-bits + 3 steps.
#include <fmt/core.h>

#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class SubpixelStage : public Stage {
 public:
  std::string title() const override { return "sub-pixel fit"; }
  std::vector<std::string> knobs() const override { return {"subpixel-bits", "subpixel-fit"}; }
  Latency latency(const Geometry& g) const override { return {0, 0, g.subpixel_steps}; }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams& streams) const override {
    if (d.strips > 1) return;  // a fit per strip, in fpstereo_strip_aggregation
    // With a left-right check the whole D travels in the tag for the check.
    const bool whole = d.carries_whole;
    const int tag_bits = 1 + d.x_bits + d.out_row_bits + d.group_bits + (whole ? d.widths.disparity : 0);
    const std::string in = streams.words, out = "refined";
    auto tag = [&](const std::string& words, const std::string& whole_d) {
      return word_tag(words, true, whole ? std::vector<std::string>{whole_d} : std::vector<std::string>{});
    };
    core.text("\n  // Sub-pixel fit: the refined word, subpixel-bits + 6 steps after the whole one.\n");
    word_wires(core, d, out, d.widths.output_word, whole);
    core.instance("fpstereo_subpixel", "subpixel",
                  {{"UF", num(d.cfg.uf)},
                   {"G", num(d.groups)},
                   {"SUM_W", num(d.widths.aggregated)},
                   {"DMAX", num(d.cfg.dmax)},
                   {"DISP_W", num(d.widths.disparity)},
                   {"K", num(d.cfg.subpixel_bits)},
                   {"EQUIANGULAR", d.cfg.subpixel_fit == SubpixelFit::Equiangular ? "1" : "0"},
                   {"OUT_W", num(d.widths.output_disparity)},
                   {"WTA_WORD_LAG", num(d.wta_word_lag)},
                   {"TAG_W", num(tag_bits)}},
                  {{"sums", "agg_sums"},
                   {"tag", tag(in, fmt::format("{}_word[{}:0]", in, d.widths.disparity - 1))},
                   {"word", in + "_word"},
                   {"tag_out", tag(out, out + "_whole")},
                   {"word_out", out + "_word"}});
    streams.words = out;
  }
  // ---- HLS: select_base refines the winner as it passes (Winner::refined).
  std::string hls_calls(const RtlDesign&, HlsStreams&) const override {
    return "\n  // Sub-pixel fit: none, select_base refines the winner.\n";
  }
};

}  // namespace

StagePtr subpixel_stage() { return std::make_shared<SubpixelStage>(); }

}  // namespace fpstereo::rtl
