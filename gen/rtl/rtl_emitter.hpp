// The Verilog elaborator: derives the hardware parameters of a configuration, picks the
// building blocks of rtl_templates/ and wires them under an AXI4-Stream top.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "config.hpp"
#include "widths.hpp"

namespace fpstereo::rtl {

// Everything the emitted Verilog is parameterised with (docs/architecture.md).
struct RtlDesign {
  StereoConfig cfg;
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
  int levels_per_stage = 3;
  int path_tree_latency = 0;
  int wta_tree_latency = 0;
  // steps from a frame's first step to aggregation, LR2's match-side aggregation and output
  int64_t agg_start = 0;
  int64_t match_start = 0;
  int64_t out_start = 0;
  int64_t cycles_per_frame = 0;      // steps from a frame's first step to its last output, plus one
  int64_t latency_cycles = 0;        // cycles_per_frame - W * H * G
  int64_t first_output_latency = 0;  // cycles from the first input pixel to the first output pixel
  int output_bits = 0;               // tdata width of m_axis_disp (8 or 16)
  int x_bits = 0, y_bits = 0, group_bits = 0, chain_bits = 0, lane_bits = 0, step_bits = 0;
};

// Throws ConfigError if the configuration is invalid.
RtlDesign plan(const StereoConfig& cfg);

struct EmittedFile {
  std::string name;  // file name, e.g. "<prefix>_top.v"
  std::string text;
};

// The top and every module it uses, the top first; each file opens with the banner.
std::vector<EmittedFile> emit(const RtlDesign& design);
// The same as one self-contained file.
std::string emit_single_file(const RtlDesign& design);

}  // namespace fpstereo::rtl
