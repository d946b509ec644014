// The golden model's streaming stages (docs/semantics.md sections 1-3 and 5a), each a class that
// turns one row of its input into one row of output, as the hardware stages do. Exposed so
// that tests can drive a single stage to its extremes.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <optional>
#include <vector>

#include "config.hpp"
#include "image.hpp"
#include "widths.hpp"

namespace fpstereo::golden {

// ---------------------------------------------------------------------------------------------
// Section 1-2: transforms and matching cost rows.

// Census codes of up to 120 bits (11x11 window), as planes of 64-bit words: plane 0 holds the
// low 64 bits of every pixel's code, plane 1 the rest, so that the transform and the Hamming
// distances run over contiguous words.
constexpr int kMaxCodeWords = 2;
struct CensusPlanes {
  int words = 1;  // planes in use: 1 for codes of at most 64 bits
  std::array<Image<uint64_t>, kMaxCodeWords> plane;
  // popcount(a(xa) xor b(xb)) on row y.
  static int hamming(const CensusPlanes& a, int xa, const CensusPlanes& b, int xb, int y) {
    int h = 0;
    for (int i = 0; i < a.words; ++i) h += __builtin_popcountll(a.plane[size_t(i)].at(xa, y) ^ b.plane[size_t(i)].at(xb, y));
    return h;
  }
};

inline int pixel_or_zero(const GrayImage& img, int x, int y) { return img.contains(x, y) ? img.at(x, y) : 0; }

// The image with a frame of r zero pixels, so windows need no bounds tests (section 1).
inline GrayImage zero_padded(const GrayImage& img, int r) {
  GrayImage padded(img.width + 2 * r, img.height + 2 * r, 0);
  for (int y = 0; y < img.height; ++y)
    std::copy(&img.at(0, y), &img.at(0, y) + img.width, &padded.at(r, y + r));
  return padded;
}

// Calls visit(x, y, centre, window_pixel) for every pixel and every window position but the
// centre, in raster order of window positions.
template <class Visit>
void for_each_window_neighbour(const GrayImage& img, int window, Visit visit) {
  const int r = window / 2;
  const GrayImage padded = zero_padded(img, r);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const int centre = img.at(x, y);
      for (int dy = -r; dy <= r; ++dy) {
        const uint8_t* row = &padded.at(x + r, y + r + dy);
        for (int dx = -r; dx <= r; ++dx)
          if (dx != 0 || dy != 0) visit(x, y, centre, int(row[dx]));
      }
    }
}

// Census codes of image row y, columns begin .. end - 1, into planes[0][x] (low 64 bits) and
// planes[1][x] (the rest, for codes above 64 bits); padded: scratch for width + window - 1 pixels.
inline void census_row(const GrayImage& img, int y, int window, uint8_t* padded,
                       const std::array<uint64_t*, kMaxCodeWords>& planes, int begin, int end) {
  const int r = window / 2, bits = window * window - 1, width = img.width;
  for (int i = 0; i < (bits + 63) / 64; ++i) std::fill(planes[size_t(i)] + begin, planes[size_t(i)] + end, 0);
  const uint8_t* centre = &img.at(0, y);
  int bit = bits - 1;  // the first window position in the most significant bit
  for (int dy = -r; dy <= r; ++dy) {
    // Row y + dy with r zeros on each side, all zeros outside the image (section 1).
    std::fill(padded, padded + width + 2 * r, 0);
    if (y + dy >= 0 && y + dy < img.height) std::copy(&img.at(0, y + dy), &img.at(0, y + dy) + width, padded + r);
    for (int dx = -r; dx <= r; ++dx) {
      if (dx == 0 && dy == 0) continue;
      const uint8_t* neighbour = padded + r + dx;
      uint64_t* codes = planes[size_t(bit / 64)];
      const int shift = bit % 64;
      for (int x = begin; x < end; ++x) codes[x] |= uint64_t(centre[x] > neighbour[x]) << shift;
      --bit;
    }
  }
}

