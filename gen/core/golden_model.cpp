// The golden model, organised as the hardware is: row by row in raster order, each stage
// consuming the previous stage's row. docs/semantics.md is the specification; section numbers
// below refer to it.
#include "golden_model.hpp"

#include <algorithm>
#include <array>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "gap_fill.hpp"
#include "golden_stages.hpp"
#include "widths.hpp"

namespace fpstereo {
namespace {

using golden::CostRows;
using golden::PathAggregator;

// ---------------------------------------------------------------------------------------------
// Section 4: winner-take-all and uniqueness over one pixel's sums.
// Sum and index in one key, the sum above the 8 index bits (dmax <= 256): the smallest key is
// the smallest sum at its smallest d, found by one vectorisable min reduction.
template <class T>
using WinnerKey = std::conditional_t<sizeof(T) <= 2, uint32_t, uint64_t>;

template <class T>
int winner(const T* S, int dmax) {
  WinnerKey<T> best = std::numeric_limits<WinnerKey<T>>::max();
  for (int d = 0; d < dmax; ++d) best = std::min(best, WinnerKey<T>(WinnerKey<T>(S[d]) << 8 | WinnerKey<T>(d)));
  return int(best & 0xff);
}

template <class T>
T min_of(const T* S, int begin, int end) {
  T m = std::numeric_limits<T>::max();
  for (int d = begin; d < end; ++d) m = std::min(m, S[d]);
  return m;
}

// The smallest sum at least two disparities from the winner (dmax >= 16: never empty).
template <class T>
uint64_t second_best(const T* S, int dmax, int best) {
  return std::min(min_of(S, 0, std::max(0, best - 1)), min_of(S, std::min(dmax, best + 2), dmax));
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
void match_disparities_from_base(const T* sum_row, int width, int dmax, int m, int* dm) {
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
    dm[xm] = best;
  }
}

// ---------------------------------------------------------------------------------------------
// Sections 6-7 on the map of output words, `invalid` the invalid word (above every disparity).

// Lower median of the valid in-image window values (0 .. values-1), in place: a ring keeps the
// unfiltered rows the window still reads. A histogram slides along the row (add the entering
// column, drop the leaving one) and a median pointer only moves as far as the counts changed.
void median_filter(DisparityImage& map, int window, uint16_t invalid, int values) {
  const int r = window / 2, width = map.width, height = map.height;
  std::vector<uint16_t> ring(size_t(window) * size_t(width));
  auto ring_row = [&](int y) { return ring.data() + size_t(y % window) * size_t(width); };
  auto keep_row = [&](int y) {
    if (y < height) std::copy(&map.at(0, y), &map.at(0, y) + width, ring_row(y));
  };
  for (int y = 0; y < r; ++y) keep_row(y);
  std::vector<int> histogram(static_cast<size_t>(values));
  std::vector<const uint16_t*> window_rows(static_cast<size_t>(window));
  for (int y = 0; y < height; ++y) {
    keep_row(y + r);
    std::fill(histogram.begin(), histogram.end(), 0);
    int rows = 0;  // the window's rows inside the image
    for (int yy = std::max(0, y - r); yy <= std::min(height - 1, y + r); ++yy) window_rows[size_t(rows++)] = ring_row(yy);
    int count = 0, median = 0, below = 0;  // below: values smaller than median
    auto update_column = [&](int x, int delta) {
      if (x < 0 || x >= width) return;
      for (int i = 0; i < rows; ++i) {
        const int v = window_rows[size_t(i)][x];
        if (v == invalid) continue;
        histogram[size_t(v)] += delta;
        count += delta;
        if (v < median) below += delta;
      }
    };
    for (int x = -r; x < r; ++x) update_column(x, +1);
    const uint16_t* centre = ring_row(y);
    uint16_t* out = &map.at(0, y);
    for (int x = 0; x < width; ++x) {
      update_column(x + r, +1);
      if (centre[x] != invalid) {
        const int target = (count - 1) / 2;  // index of the lower median in sorted order
        while (below > target) below -= histogram[size_t(--median)];
        while (below + histogram[size_t(median)] <= target) below += histogram[size_t(median++)];
        out[x] = uint16_t(median);
      }
      update_column(x - r, -1);
    }
  }
}

void interpolate_gaps(DisparityImage& map, uint16_t invalid) {
  for (int y = 0; y < map.height; ++y)
    fill_row_gaps(&map.at(0, y), map.width, [&](uint16_t v) { return v != invalid; });
}

// ---------------------------------------------------------------------------------------------
// Within-frame parallelism. The paths are independent of each other, so a helper thread can
// aggregate a share of them. It computes the cost rows itself and hands them, with its partial
// sums, to the main thread through a ring of rows; the main thread then aggregates its own paths
// on the same cost rows and does the per-pixel stages, which balances two threads. Integer sums
// do not depend on the order in which the paths are added, so the output is the same for any
// number of threads.

// The configured paths split into `groups` masks: the first path to the main thread (group 0),
// which also runs the per-pixel stages, the others dealt round-robin to the helpers.
std::vector<unsigned> path_groups(unsigned paths, int groups) {
  std::vector<unsigned> masks(size_t(groups), 0);
  int n = 0;
  for (const auto& dir : path_directions())
    if (paths & dir.mask) {
      masks[n == 0 || groups == 1 ? 0 : size_t(1 + (n - 1) % (groups - 1))] |= dir.mask;
      ++n;
    }
  return masks;
}

template <class T>
class PathGroupThread {
 public:
  PathGroupThread(const StereoConfig& group_cfg, const Widths& widths, const GrayImage& left, const GrayImage& right,
                  T sentinel)
      : cfg_(group_cfg), widths_(widths), left_(left), right_(right), sentinel_(sentinel),
        row_size_(size_t(left.width) * size_t(cfg_.dmax)), thread_([this] { run(); }) {}
  ~PathGroupThread() {
    {
      std::lock_guard<std::mutex> guard(mutex_);
      cancelled_ = true;
    }
    changed_.notify_all();
    thread_.join();
  }

