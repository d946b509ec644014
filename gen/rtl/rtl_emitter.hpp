// The Verilog elaborator: derives the hardware parameters of a configuration, picks the
// building blocks of rtl_templates/ and wires them under an AXI4-Stream top.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "config.hpp"
#include "stages.hpp"
#include "widths.hpp"

namespace fpstereo::rtl {

// Choices of the generated design that are not part of the stereo configuration.
struct RtlOptions {
  bool control = true;  // AXI4-Lite control and status (otherwise the settings are fixed)
};

// Everything the emitted Verilog is parameterised with (docs/architecture.md).
struct RtlDesign {
  StereoConfig cfg;
  RtlOptions options;
  Widths widths;
  std::string prefix;       // module name prefix, unique per configuration
  int window_radius = 0;    // r
  int cost_latency = 1;     // register stages of the cost lanes
  int column_sum_bits = 0;  // SAD/ZSAD: bits of a window column's pixel sum
  uint64_t mean_mul = 1;    // ZSAD: floor(s / N^2) == (s * mean_mul) >> mean_shift
  int mean_shift = 0;
  int groups = 0;     // G = dmax / uf: steps per pixel
  int chains = 0;     // K
  int segment = 0;    // ceil(W / K): pixels per chain per row
  int row_slots = 0;  // K * segment: slots per row-time
  // rows of the cost reorder RAM (K, one more with LR2, whose match side reads a row longer) and
  // of the disparity RAMs (K, one more for the output's lag, and one (LR1) or two (LR2) more
  // while the output waits for the match side)
  int cost_rows = 0, out_rows = 0;
  int64_t cost_depth() const { return int64_t(cost_rows) * row_slots * groups; }
  int64_t disp_depth() const { return int64_t(out_rows) * row_slots; }
  int levels_per_stage = 3;
  int path_tree_latency = 0;
  int wta_tree_latency = 0;
  // The uniqueness tree's joins are deeper than the minimum trees' compare-selects: it is
  // registered after each join (fpstereo_wta_unique); its word leaves three steps after the tree.
  static constexpr int kUniqueLevelsPerStage = 1, kUniqueWordSteps = 3;
  int unique_tree_latency = 0;
  // Steps from the winner-take-all's sums to its word: the tree, and with uniqueness (or
  // confidence) the group join's and the test's registers.
  int wta_word_lag = 0;
  // the stages in data order (stages.hpp); the schedule below is the sum of their latencies
  std::vector<StagePtr> stages;
  // steps from a frame's first step to the start of each stage with a schedule of its own, by
  // its start parameter (AGG_START: aggregation, MATCH_START: LR2's match side, OUT_START: output)
  std::map<std::string, int64_t> start_steps;
  int64_t cycles_per_frame = 0;      // from a frame's start to the next's without stalls, back to back
  int64_t lone_frame_cycles = 0;     // the same when the next frame waits for this one to drain
  int overlap_height = 0;            // the smallest frame height at which frames follow on
  int64_t extra_cycles = 0;          // cycles_per_frame - W * H * G: bubble slots, or the drain
  int64_t first_output_latency = 0;  // cycles from the first input handshake to the first output one
  int output_bits = 0;               // tdata width of m_axis_disp (8 or 16)
  // the range of the run-time image size (the configured size is the largest)
  int min_width = 0, min_height = 0;
  int x_bits = 0, y_bits = 0, group_bits = 0, chain_bits = 0, lane_bits = 0, step_bits = 0;
  int signed_y_bits = 0;  // signed row coordinates: a window centre may lie above the image
  int cost_row_bits = 0, out_row_bits = 0;  // row slot of the cost and disparity RAMs
  int cost_addr_bits = 0, disp_addr_bits = 0, end_addr_bits = 0;
};

// Throws ConfigError if the configuration is invalid.
RtlDesign plan(const StereoConfig& cfg, const RtlOptions& options = {});

// The signals of the AXI4-Lite control interface; the top's ports are s_axi_ctrl_<name>.
struct ControlPort {
  std::string name;
  bool input;  // into the core
  int bits;
};
const std::vector<ControlPort>& control_ports();

// The AXI4-Lite registers (fpstereo_control): byte offset, name, access and meaning, in address
// order. The generated C header is printed from it; the table in docs/hardware.md is checked
// against it (tests/test_register_map.cpp).
struct Register {
  uint32_t offset;
  std::string name;
  bool writable;
  std::string meaning;
};
std::vector<Register> register_map(const RtlDesign& design);
// The read-only words at 0x40 (INFO) with their names, as the design reports them.
std::vector<std::pair<std::string, uint32_t>> info_words(const RtlDesign& design);
// VERSION and CONFIG_ID as the design reports them.
uint32_t version_word();
uint32_t config_id(const RtlDesign& design);
// <prefix>_regs.h: the register map as C constants for the software that drives the core.
std::string emit_register_header(const RtlDesign& design);

struct EmittedFile {
  std::string name;  // file name, e.g. "<prefix>_top.v"
  std::string text;
};

// The top and every module it uses, the top first; each file opens with the banner.
std::vector<EmittedFile> emit(const RtlDesign& design);
// The same as one self-contained file.
std::string emit_single_file(const RtlDesign& design);

}  // namespace fpstereo::rtl