inline CensusPlanes census_transform(const GrayImage& img, int window) {
  CensusPlanes codes;
  codes.words = (window * window - 1 + 63) / 64;
  for (int i = 0; i < codes.words; ++i) codes.plane[size_t(i)] = Image<uint64_t>(img.width, img.height, 0);
  std::vector<uint8_t> padded(size_t(img.width + window - 1));
  for (int y = 0; y < img.height; ++y) {
    std::array<uint64_t*, kMaxCodeWords> rows{};
    for (int i = 0; i < codes.words; ++i) rows[size_t(i)] = &codes.plane[size_t(i)].at(0, y);
    census_row(img, y, window, padded.data(), rows, 0, img.width);
  }
  return codes;
}

inline Image<int> rank_transform(const GrayImage& img, int window) {
  Image<int> ranks(img.width, img.height, 0);
  for_each_window_neighbour(img, window,
                            [&](int x, int y, int centre, int q) { ranks.at(x, y) += q < centre; });
  return ranks;
}

// floor(window sum / N^2) over the zero-extended image (ZSAD).
inline Image<int> window_means(const GrayImage& img, int window) {
  Image<int> sums(img.width, img.height, 0);
  for_each_window_neighbour(img, window, [&](int x, int y, int, int q) { sums.at(x, y) += q; });
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) sums.at(x, y) = (sums.at(x, y) + img.at(x, y)) / (window * window);
  return sums;
}

// Produces C(x, y, d) for one row, laid out [x * dmax + d].
template <class T>
class CostRows {
 public:
  CostRows(const StereoConfig& cfg, const Widths& widths, const GrayImage& base, const GrayImage& match)
      : cfg_(cfg), cost_max_(T(widths.cost_max)), base_(base), match_(match) {
    switch (cfg.cost) {
      case CostFunction::Census:
        // Codes row by row as compute() needs them (section 1-2), in buffers kept across rows.
        padded_.resize(size_t(base.width + cfg.window - 1));
        for (auto* row : {&base_row_, &match_row_, &mirrored_row_})
          for (auto& plane : *row) plane.resize(size_t(base.width));
        break;
      case CostFunction::Shd:
        base_codes_ = census_transform(base, cfg.window);
        match_codes_ = census_transform(match, cfg.window);
        break;
      case CostFunction::Rank:
        base_ranks_ = rank_transform(base, cfg.window);
        match_ranks_ = rank_transform(match, cfg.window);
        break;
      case CostFunction::Zsad:
        base_means_ = window_means(base, cfg.window);
        match_means_ = window_means(match, cfg.window);
        break;
      case CostFunction::Sad:
        break;
    }
    if (cfg.fused_weight != 0) {
      // The term of every difference a row can hold: intensities 0 .. 255, gradients 0 .. 510.
      fused_term_of_.resize(511);
      for (int diff = 0; diff <= 510; ++diff)
        fused_term_of_[size_t(diff)] = T(cfg.fused_weight * std::min(diff, cfg.fused_trunc) / kFusedWeightDivisor);
      base_feature_.resize(size_t(base.width));
      match_feature_.resize(size_t(base.width));
    }
  }

  // Index d is the disparity min_disp + d: base pixel x against match pixel x - min_disp - d.
  // Writes the costs of columns begin .. end - 1 (a band of the row, docs/golden-model-speed.md,
  // "Threads within a frame") at their places in the row.
  void compute(int y, T* out) { compute(y, out, 0, base_.width); }
  void compute(int y, T* out, int begin, int end) {
    const int width = base_.width, dmax = cfg_.dmax, m = cfg_.min_disp;
    // The indices whose match pixel lies in the row: d_lo(x) <= d < d_hi(x).
    auto d_lo = [&](int x) { return std::clamp(x - m - width + 1, 0, dmax); };
    auto d_hi = [&](int x) { return std::clamp(x - m + 1, 0, dmax); };
    switch (cfg_.cost) {
      case CostFunction::Census:
        census_costs(y, out, begin, end);
        break;
      case CostFunction::Rank:
        for (int x = begin; x < end; ++x)
          for (int d = d_lo(x); d < d_hi(x); ++d)
            out[x * dmax + d] = T(std::abs(base_ranks_.at(x, y) - match_ranks_.at(x - m - d, y)));
        break;
      case CostFunction::Sad:
        box_sum_row(y, cfg_.window, out, begin, end, [&](int xb, int yy, int d) {
          return std::abs(pixel_or_zero(base_, xb, yy) - pixel_or_zero(match_, xb - m - d, yy));
        });
        break;
      case CostFunction::Shd:
        box_sum_row(y, cfg_.shd_window, out, begin, end, [&](int xb, int yy, int d) {
          return shd_term(xb, xb - m - d, yy);
        });
        break;
      case CostFunction::Zsad:
        for (int x = begin; x < end; ++x)
          for (int d = d_lo(x); d < d_hi(x); ++d) out[x * dmax + d] = T(zsad(x, y, m + d));
        break;
    }
    if (cfg_.fused_weight != 0) add_fused_term(y, out, begin, end);
    // Match pixel outside the row: the largest cost.
    for (int x = begin; x < end; ++x) {
      for (int d = 0; d < d_lo(x); ++d) out[x * dmax + d] = cost_max_;
      for (int d = d_hi(x); d < dmax; ++d) out[x * dmax + d] = cost_max_;
    }
  }

