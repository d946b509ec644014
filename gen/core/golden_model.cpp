// The golden model, organised as the hardware is: row by row in raster order, each stage
// consuming the previous stage's row. docs/semantics.md is the specification; section numbers
// below refer to it.
#include "golden_model.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <limits>
#include <stdexcept>
#include <system_error>
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
// smallest such d on ties; 0 if there is none), for x' in begin .. end - 1.
template <class T>
void match_disparities_from_base(const T* sum_row, int width, int dmax, int m, int begin, int end, int* dm) {
  for (int xm = begin; xm < end; ++xm) {
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

// Lower median of the valid in-image window values (0 .. values-1), in place, on rows begin ..
// end - 1: a ring keeps the unfiltered rows the window still reads, and unfiltered(y) gives the
// rows outside the band (another thread may have filtered them in place). A histogram slides
// along the row (add the entering column, drop the leaving one) and a median pointer only moves
// as far as the counts changed.
template <class Unfiltered>
void median_filter_rows(DisparityImage& map, int window, uint16_t invalid, int values, int begin, int end,
                        Unfiltered unfiltered) {
  const int r = window / 2, width = map.width, height = map.height;
  std::vector<uint16_t> ring(size_t(window) * size_t(width));
  auto ring_row = [&](int y) { return ring.data() + size_t((y + window) % window) * size_t(width); };
  auto keep_row = [&](int y) {
    if (y >= 0 && y < height) {
      const uint16_t* row = y >= begin && y < end ? &map.at(0, y) : unfiltered(y);
      std::copy(row, row + width, ring_row(y));
    }
  };
  for (int y = begin - r; y < begin + r; ++y) keep_row(y);
  std::vector<int> histogram(static_cast<size_t>(values));
  std::vector<const uint16_t*> window_rows(static_cast<size_t>(window));
  for (int y = begin; y < end; ++y) {
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

// Runs work(t) for t = 0 .. threads - 1 at once, t = 0 on the calling thread, and rethrows the
// first exception. The helpers start once all of them exist (work may wait for the others, as
// the column bands' steps do): if one cannot be created, none runs and the result is false.
template <class Work>
[[nodiscard]] bool run_on_threads(int threads, Work work) {
  std::vector<std::exception_ptr> errors(static_cast<size_t>(threads));
  std::mutex gate_mutex;
  std::condition_variable gate;
  enum class Start { Waiting, Go, Abandon } start = Start::Waiting;
  auto open_gate = [&](Start how) {
    {
      std::lock_guard<std::mutex> guard(gate_mutex);
      start = how;
    }
    gate.notify_all();
  };
  auto guarded = [&](int t) {
    try {
      work(t);
    } catch (...) {
      errors[size_t(t)] = std::current_exception();
    }
  };
  std::vector<std::thread> helpers;
  try {
    helpers.reserve(size_t(threads - 1));
    for (int t = 1; t < threads; ++t)
      helpers.emplace_back([&, t] {
        {
          std::unique_lock<std::mutex> guard(gate_mutex);
          gate.wait(guard, [&] { return start != Start::Waiting; });
          if (start == Start::Abandon) return;
        }
        guarded(t);
      });
  } catch (const std::system_error&) {
    open_gate(Start::Abandon);
    for (auto& helper : helpers) helper.join();
    return false;
  }
  open_gate(Start::Go);
  guarded(0);
  for (auto& helper : helpers) helper.join();
  for (const auto& error : errors)
    if (error) std::rethrow_exception(error);
  return true;
}

// The median filter over bands of rows, one per thread. The r rows on each side of an inner
// band edge are copied first: the neighbours read them unfiltered and filter them in place.
void median_filter(DisparityImage& map, int window, uint16_t invalid, int values, int threads) {
  const int r = window / 2, width = map.width, height = map.height;
  threads = std::clamp(height / window, 1, threads);  // bands of at least `window` rows
  auto edge = [&](int t) { return int(int64_t(t) * height / threads); };
  std::vector<uint16_t> halo(size_t(threads - 1) * size_t(2 * r) * size_t(width));
  auto halo_row = [&](int t, int y) {  // row y, within r of edge t (1 .. threads - 1)
    return halo.data() + (size_t(t - 1) * size_t(2 * r) + size_t(y - edge(t) + r)) * size_t(width);
  };
  for (int t = 1; t < threads; ++t)
    for (int y = edge(t) - r; y < edge(t) + r; ++y) std::copy(&map.at(0, y), &map.at(0, y) + width, halo_row(t, y));
  auto band = [&](int t) {
    median_filter_rows(map, window, invalid, values, edge(t), edge(t + 1),
                       [&](int y) { return y < edge(t) ? halo_row(t, y) : halo_row(t + 1, y); });
  };
  if (!run_on_threads(threads, band))  // no threads to be had: the bands one after the other
    for (int t = 0; t < threads; ++t) band(t);
}

void interpolate_gaps(DisparityImage& map, uint16_t invalid, int64_t linear_unit) {
  for (int y = 0; y < map.height; ++y)
    fill_row_gaps(&map.at(0, y), map.width, [&](uint16_t v) { return v != invalid; }, linear_unit);
}

// ---------------------------------------------------------------------------------------------
// Sections 4-5 per row: once a row's sums are complete, the winner, uniqueness, confidence,
// sub-pixel refinement and left-right check of columns begin .. end - 1, into the output words
// and the side views. Each thread keeps its own (the scratch rows are its own).

// Where the pipeline writes the planes besides the words it returns; null: not asked for.
struct SideViews {
  DisparityImage* right = nullptr;
  DisparityImage* confidence = nullptr;
};

// The match pixels whose disparities finishing columns begin .. end - 1 reads: x - m - d for the
// check, and begin .. end - 1 for the right view.
std::pair<int, int> match_columns(const StereoConfig& cfg, int width, int begin, int end) {
  const int m = cfg.min_disp;
  return {std::clamp(std::min(begin, begin - m - cfg.dmax + 1), 0, width), std::clamp(std::max(end, end - m), 0, width)};
}

// LR2's match-side costs of match pixels begin .. end - 1 from the base side's cost row: every
// cost is symmetric in its two images, so the match side's cost at (x', d) is the base side's
// at (x' + m + d, d); beyond the row it is Cmax (section 5).
template <class T>
void match_side_costs(const T* cost, int width, int dmax, int m, T cost_max, int begin, int end, T* match_cost) {
  for (int xm = begin; xm < end; ++xm)
    for (int d = 0; d < dmax; ++d) {
      const int x = xm + m + d;
      match_cost[size_t(xm) * size_t(dmax) + size_t(d)] =
          x >= 0 && x < width ? cost[size_t(x) * size_t(dmax) + size_t(d)] : cost_max;
    }
}

template <class T>
class RowFinisher {
 public:
  RowFinisher(const StereoConfig& cfg, const Widths& widths, const SideViews& side, DisparityImage& out)
      : cfg_(cfg), widths_(widths), side_(side), out_(out), width_(out.width), whole_(size_t(width_)),
        refined_(size_t(width_)), match_disparity_(size_t(width_)) {}

  // Row y from its sums (and, for LR2, the match side's sums, at least of the match_columns()).
  void finish(int y, const T* sum, const T* match_sum, int begin, int end) {
    const int width = width_, dmax = cfg_.dmax, m = cfg_.min_disp;
    int* row = whole_.data();
    for (int x = begin; x < end; ++x) {
      const T* S = sum + size_t(x) * size_t(dmax);
      const int d = winner(S, dmax);
      row[x] = (cfg_.uniqueness == 0 || is_unique(S, dmax, d, cfg_.uniqueness)) ? d : kInvalid;
      if (side_.confidence != nullptr) side_.confidence->at(x, y) = uint16_t(confidence(S, dmax, d));
      refined_[size_t(x)] = refined_disparity(S, dmax, d, cfg_);
    }

    const auto [match_begin, match_end] = match_columns(cfg_, width, begin, end);
    if (cfg_.lr == LrCheck::Lr1)
      match_disparities_from_base(sum, width, dmax, m, match_begin, match_end, match_disparity_.data());
    if (cfg_.lr == LrCheck::Lr2)
      for (int xm = match_begin; xm < match_end; ++xm)
        match_disparity_[size_t(xm)] = winner(match_sum + size_t(xm) * size_t(dmax), dmax);
    if (side_.right != nullptr)
      for (int xm = begin; xm < end; ++xm) side_.right->at(xm, y) = uint16_t(match_disparity_[size_t(xm)]);
    if (cfg_.lr != LrCheck::None)
      for (int x = begin; x < end; ++x) {
        if (row[x] == kInvalid) continue;
        const int xm = x - m - row[x];
        if (xm < 0 || xm >= width || std::abs(row[x] - match_disparity_[size_t(xm)]) > cfg_.lr_threshold)
          row[x] = kInvalid;
      }
    // The checks above use the whole disparity; the stages below the refined one.
    uint16_t* words = &out_.at(0, y);
    for (int x = begin; x < end; ++x)
      words[x] = row[x] == kInvalid ? widths_.invalid_word : uint16_t(refined_[size_t(x)]);
  }

 private:
  static constexpr int kInvalid = -1;  // a whole disparity once a check fails
  const StereoConfig& cfg_;
  const Widths& widths_;
  const SideViews side_;
  DisparityImage& out_;
  const int width_;
  // Per row: the whole disparities, the refined ones, the match side's.
  std::vector<int> whole_, refined_, match_disparity_;
};

// ---------------------------------------------------------------------------------------------
// Column bands: the frame's threads share each row by columns (docs/golden-model-speed.md).
// Pixel (x, y) of a raster-order path depends on (x - 1, y) and on x - 1, x and x + 1 of row
// y - 1 (MGM's second predecessors among them), and of the 180-degree path on (x + 1, y). With
// 2T bands of the row (thread t owns bands 2t and 2t + 1; one thread runs the row as one band,
// with no one to wait for), band b of row y runs the raster-order
// paths at step 2y + b: its left neighbour band finished row y one step earlier, its right
// neighbour finished row y - 1 one step earlier, and at every step each thread has exactly one
// band to run. The 180-degree path runs band b at step 2y + 4T - 2 - b, from the right, after
// the band's raster-order paths. LR2's match side is the same wavefront 2T steps later, when
// the base costs it reads (up to dmax columns to the right) are there. A barrier separates the
// steps. Thread t finishes its columns of row y once every band it reads has the row: its own,
// and the bands holding the sums the left-right check reads. The rows live in rings deep enough
// for the last read. What crosses between threads per row is a pixel's path costs at each band
// edge and the dmax columns the check reads, not whole rows: on the shared VM here, moving a row
// of sums between cores cost more than aggregating it.

// The threads the bands can use: every thread needs two bands of at least one column.
int column_band_threads(int width, int threads) { return std::clamp(width / 2, 1, threads); }
// One thread runs the row as one band.
int column_bands(int threads) { return threads == 1 ? 1 : 2 * threads; }

// A barrier between the bands' steps. A step takes tens of microseconds and waking a sleeping
// thread about 30 us on a VM, so a waiting thread spins first and sleeps only after 50 us.
class StepBarrier {
 public:
  explicit StepBarrier(int parties) : parties_(parties) {}
  void arrive_and_wait() {
    const unsigned generation = generation_.load(std::memory_order_acquire);
    if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == parties_) {
      arrived_.store(0, std::memory_order_relaxed);
      generation_.store(generation + 1, std::memory_order_release);
      { std::lock_guard<std::mutex> guard(mutex_); }  // a sleeper tests the generation under the lock
      passed_.notify_all();
      return;
    }
    auto passed = [&] { return generation_.load(std::memory_order_acquire) != generation; };
    const auto spin_until = std::chrono::steady_clock::now() + std::chrono::microseconds(50);
    while (std::chrono::steady_clock::now() < spin_until)
      for (int i = 0; i < 64; ++i) {
        if (passed()) return;
#if defined(__x86_64__) || defined(__i386__)
        __builtin_ia32_pause();
#endif
      }
    std::unique_lock<std::mutex> guard(mutex_);
    passed_.wait(guard, passed);
  }

 private:
  const int parties_;
  std::atomic<int> arrived_{0};
  std::atomic<unsigned> generation_{0};
  std::mutex mutex_;
  std::condition_variable passed_;
};

// The bands' schedule: the step at which each band's work on row y runs, 2y + an offset, and
// when a thread finishes a row.
struct BandSchedule {
  int width, bands;
  bool right_to_left;  // the 180-degree path
  int match_lag;       // LR2: the match side's offsets are the base side's + match_lag
  // The match side reads base costs up to dmax columns to the right: 2T steps later (even, so
  // that each thread's bands keep their parity), or in the same step on one thread.
  static int lag_for(int bands) { return bands == 1 ? 0 : bands; }
  int edge(int band) const { return int(int64_t(band) * width / bands); }
  int band_of(int x) const {  // the band holding column x
    int b = 0;
    while (b + 1 < bands && edge(b + 1) <= x) ++b;
    return b;
  }
  int raster(int band) const { return band; }
  int reverse(int band) const { return 2 * bands - 2 - band; }  // the 180-degree path
  // The offset of the last work on a row of the base side's sums (lag 0) or the match side's.
  int sums_done(int band, int lag) const { return lag + (right_to_left ? reverse(band) : raster(band)); }
  // The odd offset f at which thread t finishes row y: after each band whose sums it reads has
  // run; its own thread's work may come earlier in the same step.
  int finish_offset(const StereoConfig& cfg, int t) const {
    int f = 0;
    auto after = [&](int band, int lag) {
      const int offset = sums_done(band, lag);
      f = std::max(f, band / 2 == t ? offset : offset + 1);
    };
    for (int b = 2 * t; b < std::min(2 * t + 2, bands); ++b) after(b, 0);
    const int m = cfg.min_disp;
    const auto [match_begin, match_end] = match_columns(cfg, width, edge(2 * t), edge(2 * t + 2));
    if (cfg.lr == LrCheck::Lr1 && match_begin < match_end)  // the sums S(x' + m + d, d)
      for (int b = band_of(std::max(0, match_begin + m)); b <= band_of(std::min(width - 1, match_end - 1 + m + cfg.dmax - 1)); ++b)
        after(b, 0);
    if (cfg.lr == LrCheck::Lr2 && match_begin < match_end)  // the match side's sums
      for (int b = band_of(match_begin); b <= band_of(match_end - 1); ++b) after(b, match_lag);
    return f | 1;
  }
  // The last offset at which a row's base costs are read.
  int last_cost_read() const {
    if (match_lag != 0) return match_lag + (right_to_left ? reverse(0) : raster(bands - 1));
    return right_to_left ? reverse(0) : raster(bands - 1);
  }
};

// Sections 1-5 of the frame on `threads` threads (1 included). False, with nothing done, if the
// threads could not be created.
template <class T>
bool run_column_bands(const StereoConfig& cfg, const Widths& widths, const GrayImage& left, const GrayImage& right,
                      const SideViews& side, int threads, T sentinel, DisparityImage& out) {
  const int width = left.width, height = left.height, bands = column_bands(threads);
  const bool lr2 = cfg.lr == LrCheck::Lr2, right_to_left = (cfg.paths & kPath180) != 0;
  const BandSchedule schedule{width, bands, right_to_left, lr2 ? BandSchedule::lag_for(bands) : 0};
  auto edge = [&](int band) { return schedule.edge(band); };
  std::vector<int> finish_offset(static_cast<size_t>(threads));
  for (int t = 0; t < threads; ++t) finish_offset[size_t(t)] = schedule.finish_offset(cfg, t);
  const int last_finish = *std::max_element(finish_offset.begin(), finish_offset.end());
  // Row y + ring reuses row y's slots from step 2y + 2 ring: after the last read of row y.
  const bool keep_costs = lr2 || right_to_left;  // read after their band's step
  const int ring = std::max(last_finish, keep_costs ? schedule.last_cost_read() : 0) / 2 + 1;
  const size_t row_size = size_t(width) * size_t(cfg.dmax);
  auto ring_rows = [&](bool used) { return std::unique_ptr<T[]>(used ? new T[size_t(ring) * row_size] : nullptr); };
  // Each band writes its columns of a row before any reads them.
  const std::unique_ptr<T[]> sums = ring_rows(true), match_sums = ring_rows(lr2), costs_kept = ring_rows(keep_costs);
  auto slot = [&](const std::unique_ptr<T[]>& rows, int y) { return rows.get() + size_t(y % ring) * row_size; };
  PathAggregator<T> paths(cfg, width, sentinel, cfg.p2_adapt);
  std::optional<PathAggregator<T>> match_paths;  // LR2: constant P2 on the match side (section 3)
  if (lr2) match_paths.emplace(cfg, width, sentinel, 0);
  const int last_step = 2 * (height - 1) + last_finish;
  StepBarrier barrier(threads);

  // A thread that fails passes every later step all the same, so that none waits for ever.
  std::vector<char> setup_failed(static_cast<size_t>(threads), 0);
  return run_on_threads(threads, [&](int t) {
    std::optional<CostRows<T>> costs;
    std::unique_ptr<T[]> cost_row, match_cost_row;
    std::optional<RowFinisher<T>> finisher;
    try {
      costs.emplace(cfg, widths, left, right);
      cost_row.reset(new T[row_size]);
      if (lr2) match_cost_row.reset(new T[row_size]);
      finisher.emplace(cfg, widths, side, out);
    } catch (...) {
      setup_failed[size_t(t)] = 1;
      barrier.arrive_and_wait();
      throw;
    }
    barrier.arrive_and_wait();
    if (std::any_of(setup_failed.begin(), setup_failed.end(), [](char f) { return f != 0; })) return;
    std::exception_ptr error;
    const int band = 2 * t, f = finish_offset[size_t(t)];
    for (int step = 0; step <= last_step; ++step) {
      try {
        const int b = band + (step & 1), begin = edge(b), end = edge(b + 1);
        // The row that the work at offset `offset` does at this step, or -1.
        auto row_at = [&](int offset) {
          return step >= offset && (step - offset) % 2 == 0 && (step - offset) / 2 < height ? (step - offset) / 2 : -1;
        };
        auto match_costs = [&](int y) {
          match_side_costs(slot(costs_kept, y), width, cfg.dmax, cfg.min_disp, T(widths.cost_max), begin, end,
                           match_cost_row.get());
          return match_cost_row.get();
        };
        if (!error && b < bands) {
          if (const int y = row_at(schedule.raster(b)); y >= 0) {
            T* cost = keep_costs ? slot(costs_kept, y) : cost_row.get();
            costs->compute(y, cost, begin, end);
            paths.push_band(y, cost, slot(sums, y), left, begin, end);
          }
          if (const int y = row_at(schedule.reverse(b)); right_to_left && y >= 0)
            paths.push_band_right_to_left(y, slot(costs_kept, y), slot(sums, y), left, begin, end);
          if (const int y = row_at(schedule.match_lag + schedule.raster(b)); lr2 && y >= 0)
            match_paths->push_band(y, match_costs(y), slot(match_sums, y), right, begin, end);
          if (const int y = row_at(schedule.match_lag + schedule.reverse(b)); lr2 && right_to_left && y >= 0)
            match_paths->push_band_right_to_left(y, match_costs(y), slot(match_sums, y), right, begin, end);
        }
        if (const int y = row_at(f); !error && y >= 0)
          finisher->finish(y, slot(sums, y), lr2 ? slot(match_sums, y) : nullptr, edge(band),
                           edge(std::min(band + 2, bands)));
      } catch (...) {
        error = std::current_exception();
      }
      barrier.arrive_and_wait();
    }
    if (error) std::rethrow_exception(error);
  });
}

// ---------------------------------------------------------------------------------------------
// The pipeline, with T the storage type of costs and sums.
template <class T>
DisparityImage run_pipeline(const StereoConfig& cfg, const Widths& widths, const GrayImage& left,
                            const GrayImage& right, const SideViews& side, int threads) {
  // Larger than any path cost plus P2, and sentinel + P1 still fits in T.
  const T sentinel = T(std::numeric_limits<T>::max() - 256);
  DisparityImage out(left.width, left.height);
  // Sections 1-5, on one thread where no other was to be had (one thread needs no other).
  if (!run_column_bands<T>(cfg, widths, left, right, side, column_band_threads(left.width, threads), sentinel, out))
    (void)run_column_bands<T>(cfg, widths, left, right, side, 1, sentinel, out);

  if (cfg.speckle_size != 0)
    golden::speckle_filter(out, cfg.speckle_size, cfg.speckle_range << cfg.subpixel_bits, widths.invalid_word);
  const int dmax = cfg.dmax;
  if (cfg.median != 0)
    median_filter(out, cfg.median, widths.invalid_word, ((dmax - 1) << cfg.subpixel_bits) + 1, threads);
  if (cfg.gap_interpolation)
    interpolate_gaps(out, widths.invalid_word, cfg.gap_linear ? int64_t(1) << cfg.subpixel_bits : 0);
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
