#include "resource_model.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "synth_command.hpp"
#include "widths.hpp"

namespace fpstereo::dse {
namespace {

// ---- memories ----------------------------------------------------------------------------------

// ---- Yosys 0.23 memory_libmap for xcup ------------------------------------------------------------
// brams_xc4v.txt with HAS_SIZE_36, HAS_CASCADE and HAS_MIXWIDTH_SDP, lutrams_xcu.txt, and the
// cost rules of passes/memory/memory_libmap.cc (handle_geom): per option and base width, the
// cells needed (repl), plus 0.5 per read-mux input bit and write-demux output when the depth is
// split, plus 2 per emulation point (one: the read port is not shared with the write port).
// Ties keep the option listed first. A memory becomes FFs unless some option costs less than its
// bit count.

struct RamOption {
  int abits;
  std::vector<int> dbits;
  int cost;
  int bram18_cells, bram36_cells;  // per replicated cell
};

constexpr double kMuxFactor = 0.5, kDemuxFactor = 0.5, kEmulation = 2.0;

// Block RAM options in library order: TDP half/full/cascade, then SDP half/full. The cascade mode's
// ports are one bit wide ("width mix 1"), so it only ever holds 64K x 1.
const std::vector<RamOption>& block_options() {
  static const std::vector<RamOption> options = {
      {14, {1, 2, 4, 9, 18}, 129, 1, 0},     {15, {1, 2, 4, 9, 18, 36}, 257, 0, 1},     {16, {1}, 513, 0, 2},
      {14, {1, 2, 4, 9, 18, 36}, 129, 1, 0}, {15, {1, 2, 4, 9, 18, 36, 72}, 257, 0, 1},
  };
  return options;
}

struct Choice {
  double cost = std::numeric_limits<double>::infinity();
  int64_t cells = 0;
  int64_t deep = 1;  // cells the depth is split over (mult_a)
  const RamOption* option = nullptr;
};

int64_t ceil_div(int64_t a, int64_t b) { return (a + b - 1) / b; }

// Split cost terms shared by block and distributed RAM.
double split_cost(int64_t mult_a, int64_t bits) {
  if (mult_a == 1) return 0;
  return kMuxFactor * double((mult_a - 1) * bits) + kDemuxFactor * double(mult_a);
}

Choice best_block(int64_t words, int64_t bits) {
  Choice best;
  for (const RamOption& o : block_options())
    for (size_t b = 0; b < o.dbits.size(); ++b) {
      const int64_t unit = o.dbits[b];
      const int64_t byte = std::min<int64_t>(9, unit);  // "byte 9", or the unit when narrower
      const int64_t swizzle = ceil_div(bits, byte) * byte;
      const int64_t mult_a = ceil_div(words, int64_t(1) << (o.abits - int(b)));
      const int64_t repl = ceil_div(mult_a * swizzle, unit);
      const double cost = double(o.cost) * double(repl) + split_cost(mult_a, bits) + kEmulation;
      if (cost < best.cost) best = {cost, repl, mult_a, &o};
    }
  return best;
}

// Distributed RAM with a widthscale cost: 16 per LUT-width of data (integer division, as Yosys).
Choice best_distributed(int64_t words, int64_t bits) {
  struct Lutram {
    int abits, width;
  };
  // SDP (one write, one read port) 32 x 14 and 64 x 7; DP 32 x 8 .. 256 x 1.
  static const Lutram options[] = {{5, 14}, {6, 7}, {5, 8}, {6, 4}, {7, 2}, {8, 1}};
  Choice best;
  for (const Lutram& o : options) {
    const int64_t mult_a = ceil_div(words, int64_t(1) << o.abits);
    const double cost = double(16 * mult_a * bits / o.width) + split_cost(mult_a, bits) + kEmulation;
    if (cost < best.cost) best = {cost, 0, mult_a, nullptr};
  }
  return best;
}

}  // namespace

std::vector<MemoryEstimate> design_memories(const rtl::RtlDesign& d) {
  std::vector<MemoryEstimate> out;
  for (const auto& stage : d.stages)
    for (const auto& memory : stage->memories(d)) {
      MemoryEstimate m;
      m.name = memory.name;
      m.words = memory.words;
      m.bits = memory.bits;
      m.sync_read = memory.sync_read;
      map_memory(m);
      out.push_back(m);
    }
  return out;
}

void map_memory(MemoryEstimate& m) {
  const double logic = double(m.words * m.bits);
  const Choice lutram = best_distributed(m.words, m.bits);
  const Choice block = m.sync_read ? best_block(m.words, m.bits) : Choice{};
  m.bram18 = m.bram36 = 0;
  m.read_mux_bits = 0;
  if (block.cost < lutram.cost && block.cost < logic) {
    m.target = "bram";
    m.bram18 = int(block.cells * block.option->bram18_cells);
    m.bram36 = int(block.cells * block.option->bram36_cells);
    m.read_mux_bits = (block.deep - 1) * m.bits;
  } else if (lutram.cost < logic) {
    m.target = "lutram";
    m.read_mux_bits = (lutram.deep - 1) * m.bits;
  } else {
    m.target = "ff";
  }
}

// ---- LUT, FF, DSP ----------------------------------------------------------------------------------

const std::vector<std::string>& feature_names() {
  static const std::vector<std::string> names = {"top/control",
                                                 "path lanes",
                                                 "code cost lanes",
                                                 "pixel cost lanes",
                                                 "match ring",
                                                 "transform",
                                                 "median",
                                                 "LR1",
                                                 "LR2",
                                                 "ZSAD lanes",
                                                 "second best",
                                                 "winner-take-all tree",
                                                 "confidence",
                                                 "sub-pixel",
                                                 "adaptive P2",
                                                 "right view",
                                                 "gap interpolation",
                                                 "memory read multiplexers",
                                                 "aggregation registers",
                                                 "cost registers",
                                                 "winner-take-all registers",
                                                 "median registers",
                                                 "sub-pixel registers",
                                                 "check and gap registers",
                                                 "window cost lanes",
                                                 "speckle filter",
                                                 "fused term",
                                                 "speckle registers"};
  return names;
}

namespace {

// ---- register bits, counted from the plan as the stages' Verilog declares them -----------------
// Most flip-flops are pipeline registers whose width and depth the plan fixes; these counts are
// the FF terms (Yosys removes a few bits and merges equal registers, which the fitted
// coefficient absorbs). Shift registers without a reset and without taps become SRL LUTs and
// are not counted.

// Nodes of fpstereo_reduction_tree's registered levels over n leaves: every levels_per_stage-th
// level and the root.
double tree_register_nodes(int n, int levels_per_stage) {
  const int levels = clog2(n);
  double nodes = 0;
  for (int l = 0; l <= levels; ++l)
    if (l == levels || (l > 0 && l % levels_per_stage == 0)) nodes += double((n + (1 << l) - 1) >> l);
  return nodes;
}

// fpstereo_aggregator, its fpstereo_path_lanes and fpstereo_path_minimum per path. The lanes'
// copies of the cost word are one register after Yosys merges them.
double aggregator_registers(const rtl::RtlDesign& d, int penalty_bits) {
  const StereoConfig& c = d.cfg;
  const double uf = c.uf, paths = c.path_count(), pw = d.widths.path_cost;
  const double costs = uf * d.widths.cost;
  const bool path0 = (c.paths & kPath0) != 0, path45 = (c.paths & kPath45) != 0;
  // per path: the lanes' neighbour and stay candidates (one bit wider), the path costs, the
  // predecessor's minimum and flag; the minimum tree's registered nodes (their lane index is
  // unused) and its running minimum
  const double lanes = paths * (2 * uf * (pw + 1) + uf * pw + pw + 1);
  const double minima = paths * (tree_register_nodes(c.uf, d.levels_per_stage) + 1) * pw;
  // the predecessors' lanes held for the 45, 90 and 135 degree paths, the lanes d - 1 and the
  // minima beside them, and the per-chain minima of the 0 and 45 degree paths
  const double predecessors = (paths - (path0 ? 1 : 0)) * uf * pw + paths * 2 * pw +
                              ((path0 ? 1 : 0) + (path45 ? 1 : 0)) * d.chains * pw;
  // the tag S1 .. S5 and its delay to the minima; the schedule's counters
  const double tag = 1 + d.x_bits + (d.y_bits + 1) + d.group_bits + d.chain_bits + d.out_row_bits;
  const double tags = (4 + d.path_tree_latency) * tag + d.group_bits + 2 * d.chain_bits + d.x_bits +
                      d.cost_row_bits + d.out_row_bits;
  return lanes + minima + predecessors + 2 * costs + penalty_bits + uf * d.widths.aggregated + tags;
}

// fpstereo_wta (the plain minimum tree) or fpstereo_wta_unique (the tree of best and second best,
// registered after each join, then the group join and the test's registers), with the word's tag
// delayed beside them.
double winner_registers(const rtl::RtlDesign& d, bool second_best, double tag) {
  const double sum = d.widths.aggregated, disp = d.widths.disparity;
  if (!second_best)
    return tree_register_nodes(d.cfg.uf, d.levels_per_stage) * (sum + d.lane_bits) +
           d.wta_tree_latency * (tag + d.group_bits) + sum + disp;
  const double summary = 5 * sum + d.lane_bits + 2;  // best, all, but first, but last, second
  const double product = sum + 8;                    // a sum times the percentage
  return tree_register_nodes(d.cfg.uf, rtl::Geometry::kUniqueLevelsPerStage) * summary +
         (d.unique_tree_latency + rtl::Geometry::kUniqueWordSteps) * (tag + d.group_bits) +
         (5 * sum + disp + 2) + 8 + 2 * product + 4 * sum + 2 * disp + 3;
}

// The LUT term of the RAMs whose depth is split over several cells: their read multiplexers.
double memory_read_mux_bits(const rtl::RtlDesign& d) {
  double bits = 0;
  for (const MemoryEstimate& m : design_memories(d)) bits += double(m.read_mux_bits);
  return bits;
}

// fpstereo_point_cost (census, rank): the match ring, each lane's Hamming chunk counts (census)
// or difference (rank), its border flag and cost; the window-cost lanes of SAD, ZSAD and SHD
// are a term of their own. Then the transform's two codes, the front end's two pixel windows
// and the cost reorder's tag beside the cost latency; or, where the reorder RAM holds codes
// (fpstereo_chain_cost), the K - 1 rings waiting for their chains, the held base entry, the
// schedule's two steps and the aggregator's tag beside the cost lead. A queue of three or more
// waiting rings is a shift register that synth_xilinx maps to SRLs (shregmap -minlen 3): LUTRAM,
// no flip-flops.
double cost_registers(const rtl::RtlDesign& d, double ring) {
  const StereoConfig& c = d.cfg;
  const Widths& w = d.widths;
  double lanes = 0;
  if (c.cost == CostFunction::Census) {
    const int chunks = (w.code + 5) / 6, sets = (chunks + 7) / 8;  // 6-bit popcounts, summed by 8
    lanes = c.uf * (3.0 * chunks + 1 + w.cost + (chunks > 8 ? sets * w.cost + 1 : 0));
  } else if (c.cost == CostFunction::Rank) {
    lanes = c.uf * (w.code + 1.0 + w.cost);
  }
  const double codes = c.cost == CostFunction::Sad || c.cost == CostFunction::Zsad ? 0.0 : 2.0 * w.code;
  const double windows = 2.0 * c.window * c.window * w.pixel;
  if (d.reorders_codes) {
    constexpr int kShiftRegisterMinLength = 3;
    const double waiting = d.chains - 1 < kShiftRegisterMinLength ? (d.chains - 1.0) * c.dmax * d.code_entry_bits : 0.0;
    const double schedule = 2.0 * (d.x_bits + d.group_bits) + 1;
    const double tag = 1.0 + d.x_bits + d.y_bits + 1 + d.group_bits + d.chain_bits + d.out_row_bits;
    return ring + waiting + d.code_entry_bits + schedule + (d.cost_lead - 1) * tag + lanes + codes + windows;
  }
  const double reorder_tag = d.cost_latency * (1.0 + d.x_bits + d.cost_row_bits + d.group_bits);
  return ring + lanes + codes + windows + reorder_tag;
}

// fpstereo_median: the window of words, fpstereo_median_select's copy of it and the two beside
// the rank count, per result bit the candidates' flags (the values' lower bits ride in shift-
// register LUTs), the position's delay of 3 steps per word bit and the output registers.
double median_registers(const rtl::RtlDesign& d) {
  const int m = d.cfg.median;
  if (m == 0) return 0;
  const double word = d.widths.output_word, cells = double(m) * m;
  const double position = 1.0 + d.x_bits + d.y_bits;
  return cells * word + 3 * cells * word + 2 * cells * d.widths.output_disparity + 3 * word * position +
         (position + d.x_bits + d.signed_y_bits + 1) + word;
}

// fpstereo_subpixel: the sums of the dmax disparities it selects from (the older steps of the
// history have no taps: shift-register LUTs), the tag beside the fit's steps, the selection's
// window and three sums, and fpstereo_subpixel_fit's division steps.
double subpixel_registers(const rtl::RtlDesign& d) {
  const StereoConfig& c = d.cfg;
  if (c.subpixel_bits == 0) return 0;
  const double sum = d.widths.aggregated, disp = d.widths.disparity, k = c.subpixel_bits;
  const double tag = 1 + d.x_bits + d.out_row_bits + d.group_bits + (d.carries_whole ? disp : 0);
  const int low_bits = d.widths.disparity - d.widths.disparity / 2;
  const double window = ((1 << low_bits) + 2) * sum;
  return c.dmax * sum + d.subpixel_steps * (tag + 1) + 3 * disp + window + 3 * sum +
         (k + 2) * (2 * (sum + k) + disp);
}

// fpstereo_fused_term per lane: the difference, its truncation, the weighted term (each as wide
// as its largest value: Yosys drops the bits that stay 0), the sum, and the plain cost's wait for
// the term's 3 steps; fpstereo_fused_features' two features.
double fused_term_registers(const rtl::RtlDesign& d) {
  const StereoConfig& c = d.cfg;
  const int f = d.widths.fused_feature;  // 0 without the fused cost
  if (f == 0) return 0;
  const int largest = f == 9 ? 510 : 255, truncated = std::min(c.fused_trunc, largest);
  const double cost = d.widths.cost;
  const double lane = bits_for(uint64_t(largest)) + bits_for(uint64_t(truncated)) +
                      bits_for(uint64_t(c.fused_weight * truncated / kFusedWeightDivisor)) + cost +
                      std::max(0, 3 - d.cost_lanes_latency) * cost;
  return c.uf * lane + 2.0 * f;
}

// fpstereo_speckle's registers, as it declares them at W = row_slots: the word in flight at each
// step, the current run, the top of the stack and the class records (x, position and count
// widths), the resolution's and the kill chain's registers; and fpstereo_speckle_stage's output
// and position registers.
double speckle_registers(const rtl::RtlDesign& d) {
  const StereoConfig& c = d.cfg;
  if (c.speckle_size == 0) return 0;
  const int64_t W = d.row_slots, depth = (W + 1) / 2;
  const double x = clog2(W), p = clog2(int64_t(d.speckle_rows) * W), count = clog2(c.speckle_size + 2);
  const double word = d.widths.output_word, entry = x + count + 2 * p + 2 * x, cls = count + x + 2 * p + 1;
  const double filter = 5 * word + 12 * x + 4 * (x + 1) + 12 * p + 5 * count + entry + cls + clog2(depth + 1) +
                        clog2(d.speckle_rows) + 36;
  const double stage = 4 + 2.0 * d.x_bits + d.y_bits + d.signed_y_bits + d.widths.output_disparity + 1;
  return filter + stage;
}

// fpstereo_gap_fill's linear fill (LINEAR): per word its three operand steps and the divider's
// stages (remainder, quotient, span, the rule's flag and the smaller end's word), the pixels of
// the nearest valid words, and the position's delay. Not yet fitted: its LUTs (the divider's
// compare-subtracts, about a LUT a remainder bit a stage) are not in the LUT terms.
double linear_gap_registers(const rtl::RtlDesign& d) {
  if (!d.cfg.gap_linear) return 0;
  const double word = d.widths.output_word, disparity = word - 1, x = d.x_bits, numerator = disparity + x;
  const double operands = (1 + word + 2 * disparity + 2 * x) + (1 + word + 2 * numerator + x + (x + 1) + disparity) +
                          (2 + word + x + numerator + 1);
  const double divider = (disparity - 1) * ((numerator + 1) + disparity + x + 1 + word);
  return d.strips * (operands + divider + 2 * x) + x + (disparity + 2) * (1 + x + d.y_bits);
}

// fpstereo_lr_check's two register steps (position, words, the match side's disparity and the
// base disparity's two bounds) and fpstereo_gap_fill's four (position, a slot's words, the row's
// last valid word; the first step's four position flags; with strips the words' nearest valid
// words in the slot); with the linear fill, each word's operand steps and divider and the
// position's delay beside them.
double check_and_gap_registers(const rtl::RtlDesign& d) {
  const double position = 1.0 + d.x_bits + d.y_bits, word = d.widths.output_word;
  const double check =
      d.cfg.lr != LrCheck::None ? 2 * (position + 1) + 3 * word + d.widths.disparity + 2 * (d.widths.disparity + 2) : 0.0;
  const double gap = d.cfg.gap_interpolation ? 4 * position + (4 * d.strips - 1) * word + 4 : 0.0;
  return check + gap + linear_gap_registers(d);
}

}  // namespace

// The LUT terms are bit counts of the stages' datapaths, their coefficients LUTs per bit; the FF
// terms count the stages' register bits (above). term_ties() says which term serves which.
std::vector<double> features(const rtl::RtlDesign& d) {
  const StereoConfig& c = d.cfg;
  const Widths& w = d.widths;
  const double uf = c.uf, dmax = c.dmax;
  const double sides = c.lr == LrCheck::Lr2 ? 2 : 1;  // LR2 aggregates the match side too
  const double n = c.window, k = c.shd_window;
  // The match ring (fpstereo_match_ring.v) keeps dmax + span - 1 match columns in registers.
  double code_lanes = 0, pixel_lanes = 0, ring = 0, zero_mean = 0;
  switch (c.cost) {
    case CostFunction::Census:
    case CostFunction::Rank:
      code_lanes = uf * w.code;
      ring = dmax * w.code;
      break;
    // The window costs (fpstereo_window_cost_lanes.v): every lane sums a whole window.
    case CostFunction::Shd:
      code_lanes = uf * k * k * w.code;
      ring = (dmax + k - 1) * k * w.code;
      break;
    case CostFunction::Sad:
      pixel_lanes = uf * n * n * w.pixel;
      ring = (dmax + n - 1) * n * w.pixel;
      break;
    case CostFunction::Zsad:  // plus the ring of column sums, the means and their subtraction
      pixel_lanes = uf * n * n * w.pixel;
      zero_mean = pixel_lanes;
      ring = (dmax + n - 1) * (n * w.pixel + d.column_sum_bits);
      break;
  }
  // The fused cost's features ride beside the codes in the ring.
  const double ring_features = c.fused_weight == 0 ? 0.0 : ring / w.code * w.fused_feature;
  // The tag beside the winner-take-all's tree (fpstereo_wta, fpstereo_wta_unique).
  const double word_tag = 1 + d.x_bits + d.out_row_bits;
  // The word tag beside the confidence's division (fpstereo_confidence's data).
  const double tag = 1 + d.x_bits + d.out_row_bits + d.group_bits + w.output_word + (d.carries_whole ? w.disparity : 0);
  // fpstereo_subpixel: the selection of three sums from dmax, and the fit's K + 3 division steps
  // over sums widened by K (the sums' history is registers).
  const double kbits = c.subpixel_bits;
  const double subpixel =
      c.subpixel_bits > 0 ? dmax * w.aggregated + 3 * (kbits + 3) * (w.aggregated + kbits) : 0.0;
  // In strips (docs/ppc-hardware.md) the transform, the chain costs, the aggregator, the
  // winner-take-all, the sub-pixel fit, the confidence, adaptive P2, the fused term and the
  // median are there once per strip, the window-cost lanes (SAD, ZSAD, SHD) once per pixel of a
  // slot beside one shared ring of match columns (fpstereo_strip_window_cost).
  const double sets = d.strips;
  const bool window_costs =
      c.cost == CostFunction::Sad || c.cost == CostFunction::Zsad || c.cost == CostFunction::Shd;
  // LR2 in strips computes the match side's costs again: census and rank in its chain costs,
  // the window costs in a second fpstereo_strip_window_cost with the images swapped.
  const double cost_sides = d.strips > 1 && c.lr == LrCheck::Lr2 ? 2.0 : 1.0;
  const double ring_sets = (window_costs ? 1.0 : sets) * cost_sides;
  code_lanes *= cost_sides;
  pixel_lanes *= sets * cost_sides;
  zero_mean *= sets * cost_sides;
  return {1.0, uf * c.path_count() * w.path_cost * sides * sets, code_lanes * sets, pixel_lanes,
          (ring + ring_features) * ring_sets,
          c.cost == CostFunction::Sad || c.cost == CostFunction::Zsad ? 0.0 : 2 * n * n * w.pixel * sets,
          c.median > 0 ? double(c.median * c.median) * (w.disparity + 1) * sets : 0.0,
          c.lr == LrCheck::Lr1 ? uf * (w.aggregated + w.disparity) : 0.0,
          // LR2's uf-wide part is the second aggregation (sides); the rest is per design.
          c.lr == LrCheck::Lr2 ? 1.0 : 0.0, zero_mean,
          // fpstereo_wta_unique's tree carries the second-best sum beside the best.
          d.finds_second_best ? uf * w.aggregated * sets : 0.0,
          // fpstereo_wta's minimum tree: the base side's without that, and LR2's match side's.
          ((d.finds_second_best ? 0 : 1) + (c.lr == LrCheck::Lr2 ? 1 : 0)) * uf * w.aggregated * sets,
          // 8 restoring steps over the sums, the word waiting 10 steps beside them.
          c.confidence ? (16.0 * w.aggregated + 10 * tag) * sets : 0.0, subpixel * sets,
          // fpstereo_adaptive_p2: per path the pixel step, its product and P2; the penalties
          // then ride above the cost words.
          c.p2_adapt != 0 ? (double(d.penalty_bits) + 20.0 * c.path_count()) * sets : 0.0,
          // The right view's output register and its stream's handshake (Dm exists for the check).
          c.right_view ? 3.0 * (w.disparity + 1) : 0.0,
          // fpstereo_gap_fill: the row's words and their positions (its RAMs are block RAM).
          c.gap_interpolation ? double(w.output_word * d.strips + d.x_bits) : 0.0,
          // The read multiplexers of the RAMs whose depth is split over several cells.
          memory_read_mux_bits(d),
          // the FF terms: register bits (see above)
          (aggregator_registers(d, d.penalty_bits) +
           (c.lr == LrCheck::Lr2 ? aggregator_registers(d, 0) : 0.0)) *
              sets,
          cost_registers(d, ring + ring_features) * ring_sets + fused_term_registers(d) * sets * cost_sides,
          (winner_registers(d, d.finds_second_best, word_tag) +
           (c.lr == LrCheck::Lr2 ? winner_registers(d, false, word_tag) : 0.0)) *
              sets,
          median_registers(d) * sets, subpixel_registers(d) * sets, check_and_gap_registers(d),
          // SAD, ZSAD and SHD: every lane sums a whole window (fpstereo_window_cost_lanes)
          c.cost == CostFunction::Shd ? code_lanes * sets : pixel_lanes,
          // fpstereo_speckle and its stage: its logic, as LUTs per register bit
          speckle_registers(d),
          // fpstereo_fused_term's lanes: the difference, truncation, weighting and sum, as LUTs
          // per register bit
          fused_term_registers(d) * sets * cost_sides, speckle_registers(d)};
}

const std::vector<std::string>& group_names() {
  static const std::vector<std::string> names = {"constant", "aggregation", "stages", "registers",
                                                 "window cost lanes", "codes"};
  return names;
}

// LUT: the path lanes have their own coefficient; the codes' datapath (transform, match ring,
// code cost lanes: comparators and multiplexers, which flattening hardly shrinks) one; the other
// stages' terms share one ("stages"). Each term is weighted by the LUTs per term unit its modules
// had in the hierarchical Yosys synthesis of fit designs f02, f03, f09, f17 and f19 and held-out
// h05 (docs/resource-model.md; the weights of SAD's and ZSAD's lanes, not among those, are an
// older fit's). The fitted scales then absorb what flattening saves. FF: the register terms count
// flip-flops, so they share one coefficient (near 1: Yosys trims and merges a few); the terms
// that already are register counts (the confidence's steps, adaptive P2's, the right view's) join
// them; the window-cost lanes of SAD, ZSAD and SHD, not counted, have their own. A few
// coefficients per resource can be fitted from the few Yosys runs a refit affords (each takes
// minutes to an hour); 28 free ones could not.
const std::vector<TermTie>& term_ties() {
  static const std::vector<TermTie> ties = {
      {0, 0, 1, 1},        // top/control
      {1, 3, 1, 0},        // path lanes
      {5, 3, 1.7, 0},      // code cost lanes: census 1.85 (f02), 1.7 (f09, f17, h05); rank 5.1 (f03)
      {2, 3, 5.53235, 0},  // pixel cost lanes
      {5, 3, 1.0, 0},      // match ring (its registers: cost registers): 1.0 (h05)
      {5, 3, 1.1, 0},      // transform: census 1.08 to 1.1 (1.11 in h05), rank 1.77
      {2, 3, 5.4, 0},      // median: 5.0 (f02), 5.9 (f03)
      {2, 3, 2.5, 0},      // LR1: the match side and the check (f02)
      {2, 3, 500, 0},      // LR2: the second aggregator's own logic, the check (f03, f09)
      {2, 3, 3.50621, 0},  // ZSAD lanes
      {2, 3, 13.5, 0},     // second best: 13.1 to 15
      {2, 3, 1.6, 0},      // winner-take-all tree: LR2's match side (f03)
      {2, 3, 0.57, 1},     // confidence: 0.56 to 0.59; its steps' registers
      {2, 3, 0.65, 0},     // sub-pixel: 0.65 to 0.66
      {2, 3, 1.55, 1},     // adaptive P2: 1.37 to 1.72; its registers
      {2, 3, 1, 1},        // right view; its registers
      {2, 3, 7.0, 0},      // gap interpolation: 7.0 to 7.05
      {2, 3, 0.5, 0},      // memory read multiplexers: 0.43 to 0.77 (f02, f03, f09, f17; Yosys' cost 0.5)
      {0, 3, 0, 1},        // aggregation registers
      {0, 3, 0, 1},        // cost registers
      {0, 3, 0, 1},        // winner-take-all registers
      {0, 3, 0, 1},        // median registers
      {0, 3, 0, 1},        // sub-pixel registers
      {0, 3, 0, 1},        // check and gap registers
      {0, 4, 0, 1},        // window cost lanes
      {2, 3, 1.29, 0},     // speckle filter: 1.29 LUTs per register bit (f19)
      {2, 3, 0.79, 0},     // fused term: 0.79 (f19)
      {0, 3, 0, 1},        // speckle registers
  };
  return ties;
}

const std::vector<std::string>& dsp_feature_names() {
  static const std::vector<std::string> names = {"base", "LR1", "LR2", "ZSAD means", "uniqueness"};
  return names;
}

// DSPs are the few multiplies of RAM address arithmetic, ZSAD's means (the base window's and
// one per lane) and the uniqueness test's products (fpstereo_wta_unique).
std::vector<double> dsp_features(const rtl::RtlDesign& d) {
  return {1.0, d.cfg.lr == LrCheck::Lr1 ? 1.0 : 0.0, d.cfg.lr == LrCheck::Lr2 ? 1.0 : 0.0,
          d.cfg.cost == CostFunction::Zsad ? d.cfg.uf + 1.0 : 0.0,
          d.cfg.uniqueness != 0 ? double(d.strips) : 0.0};  // a uniqueness test per strip
}

namespace {
#include "resource_coefficients.inc"
}  // namespace

const Coefficients& fitted_coefficients() {
  static const Coefficients c = [] {
    Coefficients k = {std::vector<double>(std::begin(kLut), std::end(kLut)),
                      std::vector<double>(std::begin(kFf), std::end(kFf)),
                      std::vector<double>(std::begin(kDsp), std::end(kDsp))};
    if (k.lut.size() != feature_names().size() || k.ff.size() != feature_names().size() ||
        k.dsp.size() != dsp_feature_names().size())
      throw std::logic_error("gen/dse/resource_coefficients.inc does not have the model's terms: refit it "
                             "(bench_resource_model --refit --write)");
    return k;
  }();
  return c;
}

const FitProvenance& fit_provenance() {
  static const FitProvenance p = {std::vector<FitRecord>(std::begin(kRecords), std::end(kRecords)), kHeldOut};
  return p;
}

StereoConfig config_from_flags(const std::string& flags) {
  std::istringstream in(flags);
  std::string key, value;
  StereoConfig cfg;
  while (in >> key >> value) {
    if (key.size() < 3 || key.compare(0, 2, "--") != 0) throw ConfigError("expected --name value, got " + key);
    set_param(cfg, key.substr(2), value);
  }
  validate(cfg);
  return cfg;
}

std::vector<std::string> stale_records(const FitProvenance& p) {
  std::vector<std::string> stale;
  for (const FitRecord& r : p.records) {
    bool current = false;
    try {
      current = verilog_hash(config_from_flags(r.flags)) == r.verilog_hash;
    } catch (const ConfigError&) {  // flags the generator no longer takes: their Verilog is gone too
    }
    if (!current) stale.push_back(r.name);
  }
  return stale;
}

std::string model_note(const FitProvenance& p) {
  int fit = 0;
  for (const FitRecord& r : p.records) fit += std::string(r.role) == "fit";
  const ErrorSummary& h = p.heldout;
  std::string note = fmt::format(
      "LUT, FF and DSP are the fast resource model's estimates (no Yosys run), fitted to {} Yosys results; "
      "BRAM is the model's mapping of each memory as Yosys maps it. On {} held-out designs the model was off "
      "Yosys by a mean |error| of {:.1f} % (max {:.1f} %) in LUT and {:.1f} % (max {:.1f} %) in FF; BRAM exact "
      "on {} of {}.",
      fit, h.designs, h.lut_mean, h.lut_max, h.ff_mean, h.ff_max, h.bram_exact, h.designs);
  const std::vector<std::string> stale = stale_records(p);
  if (stale.empty()) return note + " Every one of those Yosys results is of the Verilog the generator emits today.";
  std::string names;
  for (const auto& n : stale) names += (names.empty() ? "" : " ") + n;
  return note + fmt::format(
                    " Stale: {} of the {} Yosys results came from Verilog the generator no longer emits ({}), "
                    "so these figures may be off; rerun `bench_resource_model --collect`, then `--refit`.",
                    stale.size(), p.records.size(), names);
}

namespace {
double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) s += a[i] * b[i];
  return s;
}
}  // namespace