  // The cost row y, once this thread has aggregated it (rows in order 0, 1, ...); valid until
  // release(y).
  const T* cost_row(int y) {
    std::unique_lock<std::mutex> guard(mutex_);
    changed_.wait(guard, [&] { return produced_ > y || error_; });
    if (error_) std::rethrow_exception(error_);
    return slot(cost_ring_, y);
  }

  // Adds this group's sums of row y to sum; after cost_row(y).
  void add_sums(int y, T* sum) {
    const T* __restrict partial = slot(sum_ring_, y);
    T* __restrict out = sum;
    for (size_t i = 0; i < row_size_; ++i) out[i] = T(out[i] + partial[i]);
  }

  // Row y's slots may be reused.
  void release(int y) {
    {
      std::lock_guard<std::mutex> guard(mutex_);
      consumed_ = y + 1;
    }
    changed_.notify_all();
  }

 private:
  static constexpr int kRingRows = 4;
  T* slot(std::vector<T>& ring, int y) { return ring.data() + size_t(y % kRingRows) * row_size_; }

  // The thread's state is built on the thread, so that its memory is touched (page faults,
  // initialisation) there rather than on the main thread.
  void run() {
    try {
      CostRows<T> costs(cfg_, widths_, left_, right_);
      PathAggregator<T> paths(cfg_, left_.width, sentinel_, cfg_.p2_adapt);
      cost_ring_.resize(kRingRows * row_size_);
      sum_ring_.resize(kRingRows * row_size_);
      for (int y = 0; y < left_.height; ++y) {
        {
          std::unique_lock<std::mutex> guard(mutex_);
          changed_.wait(guard, [&] { return cancelled_ || y - consumed_ < kRingRows; });
          if (cancelled_) return;
        }
        costs.compute(y, slot(cost_ring_, y));
        paths.push_row(y, slot(cost_ring_, y), slot(sum_ring_, y), left_);
        {
          std::lock_guard<std::mutex> guard(mutex_);
          produced_ = y + 1;
        }
        changed_.notify_all();
      }
    } catch (...) {
      {
        std::lock_guard<std::mutex> guard(mutex_);
        error_ = std::current_exception();
      }
      changed_.notify_all();
    }
  }

