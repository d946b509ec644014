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

// Runs work(t) for t = 0 .. threads - 1, t = 0 on the calling thread, and rethrows the first
// exception. The helpers start once all of them exist: if one cannot be created, none runs (work
// may wait for the others, as the column bands' steps do).
template <class Work>
void run_on_threads(int threads, Work work) {
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
  } catch (...) {
    open_gate(Start::Abandon);
    for (auto& helper : helpers) helper.join();
    throw;
  }
  open_gate(Start::Go);
  guarded(0);
  for (auto& helper : helpers) helper.join();
  for (const auto& error : errors)
    if (error) std::rethrow_exception(error);
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
  run_on_threads(threads, [&](int t) {
    median_filter_rows(map, window, invalid, values, edge(t), edge(t + 1),
                       [&](int y) { return y < edge(t) ? halo_row(t, y) : halo_row(t + 1, y); });
  });
}

void interpolate_gaps(DisparityImage& map, uint16_t invalid) {
  for (int y = 0; y < map.height; ++y)
    fill_row_gaps(&map.at(0, y), map.width, [&](uint16_t v) { return v != invalid; });
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

template <class T>
class RowFinisher {
 public:
  RowFinisher(const StereoConfig& cfg, const Widths& widths, const GrayImage& right, const SideViews& side,
              DisparityImage& out, T sentinel)
      : cfg_(cfg), widths_(widths), right_(right), side_(side), out_(out), width_(right.width),
        whole_(size_t(width_)), refined_(size_t(width_)), match_disparity_(size_t(width_)) {
    if (cfg.lr == LrCheck::Lr2) {
      // LR2's match side aggregates its own paths; P2 stays constant there (section 3).
      match_paths_.emplace(cfg, width_, sentinel, 0);
      match_cost_.resize(size_t(width_) * size_t(cfg.dmax));
      match_sum_.resize(match_cost_.size());
    }
  }

  // Row y from its sums (and, for LR2, its costs; LR2 needs the whole row).
  void finish(int y, const T* sum, const T* cost, int begin, int end) {
    const int width = width_, dmax = cfg_.dmax, m = cfg_.min_disp;
    int* row = whole_.data();
    for (int x = begin; x < end; ++x) {
      const T* S = sum + size_t(x) * size_t(dmax);
      const int d = winner(S, dmax);
      row[x] = (cfg_.uniqueness == 0 || is_unique(S, dmax, d, cfg_.uniqueness)) ? d : kInvalid;
      if (side_.confidence != nullptr) side_.confidence->at(x, y) = uint16_t(confidence(S, dmax, d));
      refined_[size_t(x)] = refined_disparity(S, dmax, d, cfg_);
    }

    // The match pixels the check reads (x - m - d) and those of the right view (begin .. end - 1).
    const int match_begin = std::clamp(std::min(begin, begin - m - dmax + 1), 0, width);
    const int match_end = std::clamp(std::max(end, end - m), 0, width);
    if (cfg_.lr == LrCheck::Lr1)
      match_disparities_from_base(sum, width, dmax, m, match_begin, match_end, match_disparity_.data());
    if (cfg_.lr == LrCheck::Lr2) {
      // Every cost is symmetric in its two images, so the match side's cost at (x', d) is the
      // base side's cost at (x' + m + d, d); beyond the row it is Cmax (section 5).
      for (int xm = 0; xm < width; ++xm)
        for (int d = 0; d < dmax; ++d) {
          const int x = xm + m + d;
          match_cost_[size_t(xm) * size_t(dmax) + size_t(d)] =
              x >= 0 && x < width ? cost[size_t(x) * size_t(dmax) + size_t(d)] : T(widths_.cost_max);
        }
      match_paths_->push_row(y, match_cost_.data(), match_sum_.data(), right_);
      for (int xm = 0; xm < width; ++xm)
        match_disparity_[size_t(xm)] = winner(match_sum_.data() + size_t(xm) * size_t(dmax), dmax);
    }
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
  const GrayImage& right_;
  const SideViews side_;
  DisparityImage& out_;
  const int width_;
  // Per row: the whole disparities, the refined ones, the match side's.
  std::vector<int> whole_, refined_, match_disparity_;
  std::optional<PathAggregator<T>> match_paths_;  // LR2
  std::vector<T> match_cost_, match_sum_;         // LR2
};

// ---------------------------------------------------------------------------------------------
// Column bands: the frame's threads share each row by columns (docs/golden-model-speed.md).
// Without the 180-degree path, pixel (x, y) depends on (x - 1, y) and on x - 1, x and x + 1 of
// row y - 1 (MGM's second predecessors among them). With 2T bands of the row (thread t owns bands 2t and 2t + 1), band b of
// row y runs at step 2y + b: its left neighbour band finished row y one step earlier, its right
// neighbour finished row y - 1 one step earlier, and at every step each thread has exactly one
// band to run. A barrier separates the steps. Thread t finishes its columns of row y once every
// band it reads has the row: its own, and with LR1 up to dmax - 1 columns to the right; the
// last reads come at most 2T + 1 steps after the first band of the row, so the sums live in a
// ring of T + 1 rows. What crosses between threads per row is
// a pixel's path costs at each band edge and those dmax columns, not whole rows: on the shared
// VM here, moving a row of sums between cores cost more than aggregating it.

// The threads the bands can use: every thread needs two bands of at least one column.
int column_band_threads(const StereoConfig& cfg, int width, int threads) {
  if (threads < 2 || (cfg.paths & kPath180) || cfg.lr == LrCheck::Lr2) return 1;
  return std::min(threads, width / 2);
}

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

template <class T>
void run_column_bands(const StereoConfig& cfg, const Widths& widths, const GrayImage& left, const GrayImage& right,
                      const SideViews& side, int threads, T sentinel, DisparityImage& out) {
  const int width = left.width, height = left.height, bands = 2 * threads, ring = threads + 1;
  const size_t row_size = size_t(width) * size_t(cfg.dmax);
  auto edge = [&](int band) { return int(int64_t(band) * width / bands); };
  PathAggregator<T> paths(cfg, width, sentinel, cfg.p2_adapt);
  const std::unique_ptr<T[]> sums(new T[size_t(ring) * row_size]);  // each band writes its columns first
  auto sum_row = [&](int y) { return sums.get() + size_t(y % ring) * row_size; };
  const int last_step = 2 * (height - 1) + bands + 1;  // thread T - 1 finishes the last row
  StepBarrier barrier(threads);

  // A thread that fails passes every later step all the same, so that none waits for ever.
  std::vector<char> setup_failed(static_cast<size_t>(threads), 0);
  run_on_threads(threads, [&](int t) {
    std::optional<CostRows<T>> costs;
    std::unique_ptr<T[]> cost_row;
    std::optional<RowFinisher<T>> finisher;
    try {
      costs.emplace(cfg, widths, left, right);
      cost_row.reset(new T[row_size]);
      finisher.emplace(cfg, widths, right, side, out, sentinel);
    } catch (...) {
      setup_failed[size_t(t)] = 1;
      barrier.arrive_and_wait();
      throw;
    }
    barrier.arrive_and_wait();
    if (std::any_of(setup_failed.begin(), setup_failed.end(), [](char f) { return f != 0; })) return;
    // Row y is finished at step 2y + finish_offset (odd), once the last band it reads has it: the
    // thread's own second band, or with LR1 the band of the last sum the match disparities read,
    // S(x' + m + d) for x' below max(end, end - m) (done a step before).
    int last_band = 2 * t + 1;
    if (cfg.lr == LrCheck::Lr1) {
      const int end = edge(2 * t + 2), m = cfg.min_disp;
      const int last_read = std::min(width - 1, std::max(end, end - m) - 1 + m + cfg.dmax - 1);
      while (last_band + 1 < bands && edge(last_band + 1) <= last_read) ++last_band;
    }
    const int finish_offset = last_band == 2 * t + 1 ? last_band : last_band + 1 + (last_band & 1);
    std::exception_ptr error;
    for (int step = 0; step <= last_step; ++step) {
      try {
        const int band = 2 * t + (step & 1), y = (step - band) / 2;
        if (!error && step >= band && y < height) {
          costs->compute(y, cost_row.get(), edge(band), edge(band + 1));
          paths.push_band(y, cost_row.get(), sum_row(y), left, edge(band), edge(band + 1));
        }
        const int done = (step - finish_offset) / 2;
        if (!error && (step & 1) && step >= finish_offset && done < height)
          finisher->finish(done, sum_row(done), nullptr, edge(2 * t), edge(2 * t + 2));
      } catch (...) {
        error = std::current_exception();
      }
      barrier.arrive_and_wait();
    }
    if (error) std::rethrow_exception(error);
  });
}

// ---------------------------------------------------------------------------------------------
// Path groups, where the bands do not apply (the 180-degree path, LR2): the paths are
// independent of each other, so a helper thread can aggregate a share of them. It computes the
// cost rows itself and hands them, with its partial sums, to the main thread through a ring of
// rows; the main thread then aggregates its own paths on the same cost rows and finishes the
// rows. Integer sums do not depend on the order in which the paths are added, so the output is
// the same for any number of threads.

// The configured paths split into `groups` masks: the first path to the main thread (group 0),
// which also finishes the rows, the others dealt round-robin to the helpers.
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

// ---------------------------------------------------------------------------------------------
// The pipeline, with T the storage type of costs and sums.
template <class T>
DisparityImage run_pipeline(const StereoConfig& cfg, const Widths& widths, const GrayImage& left,
                            const GrayImage& right, const SideViews& side, int threads) {
  const int width = left.width, height = left.height;
  const size_t row_size = size_t(width) * size_t(cfg.dmax);
  // Larger than any path cost plus P2, and sentinel + P1 still fits in T.
  const T sentinel = T(std::numeric_limits<T>::max() - 256);
  DisparityImage out(width, height);

  if (const int band_threads = column_band_threads(cfg, width, threads); band_threads > 1) {
    run_column_bands<T>(cfg, widths, left, right, side, band_threads, sentinel, out);
  } else {
    // The main thread aggregates the first group of paths, one helper thread each other group.
    const std::vector<unsigned> groups =
        path_groups(cfg.paths, std::clamp(threads, 1, __builtin_popcount(cfg.paths)));
    std::vector<StereoConfig> group_cfgs(groups.size(), cfg);
    for (size_t g = 0; g < groups.size(); ++g) group_cfgs[g].paths = groups[g];
    std::vector<std::unique_ptr<PathGroupThread<T>>> helpers;
    for (size_t g = 1; g < groups.size(); ++g)
      helpers.push_back(std::make_unique<PathGroupThread<T>>(group_cfgs[g], widths, left, right, sentinel));
    // Cost rows from the first helper, or computed here if there is none.
    std::optional<CostRows<T>> base_costs;
    if (helpers.empty()) base_costs.emplace(cfg, widths, left, right);
    // P2 adapts to the base image's steps (section 3).
    PathAggregator<T> base_paths(group_cfgs[0], width, sentinel, cfg.p2_adapt);
    RowFinisher<T> finisher(cfg, widths, right, side, out, sentinel);
    std::vector<T> own_cost(helpers.empty() ? row_size : 0), sum(row_size);
    for (int y = 0; y < height; ++y) {
      const T* cost = own_cost.data();
      if (base_costs) base_costs->compute(y, own_cost.data());
      for (auto& helper : helpers) cost = helper->cost_row(y);  // the same row from every helper
      base_paths.push_row(y, cost, sum.data(), left);
      for (auto& helper : helpers) helper->add_sums(y, sum.data());
      finisher.finish(y, sum.data(), cost, 0, width);
      for (auto& helper : helpers) helper->release(y);
    }
  }

  if (cfg.speckle_size != 0)
    golden::speckle_filter(out, cfg.speckle_size, cfg.speckle_range << cfg.subpixel_bits, widths.invalid_word);
  const int dmax = cfg.dmax;
  if (cfg.median != 0)
    median_filter(out, cfg.median, widths.invalid_word, ((dmax - 1) << cfg.subpixel_bits) + 1, threads);
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
