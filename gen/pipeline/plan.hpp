// The plan of a configuration's hardware (docs/architecture.md): first its geometry, every width,
// count and word layout derived once from the configuration; then the stages in data order; then
// the schedule, the sum of the stages' latencies. The RTL and HLS emitters, the register map, the
// resource model, the DSE and the test bench read this one plan.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "config.hpp"
#include "outputs.hpp"
#include "stage.hpp"
#include "widths.hpp"

namespace fpstereo::rtl {

// Choices of the generated design that are not part of the stereo configuration.
struct RtlOptions {
  bool control = true;  // AXI4-Lite control and status (otherwise the settings are fixed)
  // The generator the plan is for: the HLS kernels have the 180-degree path, the Verilog not yet.
  enum class Target { Verilog, Hls } target = Target::Verilog;
};

// Bits of the confidence (0..255) that rides above each word from the winner-take-all on.
constexpr int kConfidenceBits = 8;
// The steps fpstereo_confidence divides in, its word waiting beside.
constexpr int kConfidenceSteps = 10;

// The clocks fpstereo_speckle takes a word (its first form): a slot of G >= 4 steps gives them.
constexpr int kSpeckleClocksPerWord = 4;

// The geometry: what the configuration fixes before any stage is placed. Stages read it to state
// their latencies and memories.
struct Geometry {
  StereoConfig cfg;
  RtlOptions options;
  Widths widths;
  std::string prefix;       // module name prefix, unique per configuration
  int window_radius = 0;    // r
  // The side of the window a cost sums over: 1 for census and rank, the SHD window for SHD, N for
  // SAD and ZSAD; and the rows by which the windows delay the stream up to the cost.
  int cost_window = 1;
  int window_fill_rows = 0;
  // Shifts from a window to the transform's result (fpstereo_front_end's TRANSFORM_SLOTS): 2 for
  // rank, whose count is registered halfway (logic depth), 1 otherwise. The fused cost's features
  // and adaptive P2's steps, taken from the windows too, wait as long.
  int transform_slots = 1;
  int cost_lanes_latency = 1;  // register stages of the cost lanes
  int cost_latency = 1;        // and of the cost stage: the lanes', with the fused cost's term one more
  int column_sum_bits = 0;  // SAD/ZSAD: bits of a window column's pixel sum
  uint64_t mean_mul = 1;    // ZSAD: floor(s / N^2) == (s * mean_mul) >> mean_shift
  int mean_shift = 0;
  int groups = 0;     // G = dmax / uf: steps per pixel
  int chains = 0;     // K
  int segment = 0;    // ceil(W / K): pixels per chain per row
  int row_slots = 0;  // R = K * segment: slots per row-time
  // Strips (docs/ppc-hardware.md): with ppc = P pixels a clock the row is P strips of R pixels,
  // each aggregated by a lane set of its own, K steps behind the one to its left; a slot then
  // takes P pixels (a beat, which lies in one strip). 1 where the core takes a pixel a step.
  int strips = 1;
  // With strips, the modulus of the front end's row slot, a multiple of every strip's code rows
  // ((s + 1) * K for strip s).
  int slot_rows = 0;
  // Cycles the window stage holds a frame's last step for a following frame (G = 1 only; see
  // kFollowCycles in stage.hpp): once per frame, where bubble slots would cost every row.
  int follow_wait = 0;
  // Row-times the output waits for the left-right check's match side: 0, 1 (LR1) or 2 (LR2).
  int lr_rows = 0;
  // rows of the cost reorder RAM (K, one more with LR2, whose match side reads a row longer) and
  // of the disparity RAMs (K, one more for the output's lag, and lr_rows more)
  int cost_rows = 0, out_rows = 0;
  // Whether the reorder RAM holds each pixel's base and match entries (a code, with the fused
  // cost its feature above it) instead of its G cost words, the costs computed after it in chain
  // order (docs/architecture.md, "Code reorder"): for census and rank without LR2 or a negative
  // min-disp. Then its words are code_entry_bits * 2 wide, one per pixel, and the
  // aggregator's cost words arrive cost_lead steps after their address (2 + cost_latency; 1 from
  // the cost RAM).
  bool reorders_codes = false;
  int code_entry_bits = 0, cost_lead = 1;
  int64_t cost_depth() const { return int64_t(cost_rows) * row_slots * (reorders_codes ? 1 : groups); }
  int64_t disp_depth() const { return int64_t(out_rows) * row_slots; }
  int levels_per_stage = 2;
  int path_tree_latency = 0;
  int wta_tree_latency = 0;
  // The uniqueness tree's joins are deeper than the minimum trees' compare-selects: it is
  // registered after each join (fpstereo_wta_unique); its word leaves three steps after the tree.
  static constexpr int kUniqueLevelsPerStage = 1, kUniqueWordSteps = 3;
  int unique_tree_latency = 0;
  // Whether the winner-take-all finds the second-best sum too (the uniqueness check and the
  // confidence need it).
  bool finds_second_best = false;
  // Steps from the winner-take-all's sums to its word: the tree, and with uniqueness (or
  // confidence) the group join's and the test's registers.
  int wta_word_lag = 0;
  int subpixel_steps = 0;  // the sub-pixel fit's: subpixel-bits + 6 (0 without it)
  // Rows the speckle filter holds, its latency in rows (0 without it); the output's confidence
  // rows wait as long.
  int speckle_rows = 0;
  // The words from the winner-take-all to the disparity reorder RAM: with sub-pixel output and a
  // left-right check they carry the whole D under the refined disparity, as the check compares
  // whole disparities (semantics section 5); the RAM keeps the confidence above them.
  bool carries_whole = false;
  int reorder_word_bits = 0, reorder_ram_bits = 0;
  // The raster-order paths (0, 45, 90, 135) the aggregator runs, and their number; the 180-degree
  // path (docs/path180-hardware.md) runs on a mirrored aggregator of its own.
  unsigned raster_paths = 0;
  int raster_path_count = 0;
  bool right_to_left = false;
  // The forward chains' row-times behind the cost writes (the aggregator's CHAIN_BASE): 0, or with
  // the 180-degree path K + 2 (the mirrored chains' K, their row's write and their pipeline's tail).
  int forward_lag = 0;
  // With adaptive P2 the cost words carry, above the uf costs, each raster path's P2 (the
  // 180-degree path takes the 0-degree one of x + 1).
  int penalty_bits = 0, cost_word_bits = 0;
  // The output streams' tdata: the word's byte lane (8 or 16 bits), and with confidence 8 above.
  int output_bits = 0;
  // the range of the run-time image size (the configured size is the largest)
  int min_width = 0, min_height = 0;
  int x_bits = 0, group_bits = 0, chain_bits = 0, lane_bits = 0;
  int cost_row_bits = 0, out_row_bits = 0;  // row slot of the cost and disparity RAMs
  int cost_addr_bits = 0, disp_addr_bits = 0, end_addr_bits = 0;
};

// An output stream of the design (docs/contributing.md, "Adding an output"): the top's AXI4-Stream
// master <port>, fed by the core's handshake nets <core>_ready, _push, _first and _last and by its
// word nets, each at its bit in a pixel's pixel_bits (the bits between are zero); and the fields
// that a pixel carries, which the register map, the test bench and the docs name. A beat of tdata
// holds `pixels` pixels (ppc), pixel i at bit i * pixel_bits (UG934). Each net and field belongs
// to a plane of the models (outputs.hpp), which the test bench compares it with. Each word is also
// a frame of its own in memory (the HLS kernel's memory-mapped wrapper): <frame>, of frame_bits
// per pixel.
struct OutputNet {
  std::string name;
  int lsb = 0, bits = 0;
  Plane plane = Plane::Disparity;
};
struct OutputWord : OutputNet {
  std::string frame;
  int frame_bits = 0;  // 16 for disparities, 8 for confidences
};
struct OutputStream {
  std::string port, core, what;
  int pixel_bits = 0;
  int pixels = 1;
  int tdata_bits() const { return pixel_bits * pixels; }
  std::vector<OutputWord> words;  // the core's nets, in tdata
  std::vector<OutputNet> fields;  // "disparity", "fraction", "invalid", "confidence"
};
std::vector<OutputStream> output_streams(const Geometry& g);

// The geometry, the stages and their schedule.
struct RtlDesign : Geometry {
  // the stages in data order (stage.hpp); the schedule below is the sum of their latencies
  std::vector<StagePtr> stages;
  // steps from a frame's first step to the start of each stage with a schedule of its own, by
  // its start parameter (AGG_START: aggregation, MATCH_START: LR2's match side, OUT_START: output)
  std::map<std::string, int64_t> start_steps;
  int64_t cycles_per_frame = 0;      // from a frame's start to the next's without stalls, back to back
  int64_t lone_frame_cycles = 0;     // the same when the next frame waits for this one to drain
  int overlap_height = 0;            // the smallest frame height at which frames follow on
  int64_t extra_cycles = 0;          // cycles_per_frame - W * H * G: bubble slots, or the drain
  int64_t first_output_latency = 0;  // cycles from the first input handshake to the first output one
  // Counters that run through the drain after the frame: rows (signed ones for window centres
  // above the image) and steps.
  int y_bits = 0, signed_y_bits = 0, step_bits = 0;
};

// The geometry alone; throws ConfigError if the configuration is invalid for the hardware.
Geometry plan_geometry(const StereoConfig& cfg, const RtlOptions& options = {});
// The whole plan; throws ConfigError if the configuration is invalid for the hardware.
RtlDesign plan(const StereoConfig& cfg, const RtlOptions& options = {});

// Latency of fpstereo_min_tree and fpstereo_unique_tree over n values at levels_per_stage levels a
// register; the stages pass it to them (LAT), and fpstereo_reduction_tree, the one Verilog copy of
// this formula, checks it at elaboration.
int min_tree_latency(int n, int levels_per_stage);

}  // namespace fpstereo::rtl