ResourceEstimate estimate(const rtl::RtlDesign& d, const Coefficients& c) {
  ResourceEstimate e;
  e.memories = design_memories(d);
  for (const auto& m : e.memories) {
    e.bram18 += m.bram18;
    e.bram36 += m.bram36;
  }
  const std::vector<double> f = features(d);
  e.lut = dot(f, c.lut);
  e.ff = dot(f, c.ff);
  e.dsp = std::round(dot(dsp_features(d), c.dsp));
  return e;
}

ResourceEstimate estimate(const StereoConfig& cfg) { return estimate(rtl::plan(cfg)); }

double frames_per_second(const rtl::RtlDesign& d, double clock_mhz) {
  return clock_mhz * 1e6 / double(d.cycles_per_frame);
}

// ---- fitting ------------------------------------------------------------------------------------------

namespace {
// Solves the unconstrained weighted least squares over the columns in `passive` (normal equations,
// Gaussian elimination with partial pivoting; the systems are tiny).
std::vector<double> solve_subset(const std::vector<std::vector<double>>& a, const std::vector<double>& b,
                                 const std::vector<double>& wt, const std::vector<size_t>& passive,
                                 size_t n) {
  const size_t k = passive.size();
  std::vector<std::vector<double>> m(k, std::vector<double>(k + 1, 0));
  for (size_t r = 0; r < a.size(); ++r)
    for (size_t i = 0; i < k; ++i) {
      for (size_t j = 0; j < k; ++j) m[i][j] += wt[r] * a[r][passive[i]] * a[r][passive[j]];
      m[i][k] += wt[r] * a[r][passive[i]] * b[r];
    }
  for (size_t i = 0; i < k; ++i) m[i][i] += 1e-9 * (1 + m[i][i]);  // keeps a rank-deficient system solvable
  for (size_t col = 0; col < k; ++col) {
    size_t piv = col;
    for (size_t r = col + 1; r < k; ++r)
      if (std::abs(m[r][col]) > std::abs(m[piv][col])) piv = r;
    std::swap(m[col], m[piv]);
    for (size_t r = 0; r < k; ++r) {
      if (r == col || m[col][col] == 0) continue;
      const double f = m[r][col] / m[col][col];
      for (size_t j = col; j <= k; ++j) m[r][j] -= f * m[col][j];
    }
  }
  std::vector<double> x(n, 0);
  for (size_t i = 0; i < k; ++i) x[passive[i]] = m[i][i] == 0 ? 0 : m[i][k] / m[i][i];
  return x;
}
}  // namespace

