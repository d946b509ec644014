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
#include "widths.hpp"

namespace fpstereo {
namespace {

// ---------------------------------------------------------------------------------------------
// Section 1-2: transforms and matching cost rows.

// Census codes of up to 120 bits (11x11 window), stored in 64-bit words.
constexpr int kMaxCodeWords = 2;
using CensusCode = std::array<uint64_t, kMaxCodeWords>;

int pixel_or_zero(const GrayImage& img, int x, int y) {
  return img.contains(x, y) ? img.at(x, y) : 0;
}

Image<CensusCode> census_transform(const GrayImage& img, int window) {
  const int r = window / 2;
  Image<CensusCode> codes(img.width, img.height, CensusCode{});
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const int centre = img.at(x, y);
      CensusCode code{};
      int bit = window * window - 2;  // first window position in the most significant bit
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
          if (dx == 0 && dy == 0) continue;
          if (centre > pixel_or_zero(img, x + dx, y + dy)) code[bit / 64] |= uint64_t(1) << (bit % 64);
          --bit;
        }
      codes.at(x, y) = code;
    }
  return codes;
}

Image<int> rank_transform(const GrayImage& img, int window) {
  const int r = window / 2;
  Image<int> ranks(img.width, img.height, 0);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const int centre = img.at(x, y);
      int rank = 0;
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) rank += pixel_or_zero(img, x + dx, y + dy) < centre ? 1 : 0;
      ranks.at(x, y) = rank;
    }
  return ranks;
}

// floor(window sum / N^2) over the zero-extended image (ZSAD).
Image<int> window_means(const GrayImage& img, int window) {
  const int r = window / 2;
  Image<int> means(img.width, img.height, 0);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      int sum = 0;
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) sum += pixel_or_zero(img, x + dx, y + dy);
      means.at(x, y) = sum / (window * window);
    }
  return means;
}

int hamming(const CensusCode& a, const CensusCode& b) {
  int h = 0;
  for (int i = 0; i < kMaxCodeWords; ++i) h += __builtin_popcountll(a[i] ^ b[i]);
  return h;
}

// Produces C(x, y, d) for one row, laid out [x * dmax + d].
template <class T>
class CostRows {
 public:
  CostRows(const StereoConfig& cfg, const Widths& widths, const GrayImage& base, const GrayImage& match)
      : cfg_(cfg), cost_max_(T(widths.cost_max)), base_(base), match_(match) {
    switch (cfg.cost) {
      case CostFunction::Census:
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
  }

  void compute(int y, T* out) const {
    const int width = base_.width, dmax = cfg_.dmax;
    switch (cfg_.cost) {
      case CostFunction::Census:
        for (int x = 0; x < width; ++x)
          for (int d = 0; d <= std::min(x, dmax - 1); ++d)
            out[x * dmax + d] = T(hamming(base_codes_.at(x, y), match_codes_.at(x - d, y)));
        break;
      case CostFunction::Rank:
        for (int x = 0; x < width; ++x)
          for (int d = 0; d <= std::min(x, dmax - 1); ++d)
            out[x * dmax + d] = T(std::abs(base_ranks_.at(x, y) - match_ranks_.at(x - d, y)));
        break;
      case CostFunction::Sad:
        box_sum_row(y, cfg_.window, out, [&](int xb, int yy, int d) {
          return std::abs(pixel_or_zero(base_, xb, yy) - pixel_or_zero(match_, xb - d, yy));
        });
        break;
      case CostFunction::Shd:
        box_sum_row(y, cfg_.shd_window, out, [&](int xb, int yy, int d) {
          return hamming(code_or_zero(base_codes_, xb, yy), code_or_zero(match_codes_, xb - d, yy));
        });
        break;
      case CostFunction::Zsad:
        for (int x = 0; x < width; ++x)
          for (int d = 0; d <= std::min(x, dmax - 1); ++d) out[x * dmax + d] = T(zsad(x, y, d));
        break;
    }
    // Match pixel outside the image (x - d < 0): the largest cost.
    for (int x = 0; x < std::min(width, dmax); ++x)
      for (int d = x + 1; d < dmax; ++d) out[x * dmax + d] = cost_max_;
  }

 private:
  static CensusCode code_or_zero(const Image<CensusCode>& codes, int x, int y) {
    return codes.contains(x, y) ? codes.at(x, y) : CensusCode{};
  }

  // out[x, d] = sum over the window x offsets of (sum over the window rows of term(x', y', d)),
  // as a column sum followed by a sliding horizontal sum.
  template <class Term>
  void box_sum_row(int y, int window, T* out, Term term) const {
    const int width = base_.width, dmax = cfg_.dmax, r = window / 2;
    std::vector<int> column(size_t(width + 2 * r));
    for (int d = 0; d < dmax; ++d) {
      for (int xc = -r; xc < width + r; ++xc) {
        int sum = 0;
        for (int dy = -r; dy <= r; ++dy) sum += term(xc, y + dy, d);
        column[size_t(xc + r)] = sum;
      }
      int sum = 0;
      for (int i = 0; i < window - 1; ++i) sum += column[size_t(i)];
      for (int x = 0; x < width; ++x) {
        sum += column[size_t(x + 2 * r)];
        out[x * dmax + d] = T(sum);
        sum -= column[size_t(x)];
      }
    }
  }

  int zsad(int x, int y, int d) const {
    const int r = cfg_.window / 2;
    const int base_mean = base_means_.at(x, y), match_mean = match_means_.at(x - d, y);
    int sum = 0;
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx)
        sum += std::abs((pixel_or_zero(base_, x + dx, y + dy) - base_mean) -
                        (pixel_or_zero(match_, x - d + dx, y + dy) - match_mean));
    return sum;
  }

