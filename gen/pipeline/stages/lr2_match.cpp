// LR2's match side: a second cost volume (lane banks), aggregation and winner-take-all
// (fpstereo_lr2_match), dmax + 2 slots behind the base side's aggregation (its costs need base
// pixels up to x' + m + dmax - 1, so a positive min-disp m adds m).
#include <fmt/core.h>

#include <algorithm>
#include <cstdlib>

#include "hls_text.hpp"
#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class Lr2MatchStage : public Stage {
 public:
  std::string title() const override { return "LR2 match side"; }
  std::vector<std::string> knobs() const override { return {"lr", "paths", "p1", "p2", "min-disp"}; }
  std::string start_parameter() const override { return "MATCH_START"; }
  Latency latency(const Geometry&) const override { return {}; }
  Latency start_offset(const Geometry& g) const override {
    return {0, g.cfg.dmax + 2 + std::max(0, g.cfg.min_disp), 0};
  }
  std::vector<StageMemory> memories(const Geometry& g) const override {
    std::vector<StageMemory> out;
    for (int l = 0; l < g.cfg.uf; ++l)
      out.push_back({fmt::format("core.lr2_match.bank[{}].costs_of_lane.mem", l), g.cost_depth(), g.widths.cost});
    for (auto& m : aggregator_memories(g, "core.lr2_match.match_aggregation")) out.push_back(m);
    return out;
  }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams&) const override {
    const StereoConfig& c = d.cfg;
    core.text("\n  // LR2 match side: second cost volume, aggregation and winner-take-all.\n");
    start_flag(core, d, *this, "match_on");
    core.wire("completed_we", 1);
    core.wire("completed_waddr", d.disp_addr_bits);
    core.wire("completed_wdata", d.widths.disparity);
    core.instance("fpstereo_lr2_match", "lr2_match",
                  aggregator_parameters(d) + Connections{{"DMAX", num(c.dmax)},
                                                         {"DISP_W", num(d.widths.disparity)},
                                                         {"WTA_TREE_LAT", num(d.wta_tree_latency)},
                                                         {"DISP_AW", num(d.disp_addr_bits)},
                                                         {"LANE_W", num(d.lane_bits)},
                                                         {"MIN_DISP", num(c.min_disp)}});
  }

  // ---- HLS: the base costs regrouped per match pixel, their aggregation and winner-take-all.
  std::string hls_calls(const RtlDesign&, HlsStreams& s) const override {
    using hls::stream_declarations;
    const std::string base_costs = s.match;
    s.match = "match_disparity";
    return "\n  // LR2 match side.\n" + stream_declarations("CostWord<C>", {"match_side_costs"}) +
           stream_declarations("SumWord<C>", {"match_side_sums"}) + stream_declarations("Word<C>", {s.match}) +
           fmt::format("  match_costs<C>({}, match_side_costs, W, H);\n", base_costs) +
           "  aggregate<C, 1>(match_side_costs, match_side_sums, W, H, p1, p2);\n" +
           fmt::format("  select_match<C>(match_side_sums, {}, W, H);\n", s.match);
  }
  // Match pixel x' waits for base pixel x' + m + dmax - 1: its rows are |m + dmax - 1| pixels
  // longer (match_costs).
  HlsLoop hls_loop(const Geometry& g) const override {
    const int64_t W = g.cfg.width, H = g.cfg.height, lag = g.cfg.min_disp + g.cfg.dmax - 1;
    return {"LR2 match side", g.cfg.min_disp == 0 ? "H*(W+dmax-1)*dmax/uf" : "H*(W+|m+dmax-1|)*dmax/uf",
            H * (W + std::abs(lag)) * g.groups};
  }
};

}  // namespace

StagePtr lr2_match_stage() { return std::make_shared<Lr2MatchStage>(); }

}  // namespace fpstereo::rtl
