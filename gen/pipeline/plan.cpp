#include "plan.hpp"

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "stage_list.hpp"

namespace fpstereo::rtl {
namespace {

int ceil_div(int64_t a, int64_t b) { return int((a + b - 1) / b); }

// floor(s / divisor) == (s * mul) >> shift for every s in 0 .. max_value: the smallest shift
// whose rounded-up reciprocal is exact over the range (checked exhaustively).
std::pair<uint64_t, int> reciprocal(uint64_t divisor, uint64_t max_value) {
  for (int shift = 0; shift < 48; ++shift) {
    const uint64_t mul = ((uint64_t(1) << shift) + divisor - 1) / divisor;
    bool exact = true;
    for (uint64_t v = 0; v <= max_value && exact; ++v) exact = (v * mul) >> shift == v / divisor;
    if (exact) return {mul, shift};
  }
  throw std::logic_error("no exact reciprocal");
}

// The hardware's own rules beyond validate()'s.
void check_hardware_rules(const StereoConfig& cfg, RtlOptions::Target target) {
  validate(cfg);
  // One-pass MGM lost accuracy to SGM on every dataset (docs/accuracy.md, "MGM-style
  // aggregation"), so the aggregator keeps one predecessor per path.
  if (cfg.mgm) throw ConfigError("mgm = on: not in the hardware generators (the models have it)");
  // The speckle filter's module takes a word once in 4 clocks (docs/speckle-hardware.md).
  if (cfg.speckle_size != 0 && cfg.dmax / cfg.uf < kSpeckleClocksPerWord)
    throw ConfigError("speckle-size = " + std::to_string(cfg.speckle_size) + ": the speckle filter's stage needs dmax / uf >= " +
                      std::to_string(kSpeckleClocksPerWord) + " (" + std::to_string(cfg.dmax / cfg.uf) +
                      "); use a smaller uf or speckle-size 0");
  // A search range wider than the row searches nothing: the hardware keeps LR2's match side
  // (dmax + min-disp slots behind) and the offset's delays within a row-time.
  if (cfg.dmax + std::abs(cfg.min_disp) > cfg.width)
    throw ConfigError("min-disp = " + std::to_string(cfg.min_disp) + ": the hardware generators need dmax + |min-disp| <= width (" +
                      std::to_string(cfg.dmax + std::abs(cfg.min_disp)) + " > " + std::to_string(cfg.width) + ")");
  // The 180-degree path: the HLS kernels take it wherever the models do, the Verilog at one pixel
  // a clock beside a raster-order path (docs/path180-hardware.md).
  if ((cfg.paths & kPath180) && target == RtlOptions::Target::Verilog) {
    const std::string paths = "paths = " + paths_to_string(cfg.paths) + ": ";
    if (cfg.ppc != 1)
      throw ConfigError(paths + "the Verilog generator has the 180-degree path at ppc 1 so far (the models have it at any ppc); drop 180");
    if ((cfg.paths & kAllPaths) == 0)
      throw ConfigError(paths + "the Verilog generator needs a raster-order path beside the 180-degree one");
    if (cfg.p2_adapt != 0 && !(cfg.paths & kPath0))
      throw ConfigError(paths + "with p2-adapt the Verilog's 180-degree path takes the 0-degree path's P2: add 0");
  }
}

// LR2's match side in strips holds a row's prefix from the row's slot ceil((m + dmax - 1) / P)
// (its min-disp is -(m + dmax - 1), lr2_match_min_disp), which must lie in the row: rows of
// dmax + |m| + P - 1 pixels at least (not dmax + |m|). (Its window costs, which have no prefix,
// keep the one rule.)
int lr2_strip_min_width(const StereoConfig& c) { return c.dmax + std::abs(c.min_disp) + c.ppc - 1; }

// Whether the core takes ppc pixels a clock in strips (docs/ppc-hardware.md) for this
// configuration: every cost function (SHD over windows of more than one code) with every option
// the hardware takes at ppc > 1 (not the speckle filter, which needs uf < dmax), LR2 in rows of
// lr2_strip_min_width. Elsewhere ppc > 1 converts beats to pixels around the one-pixel core.
bool strip_options(const StereoConfig& c) {
  if (c.ppc == 1 || (c.cost == CostFunction::Shd && c.shd_window == 1)) return false;
  return c.lr != LrCheck::Lr2 || c.width >= lr2_strip_min_width(c);
}

}  // namespace

int min_tree_latency(int n, int levels_per_stage) {
  const int levels = clog2(n);
  return std::max(1, ceil_div(levels, levels_per_stage));
}

Geometry plan_geometry(const StereoConfig& cfg, const RtlOptions& options) {
  check_hardware_rules(cfg, options.target);
  Geometry g;
  g.cfg = cfg;
  g.options = options;
  // The smallest run-time size the golden model accepts with this dmax (config.cpp, validate),
  // and a row that holds the whole search range (above).
  g.min_width = std::max(8, strip_options(cfg) && cfg.lr == LrCheck::Lr2 ? lr2_strip_min_width(cfg)
                                                                          : cfg.dmax + std::abs(cfg.min_disp));
  g.min_width += (cfg.ppc - g.min_width % cfg.ppc) % cfg.ppc;  // rows are whole beats
  g.min_height = 4;
  g.widths = derive_widths(cfg);
  g.prefix = config_tag(cfg);
  g.window_radius = cfg.window / 2;
  const bool point_cost = cfg.cost == CostFunction::Census || cfg.cost == CostFunction::Rank;
  g.cost_window = point_cost ? 1 : cfg.cost == CostFunction::Shd ? cfg.shd_window : cfg.window;
  g.window_fill_rows = (cfg.cost == CostFunction::Sad ? 0 : g.window_radius) + g.cost_window / 2;
  g.transform_slots = cfg.cost == CostFunction::Rank ? 2 : 1;
  g.groups = cfg.dmax / cfg.uf;
  // The cost lanes' register steps: fpstereo_cost_lanes 2; fpstereo_window_cost_lanes 4, with
  // four more for ZSAD (the masked column sums, the match window's sum, its mean, the means'
  // difference).
  const bool windowed_cost = cfg.cost == CostFunction::Sad || cfg.cost == CostFunction::Zsad ||
                             (cfg.cost == CostFunction::Shd && cfg.shd_window > 1);
  // Census codes of more than 8 chunks of 6 bits sum their counts in sets first (one step more).
  const bool long_codes = !windowed_cost && cfg.cost != CostFunction::Rank && g.widths.code > 48;
  g.cost_lanes_latency = !windowed_cost ? (long_codes ? 3 : 2) : cfg.cost == CostFunction::Zsad ? 8 : 4;
  // The fused cost's term takes three steps beside the lanes, then one to add (fpstereo_fused_term).
  constexpr int kFusedTermSteps = 3;
  g.cost_latency = cfg.fused_weight == 0 ? g.cost_lanes_latency : std::max(g.cost_lanes_latency, kFusedTermSteps) + 1;
  g.column_sum_bits = bits_for(255u * uint64_t(cfg.window));
  const uint64_t n = uint64_t(cfg.window) * uint64_t(cfg.window);
  std::tie(g.mean_mul, g.mean_shift) =
      cfg.cost == CostFunction::Zsad ? reciprocal(n, 255 * n) : std::pair<uint64_t, int>{1, 0};
  g.path_tree_latency = min_tree_latency(cfg.uf, g.levels_per_stage);
  g.wta_tree_latency = min_tree_latency(cfg.uf, g.levels_per_stage);
  g.unique_tree_latency = min_tree_latency(cfg.uf, Geometry::kUniqueLevelsPerStage);
  g.finds_second_best = cfg.uniqueness != 0 || cfg.confidence;
  g.wta_word_lag = g.finds_second_best ? g.unique_tree_latency + Geometry::kUniqueWordSteps : g.wta_tree_latency;
  g.subpixel_steps = cfg.subpixel_bits != 0 ? cfg.subpixel_bits + 6 : 0;
  // D = S + 2 + ceil(S / 4) at a word every 4 clocks (docs/speckle-hardware.md, "Why it is bounded").
  g.speckle_rows = cfg.speckle_size != 0
                       ? cfg.speckle_size + 2 + ceil_div(cfg.speckle_size, kSpeckleClocksPerWord)
                       : 0;
  // A chain's next pixel must find the previous pixel's minimum finished: the last group, the
  // path lanes (two steps, fpstereo_path_lanes), the tree and the running minimum take
  // G - 1 + 2 + latency + 1 steps; K chains give it K * G (fpstereo_aggregator checks it).
  constexpr int kPathLanesLatency = 2;
  g.chains = std::max(2, 1 + ceil_div(g.path_tree_latency + kPathLanesLatency, g.groups));
  // Segments need at least 3 pixels (docs/architecture.md); width >= dmax gives it, as K <= 5
  // where dmax < 128 (width >= 16) and K <= 6 otherwise.
  g.segment = ceil_div(cfg.width, g.chains);
  g.row_slots = g.chains * g.segment;
  if (strip_options(cfg)) {
    // P strips of R = K * SEG pixels, R a multiple of P (a slot in one strip), the last strip
    // not empty; a row-time is R steps. More chains than the minimum may give a row-time nearer
    // W / P (4K at 128 disparities: 1920 with eight chains, 1932 with seven).
    const int P = cfg.ppc, fewest = g.chains;
    for (int K = fewest + 3; K >= fewest; --K) {
      int seg = ceil_div(cfg.width, int64_t(P) * K);
      while ((int64_t(K) * seg) % P != 0) ++seg;
      const bool fits = int64_t(P - 1) * K * seg < cfg.width && seg >= 3;  // segments of 3 pixels at least
      if (fits && (g.strips == 1 || K * seg <= g.row_slots)) {
        g.strips = P;
        g.chains = K;
        g.segment = seg;
        g.row_slots = K * seg;
      }
    }
  }
  if (g.strips > 1) {
    // A slot takes a beat: the row-time's spare slots are R - W / P.
    g.follow_wait = std::max(0, kFollowCycles - (g.row_slots - cfg.width / g.strips));
  } else if (g.groups == 1) {
    // With P pixels a beat the framing stage is done with a frame as its last beat enters the
    // beat register, P - 1 pixels before the core takes the last: the wait is that much shorter.
    g.follow_wait = std::max(0, kFollowCycles - (cfg.ppc - 1) - (g.row_slots - cfg.width));
  }
  // In strips a row is read once every strip has finished it, its match side's Dm with it: the
  // reads wait no rows more for the check.
  g.lr_rows = cfg.lr == LrCheck::None || g.strips > 1 ? 0 : cfg.lr == LrCheck::Lr1 ? 1 : 2;
  // With the 180-degree path the forward chains run K + 2 row-times later (docs/path180-hardware.md),
  // and the cost RAM keeps their rows too: the row being written, the mirrored chains' K and the
  // forward chains' K, and one row-time for the mirrored pipeline's last writes.
  g.right_to_left = (cfg.paths & kPath180) != 0;
  g.raster_paths = cfg.paths & kAllPaths;
  g.raster_path_count = cfg.path_count() - (g.right_to_left ? 1 : 0);
  g.forward_lag = g.right_to_left ? g.chains + 2 : 0;
  g.cost_rows = g.chains + g.forward_lag + (cfg.lr == LrCheck::Lr2 ? 1 : 0);
  g.out_rows = g.chains + 1 + g.lr_rows;
  if (g.strips > 1) {
    // The strips' RAMs: strip s's code RAM (s + 1) * K rows, its disparity RAM (P - s) * K + 1;
    // the widths of the largest.
    g.cost_rows = g.strips * g.chains;
    g.out_rows = g.strips * g.chains + 1;
    g.slot_rows = 1;
    for (int s = 1; s <= g.strips; ++s) g.slot_rows = std::lcm(g.slot_rows, s * g.chains);
  }
  g.carries_whole = cfg.subpixel_bits != 0 && cfg.lr != LrCheck::None;
  g.reorder_word_bits = g.widths.output_word + (g.carries_whole ? g.widths.disparity : 0);
  g.reorder_ram_bits = g.reorder_word_bits + (cfg.confidence ? kConfidenceBits : 0);
  g.penalty_bits = cfg.p2_adapt != 0 ? g.raster_path_count * g.widths.path_cost : 0;
  g.cost_word_bits = cfg.uf * g.widths.cost + g.penalty_bits;
  // LR2's match side reads cost words at one pixel a clock (fpstereo_lr2_match's lane banks), and
  // entries of its own in strips (code entries, or its own window costs' words).
  // The 180-degree path's mirrored aggregator reads cost words too.
  g.reorders_codes = point_cost && (cfg.lr != LrCheck::Lr2 || g.strips > 1) && !g.right_to_left;
  if (g.reorders_codes) {
    g.code_entry_bits = std::max(1, g.widths.code) + (cfg.fused_weight != 0 ? g.widths.fused_feature : 0);
    g.cost_lead = 2 + g.cost_latency;
  }
  g.output_bits = g.widths.output_lane + (cfg.confidence ? kConfidenceBits : 0);
  const int64_t R = g.row_slots, G = g.groups;
  g.x_bits = bits_for(uint64_t(R) * g.strips);  // with strips, a pixel's x across the P strips
  g.group_bits = bits_for(uint64_t(G - 1));
  g.chain_bits = bits_for(uint64_t(g.chains - 1));
  g.lane_bits = std::max(1, clog2(cfg.uf));
  g.cost_row_bits = clog2(g.strips > 1 ? g.slot_rows : g.cost_rows);
  g.out_row_bits = clog2(g.out_rows);
  g.cost_addr_bits = clog2(g.cost_depth());
  g.disp_addr_bits = clog2(g.disp_depth());
  g.end_addr_bits = clog2(int64_t(g.out_rows) * G);
  return g;
}

std::vector<OutputStream> output_streams(const Geometry& g) {
  const StereoConfig& c = g.cfg;
  const Widths& w = g.widths;
  OutputStream disparity{"m_axis_disp", "out", "the disparity words", g.output_bits, c.ppc,
                         {{{"out_word", 0, w.output_word}, "disparity", 16}}, {}};
  if (c.subpixel_bits != 0) disparity.fields.push_back({"fraction", 0, c.subpixel_bits});
  disparity.fields.push_back({"disparity", c.subpixel_bits, w.output_disparity - c.subpixel_bits});
  disparity.fields.push_back({"invalid", w.output_disparity, 1});
  if (c.confidence) {
    disparity.words.push_back({{"out_confidence", w.output_lane, kConfidenceBits, Plane::Confidence}, "confidence", 8});
    disparity.fields.push_back({"confidence", w.output_lane, kConfidenceBits, Plane::Confidence});
  }
  std::vector<OutputStream> streams = {disparity};
  // The right view: the match side's whole disparities, in raster order of the right image.
  if (c.right_view)
    streams.push_back({"m_axis_disp_right", "view", "the right view's whole disparities", 8, c.ppc,
                       {{{"view_word", 0, w.disparity, Plane::Right}, "right_disparity", 16}},
                       {{"disparity", 0, w.disparity, Plane::Right}}});
  return streams;
}

RtlDesign plan(const StereoConfig& cfg, const RtlOptions& options) {
  RtlDesign d;
  static_cast<Geometry&>(d) = plan_geometry(cfg, options);
  // The schedule: the stages' latencies summed in data order (docs/architecture.md, "Stages").
  // A stage's own schedule starts start_offset after its input; the step that pushes pixel
  // (x, y) is (y * R + x) * G steps after the one that pushes pixel (0, 0).
  d.stages = pipeline_stages(cfg);
  const int64_t R = d.row_slots, G = d.groups;
  int64_t at = 0;
  for (const auto& stage : d.stages) {
    if (!stage->start_parameter().empty())
      d.start_steps[stage->start_parameter()] = at + stage->start_offset(d).in_steps(R, G);
    at += stage->latency(d).in_steps(R, G);
  }
  // The output stage is the last: its latency ends with the kStepsAfterPush from the push of
  // pixel (0, 0) on.
  const int64_t push_first = at - kStepsAfterPush;
  // The step that takes the frame's last pixel (with strips, its last slot's).
  const int64_t last_pixel = (int64_t(cfg.height) - 1) * R + cfg.width / d.strips - 1;
  // Beats split into pixels for the core that takes a pixel a step (fpstereo_beat_split).
  const bool splits_beats = cfg.ppc > 1 && d.strips == 1;
  // Back-to-back frames (docs/architecture.md): the next frame's rows follow this frame's when the
  // frame is taller than the drain by two row-times (every stage's lag then lies within one frame,
  // and a frame is done before the one after the next begins). Such a frame waits follow_wait
  // cycles at its end for the next one, whether it comes or not.
  d.overlap_height = int(ceil_div(push_first, R * G) + 2);
  const bool follows_on = cfg.height >= d.overlap_height;
  d.lone_frame_cycles = at + last_pixel * G + (splits_beats ? kBeatSplitCycles : 0) + (follows_on ? d.follow_wait : 0);
  d.cycles_per_frame = follows_on ? int64_t(cfg.height) * R * G + d.follow_wait : d.lone_frame_cycles;
  // At the ports: the input register slice, the cycle in which the framing stage starts the core
  // and the one in which the sequencer starts (step 0 follows), and the output register slice.
  // With several pixels per beat, the beat's register (fpstereo_beat_split), and the output beat
  // leaves with its last pixel, (ppc - 1) slots after its first.
  d.first_output_latency = push_first + 4 + (splits_beats ? kBeatSplitCycles + (cfg.ppc - 1) * G : 0);
  d.extra_cycles = d.cycles_per_frame - int64_t(cfg.width) * cfg.height * G / d.strips;
  d.y_bits = bits_for(uint64_t(ceil_div(d.lone_frame_cycles, R * G) + 2));
  d.signed_y_bits = d.y_bits + 2;
  d.step_bits = bits_for(uint64_t(d.lone_frame_cycles + 16));
  return d;
}

}  // namespace fpstereo::rtl
