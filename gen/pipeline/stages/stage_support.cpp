#include "stage_support.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <set>

namespace fpstereo::rtl {

void start_flag(CoreBuilder& core, const RtlDesign& d, const Stage& stage, const std::string& flag) {
  const std::string start = stage.start_parameter();
  const int64_t step = d.start_steps.at(start);
  core.logic(fmt::format("  localparam {0} = {1};\n"
                         "  reg {2};\n"
                         "  always @(posedge clk)\n"
                         "    if (restart) {2} <= 1'b{3};\n"
                         "    else if (adv && step == {0} - 1) {2} <= 1'b1;\n",
                         start, step, flag, step == 0 ? 1 : 0),
             {}, {{flag, 1}});
}

void stream_wires(CoreBuilder& core, const RtlDesign& d, const PixelStream& s, int word_bits) {
  if (!s.done.empty()) core.wire(s.done, 1);
  core.wire(s.event, 1);
  core.wire(s.x, d.x_bits);
  core.wire(s.y, d.y_bits);
  core.wire(s.word, word_bits != 0 ? word_bits : d.widths.output_word);
}

Connections stream_connections(const PixelStream& in, const PixelStream& out) {
  return {{"in_x", in.x},          {"in_y", in.y}, {"in_word", in.word}, {"out_event", out.event},
          {"out_x", out.x},        {"out_y", out.y}, {"out_word", out.word}};
}

void word_wires(CoreBuilder& core, const Geometry& g, const std::string& words, int word_bits, bool with_whole) {
  core.wire(words + "_group", g.group_bits);
  core.wire(words + "_active", 1);
  core.wire(words + "_x", g.x_bits);
  core.wire(words + "_slot", g.out_row_bits);
  core.wire(words + "_word", word_bits);
  if (with_whole) core.wire(words + "_whole", g.widths.disparity);
}

std::string word_tag(const std::string& words, bool with_group, const std::vector<std::string>& extra) {
  std::string tag = fmt::format("{{{0}_active, {0}_x, {0}_slot", words);
  if (with_group) tag += ", " + words + "_group";
  for (const std::string& net : extra) tag += ", " + net;
  return tag + "}";
}

std::vector<StageMemory> aggregator_memories(const Geometry& g, const std::string& scope, int pixels) {
  const StereoConfig& c = g.cfg;
  const int width = pixels != 0 ? pixels : c.width;
  const int64_t lanes_w = int64_t(c.uf) * g.widths.path_cost;
  const int64_t row_depth = int64_t(width + 1) * g.groups;
  const int64_t state_depth = int64_t(g.chains) * g.groups;
  std::vector<StageMemory> out;
  if (c.paths & kPath0) out.push_back({scope + ".path0.state.mem", state_depth, lanes_w, false});
  if (c.paths & kPath45) {
    out.push_back({scope + ".path45.row.mem", row_depth, lanes_w});
    out.push_back({scope + ".path45.row_min.mem", width + 1, g.widths.path_cost});
    out.push_back({scope + ".path45.state.mem", state_depth, lanes_w, false});
  }
  for (int v = 0; v < 2; ++v) {
    if (!(c.paths & (v == 0 ? kPath90 : kPath135))) continue;
    const std::string p = fmt::format("{}.vertical[{}].path", scope, v);
    // with G > 1 a word carries lane 0 of the pixel's next group too (the last lane's neighbour)
    out.push_back({p + ".row.mem", row_depth, lanes_w + (g.groups > 1 ? g.widths.path_cost : 0)});
    out.push_back({p + ".row_min.mem", width + 1, g.widths.path_cost});
  }
  return out;
}

int window_centre_lag(const Geometry& g) { return (g.window_radius + g.strips - 1) / g.strips; }
int window_columns(const Geometry& g) { return g.strips * (1 + window_centre_lag(g)) + g.window_radius; }

std::string bit_field(const std::string& net, int64_t lsb, int64_t bits) {
  return fmt::format("{}[{}:{}]", net, lsb + bits - 1, lsb);
}

int code_base_wait_slots(const Geometry& g) { return code_base_wait_slots(g, g.cfg.min_disp); }

int min_disp_wait_slots(const Geometry& g, int min_disp) {
  return (std::max(0, -min_disp) + g.strips - 1) / g.strips;
}

int code_base_wait_slots(const Geometry& g, int min_disp) {
  return g.reorders_codes ? min_disp_wait_slots(g, min_disp) : 0;
}

int lr2_match_min_disp(const Geometry& g) { return -(g.cfg.min_disp + g.cfg.dmax - 1); }

namespace {

// fpstereo_strip_aggregation's MATCH_SIDE: its writes' address takes steps of its own (DM_LAG >= 3).
constexpr int kMatchSideAddressSteps = 3;

// The steps the base side's words take from the sums to the disparity RAMs' writes (the winner,
// the sub-pixel fit, the confidence and the write's register), LR1's writes' lag plus one.
int base_word_steps(const Geometry& g) { return strip_lr1_lag(g) + 1; }

}  // namespace

int strip_lr1_lag(const Geometry& g) {
  return g.wta_word_lag + g.subpixel_steps + (g.cfg.confidence ? kConfidenceSteps : 0);
}

int lr2_schedule_lead(const Geometry& g) {
  // Code entries: the base side's writes wait for adaptive P2's penalties
  // (fpstereo_strip_code_reorder's held register and EXTRA_LAT), the match side's, which has
  // none, do not. Cost words (SAD, ZSAD, SHD): the two window costs' base windows wait as the
  // code entries would (fpstereo_strip_window_cost's BASE_WAIT), the penalties leave with the
  // base side's words.
  const int penalty_wait = g.reorders_codes && g.penalty_bits != 0 ? 1 + g.cost_latency : 0;
  return min_disp_wait_slots(g, lr2_match_min_disp(g)) - min_disp_wait_slots(g, g.cfg.min_disp) - penalty_wait;
}

int lr2_dm_lag(const Geometry& g) {
  return std::max(kMatchSideAddressSteps, base_word_steps(g) - g.wta_tree_latency) +
         std::max(0, -lr2_schedule_lead(g));
}

int check_wait_slots(const Geometry& g) {
  if (g.strips == 1) return 0;
  const int P = g.strips, m = g.cfg.min_disp;
  if (g.cfg.lr == LrCheck::Lr2) {
    // The match side's later schedule, and its address steps where they outlast the base side's.
    const int address_late = std::max(0, kMatchSideAddressSteps + g.wta_tree_latency - base_word_steps(g));
    return std::max(0, lr2_schedule_lead(g)) + address_late;
  }
  return !g.cfg.right_view || m <= 0 ? 0 : (m + P - 1) / P;
}

int chain_prefix_entries(const Geometry& g) { return chain_prefix_entries(g, g.cfg.min_disp); }

int chain_prefix_entries(const Geometry& g, int min_disp) {
  return min_disp >= 0 ? 0 : std::min(-min_disp, g.cfg.dmax - 1);
}

std::string concat_high_to_low(int count, const std::function<std::string(int)>& part) {
  std::string fields;
  for (int i = count; i-- > 0;) fields += part(i) + (i ? ", " : "");
  return "{" + fields + "}";
}

Connections strip_aggregation_parameters(const RtlDesign& d) {
  Connections parameters = {{"P", num(d.strips)}};
  for (const auto& p : aggregator_parameters(d))
    if (p.first != "G" && p.first != "G_W") parameters.push_back(p);
  return parameters + fused_cost_parameters(d) +
         Connections{{"CODES", d.reorders_codes ? "1" : "0"},
                     {"HAMMING", d.cfg.cost == CostFunction::Rank ? "0" : "1"},
                     {"CODE_W", num(std::max(1, d.widths.code))},
                     {"ENTRY_W", num(std::max(1, d.code_entry_bits))},
                     {"LANES_LAT", num(d.cost_lanes_latency)},
                     {"CHAIN_LAT", num(d.cost_latency)},
                     {"COST_LEAD", num(d.cost_lead)},
                     {"RAM", "1"},
                     {"SLOT_ROWS", num(d.slot_rows)},
                     {"SLOT_W", num(d.cost_row_bits)}};
}

int64_t strip_entry_bits(const Geometry& g) {
  return g.reorders_codes ? 2 * int64_t(g.code_entry_bits) + g.penalty_bits : g.cost_word_bits;
}

int64_t lr2_strip_entry_bits(const Geometry& g) {
  return g.reorders_codes ? 2 * int64_t(g.code_entry_bits) : int64_t(g.cfg.uf) * g.widths.cost;
}

int strip_dm_address_bits(const Geometry& g) { return clog2((int64_t(g.strips) * g.chains + 1) * g.row_slots); }

Connections aggregator_parameters(const RtlDesign& g) {
  const StereoConfig& c = g.cfg;
  return {{"W", num(c.width)},
          {"ROW_SLOTS", num(g.row_slots)},
          {"K", num(g.chains)},
          {"SEGMENT", num(g.segment)},
          {"G", num(g.groups)},
          {"UF", num(c.uf)},
          {"COST_W", num(g.widths.cost)},
          {"COST_MAX", num(int64_t(g.widths.cost_max))},
          {"PATH_W", num(g.widths.path_cost)},
          {"SUM_W", num(g.widths.aggregated)},
          {"PATHS", num(g.raster_paths)},
          {"LEVELS_PER_STAGE", num(g.levels_per_stage)},
          {"PATH_TREE_LAT", num(g.path_tree_latency)},
          {"OUT_ROWS", num(g.out_rows)},
          {"OUT_ROW_W", num(g.out_row_bits)},
          {"COST_AW", num(g.cost_addr_bits)},
          {"X_W", num(g.x_bits)},
          {"Y_W", num(g.y_bits)},
          {"G_W", num(g.group_bits)},
          {"K_W", num(g.chain_bits)},
          {"COST_ROWS", num(g.cost_rows)},
          {"COST_ROW_W", num(g.cost_row_bits)}};
}

Connections mirror_aggregator_parameters(const RtlDesign& d) {
  static const std::set<std::string> its_own = {"SUM_W", "PATHS", "OUT_ROWS", "OUT_ROW_W"};
  Connections out;
  for (const auto& p : aggregator_parameters(d))
    if (!its_own.count(p.first)) out.push_back(p);
  return out;
}

Connections fused_cost_parameters(const Geometry& g) {
  const StereoConfig& c = g.cfg;
  if (c.fused_weight == 0) return {};
  return {{"WEIGHT", num(c.fused_weight)},
          {"TRUNC", num(c.fused_trunc)},
          {"FEATURE_W", num(g.widths.fused_feature)},
          {"GRADIENT", c.fused_term == FusedTerm::Gradient ? "1" : "0"}};
}

void output_register(CoreBuilder& core, const std::string& prefix, const PixelStream& stream, const std::string& event,
                     const std::string& word, int word_bits) {
  core.logic(fmt::format("  reg {0}_event_q, {0}_first_q, {0}_last_q;\n"
                         "  reg [{5}:0] {0}_word_q;\n"
                         "  always @(posedge clk)\n"
                         "    if (restart) {0}_event_q <= 1'b0;\n"
                         "    else if (adv) {0}_event_q <= {1};\n"
                         "  always @(posedge clk)\n"
                         "    if (adv) begin\n"
                         "      {0}_word_q <= {4};\n"
                         "      {0}_first_q <= {2} == 0 && {3} == 0;\n"
                         "      {0}_last_q <= {2} == frame_last_x;\n"
                         "    end\n"
                         "  assign {0}_due    = {0}_event_q;\n"
                         "  assign {0}_push   = adv && {0}_event_q;\n"
                         "  assign {0}_word   = {0}_word_q;\n"
                         "  assign {0}_first  = {0}_first_q;\n"
                         "  assign {0}_last   = {0}_last_q;\n",
                         prefix, event, stream.x, stream.y, word, word_bits - 1),
             {prefix + "_due", prefix + "_push", prefix + "_word", prefix + "_first", prefix + "_last"});
}

HlsLoop hls_window_loop(const Geometry& g, const std::string& what, int r) {
  return {what, fmt::format("(W+{0})*(H+{0})", r), (int64_t(g.cfg.width) + r) * (int64_t(g.cfg.height) + r)};
}

}  // namespace fpstereo::rtl
