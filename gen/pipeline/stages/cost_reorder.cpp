// Cost reorder RAM: the cost words in raster order in, in chain order out; or, where the geometry
// reorders codes, the pixels' code entries (fpstereo_code_reorder), whose costs fpstereo_chain_cost
// computes in chain order (the aggregation stage places it).
#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class CostReorderStage : public Stage {
 public:
  std::string title() const override { return "cost reorder"; }
  std::vector<std::string> knobs() const override { return {"uf"}; }
  Latency latency(const Geometry&) const override { return {0, 0, 1}; }  // written, then read
  std::vector<StageMemory> memories(const Geometry& g) const override {
    if (!g.reorders_codes) return {{"core.cost_reorder.cost_ram.mem", g.cost_depth(), g.cost_word_bits}};
    std::vector<StageMemory> m = {{"core.cost_reorder.code_ram.mem", g.cost_depth(), 2 * g.code_entry_bits}};
    if (g.penalty_bits != 0) m.push_back({"core.cost_reorder.extras.extra_ram.mem", g.cost_depth(), g.penalty_bits});
    return m;
  }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams&) const override {
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
    core.instance("fpstereo_cost_reorder", "cost_reorder", parameters, ports);
  }

  // Each pixel's base and match entries (code_entry: the code, with the fused cost its feature
  // above), in the RAM's one word per pixel.
  static void code_reorder(const RtlDesign& d, CoreBuilder& core) {
    const bool fused = d.cfg.fused_weight != 0;
    core.text("\n  // Code reorder RAM: each pixel's base and match entries, in chain order out.\n");
    core.wire("cost_raddr", d.cost_addr_bits);
    core.wire("code_q", 2 * d.code_entry_bits);
    // Adaptive P2's penalties, in a RAM of their own, written as they leave with the raster costs.
    Connections penalties;
    if (d.penalty_bits != 0) penalties = {{"EXTRA_W", num(d.penalty_bits)}, {"EXTRA_LAT", num(d.cost_latency)}};
    core.wire("code_penalties", std::max(1, d.penalty_bits));
    core.instance("fpstereo_code_reorder", "cost_reorder",
                  Connections{{"ROW_SLOTS", num(d.row_slots)},
                              {"ENTRY_W", num(d.code_entry_bits)},
                              {"ROWS", num(d.cost_rows)},
                              {"ROW_W", num(d.cost_row_bits)},
                              {"AW", num(d.cost_addr_bits)},
                              {"X_W", num(d.x_bits)},
                              {"Y_W", num(d.y_bits)},
                              {"SIGNED_Y_W", num(d.signed_y_bits)},
                              {"MIN_DISP", num(d.cfg.min_disp)}} +
                      penalties,
                  {{"base_entry", fused ? "{feature_base, code_base}" : "code_base"},
                   {"match_entry", fused ? "{feature_match, code_match}" : "code_match"},
                   {"extra", d.penalty_bits != 0 ? "cost_penalties" : "1'b0"},
                   {"raddr", "cost_raddr"},
                   {"q", "code_q"},
                   {"extra_q", "code_penalties"}});
  }

  // ---- HLS: aggregate's to_chain_order.
  std::string hls_calls(const RtlDesign&, HlsStreams&) const override {
    return "\n  // Cost reorder: in aggregate (to_chain_order).\n";
  }
};

}  // namespace

StagePtr cost_reorder_stage() { return std::make_shared<CostReorderStage>(); }

}  // namespace fpstereo::rtl
