// Minimal bit widths of every intermediate, derived from the configuration by closed-form
// formulas (docs/semantics.md, "Bit widths"). The one place widths come from.
#pragma once

#include <cstdint>

#include "config.hpp"

namespace fpstereo {

// Number of bits needed to hold every value in 0 .. max_value (at least 1).
int bits_for(uint64_t max_value);
// Verilog's $clog2: bits to address n entries (0 for n <= 1).
int clog2(int64_t n);

struct Widths {
  int pixel = 8;
  int code = 0;           // census code (N*N-1 bits) or rank value; 8 for SAD/ZSAD (the pixel)
  int fused_feature = 0;  // the fused cost's pixel feature: 8 (intensity), 9 (signed gradient), 0 (off)
  uint64_t cost_max = 0;  // largest matching cost (with the fused term), also the cost of an out-of-image match
  int cost = 0;
  uint64_t path_cost_max = 0;  // cost_max + P2
  int path_cost = 0;
  uint64_t aggregated_max = 0;  // paths * path_cost_max
  int aggregated = 0;
  int disparity = 0;         // bits for 0 .. dmax-1, the winner-take-all's disparity
  int output_disparity = 0;  // bits for 0 .. (dmax-1) << subpixel_bits, the output's disparity
  int output_word = 0;       // output disparity bits plus the invalid flag in the top bit
  uint16_t invalid_word = 0;
  int output_lane = 0;       // the output word's byte-aligned lane in a stream: 8 or 16 bits
  int uniqueness_product = 0;  // bits of aggregated_max * 100 (the uniqueness comparison)
};

Widths derive_widths(const StereoConfig& cfg);

}  // namespace fpstereo
