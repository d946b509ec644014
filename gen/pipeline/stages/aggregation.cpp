// Aggregation in K interleaved chains (fpstereo_aggregator); a row's last chain runs K - 1
// row-times after its first, and the sums leave the aggregator's five register stages (S0 .. S5).
// With the 180-degree path (fpstereo_right_to_left, docs/path180-hardware.md) the forward chains
// run K + 2 row-times later, behind the mirrored ones.
#include <fmt/core.h>

#include <algorithm>

#include "hls_text.hpp"
#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class AggregationStage : public Stage {
 public:
  std::string title() const override { return "aggregation"; }
  std::vector<std::string> knobs() const override { return {"paths", "p1", "p2", "mgm", "dmax", "uf"}; }
  std::string start_parameter() const override { return "AGG_START"; }
  // The sums leave S5; where the costs are computed in chain order they reach S1 cost_lead steps
  // after S0 instead of one.
  // The last chain finishes a row K - 1 row-times after the first began it; with P strips, the
  // last strip's a row-time more than P * K - 1 after the first strip's first (the output reads a
  // slot of P pixels, further right than one pixel a step would be).
  Latency latency(const Geometry& g) const override {
    if (g.strips > 1) return {int64_t(g.strips) * g.chains, 0, 4 + g.cost_lead};
    return {g.chains - 1 + g.forward_lag, 0, 4 + g.cost_lead};
  }
  std::vector<StageMemory> memories(const Geometry& g) const override {
    if (g.strips == 1) {
      std::vector<StageMemory> m = aggregator_memories(g, "core.aggregation");
      if (!g.right_to_left) return m;
      // The mirrored aggregator's 0-degree state and the L_180 RAM (the cost RAM's copy is the
      // cost reorder stage's).
      const int64_t lanes_w = int64_t(g.cfg.uf) * g.widths.path_cost;
      m.push_back({"core.right_to_left.mirror.path0.state.mem", int64_t(g.chains) * g.groups, lanes_w, false});
      m.push_back({"core.right_to_left.paths.mem", g.cost_depth(), lanes_w});
      return m;
    }
    // Each strip's aggregator over its pixels, then its disparity RAM's P banks ((P - s) * K + 1
    // rows of R / P words).
    std::vector<StageMemory> m;
    const int64_t words = g.row_slots / g.strips;
    for (int s = 0; s < g.strips; ++s) {
      const std::string strip = "core.aggregation.strip[" + std::to_string(s) + "]";
      const int pixels = std::min(g.row_slots, g.cfg.width - s * g.row_slots);
      for (auto& mem : aggregator_memories(g, strip + ".aggregation", pixels)) m.push_back(mem);
    }
    for (int s = 0; s < g.strips; ++s)
      for (int q = 0; q < g.strips; ++q)
        m.push_back({"core.aggregation.output_order.disparities.strip[" + std::to_string(s) + "].bank[" +
                         std::to_string(q) + "].ram.mem",
                     (int64_t(g.strips - s) * g.chains + 1) * words, g.reorder_ram_bits});
    if (g.cfg.lr == LrCheck::None) return m;
    if (g.cfg.lr == LrCheck::Lr1) {
      // LR1 per strip: its match state (K words).
      const int64_t state_bits = int64_t(g.cfg.uf) * (g.widths.aggregated + g.widths.disparity);
      for (int s = 0; s < g.strips; ++s)
        m.push_back({"core.aggregation.lr1_match_side.lr1_of_strip[" + std::to_string(s) + "].lr1_match.entries.mem",
                     g.chains, state_bits, false});
    }
    // The check's banks: each word's copy of every strip's Dm ((P - s) * K + 1 rows of R), with
    // LR1 of the row ends too (P * K + 1 rows). With the right view each word looks Dm(x) up
    // too, from copies of its own.
    const std::string check = "core.aggregation.output_order.checked.check.word[";
    for (int q = 0; q < g.strips; ++q)
      for (const std::string lookup : {"].lookup.", "].right_view.lookup."}) {
        if (lookup != "].lookup." && !g.cfg.right_view) break;
        const std::string at = check + std::to_string(q) + lookup;
        for (int s = 0; s < g.strips; ++s)
          m.push_back({at + "bank_of_strip[" + std::to_string(s) + "].completed.mem",
                       (int64_t(g.strips - s) * g.chains + 1) * g.row_slots, g.widths.disparity});
        if (g.cfg.lr == LrCheck::Lr1)
          m.push_back({at + "with_row_end.row_end.mem", int64_t(g.strips) * g.chains + 1,
                       int64_t(g.cfg.uf) * g.widths.disparity});
      }
    return m;
  }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams& streams) const override {
    if (d.strips > 1) return strips_verilog(d, core, streams);
    core.text("\n  // Aggregation in K interleaved chains, from step AGG_START.\n");
    start_flag(core, d, *this, "agg_on");
    core.wire("agg_sums", d.cfg.uf * d.widths.aggregated);
    core.wire("agg_active", 1);
    core.wire("agg_x", d.x_bits);
    core.wire("agg_group", d.group_bits);
    core.wire("agg_slot", d.out_row_bits);
    core.wire("agg_chain", d.chain_bits);  // LR1 follows the chains
    Connections side = {{"MATCH_SIDE", "0"}};
    if (d.cfg.p2_adapt != 0) side.push_back({"PENALTIES", num(d.raster_path_count)});
    core.wire("cost_schedule", d.x_bits + d.group_bits + 1);
    std::string cost_words = "cost_q";
    if (d.right_to_left) {
      right_to_left(d, core);
      side = side + Connections{{"CHAIN_BASE", num(d.forward_lag)}, {"RIGHT_TO_LEFT", "1"}};
      cost_words = "{path180_q, cost_q}";
    }
    if (d.reorders_codes) {
      side = side + Connections{{"CODES", "1"}, {"COST_LEAD", num(d.cost_lead)}};
      cost_words = chain_cost(d, core);
    }
    // One strip: no strips beside it to exchange edges with. The edge inputs, which one strip
    // never reads, take its own outputs (constant zeros there) rather than a replication that
    // can pass Verilator's 8K-bit limit.
    const int64_t edge_bits = int64_t(d.cfg.uf + 1) * d.widths.path_cost;
    core.wire("agg_edge", 2 * edge_bits);
    core.wire("agg_edge135", edge_bits);
    core.instance("fpstereo_aggregator", "aggregation", aggregator_parameters(d) + side,
                  {{"cost_q", cost_words},
                   {"sums", "agg_sums"},
                   {"sums_active", "agg_active"},
                   {"sums_x", "agg_x"},
                   {"sums_group", "agg_group"},
                   {"sums_chain", "agg_chain"},
                   {"sums_slot", "agg_slot"},
                   {"edge_in", "agg_edge"},
                   {"edge135_in", "agg_edge135"},
                   {"edge_out", "agg_edge"},
                   {"edge135_out", "agg_edge135"}});
  }

  // The 180-degree path: the mirrored aggregator on the cost RAM's copy (mirror_raddr, mirror_q:
  // the cost reorder stage's), its L_180 read at the forward aggregator's address
  // (fpstereo_right_to_left).
  static void right_to_left(const RtlDesign& d, CoreBuilder& core) {
    core.text("\n  // The 180-degree path: a mirrored aggregator a row-time behind the cost writes; the forward\n"
              "  // one reads each word's L_180 beside it.\n");
    core.wire("path180_q", int64_t(d.cfg.uf) * d.widths.path_cost);
    Connections parameters = mirror_aggregator_parameters(d);
    if (d.cfg.p2_adapt != 0) parameters.push_back({"PENALTIES", num(d.raster_path_count)});
    core.instance("fpstereo_right_to_left", "right_to_left", parameters,
                  {{"path_raddr", "cost_raddr"}, {"path_q", "path180_q"}});
  }

  // With strips (docs/ppc-hardware.md): fpstereo_strip_aggregation holds the strips' code RAMs,
  // their chain costs and aggregators, a winner-take-all (with the sub-pixel fit and the
  // confidence) each and their disparity RAMs, from the code writes (the cost reorder stage's) to
  // the raster order at P pixels a step (the pixel stream the disparity reorder stage names, from
  // its OUT_START on).
  static void strips_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams&) {
    const StereoConfig& c = d.cfg;
    const Widths& w = d.widths;
    const int P = d.strips;
    // A winner-take-all with the uniqueness check per strip, which the confidence's two best sums
    // come from too.
    const bool unique = c.uniqueness != 0 || c.confidence;
    core.text(fmt::format("\n  // Aggregation in {} strips of {} interleaved chains, from step AGG_START, to the raster\n"
                          "  // order's slots of {} pixels.\n",
                          P, d.chains, P));
    start_flag(core, d, AggregationStage(), "agg_on");
    core.wire("strip_raddr", int64_t(P) * d.cost_addr_bits);
    core.wire("strip_sums", int64_t(P) * c.uf * w.aggregated);
    core.wire("strip_active", P);
    core.wire("strip_x", int64_t(P) * d.x_bits);
    core.wire("strip_chain", int64_t(P) * d.chain_bits);
    core.wire("strip_slot", int64_t(P) * d.out_row_bits);
    // With LR1 its match side per strip and the check, inside fpstereo_strip_aggregation
    // (docs/ppc-hardware.md, "The left-right check in strips"); the match side's writes, which the
    // check takes there, are not read here. With LR2 the check there takes the LR2 match stage's
    // writes. Strip 0's Dm take the most address bits.
    const bool lr1 = c.lr == LrCheck::Lr1, lr2 = c.lr == LrCheck::Lr2;
    const int dm_bits = lr1 || lr2 ? strip_dm_address_bits(d) : 1;
    core.wire("strip_dm_we", P);
    core.wire("strip_dm_waddr", int64_t(P) * dm_bits);
    core.wire("strip_dm_wdata", int64_t(P) * w.disparity);
    core.wire("strip_dm_end_we", P);
    core.wire("strip_dm_end_waddr", int64_t(P) * d.out_row_bits);
    core.wire("strip_dm_end_wdata", int64_t(P) * c.uf * w.disparity);
    core.wire("right_dm", int64_t(P) * w.disparity);  // the right view reads it
    core.instance("fpstereo_strip_aggregation", "aggregation",
                  strip_aggregation_parameters(d) +
                      Connections{{"EXTRA_LAT", num(d.cost_latency)},
                                  {"BASE_WAIT", num(code_base_wait_slots(d))},
                                  {"LR1", lr1 ? "1" : "0"},
                                  {"LR2", lr2 ? "1" : "0"},
                                  {"LR1_AW", num(dm_bits)},
                                  {"LR1_LAG", num(strip_lr1_lag(d))},
                                  {"RIGHT_VIEW", c.right_view ? "1" : "0"},
                                  {"VIEW_WAIT", num(check_wait_slots(d))},
                                  {"OUTPUT", "1"},
                                  {"DISP_W", num(w.output_word - 1)},
                                  {"UNIQUE", unique ? "1" : "0"},
                                  {"WTA_LEVELS_PER_STAGE",
                                   num(unique ? Geometry::kUniqueLevelsPerStage : d.levels_per_stage)},
                                  {"WTA_TREE_LAT", num(unique ? d.unique_tree_latency : d.wta_tree_latency)},
                                  {"WTA_DISP_W", num(w.disparity)},
                                  {"SUBPIXEL_BITS", num(c.subpixel_bits)},
                                  {"EQUIANGULAR", c.subpixel_fit == SubpixelFit::Equiangular ? "1" : "0"},
                                  {"WTA_WORD_LAG", num(d.wta_word_lag)},
                                  {"SUBPIXEL_LAT", num(d.subpixel_steps)},
                                  {"CONFIDENCE", c.confidence ? "1" : "0"},
                                  {"EXTRA_ROWS", c.gap_interpolation ? "1" : "0"},
                                  {"MIN_DISP", num(c.min_disp)},
                                  {"EXTRA_W", num(d.penalty_bits)}},
                  {{"cost_raddr", "strip_raddr"},
                   {"cost_q", fmt::format("{}'d0", P * strip_entry_bits(d))},
                   {"sums", "strip_sums"},
                   {"sums_active", "strip_active"},
                   {"sums_x", "strip_x"},
                   {"sums_chain", "strip_chain"},
                   {"sums_slot", "strip_slot"},
                   {"uniqueness", c.uniqueness != 0 ? "uniqueness" : "7'd0"},
                   {"lr_threshold", lr1 || lr2 ? "lr_threshold" : "4'd0"},
                   {"read_word", c.confidence ? kStripConfidentWords : "read_word"},
                   {"right_word", "right_dm"},
                   {"dm_we", "strip_dm_we"},
                   {"dm_waddr", "strip_dm_waddr"},
                   {"dm_wdata", "strip_dm_wdata"},
                   {"dm_end_we", "strip_dm_end_we"},
                   {"dm_end_waddr", "strip_dm_end_waddr"},
                   {"dm_end_wdata", "strip_dm_end_wdata"},
                   {"match_dm_we", lr2 ? "lr2_dm_we" : fmt::format("{}'d0", P)},
                   {"match_dm_waddr", lr2 ? "lr2_dm_waddr" : fmt::format("{}'d0", int64_t(P) * dm_bits)},
                   {"match_dm_wdata", lr2 ? "lr2_dm_wdata" : fmt::format("{}'d0", int64_t(P) * w.disparity)}});
  }

  // The costs of the code entries, in the order the aggregator reads them (fpstereo_chain_cost).
  // Returns the aggregator's cost words.
  static std::string chain_cost(const RtlDesign& d, CoreBuilder& core) {
    const StereoConfig& c = d.cfg;
    const Widths& w = d.widths;
    Connections parameters = {{"HAMMING", c.cost == CostFunction::Rank ? "0" : "1"},
                              {"CODE_W", num(std::max(1, w.code))},
                              {"DMAX", num(c.dmax)},
                              {"UF", num(c.uf)},
                              {"K", num(d.chains)},
                              {"COST_W", num(w.cost)},
                              {"COST_MAX", num(int64_t(w.cost_max))},
                              {"X_W", num(d.x_bits)},
                              {"G_W", num(d.group_bits)},
                              {"MIN_DISP", num(c.min_disp)},
                              {"PREFIX", num(chain_prefix_entries(d))},
                              {"LANES_LAT", num(d.cost_lanes_latency)},
                              {"LAT", num(d.cost_latency)},
                              {"ENTRY_W", num(d.code_entry_bits)}};
    parameters = parameters + fused_cost_parameters(d);
    const int x_lsb = d.group_bits, first = d.group_bits + d.x_bits;
    core.text("  // The costs of the code entries, computed in chain order.\n");
    // With adaptive P2 the pixel's penalties leave beside its costs, above them in the word.
    const bool penalties = d.penalty_bits != 0;
    if (penalties) parameters.push_back({"EXTRA_W", num(d.penalty_bits)});
    core.wire("chain_costs", c.uf * w.cost);
    core.wire("chain_penalties", std::max(1, d.penalty_bits));
    // One strip: no ring comes from a strip to the left, none goes to one to the right. ring_in,
    // which one strip never reads, takes the stage's own ring_out rather than a replication of
    // zeros as wide as a ring (10,240 bits for A3, past Verilator's 8K-bit limit).
    const int64_t ring_bits = int64_t(c.dmax) * d.code_entry_bits;
    core.wire("chain_ring", ring_bits);
    core.instance("fpstereo_chain_cost", "chain_cost", parameters,
                  {{"group", fmt::format("cost_schedule[{}:0]", d.group_bits - 1)},
                   {"x", fmt::format("cost_schedule[{}:{}]", first - 1, x_lsb)},
                   {"row_time_first", fmt::format("cost_schedule[{}]", first)},
                   {"entry", "code_q"},
                   {"prefix", "code_prefix"},
                   {"extra", penalties ? "code_penalties" : "1'b0"},
                   {"costs", "chain_costs"},
                   {"extra_out", "chain_penalties"},
                   {"ring_in", "chain_ring"},
                   {"ring_out", "chain_ring"}});
    return penalties ? "{chain_penalties, chain_costs}" : "chain_costs";
  }

  // ---- HLS: two interleaved chains (K = 2), between reorders into chain order and back, which
  // delay the stream by a row-time; with the 180-degree path, right_to_left's mirrored chains
  // before them, three row-times more.
  std::string hls_calls(const RtlDesign&, HlsStreams& s) const override {
    const std::string costs = s.base;
    s.base = "sums";
    return "\n  // Aggregation.\n" + hls::stream_declarations("SumWord<C>", {s.base}, "kDepth") +
           fmt::format("  aggregate<C, 0>({}, {}, W, H, p1, p2);\n", costs, s.base);
  }
  HlsLoop hls_loop(const Geometry& g) const override {
    const int64_t W = g.cfg.width, H = g.cfg.height, slots = 2 * ((W + 1) / 2);
    if (g.cfg.paths & kPath180)  // right_to_left's loop, the longer
      return {"aggregation's 180-degree path (two mirrored chains)", "(H+3)*2*ceil(W/2)*dmax/uf", (H + 3) * slots * g.groups};
    return {"aggregation (two interleaved chains)", "(H+1)*2*ceil(W/2)*dmax/uf", (H + 1) * slots * g.groups};
  }
  int hls_fill_rows(const Geometry& g) const override { return g.cfg.paths & kPath180 ? 4 : 1; }
};

}  // namespace

StagePtr aggregation_stage() { return std::make_shared<AggregationStage>(); }

}  // namespace fpstereo::rtl
