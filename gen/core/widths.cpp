#include "widths.hpp"

#include <algorithm>

namespace fpstereo {

int bits_for(uint64_t max_value) {
  int bits = 1;
  while (bits < 64 && (max_value >> bits) != 0) ++bits;
  return bits;
}

int clog2(int64_t n) { return n > 1 ? bits_for(uint64_t(n - 1)) : 0; }

Widths derive_widths(const StereoConfig& cfg) {
  Widths w;
  const uint64_t n = uint64_t(cfg.window) * uint64_t(cfg.window);  // pixels in the cost window
  const uint64_t m = uint64_t(cfg.shd_window) * uint64_t(cfg.shd_window);
  switch (cfg.cost) {
    case CostFunction::Census:
      w.code = int(n - 1);
      w.cost_max = n - 1;
      break;
    case CostFunction::Rank:
      w.code = bits_for(n - 1);
      w.cost_max = n - 1;
      break;
    case CostFunction::Sad:
      w.code = w.pixel;
      w.cost_max = 255 * n;
      break;
    case CostFunction::Zsad:
      // sum |u_i - delta| with |delta - mean(u)| < 1 is below 255 n - 255/n + n <= 256 n.
      w.code = w.pixel;
      w.cost_max = 256 * n;
      break;
    case CostFunction::Shd:
      w.code = int(n - 1);
      w.cost_max = (n - 1) * m;
      break;
  }
  // The fused cost's pixel-wise term reaches its bound where the difference reaches the truncation.
  if (cfg.fused_weight != 0) {
    w.cost_max += uint64_t(cfg.fused_weight) * uint64_t(cfg.fused_trunc) / kFusedWeightDivisor;
    w.fused_feature = cfg.fused_term == FusedTerm::Gradient ? 9 : 8;  // -255 .. 255 or 0 .. 255
  }
  w.cost = bits_for(w.cost_max);
  w.path_cost_max = w.cost_max + uint64_t(cfg.p2);
  w.path_cost = bits_for(w.path_cost_max);
  w.aggregated_max = uint64_t(cfg.path_count()) * w.path_cost_max;
  w.aggregated = bits_for(w.aggregated_max);
  w.disparity = bits_for(uint64_t(cfg.dmax - 1));
  // validate() allows 0 .. 5 fraction bits; the clamp keeps the shift defined before it ran
  w.output_disparity = bits_for(uint64_t(cfg.dmax - 1) << std::clamp(cfg.subpixel_bits, 0, 8));
  w.output_word = w.output_disparity + 1;
  w.invalid_word = uint16_t(1u << w.output_disparity);
  w.output_lane = w.output_word <= 8 ? 8 : 16;
  w.uniqueness_product = bits_for(w.aggregated_max * 100);
  return w;
}

}  // namespace fpstereo
