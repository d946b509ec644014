// Window and transform: line buffers, the N x N windows and their bounds, and for census, rank and
// SHD the codes of the window centres.
#include <fmt/core.h>

#include <algorithm>

#include "hls_text.hpp"
#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class WindowStage : public Stage {
 public:
  explicit WindowStage(const StereoConfig& c) : transform_(c.cost != CostFunction::Sad && c.cost != CostFunction::Zsad) {}
  std::string title() const override { return transform_ ? "window and transform" : "window"; }
  std::vector<std::string> knobs() const override { return {"window", "cost"}; }
  // The window centred r rows and r slots behind the input (with strips, the windows of a slot's P
  // pixels, ceil(r / P) slots behind) is complete after the input's slot; its registered position
  // (and the transform's codes) transform_slots later.
  Latency latency(const Geometry& g) const override {
    return {g.window_radius, window_centre_lag(g) + 1 + g.transform_slots, 0};
  }
  std::vector<StageMemory> memories(const Geometry& g) const override {
    const int64_t bits = int64_t(g.cfg.window - 1) * g.widths.pixel * g.strips;
    return {{"core.front_end.left_window.line_buffer.mem", g.row_slots, bits},
            {"core.front_end.right_window.line_buffer.mem", g.row_slots, bits}};
  }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams&) const override {
    // With strips, P windows side by side in arrays of COLS columns (fpstereo_front_end).
    const int n = d.cfg.window, P = d.strips, cols = window_columns(d);
    const int window_bits = n * cols * 8;
    core.text("\n  // Window stage: line buffers, windows, their bounds and centres.\n");
    core.wire("shift", 1);
    core.wire("slot_end", 1);
    core.wire("group", d.group_bits);
    core.wire("window_left", window_bits);
    core.wire("window_right", window_bits);
    core.wire("row_valid", n);
    core.wire("col_valid", n + P - 1);
    core.wire("transform_x", d.x_bits);
    core.wire("transform_y", d.signed_y_bits, true);
    core.wire("transform_slot", d.cost_row_bits);
    core.wire("transform_in_frame", 1);
    core.wire("newest_row_valid", n);  // the SAD and ZSAD costs' mask
    core.instance("fpstereo_front_end", "front_end",
                  {{"N", num(n)},
                   {"ROW_SLOTS", num(d.row_slots)},
                   {"G", num(d.groups)},
                   {"COST_ROWS", num(P > 1 ? d.slot_rows : d.cost_rows)},
                   {"COST_ROW_W", num(d.cost_row_bits)},
                   {"X_W", num(d.x_bits)},
                   {"Y_W", num(d.y_bits)},
                   {"SIGNED_Y_W", num(d.signed_y_bits)},
                   {"G_W", num(d.group_bits)},
                   {"FOLLOW_WAIT", num(d.follow_wait)},
                   {"P", num(P)},
                   {"TRANSFORM_SLOTS", num(d.transform_slots)}});
    if (!transform_) return;
    const int code_bits = std::max(1, d.widths.code);
    core.wire("code_base", int64_t(P) * code_bits);
    core.wire("code_match", int64_t(P) * code_bits);
    core.instance("fpstereo_transform", "transform",
                  {{"N", num(n)},
                   {"RANK", d.cfg.cost == CostFunction::Rank ? "1" : "0"},
                   {"CODE_W", num(code_bits)},
                   {"P", num(P)},
                   {"COLS", num(cols)}});
  }

  // ---- HLS: the windows the cost sums over. SAD's are the pixel windows; the others transform the
  // pixel windows (census or rank codes, ZSAD's pixels with their means) and window the results.
  std::string hls_calls(const RtlDesign& d, HlsStreams& s) const override {
    using hls::stream_declarations;
    const HlsStreams in = s;
    s = {"base_windows", "match_windows"};
    const std::string window = "Window<Feature<C>, C::kCostWindow>";
    // With min-disp m < 0 the cost stage reads the match windows -m ahead: the base windows wait.
    std::string text = "\n  // Windows of the cost.\n" +
                       (d.cfg.min_disp < 0 ? stream_declarations(window, {s.base}, "2 - C::kMinDisp") +
                                                 stream_declarations(window, {s.match})
                                           : stream_declarations(window, {s.base, s.match}));
    if (d.cfg.cost == CostFunction::Sad)
      return text +
             fmt::format("  window_stage<Pixel, C::kWindow, C::kMaxWidth>({}, {}, W, H, Pixel(0));\n", in.base,
                         s.base) +
             fmt::format("  window_stage<Pixel, C::kWindow, C::kMaxWidth>({}, {}, W, H, Pixel(0));\n", in.match,
                         s.match);
    text += stream_declarations("Window<Pixel, C::kWindow>", {"left_pixels", "right_pixels"}) +
            stream_declarations("Feature<C>", {"left_features", "right_features"});
    for (const auto& [pixels, side] : {std::pair{in.base, "left"}, std::pair{in.match, "right"}})
      text += fmt::format("  window_stage<Pixel, C::kWindow, C::kMaxWidth>({}, {}_pixels, W, H, Pixel(0));\n",
                          pixels, side);
    for (const char* side : {"left", "right"})
      text += fmt::format("  transform_stage<C>({0}_pixels, {0}_features, W, H);\n", side);
    for (const auto& [side, windows] : {std::pair{"left", s.base}, std::pair{"right", s.match}})
      text += fmt::format(
          "  window_stage<Feature<C>, C::kCostWindow, C::kMaxWidth>({}_features, {}, W, H, "
          "zero_value<Feature<C>>());\n",
          side, windows);
    return text;
  }
  // The widest window loop; each window delays by its radius in rows.
  HlsLoop hls_loop(const Geometry& g) const override {
    return hls_window_loop(g, "windows", std::max(g.cfg.window, g.cost_window) / 2);
  }
  int hls_fill_rows(const Geometry& g) const override { return g.window_fill_rows; }

 private:
  bool transform_;
};

}  // namespace

StagePtr window_stage(const StereoConfig& cfg) { return std::make_shared<WindowStage>(cfg); }

}  // namespace fpstereo::rtl