  const StereoConfig& cfg_;
  const T cost_max_;
  const GrayImage& base_;
  const GrayImage& match_;
  Image<CensusCode> base_codes_, match_codes_;
  Image<int> base_ranks_, match_ranks_;
  Image<int> base_means_, match_means_;
};

// ---------------------------------------------------------------------------------------------
// Section 3: path costs and their sum, one row at a time. Each path keeps the row it is writing
// and the previous row; the 0-degree path reads its predecessor from the row being written.
template <class T>
class PathAggregator {
 public:
  PathAggregator(const StereoConfig& cfg, int width, T sentinel)
      : cfg_(cfg), width_(width), stride_(cfg.dmax + 2), sentinel_(sentinel) {
    for (const auto& dir : path_directions())
      if (cfg.paths & dir.mask) paths_.push_back(PathState{dir, RowBuffer(width, stride_, sentinel), RowBuffer(width, stride_, sentinel)});
  }

  // Consumes the cost row of image row y (rows arrive in order 0, 1, ...) and writes S.
  void push_row(int y, const T* cost, T* sum) {
    const int dmax = cfg_.dmax;
    std::fill(sum, sum + size_t(width_) * size_t(dmax), T(0));
    for (auto& path : paths_) {
      for (int x = 0; x < width_; ++x) {
        const int px = x + path.dir.dx;
        const bool has_pred = px >= 0 && px < width_ && (path.dir.dy == 0 || y > 0);
        T* L = path.current.costs(x);
        const T* C = cost + size_t(x) * size_t(dmax);
        if (has_pred) {
          const RowBuffer& pred_row = path.dir.dy == 0 ? path.current : path.previous;
          step(C, pred_row.costs(px), pred_row.minimum[size_t(px)], L);
        } else {
          std::copy(C, C + dmax, L);
        }
        path.current.minimum[size_t(x)] = *std::min_element(L, L + dmax);
        T* S = sum + size_t(x) * size_t(dmax);
        for (int d = 0; d < dmax; ++d) S[d] = T(S[d] + L[d]);
      }
      std::swap(path.current, path.previous);
    }
  }

