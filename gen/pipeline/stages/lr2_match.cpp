// LR2's match side: a second cost volume (lane banks), aggregation and winner-take-all
// (fpstereo_lr2_match), dmax + 2 slots behind the base side's aggregation (its costs need base
// pixels up to x' + m + dmax - 1, so a positive min-disp m adds m). In strips, a second
// fpstereo_strip_aggregation over the match image's code entries or (SAD, ZSAD, SHD) cost words
// (docs/ppc-hardware.md, "LR2 in strips"), whose winners go to the base side's check.
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
  // In strips the match side's schedule starts lr2_schedule_lead after the base side's.
  Latency start_offset(const Geometry& g) const override {
    if (g.strips > 1) return {0, 0, lr2_schedule_lead(g)};
    return {0, g.cfg.dmax + 2 + std::max(0, g.cfg.min_disp), 0};
  }
  std::vector<StageMemory> memories(const Geometry& g) const override {
    std::vector<StageMemory> out;
    if (g.strips > 1) {
      // As the base side's: each strip's code RAM and aggregator (fpstereo_strip_aggregation).
      const int64_t words = g.row_slots / g.strips;
      for (int s = 0; s < g.strips; ++s) {
        out.push_back({"core.lr2_match.code_ram.codes.strip[" + std::to_string(s) + "].ram.mem",
                       int64_t(s + 1) * g.chains * words, lr2_strip_entry_bits(g) * g.strips});
        const int pixels = std::min(g.row_slots, g.cfg.width - s * g.row_slots);
        for (auto& m : aggregator_memories(g, "core.lr2_match.strip[" + std::to_string(s) + "].aggregation", pixels))
          out.push_back(m);
      }
      return out;
    }
    for (int l = 0; l < g.cfg.uf; ++l) {
      out.push_back({fmt::format("core.lr2_match.bank[{}].costs_of_lane.mem", l), g.cost_depth(), g.widths.cost});
      if (g.right_to_left)
        out.push_back({fmt::format("core.lr2_match.bank[{}].second.costs_of_lane.mem", l), g.cost_depth(), g.widths.cost});
    }
    for (auto& m : aggregator_memories(g, "core.lr2_match.match_aggregation")) out.push_back(m);
    if (g.right_to_left) {
      // The mirrored aggregator's 0-degree state and the L_180 RAM (fpstereo_right_to_left).
      const int64_t lanes_w = int64_t(g.cfg.uf) * g.widths.path_cost;
      out.push_back({"core.lr2_match.right_to_left.mirror.mirror.path0.state.mem", int64_t(g.chains) * g.groups, lanes_w, false});
      out.push_back({"core.lr2_match.right_to_left.mirror.paths.mem", g.cost_depth(), lanes_w});
    }
    return out;
  }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams&) const override {
    if (d.strips > 1) return strips_verilog(d, core);
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
                                                         {"MIN_DISP", num(c.min_disp)},
                                                         {"FORWARD_LAG", num(d.forward_lag)}});
  }

  // In strips: the code entries with base and match swapped, or the cost words of the match side's
  // window costs (the cost reorder stage's lr2_code_*), their strips' aggregation at min-disp
  // lr2_match_min_disp, and each strip's winner written as Dm(x') (lr2_dm_*) for the check in the
  // aggregation stage's fpstereo_strip_aggregation.
  static void strips_verilog(const RtlDesign& d, CoreBuilder& core) {
    const StereoConfig& c = d.cfg;
    const Widths& w = d.widths;
    const int P = d.strips;
    core.text("\n  // LR2 match side in strips: the match image's code entries, aggregated, their winners.\n");
    start_flag(core, d, Lr2MatchStage(), "match_on");
    // What the match side leaves but its writes: read nowhere.
    const int dm_bits = strip_dm_address_bits(d);
    const std::vector<std::pair<std::string, int64_t>> unread = {
        {"raddr", int64_t(P) * d.cost_addr_bits},
        {"sums", int64_t(P) * c.uf * w.aggregated},
        {"sums_active", P},
        {"sums_x", int64_t(P) * d.x_bits},
        {"sums_chain", int64_t(P) * d.chain_bits},
        {"sums_slot", int64_t(P) * d.out_row_bits},
        {"read_done", 1},
        {"read_event", 1},
        {"read_x", d.x_bits},
        {"read_y", d.y_bits},
        {"read_word", int64_t(P) * (w.disparity + 1)},
        {"right_word", int64_t(P) * w.disparity},
        {"dm_end_we", P},
        {"dm_end_waddr", int64_t(P) * d.out_row_bits},
        {"dm_end_wdata", int64_t(P) * c.uf * w.disparity}};
    Connections ports;
    for (const auto& [port, bits] : unread) {
      core.wire("lr2_" + port, bits);
      ports.push_back({port == "raddr" ? "cost_raddr" : port, "lr2_" + port});
    }
    // Code entries are written with the base side's (the cost reorder stage's lr2_code_data beside
    // code_data); cost words as the match side's window costs leave (its lr2_code_*).
    const std::string writes = d.reorders_codes ? "code_" : "lr2_code_";
    core.wire("lr2_dm_we", P);
    core.wire("lr2_dm_waddr", int64_t(P) * dm_bits);
    core.wire("lr2_dm_wdata", int64_t(P) * w.disparity);
    core.instance("fpstereo_strip_aggregation", "lr2_match",
                  strip_aggregation_parameters(d) +
                      Connections{{"BASE_WAIT", num(code_base_wait_slots(d, lr2_match_min_disp(d)))},
                                  {"MIN_DISP", num(lr2_match_min_disp(d))},
                                  {"LR1_AW", num(dm_bits)},
                                  {"DISP_W", num(w.disparity)},
                                  {"WTA_DISP_W", num(w.disparity)},
                                  {"WTA_LEVELS_PER_STAGE", num(d.levels_per_stage)},
                                  {"WTA_TREE_LAT", num(d.wta_tree_latency)},
                                  {"MATCH_SIDE", "1"},
                                  {"DM_LAG", num(lr2_dm_lag(d))}},
                  ports + Connections{{"agg_on", "match_on"},
                                      {"cost_q", fmt::format("{}'d0", P * lr2_strip_entry_bits(d))},
                                      {"code_we", writes + "we"},
                                      {"code_slot", writes + "slot"},
                                      {"code_row", writes + "row"},
                                      {"code_data", "lr2_code_data"},
                                      {"code_extra", fmt::format("{}'d0", P)},
                                      {"code_prefix", "lr2_code_prefix"},
                                      {"out_on", "1'b0"},
                                      {"uniqueness", "7'd0"},
                                      {"lr_threshold", "4'd0"},
                                      {"dm_we", "lr2_dm_we"},
                                      {"dm_waddr", "lr2_dm_waddr"},
                                      {"dm_wdata", "lr2_dm_wdata"},
                                      {"match_dm_we", fmt::format("{}'d0", P)},
                                      {"match_dm_waddr", fmt::format("{}'d0", int64_t(P) * dm_bits)},
                                      {"match_dm_wdata", fmt::format("{}'d0", int64_t(P) * w.disparity)}});
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