  const StereoConfig cfg_;
  const Widths widths_;
  const GrayImage &left_, &right_;
  const T sentinel_;
  const size_t row_size_;
  std::vector<T> cost_ring_, sum_ring_;
  std::exception_ptr error_;
  std::mutex mutex_;
  std::condition_variable changed_;
  int produced_ = 0, consumed_ = 0;
  bool cancelled_ = false;
  std::thread thread_;  // last: starts once everything above is built
};

// Where the pipeline writes the planes besides the words it returns; null: not asked for.
struct SideViews {
  DisparityImage* right = nullptr;
  DisparityImage* confidence = nullptr;
};

// ---------------------------------------------------------------------------------------------
// The pipeline, with T the storage type of costs and sums.
template <class T>
DisparityImage run_pipeline(const StereoConfig& cfg, const Widths& widths, const GrayImage& left,
                            const GrayImage& right, const SideViews& side, int threads) {
  const int width = left.width, height = left.height, dmax = cfg.dmax;
  const size_t row_size = size_t(width) * size_t(dmax);
  // Larger than any path cost plus P2, and sentinel + P1 still fits in T.
  const T sentinel = T(std::numeric_limits<T>::max() - 256);

  // The main thread aggregates the first group of paths, one helper thread each other group.
  const std::vector<unsigned> groups = path_groups(cfg.paths, std::clamp(threads, 1, __builtin_popcount(cfg.paths)));
  std::vector<StereoConfig> group_cfgs(groups.size(), cfg);
  for (size_t g = 0; g < groups.size(); ++g) group_cfgs[g].paths = groups[g];
  std::vector<std::unique_ptr<PathGroupThread<T>>> helpers;
  for (size_t g = 1; g < groups.size(); ++g)
    helpers.push_back(std::make_unique<PathGroupThread<T>>(group_cfgs[g], widths, left, right, sentinel));
  // Cost rows from the first helper, or computed here if there is none.
  std::optional<CostRows<T>> base_costs;
  if (helpers.empty()) base_costs.emplace(cfg, widths, left, right);
  // P2 adapts to the base image's steps; LR2's match side keeps it constant (section 3).
  PathAggregator<T> base_paths(group_cfgs[0], width, sentinel, cfg.p2_adapt);
  PathAggregator<T> match_paths(cfg, width, sentinel, 0);
  std::vector<T> own_cost(helpers.empty() ? row_size : 0), sum(row_size), match_cost, match_sum;
  if (cfg.lr == LrCheck::Lr2) {
    match_cost.resize(row_size);
    match_sum.resize(row_size);
  }

  // Per row: the whole disparities (kInvalid once a check fails), the refined ones, the match side's.
  constexpr int kInvalid = -1;
  std::vector<int> whole(static_cast<size_t>(width)), refined(static_cast<size_t>(width)),
      match_disparity(static_cast<size_t>(width));
  DisparityImage out(width, height);
  for (int y = 0; y < height; ++y) {
    const T* cost = own_cost.data();
    if (base_costs) base_costs->compute(y, own_cost.data());
    for (auto& helper : helpers) cost = helper->cost_row(y);  // the same row from every helper
    base_paths.push_row(y, cost, sum.data(), left);
    for (auto& helper : helpers) helper->add_sums(y, sum.data());

    int* row = whole.data();
    for (int x = 0; x < width; ++x) {
      const T* S = sum.data() + size_t(x) * size_t(dmax);
      const int d = winner(S, dmax);
      row[x] = (cfg.uniqueness == 0 || is_unique(S, dmax, d, cfg.uniqueness)) ? d : kInvalid;
      if (side.confidence != nullptr) side.confidence->at(x, y) = uint16_t(confidence(S, dmax, d));
      refined[size_t(x)] = refined_disparity(S, dmax, d, cfg);
    }

    if (cfg.lr == LrCheck::Lr1) match_disparities_from_base(sum.data(), width, dmax, cfg.min_disp, match_disparity.data());
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
    uint16_t* words = &out.at(0, y);
    for (int x = 0; x < width; ++x) words[x] = row[x] == kInvalid ? widths.invalid_word : uint16_t(refined[size_t(x)]);
    for (auto& helper : helpers) helper->release(y);
  }

  if (cfg.speckle_size != 0)
    golden::speckle_filter(out, cfg.speckle_size, cfg.speckle_range << cfg.subpixel_bits, widths.invalid_word);
  if (cfg.median != 0) median_filter(out, cfg.median, widths.invalid_word, ((dmax - 1) << cfg.subpixel_bits) + 1);
  if (cfg.gap_interpolation) interpolate_gaps(out, widths.invalid_word);
  return out;
}

}  // namespace

Planes run_golden(const StereoConfig& cfg, const GrayImage& left, const GrayImage& right,
                  const std::vector<Plane>& planes, int threads) {
  if (left.width != right.width || left.height != right.height || left.width > cfg.width ||
      left.height > cfg.height || left.width < 1 || left.height < 1)
    throw std::invalid_argument("run_golden: images must have equal sizes within the configured size");
  Planes out;
  SideViews side;
  for (const Plane plane : planes) {
    if (const std::string why = plane_unavailable(cfg, plane); !why.empty())
      throw std::invalid_argument("run_golden: " + why);
    out[plane] = DisparityImage(left.width, left.height);
  }
  if (out.count(Plane::Right)) side.right = &out[Plane::Right];
  if (out.count(Plane::Confidence)) side.confidence = &out[Plane::Confidence];
  const Widths widths = derive_widths(cfg);
  // 16-bit storage whenever sums, and the sentinel above any path cost plus P2, fit.
  DisparityImage words =
      widths.aggregated_max + uint64_t(cfg.p2) + 512 < 65535 && widths.path_cost_max + 2u * uint64_t(cfg.p2) + 512 < 65535
          ? run_pipeline<uint16_t>(cfg, widths, left, right, side, threads)
          : run_pipeline<uint32_t>(cfg, widths, left, right, side, threads);
  if (out.count(Plane::Disparity)) out[Plane::Disparity] = std::move(words);
  return out;
}

DisparityImage run_golden(const StereoConfig& cfg, const GrayImage& left, const GrayImage& right, int threads) {
  return std::move(run_golden(cfg, left, right, {Plane::Disparity}, threads)[Plane::Disparity]);
}

}  // namespace fpstereo
