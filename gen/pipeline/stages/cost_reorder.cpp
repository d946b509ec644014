// Cost reorder RAM: the cost words in raster order in, in chain order out (with the 180-degree
// path also in the mirrored chains' order, from a copy); or, where the geometry
// reorders codes, the pixels' code entries (fpstereo_code_reorder), whose costs fpstereo_chain_cost
// computes in chain order (the aggregation stage places it). In strips the RAMs are the strips'
// own, of code entries or (SAD, ZSAD) cost words: here, their writes.
#include <fmt/core.h>

#include <algorithm>

#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class CostReorderStage : public Stage {
 public:
  std::string title() const override { return "cost reorder"; }
  std::vector<std::string> knobs() const override { return {"uf"}; }
  // Written, then read; in strips a write reaches its strip's RAM a clock later
  // (fpstereo_strip_code_reorder registers it), and below min-disp 0 a slot's entries are
  // written when its match pixels are there, code_base_wait_slots later.
  Latency latency(const Geometry& g) const override {
    return {0, code_base_wait_slots(g), g.strips > 1 ? 2 : 1};
  }
  std::vector<StageMemory> memories(const Geometry& g) const override {
    if (g.strips > 1) {
      // Strip s's RAM: (s + 1) * K rows of R / P words, a slot's P entries each (code entries, or
      // SAD's and ZSAD's cost words).
      std::vector<StageMemory> m;
      const int64_t words = g.row_slots / g.strips;
      for (int s = 0; s < g.strips; ++s)
        m.push_back({"core.aggregation.code_ram.codes.strip[" + std::to_string(s) + "].ram.mem",
                     int64_t(s + 1) * g.chains * words, strip_entry_bits(g) * g.strips});
      return m;
    }
    if (!g.reorders_codes) {
      std::vector<StageMemory> m = {{"core.cost_reorder.cost_ram.mem", g.cost_depth(), g.cost_word_bits}};
      if (g.right_to_left) m.push_back({"core.cost_reorder.second.cost_ram.mem", g.cost_depth(), g.cost_word_bits});
      return m;
    }
    std::vector<StageMemory> m = {{"core.cost_reorder.code_ram.mem", g.cost_depth(), 2 * g.code_entry_bits}};
    if (g.penalty_bits != 0) m.push_back({"core.cost_reorder.extras.extra_ram.mem", g.cost_depth(), g.penalty_bits});
    return m;
  }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams&) const override {
    if (d.strips > 1) return strip_writes(d, core);
    if (d.reorders_codes) return code_reorder(d, core);
    Connections parameters = {{"ROW_SLOTS", num(d.row_slots)},
                              {"G", num(d.groups)},
                              {"UF", num(d.cfg.uf)},
                              {"COST_W", num(d.widths.cost)},
                              {"LAT", num(d.cost_latency)},
                              {"COST_ROWS", num(d.cost_rows)},
                              {"COST_ROW_W", num(d.cost_row_bits)},
                              {"COST_AW", num(d.cost_addr_bits)},
                              {"X_W", num(d.x_bits)},
                              {"Y_W", num(d.y_bits)},
                              {"SIGNED_Y_W", num(d.signed_y_bits)},
                              {"G_W", num(d.group_bits)}};
    Connections ports;
    if (d.penalty_bits != 0) {
      parameters.push_back({"EXTRA_W", num(d.penalty_bits)});
      ports.push_back({"costs", "{cost_penalties, costs}"});
    }
    // The cost words' positions: LR2's lane banks take them.
    core.text("\n  // Cost reorder RAM.\n");
    core.wire("cost_valid", 1);
    core.wire("cost_x", d.x_bits);
    core.wire("cost_row_slot", d.cost_row_bits);
    core.wire("cost_group", d.group_bits);
    core.wire("cost_raddr", d.cost_addr_bits);
    core.wire("cost_q", d.cost_word_bits);
    if (d.right_to_left) {
      // The 180-degree path's mirrored chains read a copy (the aggregation stage's
      // fpstereo_right_to_left drives mirror_raddr).
      parameters.push_back({"SECOND_READ", "1"});
      core.wire("mirror_raddr", d.cost_addr_bits);
      core.wire("mirror_q", d.cost_word_bits);
      ports = ports + Connections{{"second_raddr", "mirror_raddr"}, {"second_q", "mirror_q"}};
    } else {
      core.wire("cost_second_q", d.cost_word_bits);  // no second reader
      ports = ports + Connections{{"second_raddr", fmt::format("{}'d0", d.cost_addr_bits)}, {"second_q", "cost_second_q"}};
    }
    core.instance("fpstereo_cost_reorder", "cost_reorder", parameters, ports);
  }

  // Each pixel's base and match entries (code_entry: the code, with the fused cost its feature
  // above), in the RAM's one word per pixel.
  static void code_reorder(const RtlDesign& d, CoreBuilder& core) {
    const bool fused = d.cfg.fused_weight != 0;
    std::string match = "code_match";
    if (fused) {
      core.wire("entry_match", d.code_entry_bits);
      core.logic("  assign entry_match = {feature_match, code_match};\n", {"entry_match"});
      match = "entry_match";
    }
    core.text("\n  // Code reorder RAM: each pixel's base and match entries, in chain order out.\n");
    core.wire("cost_raddr", d.cost_addr_bits);
    core.wire("code_q", 2 * d.code_entry_bits);
    // Adaptive P2's penalties, in a RAM of their own, written as they leave with the raster costs.
    Connections penalties;
    if (d.penalty_bits != 0)
      penalties = {{"EXTRA_W", num(d.penalty_bits)}, {"EXTRA_LAT", num(d.cost_latency)}};
    core.wire("code_penalties", std::max(1, d.penalty_bits));
    core.instance("fpstereo_code_reorder", "cost_reorder",
                  Connections{{"ROW_SLOTS", num(d.row_slots)},
                              {"ENTRY_W", num(d.code_entry_bits)},
                              {"ROWS", num(d.cost_rows)},
                              {"ROW_W", num(d.cost_row_bits)},
                              {"AW", num(d.cost_addr_bits)},
                              {"X_W", num(d.x_bits)},
                              {"MIN_DISP", num(d.cfg.min_disp)}} +
                      penalties,
                  {{"base_entry", fused ? "{feature_base, code_base}" : "code_base"},
                   {"match_entry", match},
                   {"extra", d.penalty_bits != 0 ? "cost_penalties" : "1'b0"},
                   {"raddr", "cost_raddr"},
                   {"q", "code_q"},
                   {"extra_q", "code_penalties"}});
    prefix(d, core, match, d.cfg.min_disp, "");
  }

  // With strips the RAMs are the strips' own (fpstereo_strip_code_reorder, in the aggregation
  // stage's fpstereo_strip_aggregation): here, what a shift writes there, a slot's P entries.
  static void strip_writes(const RtlDesign& d, CoreBuilder& core) {
    if (!d.reorders_codes) return strip_cost_writes(d, core);
    const int P = d.strips, entry_bits = d.code_entry_bits;
    core.text("\n  // Code writes: a slot's P pixels' entries into their strip's code RAM.\n");
    // A pixel's entry is its code, with the fused cost its feature above it.
    std::string base = "code_base", match = "code_match";
    if (d.cfg.fused_weight != 0) {
      const int code_bits = std::max(1, d.widths.code), feature_bits = d.widths.fused_feature;
      const auto entries = [&](const char* features, const char* codes) {
        return concat_high_to_low(P, [&](int q) {
          return bit_field(features, int64_t(q) * feature_bits, feature_bits) + ", " +
                 bit_field(codes, int64_t(q) * code_bits, code_bits);
        });
      };
      core.wire("entry_base", int64_t(P) * entry_bits);
      core.wire("entry_match", int64_t(P) * entry_bits);
      core.logic(fmt::format("  assign entry_base = {};\n  assign entry_match = {};\n",
                             entries("feature_base", "code_base"), entries("feature_match", "code_match")),
                 {"entry_base", "entry_match"});
      base = "entry_base";
      match = "entry_match";
    }
    const std::string turned = strip_match_entries(d, core, match, d.cfg.min_disp, "");
    core.wire("code_we", 1);
    core.wire("code_slot", d.x_bits);
    core.wire("code_row", d.cost_row_bits);
    core.wire("code_data", int64_t(2 * entry_bits) * P);
    core.wire("code_extra", int64_t(P) * std::max(1, d.penalty_bits));
    // Below min-disp 0 the base entries wait for their match pixels in fpstereo_strip_code_reorder
    // (its BASE_WAIT); the match entries are turned to meet them (strip_match_entries).
    const std::string write = "{shift && transform_in_frame, transform_x, transform_slot}";
    const std::string extra = d.penalty_bits != 0 ? "cost_penalties" : fmt::format("{}'d0", P);
    // Pixel q's entries: {its match entry, its base entry}. Adaptive P2's penalties go beside them
    // (code_extra): fpstereo_strip_code_reorder waits for them.
    const std::string data = concat_high_to_low(P, [&](int q) {
      return bit_field(turned, int64_t(q) * entry_bits, entry_bits) + ", " +
             bit_field(base, int64_t(q) * entry_bits, entry_bits);
    });
    core.logic(fmt::format("  assign {{code_we, code_slot, code_row}} = {};\n"
                           "  assign code_data = {};\n"
                           "  assign code_extra = {};\n",
                           write, data, extra),
               {"code_we", "code_slot", "code_row", "code_data", "code_extra"});
    prefix(d, core, match, d.cfg.min_disp, "");
    if (d.cfg.lr != LrCheck::Lr2) return;
    // LR2's match side (the LR2 match stage): the same writes with base and match swapped, its
    // min-disp lr2_match_min_disp, into RAMs of its own.
    core.text("  // LR2's match side's code writes: base and match entries swapped.\n");
    const int m = lr2_match_min_disp(d);
    const std::string match_turned = strip_match_entries(d, core, base, m, "lr2_");
    core.wire("lr2_code_data", int64_t(2 * entry_bits) * P);
    core.logic(fmt::format("  assign lr2_code_data = {};\n", concat_high_to_low(P, [&](int q) {
                             return bit_field(match_turned, int64_t(q) * entry_bits, entry_bits) + ", " +
                                    bit_field(match, int64_t(q) * entry_bits, entry_bits);
                           })),
               {"lr2_code_data"});
    prefix(d, core, base, m, "lr2_");
  }

  // SAD, ZSAD and SHD in strips: the cost words as they leave the cost stage, each pixel's with
  // its adaptive P2 penalties above (which leave with them).
  static void strip_cost_writes(const RtlDesign& d, CoreBuilder& core) {
    const int P = d.strips;
    const int64_t cost_bits = int64_t(d.cfg.uf) * d.widths.cost, penalty_bits = d.penalty_bits;
    core.text("\n  // Cost writes: a slot's P pixels' cost words into their strip's RAM.\n");
    core.wire("code_we", 1);
    core.wire("code_slot", d.x_bits);
    core.wire("code_row", d.cost_row_bits);
    core.wire("code_data", int64_t(P) * d.cost_word_bits);
    const int64_t extra_bits = int64_t(P) * std::max<int64_t>(1, penalty_bits);  // (unread: in code_data)
    core.wire("code_extra", extra_bits);
    core.wire("code_prefix", 1);
    const std::string data = concat_high_to_low(P, [&](int q) {
      const std::string costs = bit_field("costs", q * cost_bits, cost_bits);
      return penalty_bits == 0 ? costs : bit_field("cost_penalties", q * penalty_bits, penalty_bits) + ", " + costs;
    });
    core.logic(fmt::format("  assign {{code_we, code_slot, code_row}} = {{cost_we, cost_slot, cost_row}};\n"
                           "  assign code_data = {};\n"
                           "  assign code_extra = {}'d0;\n"
                           "  assign code_prefix = 1'b0;\n",
                           data, extra_bits),
               {"code_we", "code_slot", "code_row", "code_data", "code_extra", "code_prefix"});
    if (d.cfg.lr != LrCheck::Lr2) return;
    // LR2's match side (the LR2 match stage): its own window costs' words (no penalties), as they
    // leave, into RAMs of its own.
    core.text("  // LR2's match side's cost writes.\n");
    core.wire("lr2_code_we", 1);
    core.wire("lr2_code_slot", d.x_bits);
    core.wire("lr2_code_row", d.cost_row_bits);
    core.wire("lr2_code_data", int64_t(P) * cost_bits);
    core.wire("lr2_code_prefix", 1);
    core.logic("  assign {lr2_code_we, lr2_code_slot, lr2_code_row} = {lr2_cost_we, lr2_cost_slot, lr2_cost_row};\n"
               "  assign lr2_code_data = lr2_costs;\n"
               "  assign lr2_code_prefix = 1'b0;\n",
               {"lr2_code_we", "lr2_code_slot", "lr2_code_row", "lr2_code_data", "lr2_code_prefix"});
  }

  // The prefix, taken from the row's match slots as they pass and held from the slot whose entries
  // are written with the row's first (slot code_base_wait_slots) until the next row's, so that the
  // chain that begins the row (in strips, strip 0's) reads it then. For min-disp m; its nets'
  // names begin with `names` (LR2's match side: "lr2_").
  static void prefix(const RtlDesign& d, CoreBuilder& core, const std::string& match, int m,
                     const std::string& names) {
    const int n = chain_prefix_entries(d, m), P = d.strips, entry_bits = d.code_entry_bits;
    const std::string out = names + "code_prefix", pixels = names + "prefix_pixels", held = names + "prefix_held";
    core.wire(out, int64_t(std::max(1, n)) * entry_bits);
    if (n == 0) {
      core.logic(fmt::format("  assign {} = {}'d0;\n", out, entry_bits), {out});
      return;
    }
    // Match pixels first .. a - 1, kept in that order (prefix_pixels), held in the reverse.
    const int a = -m, first = a - n;
    const int64_t bits = int64_t(n) * entry_bits;
    std::string text = fmt::format("  // The row's match pixels {} to {}, held for its first pixel.\n"
                                   "  reg [{}:0] {};\n  reg [{}:0] {};\n"
                                   "  always @(posedge clk)\n    if (shift) begin\n",
                                   first, a - 1, bits - 1, pixels, bits - 1, held);
    for (int slot = first / P; slot <= (a - 1) / P; ++slot) {
      const int from = std::max(first, slot * P), to = std::min(a - 1, slot * P + P - 1);  // its pixels
      text += fmt::format("      if (transform_x == {}'d{}) {}[{}:{}] <= {}[{}:{}];\n", d.x_bits, slot, pixels,
                          int64_t(to - first + 1) * entry_bits - 1, int64_t(from - first) * entry_bits, match,
                          int64_t(to - slot * P + 1) * entry_bits - 1, int64_t(from - slot * P) * entry_bits);
    }
    // Entry i: match pixel a - 1 - i.
    const std::string entries = concat_high_to_low(
        n, [&](int i) { return bit_field(pixels, int64_t(a - 1 - i - first) * entry_bits, entry_bits); });
    text += fmt::format("      if (transform_x == {}'d{}) {} <= {};\n    end\n"
                        "  assign {} = {};\n",
                        d.x_bits, code_base_wait_slots(d, m), held, entries, out, held);
    core.logic(text, {out}, {{pixels, bits}, {held, bits}});
  }

  // The match entries that go beside the base entries: pixel x's word holds the match pixel
  // x - m's entry (fpstereo_code_reorder's match_wait), a slot's P entries (the net `match`) m / P
  // slots late and turned by m mod P pixels across two slots; below 0, the base entries wait
  // ceil(-m / P) slots (code_base_wait_slots) and the match entries are turned by what that wait
  // leaves over. The nets' names begin with `names`. Returns the net.
  static std::string strip_match_entries(const RtlDesign& d, CoreBuilder& core, const std::string& match, int m,
                                         const std::string& names) {
    const int P = d.strips, entry_bits = d.code_entry_bits;
    if (m == 0) return match;
    const int slots = m > 0 ? m / P : 0, turn = m > 0 ? m % P : code_base_wait_slots(d, m) * P + m;
    const int64_t bits = int64_t(P) * entry_bits;
    std::string late = match;
    if (slots > 0) {
      late = names + "match_late";
      core.wire(late, bits);
      core.instance("fpstereo_delay", names + "match_wait",
                    {{"WIDTH", num(bits)}, {"DEPTH", num(slots)}, {"RESET", "0"}},
                    {{"rst", "1'b0"}, {"en", "shift"}, {"in", match}, {"out", late}});
    }
    if (turn == 0) return late;
    // Pixel q of the slot is pixel q - turn of the late slot, or of the slot before it.
    const std::string later = names + "match_later", turned = names + "match_turned";
    core.wire(later, bits);
    core.wire(turned, bits);
    core.instance("fpstereo_delay", names + "match_turn", {{"WIDTH", num(bits)}, {"DEPTH", "1"}, {"RESET", "0"}},
                  {{"rst", "1'b0"}, {"en", "shift"}, {"in", late}, {"out", later}});
    core.logic(fmt::format("  assign {} = {{{}[{}:0], {}[{}:{}]}};\n", turned, late, (P - turn) * entry_bits - 1,
                           later, bits - 1, (P - turn) * entry_bits),
               {turned});
    return turned;
  }

  // ---- HLS: aggregate's to_chain_order.
  std::string hls_calls(const RtlDesign&, HlsStreams&) const override {
    return "\n  // Cost reorder: in aggregate (to_chain_order).\n";
  }
};

}  // namespace

StagePtr cost_reorder_stage() { return std::make_shared<CostReorderStage>(); }

}  // namespace fpstereo::rtl