 private:
  // Census costs of row y: per base pixel, the Hamming distances to the match codes of its
  // disparity range, a loop over contiguous words that the compiler vectorises.
  void census_costs(int y, T* out, int begin, int end) {
    const int width = base_.width, dmax = cfg_.dmax, m = cfg_.min_disp;
    const bool two_words = cfg_.window * cfg_.window - 1 > 64;
    census_row(base_, y, cfg_.window, padded_.data(), {base_row_[0].data(), base_row_[1].data()}, begin, end);
    // The match pixels the band reads, x - m - d for d in 0 .. dmax - 1.
    const int match_begin = std::clamp(begin - m - dmax + 1, 0, width), match_end = std::clamp(end - m, 0, width);
    if (match_begin < match_end)
      census_row(match_, y, cfg_.window, padded_.data(), {match_row_[0].data(), match_row_[1].data()}, match_begin,
                 match_end);
    // The match codes reversed: ascending disparities then read ascending addresses.
    for (int i = 0; i < (two_words ? 2 : 1); ++i)
      for (int xm = match_begin; xm < match_end; ++xm)
        mirrored_row_[size_t(i)][size_t(width - 1 - xm)] = match_row_[size_t(i)][size_t(xm)];
    const uint64_t* base0 = base_row_[0].data();
    const uint64_t* mirrored0 = mirrored_row_[0].data();
    const uint64_t* base1 = two_words ? base_row_[1].data() : nullptr;
    const uint64_t* mirrored1 = two_words ? mirrored_row_[1].data() : nullptr;
    for (int x = begin; x < end; ++x) {
      const int lo = std::clamp(x - m - width + 1, 0, dmax), hi = std::clamp(x - m + 1, 0, dmax);
      T* __restrict costs = out + size_t(x) * size_t(dmax);
      // The match pixel x - m - d sits at width - 1 - x + m + d of the mirrored row.
      const ptrdiff_t at_d0 = width - 1 - x + m;
      const uint64_t b0 = base0[x];
      const uint64_t* __restrict m0 = mirrored0 + at_d0;
      if (base1 == nullptr) {
        for (int d = lo; d < hi; ++d) costs[d] = T(__builtin_popcountll(b0 ^ m0[d]));
      } else {
        const uint64_t b1 = base1[x];
        const uint64_t* __restrict m1 = mirrored1 + at_d0;
        for (int d = lo; d < hi; ++d) costs[d] = T(__builtin_popcountll(b0 ^ m0[d]) + __builtin_popcountll(b1 ^ m1[d]));
      }
    }
  }

  // The fused cost's pixel-wise term (section 2) added to the costs of row y whose match pixel
  // lies in the row.
  void add_fused_term(int y, T* out, int begin, int end) {
    const int width = base_.width, dmax = cfg_.dmax, m = cfg_.min_disp;
    pixel_features(base_, y, base_feature_);
    pixel_features(match_, y, match_feature_);
    for (int x = begin; x < end; ++x) {
      const int lo = std::clamp(x - m - width + 1, 0, dmax), hi = std::clamp(x - m + 1, 0, dmax);
      for (int d = lo; d < hi; ++d)
        out[x * dmax + d] += fused_term_of_[size_t(std::abs(base_feature_[size_t(x)] - match_feature_[size_t(x - m - d)]))];
    }
  }

