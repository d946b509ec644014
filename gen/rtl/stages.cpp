#include "stages.hpp"

#include <fmt/core.h>

#include <utility>

#include "rtl_emitter.hpp"
#include "widths.hpp"

namespace fpstereo::rtl {
namespace {

using Values = std::vector<std::pair<std::string, std::string>>;

std::string num(int64_t v) { return std::to_string(v); }

// `module #(.P(v), ...) name (.port(signal), ...);`, wrapped at about 110 columns.
std::string instance(const std::string& module, const std::string& name, const Values& parameters,
                     const Values& ports) {
  auto list = [](const Values& values, const std::string& indent) {
    std::string text, line = indent;
    for (size_t i = 0; i < values.size(); ++i) {
      const std::string item =
          fmt::format(".{}({}){}", values[i].first, values[i].second, i + 1 < values.size() ? "," : "");
      if (line.size() > indent.size() && line.size() + item.size() + 1 > 110) {
        text += line + "\n";
        line = indent;
      }
      line += (line.size() > indent.size() ? " " : "") + item;
    }
    return text + line;
  };
  std::string text = "  " + module;
  if (!parameters.empty()) text += " #(\n" + list(parameters, "    ") + "\n  )";
  return text + " " + name + " (\n" + list(ports, "    ") + ");\n";
}

std::string wire(int bits, const std::string& name, bool is_signed = false) {
  return fmt::format("  wire {}{}{};\n", is_signed ? "signed " : "",
                     bits > 1 ? fmt::format("[{}:0] ", bits - 1) : "", name);
}

// Declarations of wires a configuration may leave unread, with the waiver Verilator's lint needs.
std::string maybe_unused(const std::string& declarations, const std::string& why) {
  return "  /* verilator lint_off UNUSEDSIGNAL */  // " + why + "\n" + declarations +
         "  /* verilator lint_on UNUSEDSIGNAL */\n";
}
std::string unused_unless(bool used, const std::string& declarations, const std::string& why) {
  return used ? declarations : maybe_unused(declarations, why);
}

// The stage's first step as a localparam, and `flag`, a register high from that step on (a
// compare with the step counter would lie on the path to every enable the flag gates).
std::string start_flag(const RtlDesign& d, const Stage& stage, const std::string& flag) {
  const std::string start = stage.start_parameter();
  const int64_t step = d.start_steps.at(start);
  return fmt::format(
      "  localparam {0} = {1};\n"
      "  reg {2};\n"
      "  always @(posedge clk)\n"
      "    if (restart) {2} <= 1'b{3};\n"
      "    else if (adv && step == {0} - 1) {2} <= 1'b1;\n",
      start, step, flag, step == 0 ? 1 : 0);
}

// The ports every stage module has: the clock, the frame's restart and the pipeline's advance,
// and the frame's size.
Values frame_ports() {
  return {{"clk", "clk"},
          {"restart", "restart"},
          {"adv", "adv"},
          {"frame_width", "frame_width"},
          {"frame_height", "frame_height"}};
}

Values operator+(Values a, const Values& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// A stage's pixel stream in and out, for the stages after the disparity reorder RAM.
Values stream_ports(const PixelStream& in, const PixelStream& out) {
  return {{"in_x", in.x},          {"in_y", in.y},   {"in_word", in.word}, {"out_event", out.event},
          {"out_x", out.x},        {"out_y", out.y}, {"out_word", out.word}};
}

// With sub-pixel output and a left-right check, the words up to the check carry the whole D under
// the refined disparity: the check compares whole disparities (semantics section 5).
bool carries_whole(const RtlDesign& d) { return d.cfg.subpixel_bits != 0 && d.cfg.lr != LrCheck::None; }
int reorder_word_bits(const RtlDesign& d) {
  return d.widths.output_word + (carries_whole(d) ? d.widths.disparity : 0);
}
// With confidence the disparity reorder RAM keeps each pixel's 8-bit confidence above its word.
constexpr int kConfidenceBits = 8;
int reorder_ram_bits(const RtlDesign& d) { return reorder_word_bits(d) + (d.cfg.confidence ? kConfidenceBits : 0); }
// The names of the words the winner-take-all, the sub-pixel fit and the confidence hand on: the
// last of them names wta_*, which the disparity reorder RAM takes.
std::string wta_out(const RtlDesign& d) {
  return d.cfg.subpixel_bits != 0 ? "whole" : d.cfg.confidence ? "plain" : "wta";
}
std::string subpixel_out(const RtlDesign& d) { return d.cfg.confidence ? "plain" : "wta"; }

// With adaptive P2 the cost words carry, beside the costs, each enabled path's P2 for the pixel
// (fpstereo_adaptive_p2), through the cost reorder RAM to the base side's path lanes.
int penalty_bits(const RtlDesign& d) { return d.cfg.p2_adapt != 0 ? d.cfg.path_count() * d.widths.path_cost : 0; }
int cost_word_bits(const RtlDesign& d) { return d.cfg.uf * d.widths.cost + penalty_bits(d); }

// A pixel stream's wires (words of word_bits, the output word's by default); the stages after it
// read what they need of them.
std::string stream_wires(const RtlDesign& d, const PixelStream& s, int word_bits = 0) {
  std::string v;
  if (!s.done.empty()) v += wire(1, s.done);
  v += wire(1, s.event) + wire(d.x_bits, s.x) + wire(d.y_bits, s.y) +
       wire(word_bits != 0 ? word_bits : d.widths.output_word, s.word);
  return maybe_unused(v, "the stages after it read what they need");
}

// ---- the HLS side's text: `hls::stream<type> a("a"), b("b");` with a FIFO depth per stream when given.
std::string hls_streams(const std::string& type, const std::vector<std::string>& names,
                        const std::string& depth = "") {
  std::string text = "  hls::stream<" + type + "> ";
  for (size_t i = 0; i < names.size(); ++i) text += (i ? ", " : "") + names[i] + "(\"" + names[i] + "\")";
  text += ";\n";
  if (!depth.empty())
    for (const auto& name : names)
      text += "#pragma HLS STREAM variable = " + name + " depth = " + depth + "\n";
  return text;
}

// The loop of a window of radius r: its centre lags the input by r rows and r pixels (window_stage).
HlsLoop hls_window_loop(const RtlDesign& d, const std::string& what, int r) {
  return {what, fmt::format("(W+{0})*(H+{0})", r), (int64_t(d.cfg.width) + r) * (int64_t(d.cfg.height) + r)};
}

// The side of the window the HLS cost sums over (the kernels' cost_window<C>()): 1 for census and
// rank, the SHD window for SHD, N for SAD and ZSAD.
int hls_cost_window(const StereoConfig& c) {
  if (c.cost == CostFunction::Census || c.cost == CostFunction::Rank) return 1;
  return c.cost == CostFunction::Shd ? c.shd_window : c.window;
}

// ---- stages -----------------------------------------------------------------------------------------

// Framing: the input register slices, the pairing and framing checks (fpstereo_video_in) and the
// control interface, in the top; the core starts its time base with the frame.
class FramingStage : public Stage {
 public:
  std::string title() const override { return "framing"; }
  std::vector<std::string> knobs() const override { return {"width", "height"}; }
  Latency latency(const RtlDesign&) const override { return {}; }
  std::vector<std::string> modules(const RtlDesign& d) const override {
    std::vector<std::string> m = {"fpstereo_sequencer", "fpstereo_axis_skid", "fpstereo_video_in"};
    if (d.options.control) m.push_back("fpstereo_control");
    return m;
  }
  std::string core_verilog(const RtlDesign& d, PixelStream&) const override {
    return "  // Frame sequencing: adv is every stage's enable.\n" + wire(1, "adv") + wire(1, "restart") +
           wire(1, "in_due") + wire(1, "out_due") + (d.cfg.right_view ? wire(1, "view_due") : std::string()) +
           wire(1, "frame_done") + wire(d.step_bits, "step") +
           wire(1, "follow_open") + wire(1, "next_frame") + wire(1, "next_taken") + wire(1, "continuing") +
           wire(1, "wrapped") +
           fmt::format(
               "  // Frames follow on (docs/architecture.md, \"Back-to-back frames\") when they are taller\n"
               "  // than the pipeline's drain.\n"
               "  localparam OVERLAP_HEIGHT = {};\n"
               "  reg overlap;\n"
               "  always @(posedge clk) overlap <= frame_height >= OVERLAP_HEIGHT;\n",
               d.overlap_height) +
           instance("fpstereo_sequencer", "sequencer", {{"STEP_W", num(d.step_bits)}},
                    {{"clk", "clk"},
                     {"rst", "rst"},
                     {"start", "start"},
                     {"idle", "idle"},
                     {"settings_held", "settings_held"},
                     {"accepting", "accepting"},
                     {"follow_open", "follow_open"},
                     {"next_frame", "next_frame"},
                     {"next_taken", "next_taken"},
                     {"continuing", "continuing"},
                     {"in_due", "in_due"},
                     {"in_valid", "in_valid"},
                     {"out_due", "out_due"},
                     {"out_ready", "out_ready"},
                     {"view_due", d.cfg.right_view ? "view_due" : "1'b0"},
                     {"view_ready", d.cfg.right_view ? "view_ready" : "1'b1"},
                     {"frame_done", "frame_done"},
                     {"adv", "adv"},
                     {"step", "step"},
                     {"restart", "restart"}});
  }

  // ---- HLS: the pixel pairs of the two video streams.
  std::string hls_calls(const RtlDesign& d, HlsStreams& s) const override {
    s = {"left", "right"};
    std::string text = "\n  // Framing: the left and right pixels.\n" + hls_streams("Pixel", {s.base, s.match});
    if (d.cfg.p2_adapt == 0) return text + "  read_pair<C>(left_in, right_in, left, right, W, H);\n";
    // Adaptive P2's penalties read the left pixels too (the cost stage).
    return text + hls_streams("Pixel", {"left_read", "guide_pixels"}) +
           "  read_pair<C>(left_in, right_in, left_read, right, W, H);\n"
           "  fork_pixels<C>(left_read, left, guide_pixels, W, H);\n";
  }
};

// Window and transform: line buffers, the N x N windows and their bounds, and for census, rank
// and SHD the codes of the window centres.
class WindowStage : public Stage {
 public:
  explicit WindowStage(const StereoConfig& c) : transform_(c.cost != CostFunction::Sad && c.cost != CostFunction::Zsad) {}
  std::string title() const override { return transform_ ? "window and transform" : "window"; }
  std::vector<std::string> knobs() const override { return {"window", "cost"}; }
  // The window centred r rows and r slots behind the input is complete after the input's slot;
  // its registered position (and the transform's codes) one slot later.
  Latency latency(const RtlDesign& d) const override {
    return {d.window_radius, d.window_radius + 2, 0};
  }
  std::vector<StageMemory> memories(const RtlDesign& d) const override {
    const int64_t bits = int64_t(d.cfg.window - 1) * d.widths.pixel;
    return {{"core.front_end.left_window.line_buffer.mem", d.row_slots, bits},
            {"core.front_end.right_window.line_buffer.mem", d.row_slots, bits}};
  }
  std::vector<std::string> modules(const RtlDesign& d) const override {
    std::vector<std::string> m = {"fpstereo_front_end", "fpstereo_raster_counter", "fpstereo_frame_row",
                                  "fpstereo_window", "fpstereo_window_bounds"};
    if (transform_)
      m.insert(m.end(), {"fpstereo_transform", d.cfg.cost == CostFunction::Rank ? "fpstereo_rank" : "fpstereo_census"});
    return m;
  }
  std::string core_verilog(const RtlDesign& d, PixelStream&) const override {
    const int n = d.cfg.window, window_bits = n * n * 8;
    std::string v = "\n  // Window stage: line buffers, windows, their bounds and centres.\n" + wire(1, "shift") +
                    wire(1, "slot_end") + wire(d.group_bits, "group") + wire(window_bits, "window_left") +
                    wire(window_bits, "window_right") + wire(n, "row_valid") + wire(n, "col_valid") +
                    wire(d.x_bits, "transform_x") + wire(d.signed_y_bits, "transform_y", true) +
                    wire(d.cost_row_bits, "transform_slot");
    v += unused_unless(!transform_, wire(n, "newest_row_valid"), "only the SAD and ZSAD costs use it");
    v += instance("fpstereo_front_end", "front_end",
                  {{"N", num(n)},
                   {"ROW_SLOTS", num(d.row_slots)},
                   {"G", num(d.groups)},
                   {"COST_ROWS", num(d.cost_rows)},
                   {"COST_K_W", num(d.cost_row_bits)},
                   {"X_W", num(d.x_bits)},
                   {"Y_W", num(d.y_bits)},
                   {"YS_W", num(d.signed_y_bits)},
                   {"G_W", num(d.group_bits)}},
                  frame_ports() + Values{{"overlap", "overlap"},
                   {"next_frame", "next_frame"},
                   {"next_taken", "next_taken"},
                   {"follow_open", "follow_open"},
                   {"continuing", "continuing"},
                   {"wrapped", "wrapped"},
                   {"in_due", "in_due"},
                   {"in_take", "in_take"},
                   {"in_left", "in_left"},
                   {"in_right", "in_right"},
                   {"group", "group"},
                   {"slot_end", "slot_end"},
                   {"shift", "shift"},
                   {"window_left", "window_left"},
                   {"window_right", "window_right"},
                   {"row_valid", "row_valid"},
                   {"col_valid", "col_valid"},
                   {"newest_row_valid", "newest_row_valid"},
                   {"transform_x", "transform_x"},
                   {"transform_y", "transform_y"},
                   {"transform_slot", "transform_slot"}});
    if (!transform_) return v;
    const int code_bits = std::max(1, d.widths.code);
    return v + wire(code_bits, "code_base") + wire(code_bits, "code_match") +
           instance("fpstereo_transform", "transform",
                    {{"N", num(n)}, {"RANK", d.cfg.cost == CostFunction::Rank ? "1" : "0"}, {"CODE_W", num(code_bits)}},
                    {{"clk", "clk"},
                     {"shift", "shift"},
                     {"window_left", "window_left"},
                     {"window_right", "window_right"},
                     {"row_valid", "row_valid"},
                     {"col_valid", "col_valid"},
                     {"code_base", "code_base"},
                     {"code_match", "code_match"}});
  }

  // ---- HLS: the windows the cost sums over. SAD's are the pixel windows; the others transform the
  // pixel windows (census or rank codes, ZSAD's pixels with their means) and window the results.
  std::string hls_calls(const RtlDesign& d, HlsStreams& s) const override {
    const HlsStreams in = s;
    s = {"base_windows", "match_windows"};
    const std::string window = "Window<Feature<C>, cost_window<C>()>";
    // With min-disp m < 0 the cost stage reads the match windows -m ahead: the base windows wait.
    std::string text = "\n  // Windows of the cost.\n" +
                       (d.cfg.min_disp < 0 ? hls_streams(window, {s.base}, "2 - C::kMinDisp") +
                                                 hls_streams(window, {s.match})
                                           : hls_streams(window, {s.base, s.match}));
    if (d.cfg.cost == CostFunction::Sad)
      return text +
             fmt::format("  window_stage<Pixel, C::kWindow, C::kMaxWidth>({}, {}, W, H, Pixel(0));\n",
                         in.base, s.base) +
             fmt::format("  window_stage<Pixel, C::kWindow, C::kMaxWidth>({}, {}, W, H, Pixel(0));\n",
                         in.match, s.match);
    text += hls_streams("Window<Pixel, C::kWindow>", {"left_pixels", "right_pixels"}) +
            hls_streams("Feature<C>", {"left_features", "right_features"});
    for (const auto& [pixels, side] : {std::pair{in.base, "left"}, std::pair{in.match, "right"}})
      text += fmt::format("  window_stage<Pixel, C::kWindow, C::kMaxWidth>({}, {}_pixels, W, H, Pixel(0));\n",
                          pixels, side);
    for (const char* side : {"left", "right"})
      text += fmt::format("  transform_stage<C>({0}_pixels, {0}_features, W, H);\n", side);
    for (const auto& [side, windows] : {std::pair{"left", s.base}, std::pair{"right", s.match}})
      text += fmt::format(
          "  window_stage<Feature<C>, cost_window<C>(), C::kMaxWidth>({}_features, {}, W, H, "
          "zero_value<Feature<C>>());\n",
          side, windows);
    return text;
  }
  // The widest window loop; each window delays by its radius in rows.
  HlsLoop hls_loop(const RtlDesign& d) const override {
    return hls_window_loop(d, "windows", std::max(d.cfg.window, hls_cost_window(d.cfg)) / 2);
  }
  int hls_fill_rows(const RtlDesign& d) const override {
    return (d.cfg.cost == CostFunction::Sad ? 0 : d.cfg.window / 2) + hls_cost_window(d.cfg) / 2;
  }

 private:
  bool transform_;
};

// Matching costs: UF per step from the match ring and the cost lanes of the cost function.
class CostStage : public Stage {
 public:
  explicit CostStage(const StereoConfig& c) : cost_(c.cost == CostFunction::Shd && c.shd_window == 1 ? CostFunction::Census : c.cost) {}
  std::string title() const override { return "cost"; }
  // min-disp delays the match columns (or, below 0, the base) before the match ring.
  std::vector<std::string> knobs() const override {
    return {"cost", "window", "shd-window", "dmax", "uf", "p2-adapt", "min-disp"};
  }
  // The base word waits a slot next to the match ring (SHD: after its code window, rs rows and
  // rs + 1 slots; ZSAD: two more, for the base window's mean; a negative min-disp m: -m more,
  // fpstereo_offset_delays); the lanes take their register stages.
  Latency latency(const RtlDesign& d) const override {
    const Latency wait = base_wait(d.cfg);
    return {wait.rows, 1 + wait.slots, d.cost_latency};
  }
  // What the base waits beside the match ring (adaptive P2's steps wait as long).
  Latency base_wait(const StereoConfig& c) const {
    const int64_t rs = cost_ == CostFunction::Shd ? c.shd_window / 2 : 0;
    const int64_t wait = cost_ == CostFunction::Shd ? rs + 1 : cost_ == CostFunction::Zsad ? 2 : 0;
    return {rs, wait + base_offset_slots(c), 0};
  }
  static int base_offset_slots(const StereoConfig& c) { return std::max(0, -c.min_disp); }
  std::vector<StageMemory> memories(const RtlDesign& d) const override {
    if (cost_ != CostFunction::Shd) return {};
    const int64_t bits = int64_t(d.cfg.shd_window - 1) * std::max(1, d.widths.code);
    std::vector<StageMemory> m = {{"core.cost.base_codes.line_buffer.mem", d.row_slots, bits},
                                  {"core.cost.match_codes.line_buffer.mem", d.row_slots, bits}};
    // Adaptive P2's steps wait the code window's rows in a ring (fpstereo_adaptive_p2).
    if (d.cfg.p2_adapt != 0 && base_wait(d.cfg).rows > 0)
      m.push_back({"core.adaptive_p2.row_wait.rows.mem", base_wait(d.cfg).rows * d.row_slots, 4 * 8});
    return m;
  }
  std::vector<std::string> modules(const RtlDesign& d) const override {
    std::vector<std::string> m = cost_modules();
    m.insert(m.end(), {"fpstereo_offset_delays", "fpstereo_delay"});
    if (d.cfg.p2_adapt != 0) m.insert(m.end(), {"fpstereo_adaptive_p2", "fpstereo_ram_sdp"});
    return m;
  }
  std::vector<std::string> cost_modules() const {
    switch (cost_) {
      case CostFunction::Census:
      case CostFunction::Rank:
        return {"fpstereo_point_cost", "fpstereo_match_ring", "fpstereo_cost_lanes"};
      case CostFunction::Sad:
      case CostFunction::Zsad:
        return {"fpstereo_pixel_window_cost", "fpstereo_window_mask", "fpstereo_match_ring",
                "fpstereo_window_cost_lanes", "fpstereo_sum_tree"};
      case CostFunction::Shd:
        break;
    }
    return {"fpstereo_code_window_cost", "fpstereo_window", "fpstereo_window_centre", "fpstereo_window_bounds",
            "fpstereo_window_mask", "fpstereo_match_ring", "fpstereo_window_cost_lanes", "fpstereo_sum_tree"};
  }
  std::string core_verilog(const RtlDesign& d, PixelStream&) const override {
    const StereoConfig& c = d.cfg;
    const Widths& w = d.widths;
    const int code_bits = std::max(1, w.code);
    Values common = {{"DMAX", num(c.dmax)},          {"UF", num(c.uf)},
                     {"COST_W", num(w.cost)},        {"COST_MAX", num(int64_t(w.cost_max))},
                     {"COST_K_W", num(d.cost_row_bits)}, {"X_W", num(d.x_bits)},
                     {"YS_W", num(d.signed_y_bits)}, {"G_W", num(d.group_bits)},
                     {"MIN_DISP", num(c.min_disp)},  {"LAT", num(d.cost_latency)}};
    Values ports = {{"clk", "clk"}, {"adv", "adv"}, {"slot_end", "slot_end"}, {"shift", "shift"}, {"group", "group"}};
    Values position = {{"transform_x", "transform_x"},   {"transform_y", "transform_y"},
                       {"transform_slot", "transform_slot"}, {"history_x", "history_x"},
                       {"history_y", "history_y"},       {"history_slot", "history_slot"},
                       {"costs", "costs"}};
    std::string module;
    Values parameters;
    switch (cost_) {
      case CostFunction::Census:
      case CostFunction::Rank:
        module = "fpstereo_point_cost";
        parameters = {{"HAMMING", cost_ == CostFunction::Census ? "1" : "0"}, {"CODE_W", num(code_bits)}};
        ports.insert(ports.end(),
                     {{"frame_width", "frame_width"}, {"code_base", "code_base"}, {"code_match", "code_match"}});
        break;
      case CostFunction::Sad:
      case CostFunction::Zsad:
        module = "fpstereo_pixel_window_cost";
        parameters = {{"N", num(c.window)},
                      {"ZERO_MEAN", cost_ == CostFunction::Zsad ? "1" : "0"},
                      {"COLSUM_W", num(d.column_sum_bits)},
                      {"MEAN_MUL", num(int64_t(d.mean_mul))},
                      {"MEAN_SHIFT", num(d.mean_shift)}};
        ports.insert(ports.end(), {{"frame_width", "frame_width"},
                                   {"window_left", "window_left"},
                                   {"window_right", "window_right"},
                                   {"row_valid", "row_valid"},
                                   {"col_valid", "col_valid"},
                                   {"newest_row_valid", "newest_row_valid"}});
        break;
      case CostFunction::Shd:
        module = "fpstereo_code_window_cost";
        parameters = {{"SHD_K", num(c.shd_window)},     {"CODE_W", num(code_bits)},
                      {"ROW_SLOTS", num(d.row_slots)},  {"COLSUM_W", num(d.column_sum_bits)},
                      {"COST_ROWS", num(d.cost_rows)},  {"Y_W", num(d.y_bits)}};
        ports.insert(ports.end(), {{"frame_width", "frame_width"},
                                   {"frame_height", "frame_height"},
                                   {"wrapped", "wrapped"},
                                   {"code_base", "code_base"},
                                   {"code_match", "code_match"}});
        break;
    }
    parameters.insert(parameters.end(), common.begin(), common.end());
    ports.insert(ports.end(), position.begin(), position.end());
    std::string v = "\n  // Cost stage: the centre whose costs the lanes compute, and UF costs per step.\n" +
                    wire(d.x_bits, "history_x") + wire(d.signed_y_bits, "history_y", true) +
                    wire(d.cost_row_bits, "history_slot") + wire(c.uf * w.cost, "costs") +
                    instance(module, "cost", parameters, ports);
    if (c.p2_adapt == 0) return v;
    return v + "  // Adaptive P2: each path's P2 for the pixel, beside its costs.\n" +
           wire(penalty_bits(d), "cost_penalties") +
           instance("fpstereo_adaptive_p2", "adaptive_p2",
                    {{"N", num(c.window)},
                     {"PATHS", num(c.paths)},
                     {"NP", num(c.path_count())},
                     {"GAIN", num(c.p2_adapt)},
                     {"PATH_W", num(w.path_cost)},
                     {"WAIT_SLOTS", num(base_wait(c).slots)},
                     {"WAIT_ROWS", num(base_wait(c).rows)},
                     {"ROW_SLOTS", num(d.row_slots)},
                     {"LAT", num(d.cost_latency)}},
                    {{"clk", "clk"},
                     {"adv", "adv"},
                     {"shift", "shift"},
                     {"window", "window_left"},
                     {"p1", "p1"},
                     {"p2", "p2"},
                     {"penalties", "cost_penalties"}});
  }

  // ---- HLS: G words of uf costs per pixel; with LR2 cost_stage also sends them to the match side.
  std::string hls_calls(const RtlDesign& d, HlsStreams& s) const override {
    const HlsStreams in = s;
    s = {"costs", "match_side_base_costs"};
    std::string text = "\n  // Cost.\n" + hls_streams("CostWord<C>", {s.base, s.match}, "kDepth");
    if (d.cfg.p2_adapt == 0)
      return text + fmt::format("  cost_stage<C>({}, {}, {}, {}, W, H);\n", in.base, in.match, s.base, s.match);
    // Adaptive P2: the pixels' penalties join their cost words. The penalties wait for the costs,
    // which the windows delay by rows: their FIFO holds those rows and one more (and with
    // min-disp m < 0 the -m pixels the cost stage's match runs ahead).
    const int64_t waiting =
        (WindowStage(d.cfg).hls_fill_rows(d) + 1) * int64_t(d.cfg.width) + std::max(0, -d.cfg.min_disp);
    return text + hls_streams("CostWord<C>", {"plain_costs"}, "kDepth") +
           hls_streams("Penalties<C>", {"penalties"}, num(waiting)) +
           fmt::format("  cost_stage<C>({}, {}, plain_costs, {}, W, H);\n", in.base, in.match, s.match) +
           "  penalty_stage<C>(guide_pixels, penalties, W, H, p1, p2);\n" +
           fmt::format("  attach_penalties<C>(plain_costs, penalties, {}, W, H);\n", s.base);
  }
  // With min-disp m < 0 each row opens with -m iterations that read match windows ahead.
  HlsLoop hls_loop(const RtlDesign& d) const override {
    if (d.cfg.min_disp >= 0) return {};
    const int64_t W = d.cfg.width, H = d.cfg.height, lead = -d.cfg.min_disp;
    return {"cost (the match -m pixels ahead)", "H*(W*dmax/uf-m)", H * (W * d.groups + lead)};
  }

 private:
  CostFunction cost_;  // SHD over a 1 x 1 window is census
};

// Cost reorder RAM: raster order in, chain order out.
class CostReorderStage : public Stage {
 public:
  std::string title() const override { return "cost reorder"; }
  std::vector<std::string> knobs() const override { return {"uf"}; }
  Latency latency(const RtlDesign&) const override { return {0, 0, 1}; }  // written, then read
  std::vector<StageMemory> memories(const RtlDesign& d) const override {
    return {{"core.cost_reorder.cost_ram.mem", d.cost_depth(), cost_word_bits(d)}};
  }
  std::vector<std::string> modules(const RtlDesign&) const override {
    return {"fpstereo_cost_reorder", "fpstereo_delay", "fpstereo_ram_sdp"};
  }
  std::string core_verilog(const RtlDesign& d, PixelStream&) const override {
    const std::string cost_tag = wire(1, "cost_valid") + wire(d.x_bits, "cost_x") +
                                 wire(d.cost_row_bits, "cost_row_slot") + wire(d.group_bits, "cost_group");
    Values parameters = {{"ROW_SLOTS", num(d.row_slots)},
                         {"G", num(d.groups)},
                         {"UF", num(d.cfg.uf)},
                         {"COST_W", num(d.widths.cost)},
                         {"LAT", num(d.cost_latency)},
                         {"COST_ROWS", num(d.cost_rows)},
                         {"COST_K_W", num(d.cost_row_bits)},
                         {"COST_AW", num(d.cost_addr_bits)},
                         {"X_W", num(d.x_bits)},
                         {"Y_W", num(d.y_bits)},
                         {"YS_W", num(d.signed_y_bits)},
                         {"G_W", num(d.group_bits)}};
    const bool penalties = penalty_bits(d) != 0;
    if (penalties) parameters.push_back({"EXTRA_W", num(penalty_bits(d))});
    return "\n  // Cost reorder RAM.\n" +
           unused_unless(d.cfg.lr == LrCheck::Lr2, cost_tag, "LR2's lane banks take the cost words' positions") +
           wire(d.cost_addr_bits, "cost_raddr") + wire(cost_word_bits(d), "cost_q") +
           instance("fpstereo_cost_reorder", "cost_reorder", parameters,
                    frame_ports() + Values{{"group", "group"},
                     {"history_x", "history_x"},
                     {"history_y", "history_y"},
                     {"history_slot", "history_slot"},
                     {"costs", penalties ? "{cost_penalties, costs}" : "costs"},
                     {"cost_valid", "cost_valid"},
                     {"cost_x", "cost_x"},
                     {"cost_row_slot", "cost_row_slot"},
                     {"cost_group", "cost_group"},
                     {"cost_raddr", "cost_raddr"},
                     {"cost_q", "cost_q"}});
  }

  // ---- HLS: aggregate's to_chain_order.
  std::string hls_calls(const RtlDesign&, HlsStreams&) const override {
    return "\n  // Cost reorder: in aggregate (to_chain_order).\n";
  }
};

// The aggregator's memories below scope (fpstereo_aggregator.v).
std::vector<StageMemory> aggregator_memories(const RtlDesign& d, const std::string& scope) {
  const StereoConfig& c = d.cfg;
  const int64_t lanes_w = int64_t(c.uf) * d.widths.path_cost;
  const int64_t row_depth = int64_t(c.width + 1) * d.groups;
  const int64_t state_depth = int64_t(d.chains) * d.groups;
  std::vector<StageMemory> out;
  if (c.paths & kPath0) out.push_back({scope + ".path0.state.mem", state_depth, lanes_w, false});
  if (c.paths & kPath45) {
    out.push_back({scope + ".path45.row.mem", row_depth, lanes_w});
    out.push_back({scope + ".path45.row_min.mem", c.width + 1, d.widths.path_cost});
    out.push_back({scope + ".path45.state.mem", state_depth, lanes_w, false});
  }
  for (int v = 0; v < 2; ++v) {
    if (!(c.paths & (v == 0 ? kPath90 : kPath135))) continue;
    const std::string p = fmt::format("{}.vertical[{}].path", scope, v);
    out.push_back({p + ".row.mem", row_depth, lanes_w});
    out.push_back({p + ".row_min.mem", c.width + 1, d.widths.path_cost});
  }
  return out;
}

// The aggregator's parameters but MATCH_SIDE, which the LR2 match side's module sets itself.
Values aggregator_parameters(const RtlDesign& d) {
  const StereoConfig& c = d.cfg;
  return {{"W", num(c.width)},
          {"ROW_SLOTS", num(d.row_slots)},
          {"K", num(d.chains)},
          {"SLEN", num(d.segment)},
          {"G", num(d.groups)},
          {"UF", num(c.uf)},
          {"COST_W", num(d.widths.cost)},
          {"COST_MAX", num(int64_t(d.widths.cost_max))},
          {"PATH_W", num(d.widths.path_cost)},
          {"SUM_W", num(d.widths.aggregated)},
          {"PATHS", num(c.paths)},
          {"LEVELS_PER_STAGE", num(d.levels_per_stage)},
          {"PATH_TREE_LAT", num(d.path_tree_latency)},
          {"OUT_ROWS", num(d.out_rows)},
          {"OUT_K_W", num(d.out_row_bits)},
          {"COST_AW", num(d.cost_addr_bits)},
          {"X_W", num(d.x_bits)},
          {"Y_W", num(d.y_bits)},
          {"G_W", num(d.group_bits)},
          {"K_W", num(d.chain_bits)},
          {"COST_ROWS", num(d.cost_rows)},
          {"COST_K_W", num(d.cost_row_bits)}};
}

// Aggregation in K interleaved chains; a row's last chain runs K - 1 row-times after its first,
// and the sums leave the aggregator's five register stages (S0 .. S5).
class AggregationStage : public Stage {
 public:
  std::string title() const override { return "aggregation"; }
  std::vector<std::string> knobs() const override { return {"paths", "p1", "p2", "mgm", "dmax", "uf"}; }
  std::string start_parameter() const override { return "AGG_START"; }
  Latency latency(const RtlDesign& d) const override { return {d.chains - 1, 0, 5}; }
  std::vector<StageMemory> memories(const RtlDesign& d) const override {
    return aggregator_memories(d, "core.aggregation");
  }
  std::vector<std::string> modules(const RtlDesign&) const override {
    return {"fpstereo_aggregator", "fpstereo_frame_row", "fpstereo_path_lanes", "fpstereo_path_minimum",
            "fpstereo_min_tree", "fpstereo_delay", "fpstereo_ram_sdp", "fpstereo_ram_async"};
  }
  std::string core_verilog(const RtlDesign& d, PixelStream&) const override {
    std::string v = "\n  // Aggregation in K interleaved chains, from step AGG_START.\n" +
                    start_flag(d, *this, "agg_on") +
                    wire(d.cfg.uf * d.widths.aggregated, "agg_sums") + wire(1, "agg_active") + wire(d.x_bits, "agg_x") +
                    wire(d.group_bits, "agg_group") + wire(d.out_row_bits, "agg_slot");
    v += unused_unless(d.cfg.lr == LrCheck::Lr1, wire(d.chain_bits, "agg_chain"), "only LR1 follows the chains");
    Values side = {{"MATCH_SIDE", "0"}};
    if (d.cfg.p2_adapt != 0) side.push_back({"PENALTIES", num(d.cfg.path_count())});
    return v + instance("fpstereo_aggregator", "aggregation", aggregator_parameters(d) + side,
                        frame_ports() + Values{{"p1", "p1"},
                         {"p2", "p2"},
                         {"agg_on", "agg_on"},
                         {"overlap", "overlap"},
                         {"wrapped", "wrapped"},
                         {"cost_raddr", "cost_raddr"},
                         {"cost_q", "cost_q"},
                         {"sums", "agg_sums"},
                         {"sums_active", "agg_active"},
                         {"sums_x", "agg_x"},
                         {"sums_group", "agg_group"},
                         {"sums_chain", "agg_chain"},
                         {"sums_slot", "agg_slot"}});
  }

  // ---- HLS: two interleaved chains (K = 2), between reorders into chain order and back, which
  // delay the stream by a row-time.
  std::string hls_calls(const RtlDesign&, HlsStreams& s) const override {
    const std::string costs = s.base;
    s.base = "sums";
    return "\n  // Aggregation.\n" + hls_streams("SumWord<C>", {s.base}, "kDepth") +
           fmt::format("  aggregate<C, 0>({}, {}, W, H, p1, p2);\n", costs, s.base);
  }
  HlsLoop hls_loop(const RtlDesign& d) const override {
    const int64_t W = d.cfg.width, H = d.cfg.height;
    return {"aggregation (two interleaved chains)", "(H+1)*2*ceil(W/2)*dmax/uf",
            (H + 1) * 2 * ((W + 1) / 2) * d.groups};
  }
  int hls_fill_rows(const RtlDesign&) const override { return 1; }
};

// The match side's writes into the left-right check's RAM of completed pixels.
std::string completed_wires(const RtlDesign& d) {
  return wire(1, "completed_we") + wire(d.disp_addr_bits, "completed_waddr") +
         wire(d.widths.disparity, "completed_wdata");
}

// LR1's match side: Dm from the base side's sums, beside the main stream.
class Lr1MatchStage : public Stage {
 public:
  std::string title() const override { return "LR1 match side"; }
  std::vector<std::string> knobs() const override { return {"lr", "min-disp"}; }
  Latency latency(const RtlDesign&) const override { return {}; }
  std::vector<StageMemory> memories(const RtlDesign& d) const override {
    return {{"core.lr1_match.entries.mem", int64_t(d.chains) * d.groups,
             int64_t(d.cfg.uf) * (d.widths.aggregated + d.widths.disparity), false}};
  }
  std::vector<std::string> modules(const RtlDesign&) const override {
    return {"fpstereo_lr1_match", "fpstereo_ram_async"};
  }
  std::string core_verilog(const RtlDesign& d, PixelStream&) const override {
    const StereoConfig& c = d.cfg;
    return "\n  // LR1 match side: Dm(x') from the base side's sums.\n" + completed_wires(d) + wire(1, "row_end_we") +
           wire(d.end_addr_bits, "row_end_waddr") + wire(c.uf * d.widths.disparity, "row_end_wdata") +
           instance("fpstereo_lr1_match", "lr1_match",
                    {{"K", num(d.chains)},
                     {"G", num(d.groups)},
                     {"UF", num(c.uf)},
                     {"DMAX", num(c.dmax)},
                     {"ROW_SLOTS", num(d.row_slots)},
                     {"SUM_W", num(d.widths.aggregated)},
                     {"DISP_W", num(d.widths.disparity)},
                     {"OUT_K_W", num(d.out_row_bits)},
                     {"DISP_AW", num(d.disp_addr_bits)},
                     {"END_AW", num(d.end_addr_bits)},
                     {"X_W", num(d.x_bits)},
                     {"G_W", num(d.group_bits)},
                     {"K_W", num(d.chain_bits)},
                     {"MIN_DISP", num(c.min_disp)}},
                    {{"clk", "clk"},
                     {"adv", "adv"},
                     {"frame_width", "frame_width"},
                     {"sums", "agg_sums"},
                     {"active", "agg_active"},
                     {"x", "agg_x"},
                     {"group", "agg_group"},
                     {"chain", "agg_chain"},
                     {"slot", "agg_slot"},
                     {"completed_we", "completed_we"},
                     {"completed_waddr", "completed_waddr"},
                     {"completed_wdata", "completed_wdata"},
                     {"row_end_we", "row_end_we"},
                     {"row_end_waddr", "row_end_waddr"},
                     {"row_end_wdata", "row_end_wdata"}});
  }

  // ---- HLS: select_base finds Dm from the base side's sums as they pass.
  std::string hls_calls(const RtlDesign&, HlsStreams& s) const override {
    s.match = "match_disparity";
    return "\n  // LR1 match side: Dm, found by select_base (winner-take-all).\n" +
           hls_streams("Word<C>", {s.match});
  }
  // select_base sends the Dm not final within the row at its start or end: min(|m + dmax - 1|, W)
  // iterations per row beyond the sums'.
  HlsLoop hls_loop(const RtlDesign& d) const override {
    const int64_t W = d.cfg.width, H = d.cfg.height, lag = d.cfg.min_disp + d.cfg.dmax - 1;
    return {"LR1 winner-take-all (Dm at the row ends)",
            d.cfg.min_disp == 0 ? "H*(W*dmax/uf+dmax-1)" : "H*(W*dmax/uf+|m+dmax-1|)",
            H * (W * d.groups + std::min(std::abs(lag), W))};
  }
};

// LR2's match side: a second cost volume (lane banks), aggregation and winner-take-all, dmax + 2
// slots behind the base side's aggregation (its costs need base pixels up to x' + m + dmax - 1,
// so a positive min-disp m adds m).
class Lr2MatchStage : public Stage {
 public:
  std::string title() const override { return "LR2 match side"; }
  std::vector<std::string> knobs() const override { return {"lr", "paths", "p1", "p2", "min-disp"}; }
  std::string start_parameter() const override { return "MATCH_START"; }
  Latency latency(const RtlDesign&) const override { return {}; }
  Latency start_offset(const RtlDesign& d) const override { return {0, d.cfg.dmax + 2 + std::max(0, d.cfg.min_disp), 0}; }
  std::vector<StageMemory> memories(const RtlDesign& d) const override {
    std::vector<StageMemory> out;
    for (int l = 0; l < d.cfg.uf; ++l)
      out.push_back({fmt::format("core.lr2_match.bank[{}].costs_of_lane.mem", l), d.cost_depth(), d.widths.cost});
    for (auto& m : aggregator_memories(d, "core.lr2_match.match_aggregation")) out.push_back(m);
    return out;
  }
  std::vector<std::string> modules(const RtlDesign&) const override {
    return {"fpstereo_lr2_match", "fpstereo_ram_sdp", "fpstereo_aggregator", "fpstereo_frame_row", "fpstereo_wta",
            "fpstereo_min_tree", "fpstereo_delay"};
  }
  std::string core_verilog(const RtlDesign& d, PixelStream&) const override {
    const StereoConfig& c = d.cfg;
    Values parameters = aggregator_parameters(d);
    parameters.insert(parameters.end(), {{"DMAX", num(c.dmax)},
                                         {"DISP_W", num(d.widths.disparity)},
                                         {"WTA_TREE_LAT", num(d.wta_tree_latency)},
                                         {"DISP_AW", num(d.disp_addr_bits)},
                                         {"LANE_W", num(d.lane_bits)},
                                         {"MIN_DISP", num(c.min_disp)}});
    return "\n  // LR2 match side: second cost volume, aggregation and winner-take-all.\n" +
           start_flag(d, *this, "match_on") + completed_wires(d) +
           instance("fpstereo_lr2_match", "lr2_match", parameters,
                    frame_ports() + Values{{"match_on", "match_on"},
                     {"overlap", "overlap"},
                     {"wrapped", "wrapped"},
                     {"p1", "p1"},
                     {"p2", "p2"},
                     {"cost_valid", "cost_valid"},
                     {"cost_x", "cost_x"},
                     {"cost_row_slot", "cost_row_slot"},
                     {"cost_group", "cost_group"},
                     {"costs", "costs"},
                     {"completed_we", "completed_we"},
                     {"completed_waddr", "completed_waddr"},
                     {"completed_wdata", "completed_wdata"}});
  }

  // ---- HLS: the base costs regrouped per match pixel, their aggregation and winner-take-all.
  std::string hls_calls(const RtlDesign&, HlsStreams& s) const override {
    const std::string base_costs = s.match;
    s.match = "match_disparity";
    return "\n  // LR2 match side.\n" + hls_streams("CostWord<C>", {"match_side_costs"}) +
           hls_streams("SumWord<C>", {"match_side_sums"}) + hls_streams("Word<C>", {s.match}) +
           fmt::format("  match_costs<C>({}, match_side_costs, W, H);\n", base_costs) +
           "  aggregate<C, 1>(match_side_costs, match_side_sums, W, H, p1, p2);\n" +
           fmt::format("  select_match<C>(match_side_sums, {}, W, H);\n", s.match);
  }
  // Match pixel x' waits for base pixel x' + m + dmax - 1: its rows are |m + dmax - 1| pixels
  // longer (match_costs).
  HlsLoop hls_loop(const RtlDesign& d) const override {
    const int64_t W = d.cfg.width, H = d.cfg.height, lag = d.cfg.min_disp + d.cfg.dmax - 1;
    return {"LR2 match side", d.cfg.min_disp == 0 ? "H*(W+dmax-1)*dmax/uf" : "H*(W+|m+dmax-1|)*dmax/uf",
            H * (W + std::abs(lag)) * d.groups};
  }
};

// Winner-take-all (with the uniqueness check when configured): the running minimum's register.
class WtaStage : public Stage {
 public:
  explicit WtaStage(const StereoConfig& c) : unique_(finds_second_best(c)) {}
  std::string title() const override { return unique_ ? "winner-take-all with uniqueness" : "winner-take-all"; }
  std::vector<std::string> knobs() const override { return {"uniqueness"}; }
  Latency latency(const RtlDesign& d) const override { return {0, 0, d.wta_word_lag + 1}; }
  std::vector<std::string> modules(const RtlDesign&) const override {
    if (unique_) return {"fpstereo_wta_unique", "fpstereo_unique_tree", "fpstereo_unique_join", "fpstereo_delay"};
    return {"fpstereo_wta", "fpstereo_min_tree", "fpstereo_delay"};
  }
  std::string core_verilog(const RtlDesign& d, PixelStream&) const override {
    const int tag_bits = 1 + d.x_bits + d.out_row_bits;
    // The words go on to the sub-pixel fit or the confidence when they are there (wta_out).
    const std::string out = wta_out(d);
    Values ports = {{"clk", "clk"},
                    {"restart", "restart"},
                    {"adv", "adv"},
                    {"sums", "agg_sums"},
                    {"group", "agg_group"},
                    {"tag", "{agg_active, agg_x, agg_slot}"}};
    if (unique_) ports.push_back({"uniqueness", d.cfg.uniqueness != 0 ? "uniqueness" : "7'd0"});
    ports.insert(ports.end(), {{"group_out", out + "_group"},
                               {"tag_out", fmt::format("{{{0}_active, {0}_x, {0}_slot}}", out)},
                               {"word", out + "_word"}});
    std::string sums;
    if (unique_) {
      ports.insert(ports.end(), {{"best_sum", "winner_best"}, {"second_sum", "winner_second"}});
      sums = unused_unless(d.cfg.confidence,
                           wire(d.widths.aggregated, "winner_best") + wire(d.widths.aggregated, "winner_second"),
                           "the confidence divides them");
    }
    return "\n  // Winner-take-all: the pixel's word in its last group's step.\n" + wire(d.group_bits, out + "_group") +
           wire(1, out + "_active") + wire(d.x_bits, out + "_x") + wire(d.out_row_bits, out + "_slot") +
           wire(d.widths.disparity + 1, out + "_word") + sums +
           instance(unique_ ? "fpstereo_wta_unique" : "fpstereo_wta", "wta",
                    {{"UF", num(d.cfg.uf)},
                     {"SUM_W", num(d.widths.aggregated)},
                     {"DISP_W", num(d.widths.disparity)},
                     {"LANE_W", num(d.lane_bits)},
                     {"G_W", num(d.group_bits)},
                     {"TAG_W", num(tag_bits)},
                     {"LEVELS_PER_STAGE", num(unique_ ? RtlDesign::kUniqueLevelsPerStage : d.levels_per_stage)},
                     {"TREE_LAT", num(unique_ ? d.unique_tree_latency : d.wta_tree_latency)}},
                    ports);
  }

  // ---- HLS: select_base, with LR1 also Dm into the match side's stream; without a left-right
  // check that stream is never written. D waits in its FIFO for Dm: up to dmax pixels with LR1,
  // the match side's extra latency with LR2, and with min-disp m > 0 m pixels more (Dm(x) is
  // final after base pixel x + m + dmax - 1). With confidence, each pixel's goes to the output
  // (write_confident_words) past the check, the median's rows and gap interpolation's row.
  std::string hls_calls(const RtlDesign& d, HlsStreams& s) const override {
    const int64_t later = std::max(0, d.cfg.min_disp);
    std::string text = std::string("\n  // Winner-take-all") + (unique_ ? " with uniqueness" : "") + ".\n" +
                       hls_streams("BaseWord<C>", {"disparity"},
                                   later == 0 ? "2 * C::kDmax + 4" : "2 * C::kDmax + C::kMinDisp + 4");
    if (d.cfg.lr == LrCheck::None) {
      s.match = "match_disparity";
      text += hls_streams("Word<C>", {s.match});
    }
    const int64_t waiting_rows = d.cfg.median / 2 + (d.cfg.gap_interpolation ? 1 : 0) + 3;
    text += hls_streams("ap_uint<8>", {"confidences"},
                        d.cfg.confidence ? num(waiting_rows * d.cfg.width + 2 * d.cfg.dmax + later + 4) : "");
    text += fmt::format("  select_base<C>({}, disparity, {}, confidences, W, H, uniqueness);\n", s.base, s.match);
    s.base = "disparity";
    return text;
  }

 private:
  bool unique_;
};

// Sub-pixel refinement of the winner-take-all's words (fpstereo_subpixel): the sums at D - 1, D
// and D + 1 selected in the two steps after the word, then the fit's K + 3 steps.
class SubpixelStage : public Stage {
 public:
  std::string title() const override { return "sub-pixel fit"; }
  std::vector<std::string> knobs() const override { return {"subpixel-bits", "subpixel-fit"}; }
  Latency latency(const RtlDesign& d) const override { return {0, 0, d.cfg.subpixel_bits + 6}; }
  std::vector<std::string> modules(const RtlDesign&) const override {
    return {"fpstereo_subpixel", "fpstereo_subpixel_fit", "fpstereo_delay"};
  }
  std::string core_verilog(const RtlDesign& d, PixelStream&) const override {
    // With a left-right check the whole D travels in the tag (wta_whole) for the check.
    const bool whole = carries_whole(d);
    const int tag_bits = 1 + d.x_bits + d.out_row_bits + d.group_bits + (whole ? d.widths.disparity : 0);
    const std::string tag = "{whole_active, whole_x, whole_slot, whole_group" +
                            (whole ? fmt::format(", whole_word[{}:0]}}", d.widths.disparity - 1) : std::string("}"));
    const std::string o = subpixel_out(d);
    const std::string tag_out =
        fmt::format("{{{0}_active, {0}_x, {0}_slot, {0}_group", o) + (whole ? fmt::format(", {}_whole}}", o) : "}");
    return "\n  // Sub-pixel fit: the refined word, subpixel-bits + 6 steps after the whole one.\n" +
           wire(d.group_bits, o + "_group") + wire(1, o + "_active") + wire(d.x_bits, o + "_x") +
           wire(d.out_row_bits, o + "_slot") + wire(d.widths.output_word, o + "_word") +
           (whole ? wire(d.widths.disparity, o + "_whole") : std::string()) +
           instance("fpstereo_subpixel", "subpixel",
                    {{"UF", num(d.cfg.uf)},
                     {"G", num(d.groups)},
                     {"SUM_W", num(d.widths.aggregated)},
                     {"DMAX", num(d.cfg.dmax)},
                     {"DISP_W", num(d.widths.disparity)},
                     {"K", num(d.cfg.subpixel_bits)},
                     {"EQUIANGULAR", d.cfg.subpixel_fit == SubpixelFit::Equiangular ? "1" : "0"},
                     {"OUT_W", num(d.widths.output_disparity)},
                     {"TREE_LAT", num(d.wta_word_lag)},
                     {"TAG_W", num(tag_bits)}},
                    {{"clk", "clk"},
                     {"restart", "restart"},
                     {"adv", "adv"},
                     {"sums", "agg_sums"},
                     {"tag", tag},
                     {"word", "whole_word"},
                     {"tag_out", tag_out},
                     {"word_out", o + "_word"}});
  }
  // ---- HLS: select_base refines the winner as it passes (Winner::refined).
  std::string hls_calls(const RtlDesign&, HlsStreams&) const override {
    return "\n  // Sub-pixel fit: none, select_base refines the winner.\n";
  }
};

// Confidence (fpstereo_confidence): each pixel's 255 (S2 - S1) / S2 from the winner-take-all's
// sums, divided in kConfidenceSteps steps while its word waits beside; it then travels above the
// word through the disparity reorder RAM and, rows later, to the output (OutputStage).
constexpr int kConfidenceSteps = 10;
class ConfidenceStage : public Stage {
 public:
  std::string title() const override { return "confidence"; }
  std::vector<std::string> knobs() const override { return {"confidence"}; }
  Latency latency(const RtlDesign&) const override { return {0, 0, kConfidenceSteps}; }
  std::vector<std::string> modules(const RtlDesign&) const override {
    return {"fpstereo_confidence", "fpstereo_delay"};
  }
  std::string core_verilog(const RtlDesign& d, PixelStream&) const override {
    const bool whole = carries_whole(d);
    const int data_bits = 1 + d.x_bits + d.out_row_bits + d.group_bits + d.widths.output_word +
                          (whole ? d.widths.disparity : 0);
    auto data = [&](const std::string& p) {
      return fmt::format("{{{0}_active, {0}_x, {0}_slot, {0}_group, {0}_word", p) +
             (whole ? fmt::format(", {}_whole}}", p) : "}");
    };
    // The sub-pixel fit, when there, holds the words its latency after the sums.
    const int64_t waited = d.cfg.subpixel_bits != 0 ? SubpixelStage().latency(d).steps : 0;
    return "\n  // Confidence: the word waits beside the division.\n" + wire(d.group_bits, "wta_group") +
           wire(1, "wta_active") + wire(d.x_bits, "wta_x") + wire(d.out_row_bits, "wta_slot") +
           wire(d.widths.output_word, "wta_word") + (whole ? wire(d.widths.disparity, "wta_whole") : std::string()) +
           wire(kConfidenceBits, "wta_confidence") +
           instance("fpstereo_confidence", "confidence_divider",
                    {{"SUM_W", num(d.widths.aggregated)},
                     {"DATA_W", num(data_bits)},
                     {"IN_DELAY", num(waited)},
                     {"LAT", num(kConfidenceSteps)}},
                    {{"clk", "clk"},
                     {"restart", "restart"},
                     {"adv", "adv"},
                     {"best", "winner_best"},
                     {"second", "winner_second"},
                     {"data_in", data("plain")},
                     {"data_out", data("wta")},
                     {"confidence", "wta_confidence"}});
  }
  // ---- HLS: select_base computes it (Winner::confidence).
  std::string hls_calls(const RtlDesign&, HlsStreams&) const override {
    return "\n  // Confidence: none, select_base computes it.\n";
  }
};

// Disparity reorder RAM: chain order in, one word per slot in raster order out. With a
// left-right check the reads wait one (LR1) or two (LR2) more row-times for the match side.
class DisparityReorderStage : public Stage {
 public:
  std::string title() const override { return "disparity reorder"; }
  std::vector<std::string> knobs() const override { return {"lr"}; }
  std::string start_parameter() const override { return "OUT_START"; }
  Latency latency(const RtlDesign& d) const override { return {lr_rows(d), 1, 0}; }
  Latency start_offset(const RtlDesign& d) const override { return {lr_rows(d), 0, 0}; }
  std::vector<StageMemory> memories(const RtlDesign& d) const override {
    return {{"core.disparity_reorder.disp_ram.mem", d.disp_depth(), reorder_ram_bits(d)}};
  }
  std::vector<std::string> modules(const RtlDesign&) const override {
    return {"fpstereo_disparity_reorder", "fpstereo_raster_counter", "fpstereo_frame_row", "fpstereo_ram_sdp"};
  }
  std::string core_verilog(const RtlDesign& d, PixelStream& stream) const override {
    stream = {"read_done", "read_event", "read_x", "read_y", "read_word"};
    const bool confidence = d.cfg.confidence;
    return "\n  // Disparity reorder RAM, read in raster order from step OUT_START.\n" +
           start_flag(d, *this, "out_on") + stream_wires(d, stream, reorder_word_bits(d)) +
           (confidence ? wire(kConfidenceBits, "read_confidence") : std::string()) +
           unused_unless(d.cfg.lr != LrCheck::None, wire(d.out_row_bits, "read_slot_row"), "the left-right check reads with it") +
           instance("fpstereo_disparity_reorder", "disparity_reorder",
                    {{"ROW_SLOTS", num(d.row_slots)},
                     {"G", num(d.groups)},
                     {"DISP_W", num(reorder_ram_bits(d) - 1)},
                     {"OUT_ROWS", num(d.out_rows)},
                     {"OUT_K_W", num(d.out_row_bits)},
                     {"DISP_AW", num(d.disp_addr_bits)},
                     {"EXTRA_ROWS", d.cfg.gap_interpolation ? "1" : "0"},
                     {"X_W", num(d.x_bits)},
                     {"Y_W", num(d.y_bits)},
                     {"G_W", num(d.group_bits)}},
                    {{"clk", "clk"},
                     {"restart", "restart"},
                     {"adv", "adv"},
                     {"out_on", "out_on"},
                     {"overlap", "overlap"},
                     {"frame_width", "frame_width"},
                     {"frame_height", "frame_height"},
                     {"active", "wta_active"},
                     {"x", "wta_x"},
                     {"slot", "wta_slot"},
                     {"group", "wta_group"},
                     {"word", std::string(confidence ? "{wta_confidence, " : "{") +
                                  (carries_whole(d) ? "wta_word, wta_whole}" : "wta_word}")},
                     {"read_done", "read_done"},
                     {"read_event", "read_event"},
                     {"read_x", "read_x"},
                     {"read_y", "read_y"},
                     {"read_slot_row", "read_slot_row"},
                     {"read_word", confidence ? "{read_confidence, read_word}" : "read_word"}});
  }

  // ---- HLS: select_base writes raster order.
  std::string hls_calls(const RtlDesign&, HlsStreams&) const override {
    return "\n  // Disparity reorder: none, select_base writes raster order.\n";
  }

 private:
  static int lr_rows(const RtlDesign& d) { return d.cfg.lr == LrCheck::None ? 0 : d.cfg.lr == LrCheck::Lr1 ? 1 : 2; }
};

// Left-right check: three steps (the RAM reads, Dm registered, the check registered), against the
// match side's completed pixels (LR1 also its row ends).
class LrCheckStage : public Stage {
 public:
  explicit LrCheckStage(const StereoConfig& c) : row_end_(c.lr == LrCheck::Lr1) {}
  std::string title() const override { return "left-right check"; }
  std::vector<std::string> knobs() const override { return {"lr", "lr-threshold", "min-disp"}; }
  Latency latency(const RtlDesign&) const override { return {0, 0, 3}; }
  std::vector<StageMemory> memories(const RtlDesign& d) const override {
    // One lookup of Dm for the check; with the right view a second one for Dm(x).
    std::vector<StageMemory> out;
    for (const std::string lookup : {"lookup", "right_view.lookup"}) {
      if (lookup != "lookup" && !d.cfg.right_view) break;
      const std::string at = "core.lr_check." + lookup;
      out.push_back({at + ".completed.mem", d.disp_depth(), d.widths.disparity});
      if (row_end_)
        out.push_back({at + ".row_end.row_end.mem", int64_t(d.out_rows) * d.groups,
                       int64_t(d.cfg.uf) * d.widths.disparity});
    }
    return out;
  }
  std::vector<std::string> modules(const RtlDesign&) const override {
    return {"fpstereo_lr_check", "fpstereo_match_lookup", "fpstereo_ram_sdp"};
  }
  std::string core_verilog(const RtlDesign& d, PixelStream& stream) const override {
    const StereoConfig& c = d.cfg;
    const PixelStream in = stream;
    stream = {"checked_done", "checked_event", "checked_x", "checked_y", "checked_word"};
    std::string v = "\n  // Left-right check.\n" + stream_wires(d, stream) +
                    unused_unless(c.right_view, wire(d.widths.disparity, "right_dm"), "only the right view reads it");
    Values ports = {{"clk", "clk"},
                    {"restart", "restart"},
                    {"adv", "adv"},
                    {"frame_width", "frame_width"},
                    {"lr_threshold", "lr_threshold"},
                    {"completed_we", "completed_we"},
                    {"completed_waddr", "completed_waddr"},
                    {"completed_wdata", "completed_wdata"}};
    if (row_end_)
      ports.insert(ports.end(), {{"row_end_we", "row_end_we"},
                                 {"row_end_waddr", "row_end_waddr"},
                                 {"row_end_wdata", "row_end_wdata"}});
    else
      ports.insert(ports.end(), {{"row_end_we", "1'b0"},
                                 {"row_end_waddr", fmt::format("{}'d0", d.end_addr_bits)},
                                 {"row_end_wdata", fmt::format("{}'d0", c.uf * d.widths.disparity)}});
    ports.insert(ports.end(), {{"read_done", in.done},
                               {"read_event", in.event},
                               {"read_x", in.x},
                               {"read_y", in.y},
                               {"read_slot_row", "read_slot_row"},
                               {"read_word", in.word},
                               {"checked_done", stream.done},
                               {"checked_event", stream.event},
                               {"checked_x", stream.x},
                               {"checked_y", stream.y},
                               {"checked_word", stream.word},
                               {"right_word", "right_dm"}});
    return v + instance("fpstereo_lr_check", "lr_check",
                        {{"ROW_SLOTS", num(d.row_slots)},
                         {"G", num(d.groups)},
                         {"UF", num(c.uf)},
                         {"DMAX", num(c.dmax)},
                         {"DISP_W", num(d.widths.disparity)},
                         {"REFINED_W", num(carries_whole(d) ? d.widths.output_disparity : 0)},
                         {"OUT_ROWS", num(d.out_rows)},
                         {"OUT_K_W", num(d.out_row_bits)},
                         {"DISP_AW", num(d.disp_addr_bits)},
                         {"ROW_END", row_end_ ? "1" : "0"},
                         {"END_AW", num(d.end_addr_bits)},
                         {"RIGHT_VIEW", c.right_view ? "1" : "0"},
                         {"X_W", num(d.x_bits)},
                         {"Y_W", num(d.y_bits)},
                         {"LANE_W", num(d.lane_bits)},
                         {"MIN_DISP", num(c.min_disp)}},
                        ports);
  }

  // ---- HLS.
  std::string hls_calls(const RtlDesign&, HlsStreams& s) const override {
    const HlsStreams in = s;
    s = {"checked", ""};
    // Without the right view, right_view is never written.
    return "\n  // Left-right check.\n" + hls_streams("Word<C>", {s.base, "right_view"}) +
           fmt::format("  lr_check<C>({}, {}, {}, right_view, W, H, lr_threshold);\n", in.base, in.match, s.base);
  }
  // With min-disp m < 0 each row reads min(-m, W) of Dm ahead of its first D.
  HlsLoop hls_loop(const RtlDesign& d) const override {
    if (d.cfg.min_disp >= 0) return {};
    const int64_t W = d.cfg.width, H = d.cfg.height, lead = std::min<int64_t>(-d.cfg.min_disp, W);
    return {"left-right check (Dm -m pixels ahead)", "H*(W+min(-m,W))", H * (W + lead)};
  }

 private:
  bool row_end_;
};

// Median filter: its window's newest word is rm rows and rm slots past the centre; the
// selection takes three steps per word bit, and a step each for the window and the result.
class MedianStage : public Stage {
 public:
  std::string title() const override { return "median filter"; }
  std::vector<std::string> knobs() const override { return {"median"}; }
  Latency latency(const RtlDesign& d) const override {
    const int rm = d.cfg.median / 2;
    return {rm, rm, 2 + 3 * d.widths.output_word};
  }
  std::vector<StageMemory> memories(const RtlDesign& d) const override {
    return {{"core.median.line_window.line_buffer.mem", d.row_slots,
             int64_t(d.cfg.median - 1) * d.widths.output_word}};
  }
  std::vector<std::string> modules(const RtlDesign&) const override {
    return {"fpstereo_median", "fpstereo_window", "fpstereo_window_centre", "fpstereo_window_bounds",
            "fpstereo_median_select", "fpstereo_delay"};
  }
  std::string core_verilog(const RtlDesign& d, PixelStream& stream) const override {
    const PixelStream in = stream;
    stream = {"", "median_event", "median_x", "median_y", "median_word"};
    return "\n  // Median filter.\n" + stream_wires(d, stream) +
           instance("fpstereo_median", "median",
                    {{"M", num(d.cfg.median)},
                     {"ROW_SLOTS", num(d.row_slots)},
                     {"DISP_W", num(d.widths.output_disparity)},
                     {"EXTRA_ROWS", d.cfg.gap_interpolation ? "1" : "0"},
                     {"X_W", num(d.x_bits)},
                     {"Y_W", num(d.y_bits)},
                     {"YS_W", num(d.signed_y_bits)}},
                    frame_ports() + Values{{"wrapped", "wrapped"}, {"in_done", in.done}} + stream_ports(in, stream));
  }

  // ---- HLS: the median window (positions outside the image invalid) and the selection.
  std::string hls_calls(const RtlDesign&, HlsStreams& s) const override {
    const std::string in = s.base;
    s.base = "filtered";
    return "\n  // Median filter.\n" + hls_streams("Window<Word<C>, C::kMedian>", {"median_windows"}) +
           hls_streams("Word<C>", {s.base}) +
           fmt::format(
               "  window_stage<Word<C>, C::kMedian, C::kMaxWidth>({}, median_windows, W, H, "
               "Word<C>(C::kInvalidWord));\n",
               in) +
           fmt::format("  median_stage<C>(median_windows, {}, W, H);\n", s.base);
  }
  HlsLoop hls_loop(const RtlDesign& d) const override {
    return hls_window_loop(d, "median window", d.cfg.median / 2);
  }
  int hls_fill_rows(const RtlDesign& d) const override { return d.cfg.median / 2; }
};

// Gap interpolation, one row behind its input.
class GapStage : public Stage {
 public:
  std::string title() const override { return "gap interpolation"; }
  std::vector<std::string> knobs() const override { return {"gap-interp"}; }
  Latency latency(const RtlDesign&) const override { return {1, 0, 3}; }
  std::vector<StageMemory> memories(const RtlDesign& d) const override {
    return {{"core.gap.words.mem", 2 * int64_t(d.cfg.width), d.widths.output_word + d.x_bits},
            {"core.gap.right_neighbours.mem", 2 * int64_t(d.cfg.width), d.widths.output_word}};
  }
  std::vector<std::string> modules(const RtlDesign&) const override { return {"fpstereo_gap_fill"}; }
  std::string core_verilog(const RtlDesign& d, PixelStream& stream) const override {
    const PixelStream in = stream;
    stream = {"", "gap_event", "gap_x", "gap_y", "gap_word"};
    return "\n  // Gap interpolation.\n" + stream_wires(d, stream) +
           instance("fpstereo_gap_fill", "gap",
                    {{"W", num(d.cfg.width)},
                     {"WORD_W", num(d.widths.output_word)},
                     {"X_W", num(d.x_bits)},
                     {"Y_W", num(d.y_bits)}},
                    frame_ports() + Values{{"wrapped", "wrapped"}, {"in_event", in.event}} + stream_ports(in, stream));
  }

  // ---- HLS: one row behind its input.
  std::string hls_calls(const RtlDesign&, HlsStreams& s) const override {
    const std::string in = s.base;
    s.base = "filled";
    return "\n  // Gap interpolation.\n" + hls_streams("Word<C>", {s.base}) +
           fmt::format("  gap_fill<C>({}, {}, W, H);\n", in, s.base);
  }
  int hls_fill_rows(const RtlDesign&) const override { return 1; }
};

// An output register: the stream's word with its first and last flags, pushed in the step after
// its event (the sequencer stalls while the output register slice is full). `prefix`_due is the
// sequencer's input; the core's ports are `prefix`_push, _word, _first and _last.
std::string output_register(const std::string& prefix, const PixelStream& stream, const std::string& event,
                            const std::string& word, int word_bits) {
  return fmt::format(
      "  reg {0}_event_q, {0}_first_q, {0}_last_q;\n"
      "  reg [{5}:0] {0}_word_q;\n"
      "  always @(posedge clk)\n"
      "    if (restart) {0}_event_q <= 1'b0;\n"
      "    else if (adv) {0}_event_q <= {1};\n"
      "  always @(posedge clk)\n"
      "    if (adv) begin\n"
      "      {0}_word_q <= {4};\n"
      "      {0}_first_q <= {2} == 0 && {3} == 0;\n"
      "      {0}_last_q <= {2} == frame_width - 1'b1;\n"
      "    end\n"
      "  assign {0}_due    = {0}_event_q;\n"
      "  assign {0}_push   = adv && {0}_event_q;\n"
      "  assign {0}_word   = {0}_word_q;\n"
      "  assign {0}_first  = {0}_first_q;\n"
      "  assign {0}_last   = {0}_last_q;\n",
      prefix, event, stream.x, stream.y, word, word_bits - 1);
}

// Right view (with right-view): the left-right check's Dm(x) at each pixel x of its stream, the
// right image's disparity, to a second output stream (m_axis_disp_right). Beside the stream: the
// main output is at least as late, so the frame ends with the main output's last push.
class RightViewStage : public Stage {
 public:
  std::string title() const override { return "right view"; }
  std::vector<std::string> knobs() const override { return {"right-view"}; }
  Latency latency(const RtlDesign&) const override { return {}; }
  std::vector<std::string> modules(const RtlDesign&) const override { return {}; }
  std::string core_verilog(const RtlDesign& d, PixelStream& stream) const override {
    // With a median or gap interpolation the stream runs rows past the frame (their lookahead):
    // rows below the frame, or once the rows wrap (back-to-back frames) the next frame's rows,
    // which are real only if that frame follows on (continuing, known since the input passed
    // the frame's end, rows earlier).
    const std::string view = "\n  // Right view: Dm(x) registered, pushed to its own output in the next step.\n";
    if (d.cfg.median == 0 && !d.cfg.gap_interpolation)
      return view + output_register("view", stream, stream.event, "right_dm", d.widths.disparity);
    return view +
           fmt::format(
               "  reg view_beyond;  // past the frame's last pixel, and no frame follows\n"
               "  always @(posedge clk)\n"
               "    if (restart) view_beyond <= 1'b0;\n"
               "    else if (adv && {0} && {1} == frame_width - 1'b1 && {2} == frame_height - 1'b1)\n"
               "      view_beyond <= !continuing;\n",
               stream.event, stream.x, stream.y) +
           output_register("view", stream,
                           fmt::format("{} && {} < frame_height && !view_beyond", stream.event, stream.y),
                           "right_dm", d.widths.disparity);
  }
  // ---- HLS: lr_check writes the right view's words.
  std::string hls_calls(const RtlDesign&, HlsStreams&) const override {
    return "\n  // Right view.\n  write_words<C>(right_view, right_out, W, H);\n";
  }
};

// Output: one register stage, so that what the sequencer's enable depends on (out_due,
// frame_done) comes from flip-flops; each pixel's word is pushed in the step after its stream
// event. The frame ends with its last pixel; the core is idle for one cycle, and the next frame's
// step 0 comes two cycles after its start (fpstereo_sequencer).
class OutputStage : public Stage {
 public:
  std::string title() const override { return "output"; }
  std::vector<std::string> knobs() const override { return {}; }
  Latency latency(const RtlDesign&) const override { return {0, 0, 1 + kStepsAfterPush}; }
  std::vector<std::string> modules(const RtlDesign& d) const override {
    if (confidence_rows(d) != 0) return {"fpstereo_axis_skid", "fpstereo_confidence_rows", "fpstereo_ram_sdp"};
    return {"fpstereo_axis_skid"};
  }
  std::vector<StageMemory> memories(const RtlDesign& d) const override {
    if (!confidence_rows(d)) return {};
    return {{"core.confidence_rows.confidences.mem", int64_t(confidence_rows(d)) * d.cfg.width, kConfidenceBits}};
  }
  std::string core_verilog(const RtlDesign& d, PixelStream& stream) const override {
    return "\n  // Output: registered, so that the sequencer's inputs are flip-flops.\n" +
           output_register("out", stream, stream.event, stream.word, d.widths.output_word) +
           (d.cfg.confidence ? confidence_verilog(d, stream) : std::string()) +
           fmt::format(
               "  reg frame_done_q;\n"
               "  always @(posedge clk)\n"
               "    if (restart) frame_done_q <= 1'b0;\n"
               "    else if (adv) frame_done_q <= {0} && {1} == frame_width - 1'b1 && {2} == frame_height - 1'b1;\n"
               "  assign frame_done = frame_done_q;\n"
               "  assign frame_end  = adv && frame_done;\n",
               stream.event, stream.x, stream.y);
  }

  // ---- HLS: the words into the output video stream, with confidence each above its word.
  std::string hls_calls(const RtlDesign& d, HlsStreams& s) const override {
    if (d.cfg.confidence)
      return fmt::format("\n  // Output.\n  write_confident_words<C>({}, confidences, out, W, H);\n", s.base);
    return fmt::format("\n  // Output.\n  write_words<C>({}, out, W, H);\n", s.base);
  }

 private:
  // Rows of confidences between the disparity reorder RAM and the output: more than the rows the
  // median and gap interpolation delay the stream; none when nothing but the check lies between.
  static int confidence_rows(const RtlDesign& d) {
    if (!d.cfg.confidence || (d.cfg.median == 0 && !d.cfg.gap_interpolation && d.cfg.lr == LrCheck::None)) return 0;
    return d.cfg.median / 2 + (d.cfg.gap_interpolation ? 1 : 0) + 2;
  }
  // The pixel's confidence beside its word, registered with it.
  static std::string confidence_verilog(const RtlDesign& d, const PixelStream& stream) {
    const int rows = confidence_rows(d);
    if (rows == 0)
      return "  reg [7:0] out_confidence_q;\n"
             "  always @(posedge clk)\n"
             "    if (adv) out_confidence_q <= read_confidence;\n"
             "  assign out_confidence = out_confidence_q;\n";
    const int row_bits = bits_for(uint64_t(rows - 1));
    return instance("fpstereo_confidence_rows", "confidence_rows",
                    {{"W", num(d.cfg.width)},
                     {"ROWS", num(rows)},
                     {"ROW_K_W", num(row_bits)},
                     {"AW", num(bits_for(uint64_t(rows) * d.cfg.width - 1))},
                     {"X_W", num(d.x_bits)}},
                    {{"clk", "clk"},
                     {"restart", "restart"},
                     {"adv", "adv"},
                     {"frame_width", "frame_width"},
                     {"in_event", "read_event"},
                     {"in_x", "read_x"},
                     {"in_confidence", "read_confidence"},
                     {"out_event", stream.event},
                     {"out_x", stream.x},
                     {"out_confidence", "out_confidence"}});
  }
};

}  // namespace

std::vector<StagePtr> pipeline_stages(const StereoConfig& c) {
  std::vector<StagePtr> stages = {std::make_shared<FramingStage>(), std::make_shared<WindowStage>(c),
                                  std::make_shared<CostStage>(c), std::make_shared<CostReorderStage>()};
  if (c.lr == LrCheck::Lr2) stages.push_back(std::make_shared<Lr2MatchStage>());
  stages.push_back(std::make_shared<AggregationStage>());
  if (c.lr == LrCheck::Lr1) stages.push_back(std::make_shared<Lr1MatchStage>());
  stages.push_back(std::make_shared<WtaStage>(c));
  if (c.subpixel_bits != 0) stages.push_back(std::make_shared<SubpixelStage>());
  if (c.confidence) stages.push_back(std::make_shared<ConfidenceStage>());
  stages.push_back(std::make_shared<DisparityReorderStage>());
  if (c.lr != LrCheck::None) stages.push_back(std::make_shared<LrCheckStage>(c));
  if (c.right_view) stages.push_back(std::make_shared<RightViewStage>());
  if (c.median != 0) stages.push_back(std::make_shared<MedianStage>());
  if (c.gap_interpolation) stages.push_back(std::make_shared<GapStage>());
  stages.push_back(std::make_shared<OutputStage>());
  return stages;
}

}  // namespace fpstereo::rtl