std::vector<double> fit_nonnegative(const std::vector<std::vector<double>>& a, const std::vector<double>& b,
                                    const std::vector<double>& wt) {
  const size_t n = a.empty() ? 0 : a.front().size();
  std::vector<double> x(n, 0);
  std::vector<bool> in_passive(n, false);
  const double tol = 1e-10;
  for (int outer = 0; outer < 100; ++outer) {
    // Gradient of the weighted residual: the most promising column to free.
    std::vector<double> g(n, 0);
    for (size_t r = 0; r < a.size(); ++r) {
      double res = b[r];
      for (size_t j = 0; j < n; ++j) res -= a[r][j] * x[j];
      for (size_t j = 0; j < n; ++j) g[j] += wt[r] * a[r][j] * res;
    }
    size_t best = n;
    for (size_t j = 0; j < n; ++j)
      if (!in_passive[j] && g[j] > tol && (best == n || g[j] > g[best])) best = j;
    if (best == n) break;
    in_passive[best] = true;
    for (int inner = 0; inner < 100; ++inner) {
      std::vector<size_t> passive;
      for (size_t j = 0; j < n; ++j)
        if (in_passive[j]) passive.push_back(j);
      const std::vector<double> z = solve_subset(a, b, wt, passive, n);
      bool feasible = true;
      for (size_t j : passive) feasible = feasible && z[j] > tol;
      if (feasible) {
        x = z;
        break;
      }
      // Step towards z until a coefficient reaches zero; it leaves the passive set.
      double alpha = 1;
      for (size_t j : passive)
        if (z[j] <= tol) alpha = std::min(alpha, x[j] / (x[j] - z[j]));
      for (size_t j = 0; j < n; ++j) x[j] += alpha * (z[j] - x[j]);
      for (size_t j : passive)
        if (x[j] <= tol) {
          x[j] = 0;
          in_passive[j] = false;
        }
    }
  }
  return x;
}

}  // namespace fpstereo::dse