  // Row y's intensities, or its horizontal gradients I(x+1, y) - I(x-1, y) on the zero-extended image.
  void pixel_features(const GrayImage& img, int y, std::vector<int>& feature) const {
    for (int x = 0; x < img.width; ++x)
      feature[size_t(x)] = cfg_.fused_term == FusedTerm::Intensity
                               ? img.at(x, y)
                               : pixel_or_zero(img, x + 1, y) - pixel_or_zero(img, x - 1, y);
  }

  // One SHD term: the Hamming distance of two census codes, each zero outside the image.
  int shd_term(int xb, int xm, int y) const {
    const bool base_in = base_codes_.plane[0].contains(xb, y), match_in = base_codes_.plane[0].contains(xm, y);
    if (base_in && match_in) return CensusPlanes::hamming(base_codes_, xb, match_codes_, xm, y);
    int h = 0;
    for (int i = 0; i < base_codes_.words; ++i) {
      const uint64_t code = base_in ? base_codes_.plane[size_t(i)].at(xb, y)
                            : match_in ? match_codes_.plane[size_t(i)].at(xm, y) : 0;
      h += __builtin_popcountll(code);
    }
    return h;
  }

  // out[x, d] for x in begin .. end - 1 = sum over the window x offsets of (sum over the window
  // rows of term(x', y', d)), as a column sum followed by a sliding horizontal sum.
  template <class Term>
  void box_sum_row(int y, int window, T* out, int begin, int end, Term term) const {
    const int dmax = cfg_.dmax, r = window / 2;
    std::vector<int> column(size_t(end - begin + 2 * r));  // columns begin - r .. end + r - 1
    for (int d = 0; d < dmax; ++d) {
      for (int xc = begin - r; xc < end + r; ++xc) {
        int sum = 0;
        for (int dy = -r; dy <= r; ++dy) sum += term(xc, y + dy, d);
        column[size_t(xc - begin + r)] = sum;
      }
      int sum = 0;
      for (int i = 0; i < window - 1; ++i) sum += column[size_t(i)];
      for (int x = begin; x < end; ++x) {
        sum += column[size_t(x - begin + 2 * r)];
        out[x * dmax + d] = T(sum);
        sum -= column[size_t(x - begin)];
      }
    }
  }

  // The ZSAD cost of base pixel x against match pixel x - shift.
  int zsad(int x, int y, int shift) const {
    const int r = cfg_.window / 2;
    const int base_mean = base_means_.at(x, y), match_mean = match_means_.at(x - shift, y);
    int sum = 0;
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx)
        sum += std::abs((pixel_or_zero(base_, x + dx, y + dy) - base_mean) -
                        (pixel_or_zero(match_, x - shift + dx, y + dy) - match_mean));
    return sum;
  }

  const StereoConfig& cfg_;
  const T cost_max_;
  const GrayImage& base_;
  const GrayImage& match_;
  CensusPlanes base_codes_, match_codes_;  // SHD
  // Census: one row of codes per image, the match row also reversed, and scratch for census_row.
  std::array<std::vector<uint64_t>, kMaxCodeWords> base_row_, match_row_, mirrored_row_;
  std::vector<uint8_t> padded_;
  Image<int> base_ranks_, match_ranks_;
  Image<int> base_means_, match_means_;
  std::vector<T> fused_term_of_;                   // the fused term by pixel-wise difference
  std::vector<int> base_feature_, match_feature_;  // one row of intensities or gradients
};

