// LR1's match side: Dm from the base side's sums as they pass, beside the main stream
// (fpstereo_lr1_match), into the left-right check's RAMs of completed pixels and row ends.
#include <fmt/core.h>

#include <algorithm>
#include <cstdlib>

#include "hls_text.hpp"
#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class Lr1MatchStage : public Stage {
 public:
  std::string title() const override { return "LR1 match side"; }
  std::vector<std::string> knobs() const override { return {"lr", "min-disp"}; }
  Latency latency(const Geometry&) const override { return {}; }
  std::vector<StageMemory> memories(const Geometry& g) const override {
    if (g.strips > 1) return {};  // in strips, the aggregation stage's (fpstereo_strip_aggregation)
    return {{"core.lr1_match.entries.mem", int64_t(g.chains) * g.groups,
             int64_t(g.cfg.uf) * (g.widths.aggregated + g.widths.disparity), false}};
  }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams&) const override {
    if (d.strips > 1) return;  // in strips, one per strip in the aggregation stage's module
    const StereoConfig& c = d.cfg;
    core.text("\n  // LR1 match side: Dm(x') from the base side's sums.\n");
    core.wire("completed_we", 1);
    core.wire("completed_waddr", d.disp_addr_bits);
    core.wire("completed_wdata", d.widths.disparity);
    core.wire("row_end_we", 1);
    core.wire("row_end_waddr", d.end_addr_bits);
    core.wire("row_end_wdata", c.uf * d.widths.disparity);
    // One pixel a clock: no strips, no edge between them. edge_in, unread, takes the instance's
    // own edge_out (as the chain cost's ring_in does: zeros that wide pass Verilator's limit).
    core.wire("lr1_edge", int64_t(c.uf) * (d.widths.aggregated + d.widths.disparity));
    core.instance("fpstereo_lr1_match", "lr1_match",
                  {{"K", num(d.chains)},
                   {"G", num(d.groups)},
                   {"UF", num(c.uf)},
                   {"DMAX", num(c.dmax)},
                   {"ROW_SLOTS", num(d.row_slots)},
                   {"SUM_W", num(d.widths.aggregated)},
                   {"DISP_W", num(d.widths.disparity)},
                   {"OUT_ROW_W", num(d.out_row_bits)},
                   {"DISP_AW", num(d.disp_addr_bits)},
                   {"END_AW", num(d.end_addr_bits)},
                   {"X_W", num(d.x_bits)},
                   {"G_W", num(d.group_bits)},
                   {"K_W", num(d.chain_bits)},
                   {"MIN_DISP", num(c.min_disp)}},
                  {{"sums", "agg_sums"},
                   {"active", "agg_active"},
                   {"x", "agg_x"},
                   {"group", "agg_group"},
                   {"chain", "agg_chain"},
                   {"slot", "agg_slot"},
                   {"edge_in", "lr1_edge"},
                   {"edge_out", "lr1_edge"}});
  }

  // ---- HLS: select_base finds Dm from the base side's sums as they pass.
  std::string hls_calls(const RtlDesign&, HlsStreams& s) const override {
    s.match = "match_disparity";
    return "\n  // LR1 match side: Dm, found by select_base (winner-take-all).\n" +
           hls::stream_declarations("Word<C>", {s.match});
  }
  // select_base sends the Dm not final within the row at its start or end: min(|m + dmax - 1|, W)
  // iterations per row beyond the sums'.
  HlsLoop hls_loop(const Geometry& g) const override {
    const int64_t W = g.cfg.width, H = g.cfg.height, lag = g.cfg.min_disp + g.cfg.dmax - 1;
    return {"LR1 winner-take-all (Dm at the row ends)",
            g.cfg.min_disp == 0 ? "H*(W*dmax/uf+dmax-1)" : "H*(W*dmax/uf+|m+dmax-1|)",
            H * (W * g.groups + std::min(std::abs(lag), W))};
  }
};

}  // namespace

StagePtr lr1_match_stage() { return std::make_shared<Lr1MatchStage>(); }

}  // namespace fpstereo::rtl
