// Winner-take-all (with the uniqueness check, or the second best for the confidence): the pixel's
// word in its last group's step, after the running minimum's register.
#include <fmt/core.h>

#include <algorithm>

#include "hls_text.hpp"
#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class WtaStage : public Stage {
 public:
  explicit WtaStage(const StereoConfig& c) : unique_(c.uniqueness != 0 || c.confidence) {}
  std::string title() const override { return unique_ ? "winner-take-all with uniqueness" : "winner-take-all"; }
  std::vector<std::string> knobs() const override { return {"uniqueness"}; }
  Latency latency(const Geometry& g) const override { return {0, 0, g.wta_word_lag + 1}; }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams& streams) const override {
    if (d.strips > 1) return;  // a winner-take-all per strip, in fpstereo_strip_aggregation
    streams.words = "winner";
    core.text("\n  // Winner-take-all: the pixel's word in its last group's step.\n");
    word_wires(core, d, streams.words, d.widths.disparity + 1, false);
    Connections ports = {{"sums", "agg_sums"},
                         {"group", "agg_group"},
                         {"tag", "{agg_active, agg_x, agg_slot}"},
                         {"group_out", "winner_group"},
                         {"tag_out", word_tag("winner", false)},
                         {"word", "winner_word"}};
    if (unique_) {
      // The two best sums: the confidence divides them.
      core.wire("winner_best", d.widths.aggregated);
      core.wire("winner_second", d.widths.aggregated);
      ports = ports + Connections{{"uniqueness", d.cfg.uniqueness != 0 ? "uniqueness" : "7'd0"},
                                  {"best_sum", "winner_best"},
                                  {"second_sum", "winner_second"}};
    }
    core.instance(unique_ ? "fpstereo_wta_unique" : "fpstereo_wta", "wta",
                  {{"UF", num(d.cfg.uf)},
                   {"SUM_W", num(d.widths.aggregated)},
                   {"DISP_W", num(d.widths.disparity)},
                   {"LANE_W", num(d.lane_bits)},
                   {"G_W", num(d.group_bits)},
                   {"TAG_W", num(1 + d.x_bits + d.out_row_bits)},
                   {"LEVELS_PER_STAGE", num(unique_ ? Geometry::kUniqueLevelsPerStage : d.levels_per_stage)},
                   {"TREE_LAT", num(unique_ ? d.unique_tree_latency : d.wta_tree_latency)}},
                  ports);
  }

  // ---- HLS: select_base, with LR1 also Dm into the match side's stream; without a left-right
  // check that stream is never written. D waits in its FIFO for Dm: up to dmax pixels with LR1,
  // the match side's extra latency with LR2, and with min-disp m > 0 m pixels more (Dm(x) is
  // final after base pixel x + m + dmax - 1). With confidence, each pixel's goes to the output
  // (write_confident_words) past the check, the median's rows and gap interpolation's row.
  std::string hls_calls(const RtlDesign& d, HlsStreams& s) const override {
    using hls::stream_declarations;
    const int64_t later = std::max(0, d.cfg.min_disp);
    std::string text = std::string("\n  // Winner-take-all") + (unique_ ? " with uniqueness" : "") + ".\n" +
                       stream_declarations("BaseWord<C>", {"disparity"},
                                           later == 0 ? "2 * C::kDmax + 4" : "2 * C::kDmax + C::kMinDisp + 4");
    if (d.cfg.lr == LrCheck::None) {
      s.match = "match_disparity";
      text += stream_declarations("Word<C>", {s.match});
    }
    const int64_t waiting_rows = d.cfg.median / 2 + (d.cfg.gap_interpolation ? 1 : 0) + 3;
    text += stream_declarations("ap_uint<8>", {"confidences"},
                                d.cfg.confidence ? num(waiting_rows * d.cfg.width + 2 * d.cfg.dmax + later + 4) : "");
    text += fmt::format("  select_base<C>({}, disparity, {}, confidences, W, H, uniqueness);\n", s.base, s.match);
    s.base = "disparity";
    return text;
  }

 private:
  bool unique_;
};

}  // namespace

StagePtr wta_stage(const StereoConfig& cfg) { return std::make_shared<WtaStage>(cfg); }

}  // namespace fpstereo::rtl