// ---------------------------------------------------------------------------------------------
// Section 3: path costs and their sum, one row at a time. Each raster-order path keeps two rows,
// row y in buffer y % 2: the row it is writing and the previous row; the 0-degree path reads its
// predecessor from the row being written. The 180-degree path runs over the row once its costs
// are all known, from the last pixel to the first, in a second pass that adds to the sums.
// A row may be pushed in column bands, from several threads, in an order that respects the
// recursion's dependencies (golden_model.cpp, "Column bands"): a pixel of a raster-order path
// reads its left neighbour in its row and three neighbours in the row above; of the 180-degree
// path, its right neighbour.
// With mgm on, each path also reads a second predecessor, a right angle from the first
// (section 3, "MGM"): the 0-degree path's is (x, y-1), the 90-degree path's (x-1, y).
template <class T>
class PathAggregator {
 public:
  // adapt: the gain k of the adaptive P2 (0: constant P2), for the side whose image guides it.
  PathAggregator(const StereoConfig& cfg, int width, T sentinel, int adapt)
      : cfg_(cfg), width_(width), stride_(cfg.dmax + 2), adapt_(adapt), zeros_(size_t(stride_), T(0)) {
    for (const auto& dir : path_directions())
      if ((cfg.paths & dir.mask) && dir.mask != kPath180)
        paths_.push_back(PathState{dir, cfg.mgm ? mgm_offset(dir) : Offset{},
                                   {RowBuffer(width, stride_, sentinel), RowBuffer(width, stride_, sentinel)}});
    if (cfg.paths & kPath180) right_to_left_.emplace(width, stride_, sentinel);
  }

  // Consumes the cost row of image row y (rows arrive in order 0, 1, ...) and writes S; guide is
  // the image whose steps lower P2 (read only when adapt is not 0).
  void push_row(int y, const T* cost, T* sum, const GrayImage& guide) {
    last_row_ = y;
    push_band(y, cost, sum, guide, 0, width_);
    if (right_to_left_) push_band_right_to_left(y, cost, sum, guide, 0, width_);
  }

  // The raster-order paths alone on columns begin .. end - 1 of row y (cost and sum: the whole
  // row's layout); they write the sums.
  void push_band(int y, const T* cost, T* sum, const GrayImage& guide, int begin, int end) {
    if (paths_.empty()) {
      std::fill(sum + size_t(begin) * size_t(cfg_.dmax), sum + size_t(end) * size_t(cfg_.dmax), T(0));
    } else if (!cfg_.mgm) {
      switch (paths_.size()) {
        case 1: push_band_fused<1>(y, cost, sum, guide, begin, end); break;
        case 2: push_band_fused<2>(y, cost, sum, guide, begin, end); break;
        case 3: push_band_fused<3>(y, cost, sum, guide, begin, end); break;
        default: push_band_fused<4>(y, cost, sum, guide, begin, end); break;
      }
    } else {
      const size_t dmax = size_t(cfg_.dmax);
      for (int x = begin; x < end; ++x) {
        T* S = sum + size_t(x) * dmax;
        std::fill(S, S + dmax, T(0));
        for (auto& path : paths_)
          path.rows[y & 1].minimum[size_t(x)] = push_mgm_pixel(path, x, y, cost + size_t(x) * dmax, S, guide);
      }
    }
  }

  bool has_right_to_left() const { return right_to_left_.has_value(); }

  // The 180-degree path on columns end - 1 down to begin of row y, each pixel against its right
  // neighbour (x + 1, y), the row's last pixel a path start; adds its costs to the sums the
  // raster-order paths wrote. Column end, if any, is of the same row (pushed before).
  void push_band_right_to_left(int y, const T* cost, T* sum, const GrayImage& guide, int begin, int end) {
    const size_t dmax = size_t(cfg_.dmax);
    RowBuffer& row = *right_to_left_;
    // The predecessor that pixel x - 1 reads.
    auto at = [&](int x) {
      const T minimum = row.minimum[size_t(x)];
      return Predecessor{row.costs(x), minimum, T(minimum + penalty2(guide.at(x - 1, y), guide.at(x, y)))};
    };
    std::array<T, 1> minimum;
    Predecessor pred = end < width_ ? at(end) : Predecessor{zeros_.data() + 1, 0, 0};
    for (int x = end - 1; x >= begin; --x) {
      step_paths<1>(cost + size_t(x) * dmax, sum + size_t(x) * dmax, {pred}, {row.costs(x)}, minimum);
      row.minimum[size_t(x)] = minimum[0];
      if (x > 0) pred = at(x);
    }
  }

  // The path costs of the last row pushed, for tests that check widths.
  T max_path_cost() const {
    T m = 0;
    auto row_max = [&](const RowBuffer& row) {
      for (int x = 0; x < width_; ++x) {
        const T* L = row.costs(x);
        m = std::max(m, *std::max_element(L, L + cfg_.dmax));
      }
    };
    for (const auto& path : paths_) row_max(path.rows[last_row_ & 1]);
    if (right_to_left_) row_max(*right_to_left_);
    return m;
  }

