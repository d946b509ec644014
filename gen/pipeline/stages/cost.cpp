// Matching costs: uf per step from the match ring and the cost lanes of the cost function; with
// the fused cost, the pixel-wise term added (fpstereo_fused_features, fpstereo_fused_term); with
// adaptive P2, each path's P2 for the pixel beside its costs (fpstereo_adaptive_p2).
#include <fmt/core.h>

#include <algorithm>

#include "hls_text.hpp"
#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

// SHD in strips: the code windows' centres lag the entering codes ceil(rs / P) slots, and their
// arrays hold P more columns a slot of lag and rs (fpstereo_strip_code_windows).
int code_window_lag(const Geometry& g) { return (g.cfg.shd_window / 2 + g.strips - 1) / g.strips; }
int code_window_columns(const Geometry& g) {
  return g.strips * (1 + code_window_lag(g)) + g.cfg.shd_window / 2;
}

class CostStage : public Stage {
 public:
  explicit CostStage(const StereoConfig& c)
      : cost_(c.cost == CostFunction::Shd && c.shd_window == 1 ? CostFunction::Census : c.cost) {}
  std::string title() const override { return "cost"; }
  // min-disp delays the match columns (or, below 0, the base) before the match ring.
  std::vector<std::string> knobs() const override {
    return {"cost", "window", "shd-window", "dmax", "uf", "p2-adapt", "min-disp", "fused-weight", "fused-trunc",
            "fused-term"};
  }
  // The base word waits a slot next to the match ring (SHD: after its code window, rs rows and
  // rs + 1 slots; ZSAD: two more, for the base window's mean; a negative min-disp m: -m more,
  // fpstereo_cost_history); the lanes take their register stages (with the fused cost, the term's).
  // In strips the code entries' costs follow the code RAMs (fpstereo_chain_cost), whose writes
  // wait only for adaptive P2's penalties (fpstereo_strip_code_reorder's EXTRA_LAT): without them
  // the lanes' steps are not waited for here. (A strip reads a slot's word up to the row-time's
  // end; reads more than K steps behind the writes found a strip's last word overwritten where
  // SEG = P: the fused cost's four steps did, at 64 x 24, dmax 16, ppc 4.) SAD's and ZSAD's cost
  // words are written as they leave the lanes.
  Latency latency(const Geometry& g) const override {
    const Latency wait = base_wait(g);
    const bool codes_wait_for_nothing = g.strips > 1 && g.reorders_codes && g.penalty_bits == 0;
    return {wait.rows, 1 + wait.slots, codes_wait_for_nothing ? 0 : g.cost_latency};
  }
  std::vector<StageMemory> memories(const Geometry& g) const override {
    if (cost_ != CostFunction::Shd) return {};
    // In strips a line buffer word holds a slot's P codes (fpstereo_strip_code_windows).
    const int64_t bits = int64_t(g.cfg.shd_window - 1) * std::max(1, g.widths.code) * g.strips;
    const std::string at = g.strips > 1 ? "core.code_windows." : "core.cost.";
    std::vector<StageMemory> m = {{at + "base_codes.line_buffer.mem", g.row_slots, bits},
                                  {at + "match_codes.line_buffer.mem", g.row_slots, bits}};
    // The fused cost's features wait beside the codes in windows of their own.
    if (g.cfg.fused_weight != 0) {
      const int64_t feature_bits = int64_t(g.cfg.shd_window - 1) * g.widths.fused_feature * g.strips;
      m.push_back({at + "with_features.base_features.line_buffer.mem", g.row_slots, feature_bits});
      m.push_back({at + "with_features.match_features.line_buffer.mem", g.row_slots, feature_bits});
    }
    // Adaptive P2's steps wait the code window's rows in a ring (fpstereo_adaptive_p2; in strips,
    // one per pixel of the slot).
    if (g.cfg.p2_adapt != 0 && base_wait(g).rows > 0)
      for (int q = 0; q < g.strips; ++q)
        m.push_back({g.strips > 1 ? fmt::format("core.adaptive_p2_{}.row_wait.rows.mem", q)
                                  : std::string("core.adaptive_p2.row_wait.rows.mem"),
                     base_wait(g).rows * g.row_slots, 4 * 8});
    return m;
  }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams&) const override {
    const StereoConfig& c = d.cfg;
    const Widths& w = d.widths;
    // Where the reorder RAM holds codes, the costs are computed after it (the aggregation stage's
    // fpstereo_chain_cost); this stage adds only the fused cost's features and adaptive P2.
    if (d.reorders_codes) {
      if (c.fused_weight != 0)
        core.text("\n  // Cost stage: the fused cost's features beside the codes; the costs follow the code reorder RAM.\n");
    } else {
      core.text("\n  // Cost stage: the centre whose costs the lanes compute, and UF costs per step.\n");
    }
    // The fused cost's pixel features, beside the transform's codes (census, rank and SHD, the
    // costs validate() lets have it).
    if (c.fused_weight != 0) fused_features(d, core);
    if (!d.reorders_codes) {
      if (d.strips > 1)
        strip_window_cost(d, core);
      else
        raster_cost(d, core);
    }
    if (c.p2_adapt == 0) return;
    core.text("  // Adaptive P2: each path's P2 for the pixel, beside its costs.\n");
    const Connections parameters = {{"N", num(c.window)},
                                    {"PATHS", num(d.raster_paths)},
                                    {"NP", num(d.raster_path_count)},
                                    {"GAIN", num(c.p2_adapt)},
                                    {"PATH_W", num(w.path_cost)},
                                    {"WAIT_SLOTS", num(base_wait(d).slots + d.transform_slots - 1)},
                                    {"WAIT_ROWS", num(base_wait(d).rows)},
                                    {"ROW_SLOTS", num(d.row_slots)},
                                    {"LAT", num(d.cost_latency)}};
    if (d.strips == 1) {
      core.wire("cost_penalties", d.penalty_bits);
      core.instance("fpstereo_adaptive_p2", "adaptive_p2", parameters,
                    {{"window", "window_left"}, {"penalties", "cost_penalties"}});
      return;
    }
    // With strips, one per pixel of the slot, on its window; cost_penalties holds pixel q's at
    // q * penalty_bits.
    const auto pixel_net = [](int q) { return fmt::format("cost_penalties_{}", q); };
    for (int q = 0; q < d.strips; ++q) {
      core.wire(pixel_net(q), d.penalty_bits);
      core.instance("fpstereo_adaptive_p2", fmt::format("adaptive_p2_{}", q), parameters,
                    {{"window", strip_window(d, core, "window_left", q, "adaptive_p2")}, {"penalties", pixel_net(q)}});
    }
    core.wire("cost_penalties", int64_t(d.strips) * d.penalty_bits);
    core.logic(fmt::format("  assign cost_penalties = {};\n", concat_high_to_low(d.strips, pixel_net)),
               {"cost_penalties"});
  }

  // The fused cost's features of the base and match windows' centres, registered with the codes;
  // with strips one pair per pixel of the slot (pixel q's at q * FEATURE_W).
  static void fused_features(const RtlDesign& d, CoreBuilder& core) {
    const StereoConfig& c = d.cfg;
    const int bits = d.widths.fused_feature, P = d.strips;
    const Connections parameters = {{"N", num(c.window)},
                                    {"GRADIENT", c.fused_term == FusedTerm::Gradient ? "1" : "0"},
                                    {"FEATURE_W", num(bits)},
                                    {"SLOTS", num(d.transform_slots)}};
    core.wire("feature_base", int64_t(P) * bits);
    core.wire("feature_match", int64_t(P) * bits);
    if (P == 1) {
      core.instance("fpstereo_fused_features", "fused_features", parameters);
      return;
    }
    const auto base = [](int q) { return fmt::format("feature_base_{}", q); };
    const auto match = [](int q) { return fmt::format("feature_match_{}", q); };
    for (int q = 0; q < P; ++q) {
      core.wire(base(q), bits);
      core.wire(match(q), bits);
      core.instance("fpstereo_fused_features", fmt::format("fused_features_{}", q), parameters,
                    {{"window_left", strip_window(d, core, "window_left", q, "fused")},
                     {"window_right", strip_window(d, core, "window_right", q, "fused")},
                     {"col_valid", bit_field("col_valid", q, c.window)},
                     {"feature_base", base(q)},
                     {"feature_match", match(q)}});
    }
    core.logic(fmt::format("  assign feature_base = {};\n  assign feature_match = {};\n", concat_high_to_low(P, base),
                           concat_high_to_low(P, match)),
               {"feature_base", "feature_match"});
  }

  // With strips, pixel q's N x N window out of one of the front end's arrays (fpstereo_window_cut,
  // as fpstereo_transform takes it), in a net `<user>_<array>_<q>`. Returns the net.
  static std::string strip_window(const RtlDesign& d, CoreBuilder& core, const std::string& array, int q,
                                  const std::string& user) {
    const int n = d.cfg.window;
    const std::string net = fmt::format("{}_{}_{}", user, array, q);
    core.wire(net, int64_t(n) * n * 8);
    core.instance("fpstereo_window_cut", net + "_cut",
                  {{"N", num(n)}, {"COLS", num(window_columns(d))}, {"Q", num(q)}},
                  {{"array", array}, {"window", net}});
    return net;
  }

  // The raster cost stage of the cost function: the centre it holds and its lanes' costs.
  void raster_cost(const RtlDesign& d, CoreBuilder& core) const {
    const StereoConfig& c = d.cfg;
    const Widths& w = d.widths;
    const int code_bits = std::max(1, w.code);
    std::string module;
    Connections parameters;
    switch (cost_) {
      case CostFunction::Census:
      case CostFunction::Rank:
        module = "fpstereo_point_cost";
        parameters = {{"HAMMING", cost_ == CostFunction::Census ? "1" : "0"}, {"CODE_W", num(code_bits)}};
        break;
      case CostFunction::Sad:
      case CostFunction::Zsad:
        module = "fpstereo_pixel_window_cost";
        parameters = {{"N", num(c.window)},
                      {"ZERO_MEAN", cost_ == CostFunction::Zsad ? "1" : "0"},
                      {"COLUMN_SUM_W", num(d.column_sum_bits)},
                      {"MEAN_MUL", num(int64_t(d.mean_mul))},
                      {"MEAN_SHIFT", num(d.mean_shift)}};
        break;
      case CostFunction::Shd:
        module = "fpstereo_code_window_cost";
        parameters = {{"SHD_K", num(c.shd_window)},    {"CODE_W", num(code_bits)},
                      {"ROW_SLOTS", num(d.row_slots)}, {"COLUMN_SUM_W", num(d.column_sum_bits)},
                      {"COST_ROWS", num(d.cost_rows)}, {"Y_W", num(d.y_bits)}};
        break;
    }
    // The code costs take the features; without the fused cost their ports read 0 and its
    // parameters keep their defaults (off), so its unused settings change no text.
    Connections features;
    if (cost_ != CostFunction::Sad && cost_ != CostFunction::Zsad) {
      parameters = parameters + Connections{{"LANES_LAT", num(d.cost_lanes_latency)}};
      if (c.fused_weight == 0) features = {{"feature_base", "8'd0"}, {"feature_match", "8'd0"}};
    }
    parameters = parameters + fused_cost_parameters(d);
    core.wire("history_x", d.x_bits);
    core.wire("history_y", d.signed_y_bits, true);
    core.wire("history_slot", d.cost_row_bits);
    core.wire("costs", c.uf * w.cost);
    core.instance(module, "cost",
                  parameters + Connections{{"DMAX", num(c.dmax)},
                                           {"UF", num(c.uf)},
                                           {"COST_W", num(w.cost)},
                                           {"COST_MAX", num(int64_t(w.cost_max))},
                                           {"COST_ROW_W", num(d.cost_row_bits)},
                                           {"X_W", num(d.x_bits)},
                                           {"SIGNED_Y_W", num(d.signed_y_bits)},
                                           {"G_W", num(d.group_bits)},
                                           {"MIN_DISP", num(c.min_disp)},
                                           {"LAT", num(d.cost_latency)}},
                  features);
  }

  // What fpstereo_strip_window_cost takes its windows from: the base and match arrays, their
  // features (the fused cost's), the arrays' shape and the positions and masks beside them (the
  // front end's nets where not named).
  struct WindowArrays {
    std::string left, right, left_features, right_features;
    int n = 0, columns = 0, elem_bits = 8;
    Connections positions;
  };

  // SHD in strips: the transform's codes (and the fused cost's features) in SHD_K x SHD_K windows,
  // P columns a shift (fpstereo_strip_code_windows).
  static WindowArrays code_windows(const RtlDesign& d, CoreBuilder& core, int64_t feature_bits) {
    const StereoConfig& c = d.cfg;
    const bool fused = c.fused_weight != 0;
    WindowArrays a{"codes_left", "codes_right", "code_features_left", "code_features_right", c.shd_window,
                   code_window_columns(d), std::max(1, d.widths.code),
                   Connections{{"row_valid", "code_row_valid"},
                               {"col_valid", "code_col_valid"},
                               {"newest_row_valid", "code_newest_row_valid"},
                               {"transform_in_frame", "codes_in_frame"},
                               {"transform_x", "codes_x"},
                               {"transform_slot", "codes_slot"}}};
    core.text("  // SHD's code windows, P columns a shift.\n");
    const int64_t elements = int64_t(a.n) * a.columns;
    // (the feature windows read 0 without the fused cost)
    core.wire(a.left_features, elements * feature_bits);
    core.wire(a.right_features, elements * feature_bits);
    Connections features = {{"features_left", a.left_features}, {"features_right", a.right_features}};
    if (!fused)
      features = features + Connections{{"feature_base", fmt::format("{}'d0", d.strips * feature_bits)},
                                        {"feature_match", fmt::format("{}'d0", d.strips * feature_bits)}};
    core.wire(a.left, elements * a.elem_bits);
    core.wire(a.right, elements * a.elem_bits);
    core.wire("code_row_valid", a.n);
    core.wire("code_col_valid", a.n + d.strips - 1);
    core.wire("code_newest_row_valid", a.n);
    core.wire("codes_in_frame", 1);
    core.wire("codes_x", d.x_bits);
    core.wire("codes_slot", d.cost_row_bits);
    core.instance("fpstereo_strip_code_windows", "code_windows",
                  {{"P", num(d.strips)},
                   {"SHD_K", num(a.n)},
                   {"CODE_W", num(a.elem_bits)},
                   {"ROW_SLOTS", num(d.row_slots)},
                   {"ROWS", num(d.slot_rows)},
                   {"ROW_W", num(d.cost_row_bits)},
                   {"X_W", num(d.x_bits)},
                   {"Y_W", num(d.y_bits)},
                   {"SIGNED_Y_W", num(d.signed_y_bits)},
                   {"CODE_LAG", num(code_window_lag(d))},
                   {"COLS", num(a.columns)},
                   {"FUSED", fused ? "1" : "0"},
                   {"FEATURE_W", num(feature_bits)}},
                  Connections{{"row_valid", "code_row_valid"},
                              {"col_valid", "code_col_valid"},
                              {"newest_row_valid", "code_newest_row_valid"},
                              {"taken_in_frame", "codes_in_frame"},
                              {"taken_x", "codes_x"},
                              {"taken_slot", "codes_slot"}} +
                      features);
    return a;
  }

  // With strips (SAD, ZSAD and SHD): a slot's P pixels' cost words a step, with the slot they
  // belong to (cost_we, cost_slot, cost_row), which the cost reorder stage writes into the strips'
  // RAMs. SAD and ZSAD take the front end's pixel windows; SHD windows the transform's codes first
  // (code_windows) and sums their Hamming distances, with the fused cost beside windows of the
  // pixels' features. With LR2 a second instance computes the match side's costs.
  void strip_window_cost(const RtlDesign& d, CoreBuilder& core) const {
    const StereoConfig& c = d.cfg;
    const bool shd = cost_ == CostFunction::Shd;
    // Without the fused cost the features' ports keep their width of 8 and read 0.
    const int64_t feature_bits = c.fused_weight != 0 ? d.widths.fused_feature : 8;
    WindowArrays arrays;
    if (shd) {
      arrays = code_windows(d, core, feature_bits);
    } else {  // SAD and ZSAD: the front end's pixels, and no fused cost
      const std::string zeros = fmt::format("{}'d0", int64_t(c.window) * window_columns(d) * feature_bits);
      arrays = {"window_left", "window_right", zeros, zeros, c.window, window_columns(d), 8, {}};
    }
    const Connections parameters = Connections{{"P", num(d.strips)},
                                               {"N", num(arrays.n)},
                                               {"COLS", num(arrays.columns)},
                                               {"ZERO_MEAN", cost_ == CostFunction::Zsad ? "1" : "0"},
                                               {"HAMMING", shd ? "1" : "0"},
                                               {"ELEM_W", num(arrays.elem_bits)},
                                               {"UF", num(c.uf)},
                                               {"COST_W", num(d.widths.cost)},
                                               {"COST_MAX", num(int64_t(d.widths.cost_max))},
                                               {"COLUMN_SUM_W", num(d.column_sum_bits)},
                                               {"MEAN_MUL", num(int64_t(d.mean_mul))},
                                               {"MEAN_SHIFT", num(d.mean_shift)},
                                               {"ROW_W", num(d.cost_row_bits)},
                                               {"X_W", num(d.x_bits)},
                                               {"LANES_LAT", num(d.cost_lanes_latency)},
                                               {"LAT", num(d.cost_latency)}} +
                                   fused_cost_parameters(d);
    // The costs with the left image's windows as the base (the nets begin with `names`), or with
    // the roles swapped.
    const auto window_cost = [&](const std::string& names, int min_disp, bool swapped) {
      core.wire(names + "cost_we", 1);
      core.wire(names + "cost_slot", d.x_bits);
      core.wire(names + "cost_row", d.cost_row_bits);
      core.wire(names + "costs", int64_t(d.strips) * c.uf * d.widths.cost);
      core.instance("fpstereo_strip_window_cost", names + "cost", parameters + Connections{{"MIN_DISP", num(min_disp)}},
                    arrays.positions +
                        Connections{{"window_left", swapped ? arrays.right : arrays.left},
                                    {"window_right", swapped ? arrays.left : arrays.right},
                                    {"features_left", swapped ? arrays.right_features : arrays.left_features},
                                    {"features_right", swapped ? arrays.left_features : arrays.right_features},
                                    {"cost_we", names + "cost_we"},
                                    {"cost_slot", names + "cost_slot"},
                                    {"cost_row", names + "cost_row"},
                                    {"costs", names + "costs"}});
    };
    window_cost("", c.min_disp, false);
    if (c.lr != LrCheck::Lr2) return;
    // LR2's match side (the LR2 match stage): the costs of the match image's pixels, its windows
    // the base, at its min-disp; every cost is symmetric in its two windows (docs/semantics.md,
    // "LR2").
    core.text("  // LR2's match side's costs: the images' roles swapped.\n");
    window_cost("lr2_", lr2_match_min_disp(d), true);
  }

  // ---- HLS: G words of uf costs per pixel; with LR2 cost_stage also sends them to the match side.
  std::string hls_calls(const RtlDesign& d, HlsStreams& s) const override {
    using hls::stream_declarations;
    const HlsStreams in = s;
    s = {"costs", "match_side_base_costs"};
    std::string text = "\n  // Cost.\n" + stream_declarations("CostWord<C>", {s.base, s.match}, "kDepth");
    if (d.cfg.p2_adapt == 0)
      return text + fmt::format("  cost_stage<C>({}, {}, {}, {}, W, H);\n", in.base, in.match, s.base, s.match);
    // Adaptive P2: the pixels' penalties join their cost words. The penalties wait for the costs,
    // which the windows delay by rows: their FIFO holds those rows and one more (and with
    // min-disp m < 0 the -m pixels the cost stage's match runs ahead).
    const int64_t waiting = (d.window_fill_rows + 1) * int64_t(d.cfg.width) + std::max(0, -d.cfg.min_disp);
    return text + stream_declarations("CostWord<C>", {"plain_costs"}, "kDepth") +
           stream_declarations("Penalties<C>", {"penalties"}, num(waiting)) +
           fmt::format("  cost_stage<C>({}, {}, plain_costs, {}, W, H);\n", in.base, in.match, s.match) +
           "  penalty_stage<C>(guide_pixels, penalties, W, H, p1, p2);\n" +
           fmt::format("  attach_penalties<C>(plain_costs, penalties, {}, W, H);\n", s.base);
  }
  // With min-disp m < 0 each row opens with -m iterations that read match windows ahead.
  HlsLoop hls_loop(const Geometry& g) const override {
    if (g.cfg.min_disp >= 0) return {};
    const int64_t W = g.cfg.width, H = g.cfg.height, lead = -g.cfg.min_disp;
    return {"cost (the match -m pixels ahead)", "H*(W*dmax/uf-m)", H * (W * g.groups + lead)};
  }

 private:
  // What the base waits beside the match ring (adaptive P2's steps wait as long). Where the
  // reorder holds codes, a negative min-disp's wait is the cost reorder stage's; in strips the
  // base waits whole slots, min_disp_wait_slots (fpstereo_strip_window_cost's BASE_WAIT), and SHD's code
  // window code_window_lag slots, then two more (its arrays, and the cost stage taking them).
  Latency base_wait(const Geometry& g) const {
    const StereoConfig& c = g.cfg;
    const int64_t rs = cost_ == CostFunction::Shd ? c.shd_window / 2 : 0;
    const int64_t shd_wait = g.strips > 1 ? code_window_lag(g) + 2 : rs + 1;
    const int64_t wait = cost_ == CostFunction::Shd ? shd_wait : cost_ == CostFunction::Zsad ? 2 : 0;
    return {rs, wait + (g.reorders_codes ? 0 : min_disp_wait_slots(g, c.min_disp)), 0};
  }

  CostFunction cost_;  // SHD over a 1 x 1 window is census
};

}  // namespace

StagePtr cost_stage(const StereoConfig& cfg) { return std::make_shared<CostStage>(cfg); }

}  // namespace fpstereo::rtl