  // The path costs of the last row pushed, for tests that check widths.
  T max_path_cost() const {
    T m = 0;
    for (const auto& path : paths_)
      for (int x = 0; x < width_; ++x) {
        const T* L = path.previous.costs(x);
        m = std::max(m, *std::max_element(L, L + cfg_.dmax));
      }
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
  struct PathState {
    PathDirection dir;
    RowBuffer current, previous;
  };

  void step(const T* C, const T* pred, T pred_min, T* L) const {
    const T p1 = T(cfg_.p1);
    const T jump = T(pred_min + cfg_.p2);
    for (int d = 0; d < cfg_.dmax; ++d) {
      const T neighbour = T(std::min(pred[d - 1], pred[d + 1]) + p1);
      L[d] = T(C[d] + std::min(std::min(pred[d], jump), neighbour) - pred_min);
    }
  }

  const StereoConfig& cfg_;
  const int width_, stride_;
  const T sentinel_;
  std::vector<PathState> paths_;
};

// ---------------------------------------------------------------------------------------------
// Section 4: winner-take-all and uniqueness over one pixel's sums.
template <class T>
int winner(const T* S, int dmax) {
  int best = 0;
  for (int d = 1; d < dmax; ++d)
    if (S[d] < S[best]) best = d;
  return best;
}

template <class T>
bool is_unique(const T* S, int dmax, int best, int ratio) {
  uint64_t second = std::numeric_limits<uint64_t>::max();
  for (int d = 0; d < dmax; ++d)
    if (std::abs(d - best) >= 2) second = std::min<uint64_t>(second, S[d]);
  return !(second * uint64_t(100 - ratio) < uint64_t(S[best]) * 100);
}

// Section 5, LR1: Dm(x') = argmin_d S(x' + d, d) over d with x' + d < W.
template <class T>
std::vector<int> match_disparities_from_base(const T* sum_row, int width, int dmax) {
  std::vector<int> dm(static_cast<size_t>(width));
  for (int xm = 0; xm < width; ++xm) {
    int best = 0;
    T best_sum = sum_row[size_t(xm) * size_t(dmax)];
    for (int d = 1; d < dmax && xm + d < width; ++d) {
      const T s = sum_row[size_t(xm + d) * size_t(dmax) + size_t(d)];
      if (s < best_sum) {
        best = d;
        best_sum = s;
      }
    }
    dm[size_t(xm)] = best;
  }
  return dm;
}

// ---------------------------------------------------------------------------------------------
// Sections 6-7 on a map of disparities with -1 for invalid.
constexpr int kInvalid = -1;

Image<int> median_filter(const Image<int>& in, int window) {
  const int r = window / 2;
  Image<int> out = in;
  std::vector<int> values;
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      if (in.at(x, y) == kInvalid) continue;
      values.clear();
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx)
          if (in.contains(x + dx, y + dy) && in.at(x + dx, y + dy) != kInvalid) values.push_back(in.at(x + dx, y + dy));
      const size_t lower_median = (values.size() - 1) / 2;
      std::nth_element(values.begin(), values.begin() + long(lower_median), values.end());
      out.at(x, y) = values[lower_median];
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
                            const GrayImage& right) {
  const int width = left.width, height = left.height, dmax = cfg.dmax;
  const size_t row_size = size_t(width) * size_t(dmax);
  // Larger than any path cost plus P2, and sentinel + P1 still fits in T.
  const T sentinel = T(std::numeric_limits<T>::max() - 256);

  CostRows<T> base_costs(cfg, widths, left, right);
  PathAggregator<T> base_paths(cfg, width, sentinel);
  PathAggregator<T> match_paths(cfg, width, sentinel);
  std::vector<T> cost(row_size), sum(row_size), match_cost, match_sum;
  if (cfg.lr == LrCheck::Lr2) {
    match_cost.resize(row_size);
    match_sum.resize(row_size);
  }

  Image<int> disparity(width, height, kInvalid);
  for (int y = 0; y < height; ++y) {
    base_costs.compute(y, cost.data());
    base_paths.push_row(y, cost.data(), sum.data());

    int* row = &disparity.at(0, y);
    for (int x = 0; x < width; ++x) {
      const T* S = sum.data() + size_t(x) * size_t(dmax);
      const int d = winner(S, dmax);
      row[x] = (cfg.uniqueness == 0 || is_unique(S, dmax, d, cfg.uniqueness)) ? d : kInvalid;
    }

    std::vector<int> match_disparity;
    if (cfg.lr == LrCheck::Lr1) match_disparity = match_disparities_from_base(sum.data(), width, dmax);
    if (cfg.lr == LrCheck::Lr2) {
      // Every cost is symmetric in its two images, so the match side's cost at (x', d) is the
      // base side's cost at (x' + d, d); beyond the right border it is Cmax (section 5).
      for (int xm = 0; xm < width; ++xm)
        for (int d = 0; d < dmax; ++d)
          match_cost[size_t(xm) * size_t(dmax) + size_t(d)] =
              xm + d < width ? cost[size_t(xm + d) * size_t(dmax) + size_t(d)] : T(widths.cost_max);
      match_paths.push_row(y, match_cost.data(), match_sum.data());
      match_disparity.resize(size_t(width));
      for (int xm = 0; xm < width; ++xm)
        match_disparity[size_t(xm)] = winner(match_sum.data() + size_t(xm) * size_t(dmax), dmax);
    }
    if (cfg.lr != LrCheck::None)
      for (int x = 0; x < width; ++x) {
        if (row[x] == kInvalid) continue;
        const int xm = x - row[x];
        if (xm < 0 || std::abs(row[x] - match_disparity[size_t(xm)]) > cfg.lr_threshold) row[x] = kInvalid;
      }
  }

  if (cfg.median != 0) disparity = median_filter(disparity, cfg.median);
  if (cfg.gap_interpolation) interpolate_gaps(disparity);

  DisparityImage out(width, height);
  for (size_t i = 0; i < out.pixels.size(); ++i)
    out.pixels[i] = disparity.pixels[i] == kInvalid ? widths.invalid_word : uint16_t(disparity.pixels[i]);
  return out;
}

}  // namespace

DisparityImage run_golden(const StereoConfig& cfg, const GrayImage& left, const GrayImage& right) {
  if (left.width != right.width || left.height != right.height || left.width > cfg.width ||
      left.height > cfg.height || left.width < 1 || left.height < 1)
    throw std::invalid_argument("run_golden: images must have equal sizes within the configured size");
  const Widths widths = derive_widths(cfg);
  // 16-bit storage whenever sums, and the sentinel above any path cost plus P2, fit.
  if (widths.aggregated_max + uint64_t(cfg.p2) + 512 < 65535 && widths.path_cost_max + 2u * uint64_t(cfg.p2) + 512 < 65535)
    return run_pipeline<uint16_t>(cfg, widths, left, right);
  return run_pipeline<uint32_t>(cfg, widths, left, right);
}

}  // namespace fpstereo