 private:
  // One row of path costs: dmax values per pixel framed by a sentinel on each side, so the
  // d-1 and d+1 terms need no range test (the sentinel never wins the minimum).
  struct RowBuffer {
    RowBuffer(int width, int stride, T sentinel)
        : stride(stride), values(size_t(width) * size_t(stride), sentinel), minimum(size_t(width), 0) {}
    T* costs(int x) { return values.data() + size_t(x) * size_t(stride) + 1; }
    const T* costs(int x) const { return values.data() + size_t(x) * size_t(stride) + 1; }
    int stride;
    std::vector<T> values;
    std::vector<T> minimum;
  };
  // A predecessor's offset from the pixel; used = false: none.
  struct Offset {
    int dx = 0, dy = 0;
    bool used = false;
  };
  // MGM's second predecessor: the first turned by a right angle, towards the causal side.
  static Offset mgm_offset(const PathDirection& dir) {
    switch (dir.angle) {
      case 0: return {0, -1, true};    // after (x-1, y): (x, y-1)
      case 45: return {1, -1, true};   // after (x-1, y-1): (x+1, y-1)
      case 90: return {-1, 0, true};   // after (x, y-1): (x-1, y)
      default: return {-1, -1, true};  // 135, after (x+1, y-1): (x-1, y-1)
    }
  }
  struct PathState {
    PathDirection dir;
    Offset second;
    std::array<RowBuffer, 2> rows;  // row y in rows[y % 2]
  };

  // One predecessor in the recursion of section 3: its path costs, their minimum, and the jump
  // minimum + P2. A path start reads a row of zeros (minimum 0, jump 0), which makes L = C.
  struct Predecessor {
    const T* costs;
    T minimum, jump;
  };
  [[gnu::always_inline]] Predecessor predecessor(const PathState& path, Offset o, int x, int y, const GrayImage& guide) const {
    if (x + o.dx < 0 || x + o.dx >= width_ || (o.dy != 0 && y == 0)) return {zeros_.data() + 1, 0, 0};
    const RowBuffer& row = path.rows[(y + o.dy) & 1];
    const int px = x + o.dx;
    const T minimum = row.minimum[size_t(px)];
    return {row.costs(px), minimum, T(minimum + penalty2(guide.at(x, y), guide.at(px, y + o.dy)))};
  }

  // Without MGM: every path of a pixel in one pass over the disparities, so that the pixel's
  // costs are read and its sums written once.
  template <int N>
  void push_band_fused(int y, const T* cost, T* sum, const GrayImage& guide, int begin, int end) {
    const size_t dmax = size_t(cfg_.dmax);
    std::array<Predecessor, N> pred;
    std::array<T*, N> L;
    std::array<T, N> minimum;
    for (int x = begin; x < end; ++x) {
      T* S = sum + size_t(x) * dmax;
      std::fill(S, S + dmax, T(0));
      for (int p = 0; p < N; ++p) {
        PathState& path = paths_[size_t(p)];
        pred[size_t(p)] = predecessor(path, {path.dir.dx, path.dir.dy, true}, x, y, guide);
        L[size_t(p)] = path.rows[y & 1].costs(x);
      }
      step_paths<N>(cost + size_t(x) * dmax, S, pred, L, minimum);
      for (int p = 0; p < N; ++p) paths_[size_t(p)].rows[y & 1].minimum[size_t(x)] = minimum[size_t(p)];
    }
  }

  // With MGM: path costs of pixel (x, y) on one path; adds them to S and returns their minimum.
  T push_mgm_pixel(PathState& path, int x, int y, const T* C, T* S, const GrayImage& guide) const {
    const Offset first{path.dir.dx, path.dir.dy, true}, second = path.second;
    auto inside = [&](Offset o) { return x + o.dx >= 0 && x + o.dx < width_ && (o.dy == 0 || y > 0); };
    T* L = path.rows[y & 1].costs(x);
    if (inside(first) && inside(second))
      return step2(C, predecessor(path, first, x, y, guide), predecessor(path, second, x, y, guide), L, S);
    std::array<T, 1> minimum;
    step_paths<1>(C, S, {predecessor(path, inside(first) ? first : second, x, y, guide)}, {L}, minimum);
    return minimum[0];
  }

