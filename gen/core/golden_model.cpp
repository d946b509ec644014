// The golden model, organised as the hardware is: row by row in raster order, each stage
// consuming the previous stage's row. docs/semantics.md is the specification; section numbers
// below refer to it.
#include "golden_model.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "gap_fill.hpp"
#include "golden_stages.hpp"
#include "widths.hpp"

namespace fpstereo {
namespace {

using golden::CostRows;
using golden::PathAggregator;

// ---------------------------------------------------------------------------------------------
// Section 4: winner-take-all and uniqueness over one pixel's sums.
template <class T>
int winner(const T* S, int dmax) {
  // The minimum first (a vectorisable reduction), then its first position: the smallest d.
  const T best = *std::min_element(S, S + dmax);
  return int(std::find(S, S + dmax, best) - S);
}

// The smallest sum at least two disparities from the winner (dmax >= 16: never empty).
template <class T>
uint64_t second_best(const T* S, int dmax, int best) {
  uint64_t second = std::numeric_limits<uint64_t>::max();
  for (int d = 0; d < dmax; ++d)
    if (std::abs(d - best) >= 2) second = std::min<uint64_t>(second, S[d]);
  return second;
}

template <class T>
bool is_unique(const T* S, int dmax, int best, int ratio) {
  return !(second_best(S, dmax, best) * uint64_t(100 - ratio) < uint64_t(S[best]) * 100);
}

// Section 4, confidence: the margin of the second best over the best, 255 (S2 - S1) / S2.
template <class T>
int confidence(const T* S, int dmax, int best) {
  const uint64_t second = second_best(S, dmax, best);
  return second == 0 ? 0 : int(255 * (second - S[best]) / second);
}

// Section 4, sub-pixel: the winner d refined to units of 2^-bits from the sums at d - 1, d and
// d + 1; at the ends of the range it stays whole.
template <class T>
int refined_disparity(const T* S, int dmax, int d, const StereoConfig& cfg) {
  const int bits = cfg.subpixel_bits;
  if (bits == 0 || d == 0 || d == dmax - 1) return d << bits;
  const int64_t left = S[d - 1], best = S[d], right = S[d + 1];
  // left > best (d is the first minimum) and right >= best, so the half denominator is positive
  // and the offset num / (2 * half_den) lies in [-1/2, 1/2], towards the lower neighbour.
  const int64_t num = left - right;
  const int64_t half_den =
      cfg.subpixel_fit == SubpixelFit::Equiangular ? std::max(left, right) - best : left + right - 2 * best;
  const int64_t offset = ((std::abs(num) << bits) + half_den) / (2 * half_den);  // rounded half up
  return (d << bits) + int(num < 0 ? -offset : offset);
}

// Section 5, LR1: Dm(x') = argmin_d S(x' + m + d, d) over d with x' + m + d in the row (the
// smallest such d on ties; 0 if there is none).
template <class T>
std::vector<int> match_disparities_from_base(const T* sum_row, int width, int dmax, int m) {
  std::vector<int> dm(static_cast<size_t>(width));
  for (int xm = 0; xm < width; ++xm) {
    int best = 0;
    bool found = false;
    T best_sum = 0;
    for (int d = std::max(0, -m - xm); d < dmax && xm + m + d < width; ++d) {
      const T s = sum_row[size_t(xm + m + d) * size_t(dmax) + size_t(d)];
      if (!found || s < best_sum) {
        best = d;
        best_sum = s;
        found = true;
      }
    }
    dm[size_t(xm)] = best;
  }
  return dm;
}

// ---------------------------------------------------------------------------------------------
// Sections 6-7 on a map of disparities with -1 for invalid.
constexpr int kInvalid = -1;

// Lower median of the valid in-image window values (0 .. values-1), with a histogram that
// slides along the row (add the entering column, drop the leaving one) and a median pointer
// that only moves as far as the counts changed.
Image<int> median_filter(const Image<int>& in, int window, int values) {
  const int r = window / 2;
  Image<int> out = in;
  std::vector<int> histogram(static_cast<size_t>(values));
  for (int y = 0; y < in.height; ++y) {
    std::fill(histogram.begin(), histogram.end(), 0);
    int count = 0, median = 0, below = 0;  // below: values smaller than median
    auto update_column = [&](int x, int delta) {
      if (x < 0 || x >= in.width) return;
      for (int yy = std::max(0, y - r); yy <= std::min(in.height - 1, y + r); ++yy) {
        const int v = in.at(x, yy);
        if (v == kInvalid) continue;
        histogram[size_t(v)] += delta;
        count += delta;
        if (v < median) below += delta;
      }
    };
    for (int x = -r; x < r; ++x) update_column(x, +1);
    for (int x = 0; x < in.width; ++x) {
      update_column(x + r, +1);
      if (in.at(x, y) != kInvalid) {
        const int target = (count - 1) / 2;  // index of the lower median in sorted order
        while (below > target) below -= histogram[size_t(--median)];
        while (below + histogram[size_t(median)] <= target) below += histogram[size_t(median++)];
        out.at(x, y) = median;
      }
      update_column(x - r, -1);
    }
  }
  return out;
}

void interpolate_gaps(Image<int>& map) {
  for (int y = 0; y < map.height; ++y)
    fill_row_gaps(&map.at(0, y), map.width, [](int v) { return v != kInvalid; });
}

// ---------------------------------------------------------------------------------------------
// The pipeline, with T the storage type of costs and sums.
template <class T>
DisparityImage run_pipeline(const StereoConfig& cfg, const Widths& widths, const GrayImage& left,
                            const GrayImage& right, const SideViews& side) {
  const int width = left.width, height = left.height, dmax = cfg.dmax;
  const size_t row_size = size_t(width) * size_t(dmax);
  // Larger than any path cost plus P2, and sentinel + P1 still fits in T.
  const T sentinel = T(std::numeric_limits<T>::max() - 256);

  CostRows<T> base_costs(cfg, widths, left, right);
  // P2 adapts to the base image's steps; LR2's match side keeps it constant (section 3).
  PathAggregator<T> base_paths(cfg, width, sentinel, cfg.p2_adapt);
  PathAggregator<T> match_paths(cfg, width, sentinel, 0);
  std::vector<T> cost(row_size), sum(row_size), match_cost, match_sum;
  if (cfg.lr == LrCheck::Lr2) {
    match_cost.resize(row_size);
    match_sum.resize(row_size);
  }

  Image<int> disparity(width, height, kInvalid);
  std::vector<int> refined(static_cast<size_t>(width));
  for (int y = 0; y < height; ++y) {
    base_costs.compute(y, cost.data());
    base_paths.push_row(y, cost.data(), sum.data(), left);

    int* row = &disparity.at(0, y);
    for (int x = 0; x < width; ++x) {
      const T* S = sum.data() + size_t(x) * size_t(dmax);
      const int d = winner(S, dmax);
      row[x] = (cfg.uniqueness == 0 || is_unique(S, dmax, d, cfg.uniqueness)) ? d : kInvalid;
      if (side.confidence != nullptr) side.confidence->at(x, y) = uint16_t(confidence(S, dmax, d));
      refined[size_t(x)] = refined_disparity(S, dmax, d, cfg);
    }

    std::vector<int> match_disparity;
    if (cfg.lr == LrCheck::Lr1) match_disparity = match_disparities_from_base(sum.data(), width, dmax, cfg.min_disp);
    if (cfg.lr == LrCheck::Lr2) {
      // Every cost is symmetric in its two images, so the match side's cost at (x', d) is the
      // base side's cost at (x' + m + d, d); beyond the row it is Cmax (section 5).
      for (int xm = 0; xm < width; ++xm)
        for (int d = 0; d < dmax; ++d) {
          const int x = xm + cfg.min_disp + d;
          match_cost[size_t(xm) * size_t(dmax) + size_t(d)] =
              x >= 0 && x < width ? cost[size_t(x) * size_t(dmax) + size_t(d)] : T(widths.cost_max);
        }
      match_paths.push_row(y, match_cost.data(), match_sum.data(), right);
      match_disparity.resize(size_t(width));
      for (int xm = 0; xm < width; ++xm)
        match_disparity[size_t(xm)] = winner(match_sum.data() + size_t(xm) * size_t(dmax), dmax);
    }
    if (side.right != nullptr)
      for (int xm = 0; xm < width; ++xm) side.right->at(xm, y) = uint16_t(match_disparity[size_t(xm)]);
    if (cfg.lr != LrCheck::None)
      for (int x = 0; x < width; ++x) {
        if (row[x] == kInvalid) continue;
        const int xm = x - cfg.min_disp - row[x];
        if (xm < 0 || xm >= width || std::abs(row[x] - match_disparity[size_t(xm)]) > cfg.lr_threshold)
          row[x] = kInvalid;
      }
    // The checks above use the whole disparity; the stages below the refined one.
    for (int x = 0; x < width; ++x)
      if (row[x] != kInvalid) row[x] = refined[size_t(x)];
  }

  if (cfg.median != 0) disparity = median_filter(disparity, cfg.median, ((dmax - 1) << cfg.subpixel_bits) + 1);
  if (cfg.gap_interpolation) interpolate_gaps(disparity);

  DisparityImage out(width, height);
  for (size_t i = 0; i < out.pixels.size(); ++i)
    out.pixels[i] = disparity.pixels[i] == kInvalid ? widths.invalid_word : uint16_t(disparity.pixels[i]);
  return out;
}

}  // namespace

DisparityImage run_golden(const StereoConfig& cfg, const GrayImage& left, const GrayImage& right,
                          const SideViews& side) {
  if (left.width != right.width || left.height != right.height || left.width > cfg.width ||
      left.height > cfg.height || left.width < 1 || left.height < 1)
    throw std::invalid_argument("run_golden: images must have equal sizes within the configured size");
  if (side.right != nullptr) {
    if (cfg.lr == LrCheck::None) throw std::invalid_argument("run_golden: the right view needs a left-right check");
    *side.right = DisparityImage(left.width, left.height);
  }
  if (side.confidence != nullptr) *side.confidence = DisparityImage(left.width, left.height);
  const Widths widths = derive_widths(cfg);
  // 16-bit storage whenever sums, and the sentinel above any path cost plus P2, fit.
  if (widths.aggregated_max + uint64_t(cfg.p2) + 512 < 65535 &&
      widths.path_cost_max + 2u * uint64_t(cfg.p2) + 512 < 65535)
    return run_pipeline<uint16_t>(cfg, widths, left, right, side);
  return run_pipeline<uint32_t>(cfg, widths, left, right, side);
}

}  // namespace fpstereo