  // Section 3's P2 between a pixel of intensity i and its predecessor's, j.
  int penalty2(int i, int j) const {
    return adapt_ == 0 ? cfg_.p2 : std::max(cfg_.p1, cfg_.p2 - ((adapt_ * std::abs(i - j)) >> 2));
  }

  // The recursion of section 3 on N paths, each against its own predecessor: writes each
  // path's L and minimum and adds the L to S.
  template <int N>
  void step_paths(const T* __restrict C, T* __restrict S, const std::array<Predecessor, N>& pred,
                  const std::array<T*, N>& L, std::array<T, N>& minimum) const {
    const T p1 = T(cfg_.p1);
    minimum.fill(std::numeric_limits<T>::max());
    // Each L is its own pixel's slot, apart from every predecessor, C and S.
#pragma GCC ivdep
    for (int d = 0; d < cfg_.dmax; ++d) {
      T s = S[d];
      for (int p = 0; p < N; ++p) {
        const T* q = pred[size_t(p)].costs;
        const T neighbour = T(std::min(q[d - 1], q[d + 1]) + p1);
        const T l = T(C[d] + std::min(std::min(q[d], pred[size_t(p)].jump), neighbour) - pred[size_t(p)].minimum);
        L[size_t(p)][d] = l;
        s = T(s + l);
        minimum[size_t(p)] = std::min(minimum[size_t(p)], l);
      }
      S[d] = s;
    }
  }

  // MGM's recursion with two predecessors: C plus the floor of the mean of the two predecessor
  // terms, each as in step_paths() against its own predecessor; adds L to S and returns min_d L.
  T step2(const T* __restrict C, const Predecessor& first, const Predecessor& second, T* __restrict L,
          T* __restrict S) const {
    const T p1 = T(cfg_.p1);
    const T* __restrict pred1 = first.costs;
    const T* __restrict pred2 = second.costs;
    T minimum = std::numeric_limits<T>::max();
    for (int d = 0; d < cfg_.dmax; ++d) {
      const T t1 =
          T(std::min(std::min(pred1[d], first.jump), T(std::min(pred1[d - 1], pred1[d + 1]) + p1)) - first.minimum);
      const T t2 =
          T(std::min(std::min(pred2[d], second.jump), T(std::min(pred2[d - 1], pred2[d + 1]) + p1)) - second.minimum);
      const T l = T(C[d] + ((t1 + t2) >> 1));
      L[d] = l;
      S[d] = T(S[d] + l);
      minimum = std::min(minimum, l);
    }
    return minimum;
  }

  const StereoConfig& cfg_;
  const int width_, stride_, adapt_;
  std::vector<PathState> paths_;            // the raster-order paths
  std::optional<RowBuffer> right_to_left_;  // the 180-degree path's costs of the last row
  std::vector<T> zeros_;  // the predecessor of a path start
  int last_row_ = 0;  // of push_row(), for max_path_cost()
};

// ---------------------------------------------------------------------------------------------
// Section 5a: the speckle filter, in one pass over the rows as the hardware will run it.
//
// Each row is cut into runs: maximal horizontal stretches of valid words whose neighbours differ
// by at most the range. A run gets a label, and union-find joins it with every label above it
// that a vertical neighbour pair within the range connects. A region's count of pixels lives at
// its root and saturates at S + 1; the root is always a label of the newest row the region
// reaches (a union always involves a label of the row being labelled, and that one becomes the
// root), so no parent lies in an older row than its child, and no label in use points into a
// row that has left the ring.
//
// Delay: row y leaves after row y + S has been labelled, S rows. By then the region of each of
// its pixels is decided: if it still has a pixel in row y + S it spans at least S + 1 rows, so
// it has more than S pixels and is kept; otherwise it is closed (no later row can reach it) and
// its count is final. Either way "count > S" is the region's fate, the same rule at every
// pixel. Once the frame has ended every region is closed and the rows still held leave.
//
// Memory, the hardware's budget: S + 1 rows of words and of labels (a label per pixel, a run's
// label = slot * width + the run's first column, so L = min(S + 1, H) * width labels of
// bits_for(L - 1) bits) and, per label, its parent and its count of bits_for(S + 1) bits. A
// frame of at most S + 1 rows is held whole.
class SpeckleFilter {
 public:
  // size: S >= 1; range: the largest step within a region, in output-word units (r << sub-pixel
  // bits); invalid: the invalid word, never part of a region.
  SpeckleFilter(int width, int height, int size, int range, uint16_t invalid)
      : width_(width), size_(size), range_(range), invalid_(invalid), slots_(std::min(size + 1, height)),
        words_(size_t(slots_) * size_t(width)), labels_(words_.size()), parent_(words_.size()),
        count_(words_.size()) {}

  // Labels the next row (rows 0, 1, ... in order).
  void push_row(const uint16_t* words) {
    const int y = pushed_++;
    uint16_t* row = word_row(y);
    int* labels = label_row(y);
    const uint16_t* above = y > 0 ? word_row(y - 1) : nullptr;
    const int* above_labels = y > 0 ? label_row(y - 1) : nullptr;
    std::copy(words, words + width_, row);
    for (int x = 0; x < width_; ++x) {
      if (row[x] == invalid_) {
        labels[x] = kNoLabel;
        continue;
      }
      if (x > 0 && connected(row[x - 1], row[x])) {
        labels[x] = labels[x - 1];
        int& count = count_[size_t(find(labels[x]))];
        count = std::min(count + 1, size_ + 1);
      } else {
        labels[x] = slot(y) * width_ + x;  // a new run
        parent_[size_t(labels[x])] = labels[x];
        count_[size_t(labels[x])] = 1;
      }
      if (above != nullptr && connected(above[x], row[x])) unite(labels[x], above_labels[x]);
    }
  }

  // Writes row y with its speckles invalid: once row y + S has been pushed, or for any row still
  // held once the last row of the frame has been.
  void decided_row(int y, uint16_t* out) {
    const uint16_t* row = word_row(y);
    const int* labels = label_row(y);
    for (int x = 0; x < width_; ++x)
      out[x] = row[x] != invalid_ && count_[size_t(find(labels[x]))] <= size_ ? invalid_ : row[x];
  }

 private:
  static constexpr int kNoLabel = -1;

  int slot(int y) const { return y % slots_; }
  uint16_t* word_row(int y) { return words_.data() + size_t(slot(y)) * size_t(width_); }
  int* label_row(int y) { return labels_.data() + size_t(slot(y)) * size_t(width_); }

  // Both valid and within the range of each other.
  bool connected(uint16_t a, uint16_t b) const {
    return a != invalid_ && b != invalid_ && std::abs(int(a) - int(b)) <= range_;
  }

  int find(int label) {
    while (parent_[size_t(label)] != label) {
      parent_[size_t(label)] = parent_[size_t(parent_[size_t(label)])];  // path halving: never to an older row
      label = parent_[size_t(label)];
    }
    return label;
  }

  // current: a label of the row being labelled, whose root stays the root.
  void unite(int current, int above) {
    const int root = find(current), other = find(above);
    if (root == other) return;
    parent_[size_t(other)] = root;
    count_[size_t(root)] = std::min(count_[size_t(root)] + count_[size_t(other)], size_ + 1);
  }

  const int width_, size_, range_;
  const uint16_t invalid_;
  const int slots_;  // S + 1 rows, the one labelled and the S it decides, or the whole frame
  std::vector<uint16_t> words_;
  std::vector<int> labels_, parent_, count_;
  int pushed_ = 0;
};

// Section 5a on a map of words, in place: row y is written back once the filter has decided it,
// S rows after it entered.
inline void speckle_filter(DisparityImage& map, int size, int range, uint16_t invalid) {
  SpeckleFilter filter(map.width, map.height, size, range, invalid);
  for (int y = 0; y < map.height; ++y) {
    filter.push_row(&map.at(0, y));
    if (y >= size) filter.decided_row(y - size, &map.at(0, y - size));
  }
  for (int y = std::max(0, map.height - size); y < map.height; ++y) filter.decided_row(y, &map.at(0, y));
}

}  // namespace fpstereo::golden
