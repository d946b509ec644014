// Cycle-level model of the speckle filter's streaming hardware form (docs/speckle-hardware.md).
// Every call to clock() is one clock: at most one word enters, and each memory sees at most the
// reads and writes per clock that the document lists. The model checks the design's bounds as it
// runs (stack and finalisation-queue depths, the one-write-per-clock rules, the readiness of the
// row-end resolution); a violated bound throws std::logic_error with the rule it broke.
#pragma once

#include <algorithm>
#include <cstdint>
#include <deque>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fpstereo::speckle_hw {

// The rows the stage holds for a speckle size S when a word enters at most once every k clocks:
// S rows for a region to close and one to see it closed, ceil(S / k) for the kill chain (its
// backlog is under S * W runs, drained one a clock) and one for the chain's own pipeline.
inline int rows_held(int size, int clocks_per_word = 1) { return size + 2 + (size + clocks_per_word - 1) / clocks_per_word; }

class StreamingSpeckleModel {
 public:
  // width: pixels a row; size: S >= 1; range: R = r << sub-pixel bits; invalid: the invalid word.
  StreamingSpeckleModel(int width, int size, int range, uint16_t invalid, int rows = 0)
      : width_(width), size_(size), range_(range), invalid_(invalid), rows_(rows > 0 ? rows : rows_held(size)),
        words_(size_t(rows_) * size_t(width), invalid), kill_(words_.size(), 0), next_(words_.size(), 0),
        prev_words_(size_t(width), invalid), row_labels_(size_t(width), kNone),
        parent_(2, std::vector<int>(size_t(width))), resolved_(2, std::vector<int>(size_t(width))),
        classes_(2, std::vector<ClassRecord>(size_t(width))),
        run_row_(words_.size(), -1), pixel_row_(words_.size(), -1) {}

  struct Output {
    int row;  // the stream's row count: frames follow each other without a gap
    int x;
    uint16_t word;
  };

  // One clock. word: the entering word, or nothing in an idle clock; frame_start: the entering
  // word's row is a frame's first (nothing above it connects). Returns the word that leaves, the
  // one rows() rows before in the same column, once the stream has filled the stage.
  std::optional<Output> clock(std::optional<uint16_t> word, bool frame_start = false) {
    std::optional<Output> out;
    if (word) out = leave();  // read first: a kill written in this clock is too late for it
    resolve_step();
    kill_step();
    if (word) label(*word, frame_start);
    drain_finalised();
    return out;
  }

  int rows() const { return rows_; }
  int max_stack_depth() const { return max_stack_; }
  int max_finalise_queue() const { return max_queue_; }
  // The fewest rows left before a killed run's row would have left, over all kills.
  long min_kill_slack_rows() const { return min_slack_; }

 private:
  static constexpr int kNone = -1;
  static constexpr size_t kFinaliseQueue = 1;

  struct List {  // a small set's runs as a chain through next_ (meaningless once big)
    int head = 0, tail = 0;
  };
  struct Set {  // a set of the row being labelled: the current run's or an open one on the stack
    int tag = kNone;  // unique in the row while on the stack
    int label = 0;    // its root label (the smallest label of the row in it)
    int count = 0;    // saturated at S + 1: S + 1 means big, for good
    List runs;
    int last_left = 0;   // x of its last pixel in the row being labelled
    int last_right = 0;  // x of its last pixel in the row above (valid while on the stack)
  };
  struct ClassRecord {  // a closed set of a labelled row, at its root label
    int count = 0;
    int last_x = 0;
    List runs;
    // Set by the next row when it meets the class, with the tag of the stack entry it joined;
    // cleared by the finalisation that writes the record, so no stale mark survives a row.
    bool met = false;
    int tag = kNone;
  };
  struct Finalised {
    int bank;
    int label;
    ClassRecord record;
  };

  bool connected(uint16_t a, uint16_t b) const {
    return a != invalid_ && b != invalid_ && std::abs(int(a) - int(b)) <= range_;
  }
  bool big(int count) const { return count > size_; }
  int add(int a, int b) const { return std::min(a + b, size_ + 1); }
  static void require(bool ok, const char* rule) {
    if (!ok) throw std::logic_error(std::string("speckle hardware model: ") + rule);
  }

  int slot(long row) const { return int(row % rows_); }
  size_t position(long row, int x) const { return size_t(slot(row)) * size_t(width_) + size_t(x); }
  int bank(long row) const { return int(row & 1); }

  // --- the exit: the word of the same column rows_ rows back, read before it is overwritten ---
  std::optional<Output> leave() {
    const long row = row_ - rows_;
    if (row < 0) return std::nullopt;
    const size_t at = position(row_, x_);
    const uint16_t word = words_[at];
    const bool run_start = x_ == 0 || !connected(exit_left_, word);
    if (run_start) exit_run_killed_ = kill_[at] != 0;  // a run's fate is kept at its first pixel
    exit_left_ = word;
    const bool removed = word != invalid_ && exit_run_killed_;
    return Output{int(row), x_, removed ? invalid_ : word};
  }

  // --- the row-end resolution of the previous row's labels: one label a clock from the row's end ---
  void resolve_step() {
    if (resolve_next_ >= resolve_count_) return;
    const int b = bank(row_ - 1), l = resolve_next_++;
    const int p = parent_[size_t(b)][size_t(l)];  // parent[l] <= l: one pass in label order finds every root
    resolved_[size_t(b)][size_t(l)] = p == l ? l : resolved_[size_t(b)][size_t(p)];
  }

  // --- the kill chain: one run a clock ---
  void kill_step() {
    if (!kill_pending_) return;
    const size_t at = size_t(kill_at_);
    require(run_row_[at] == pixel_row_[at], "a kill reached a run whose row has left");
    min_slack_ = std::min(min_slack_, run_row_[at] + rows_ - row_);
    kill_[at] = 1;
    if (kill_at_ == kill_tail_)
      kill_pending_ = false;
    else
      kill_at_ = next_[at];
  }

  void enqueue_kill(const List& runs) {
    if (kill_pending_) {
      write_next(kill_tail_, runs.head);
    } else {
      kill_pending_ = true;
      kill_at_ = runs.head;
    }
    kill_tail_ = runs.tail;
  }

  void write_next(int at, int value) {
    require(next_writes_this_clock_ == 0, "two writes to next[] in one clock");
    ++next_writes_this_clock_;
    next_[size_t(at)] = value;
  }

  // Joins list b to list a if the joined set stays small; a big set keeps no list.
  void join_lists(Set& a, const List& b, int b_count) {
    const int count = add(a.count, b_count);
    if (!big(count)) {
      write_next(a.runs.tail, b.head);
      a.runs.tail = b.tail;
    }
    a.count = count;
  }

  ClassRecord& class_of_row_above(int label) {
    const int b = bank(row_ - 1);
    for (Finalised& f : finalising_)  // the queue's bypass
      if (f.bank == b && f.label == label) return f.record;
    return classes_[size_t(b)][size_t(label)];
  }

  void finalise(const Set& set) {
    finalising_.push_back({bank(row_), set.label, {set.count, set.last_left, set.runs}});
    max_queue_ = std::max(max_queue_, int(finalising_.size()));
  }

  // The row's class table takes two writes a clock (a true dual-port bank: the other bank, the row
  // above's, is only read, on one port); the third set a row's last pixel can close waits a clock.
  void drain_finalised() {
    for (int port = 0; port < 2 && !finalising_.empty(); ++port) {
      const Finalised f = finalising_.front();
      finalising_.pop_front();
      classes_[size_t(f.bank)][size_t(f.label)] = f.record;
    }
    require(finalising_.size() <= kFinaliseQueue, "more than one finalised set waiting after a clock");
  }

  void end_current_run() {
    if (!current_) return;
    if (!current_on_stack_) finalise(*current_);
    current_.reset();
    current_on_stack_ = false;
  }

  Set& holder() { return current_on_stack_ ? stack_.back() : *current_; }

  // --- the labeller: one pixel (x_, row_) a clock ---
  void label(uint16_t word, bool frame_start) {
    next_writes_this_clock_ = 0;
    if (x_ == 0) start_row(frame_start);
    const int b = bank(row_), above_bank = bank(row_ - 1);
    const uint16_t above = prev_words_[size_t(x_)];
    const int above_label = row_labels_[size_t(x_)];  // read before this row's label replaces it
    int c = kNone;
    if (above_label != kNone) {
      require(above_label < resolve_next_, "a label read before the row-end resolution reached it");
      c = resolved_[size_t(above_bank)][size_t(above_label)];
    }
    const bool left = x_ > 0 && connected(left_word_, word);
    const bool up = !above_frame_start_ && c != kNone && connected(above, word);
    if (!left) end_current_run();
    int this_label = kNone;
    if (word != invalid_) {
      if (!left) {
        const int n = next_label_++;
        const int run = int(position(row_, x_));
        run_row_[size_t(run)] = row_;
        current_ = Set{kNone, n, 1, List{run, run}, x_, 0};
        parent_[size_t(b)][size_t(n)] = n;
      } else {
        Set& s = holder();
        s.count = add(s.count, 1);
        s.last_left = x_;
      }
      if (up) join_above(c, b);
      this_label = holder().label;
    }
    if (c != kNone) close_if_done(c);
    if (!stack_.empty() && stack_.back().last_right == x_) pop();
    row_labels_[size_t(x_)] = this_label;
    prev_words_[size_t(x_)] = word;
    words_[position(row_, x_)] = word;
    kill_[position(row_, x_)] = 0;
    pixel_row_[position(row_, x_)] = row_;
    left_word_ = word;
    if (++x_ == width_) end_row();
  }

  void start_row(bool frame_start) { above_frame_start_ = frame_start || row_ == 0; }

  void join_above(int c, int b) {
    ClassRecord& j = class_of_row_above(c);
    if (j.met) {  // c's set already has pixels in this row: planarity makes it the top
      require(!stack_.empty() && stack_.back().tag == j.tag, "a met class is not the top of the stack");
      if (current_on_stack_) return;  // the same set
      Set& top = stack_.back();
      Set& cur = *current_;
      const int count = add(top.count, cur.count);
      if (!big(count)) {
        write_next(top.runs.tail, cur.runs.head);
        top.runs.tail = cur.runs.tail;
      }
      top.count = count;
      top.last_left = x_;
      const int root = std::min(top.label, cur.label), other = std::max(top.label, cur.label);
      parent_[size_t(b)][size_t(other)] = root;
      top.label = root;
      current_.reset();
      current_on_stack_ = true;
      current_ = top;  // marker only: the data lives in the stack's top while on the stack
      return;
    }
    const ClassRecord above = j;
    Set& s = holder();
    join_lists(s, above.runs, above.count);
    j.met = true;
    if (current_on_stack_) {
      s.last_right = std::max(s.last_right, above.last_x);
      j.tag = s.tag;
    } else if (above.last_x > x_) {
      Set opened = *current_;
      opened.tag = next_tag_++;
      opened.last_right = above.last_x;
      stack_.push_back(opened);
      max_stack_ = std::max(max_stack_, int(stack_.size()));
      current_on_stack_ = true;
      j.tag = opened.tag;
    } else {
      j.tag = kNone;  // absorbed at its last pixel: never met again
    }
  }

  // A class of the row above whose last pixel is at x_ and that this row did not meet is closed.
  void close_if_done(int c) {
    const ClassRecord& above = class_of_row_above(c);
    if (above.last_x != x_ || above.met) return;
    if (!big(above.count)) enqueue_kill(above.runs);
  }

  void pop() {
    const Set top = stack_.back();
    stack_.pop_back();
    if (current_on_stack_) {
      current_ = top;
      current_on_stack_ = false;
    } else {
      finalise(top);
    }
  }

  void end_row() {
    end_current_run();
    require(stack_.empty(), "an open set left at the end of a row");
    resolve_count_ = next_label_;  // the row's labels resolve from the next clock on
    resolve_next_ = 0;
    next_label_ = 0;
    next_tag_ = 0;
    x_ = 0;
    ++row_;
  }

  const int width_, size_, range_;
  const uint16_t invalid_;
  const int rows_;
  std::vector<uint16_t> words_;      // rows_ x W: the words held
  std::vector<uint8_t> kill_;        // rows_ x W: a run's kill bit at its first pixel
  std::vector<int> next_;            // rows_ x W: the run chains, by a run's first pixel
  std::vector<uint16_t> prev_words_;  // W: the row above
  std::vector<int> row_labels_;       // W: a label a pixel, the row above's until overwritten
  std::vector<std::vector<int>> parent_, resolved_;  // 2 banks x W, by label
  std::vector<std::vector<ClassRecord>> classes_;    // 2 banks x W, by root label
  std::vector<Set> stack_;
  std::optional<Set> current_;
  bool current_on_stack_ = false;
  std::deque<Finalised> finalising_;
  long row_ = 0;
  int x_ = 0;
  uint16_t left_word_ = 0, exit_left_ = 0;
  bool exit_run_killed_ = false, above_frame_start_ = true;
  int next_label_ = 0, next_tag_ = 0, resolve_next_ = 0, resolve_count_ = 0;
  bool kill_pending_ = false;
  int kill_at_ = 0, kill_tail_ = 0;
  int next_writes_this_clock_ = 0;
  std::vector<long> run_row_, pixel_row_;  // checks only: the row a run started in, a position holds
  long min_slack_ = 1L << 40;
  int max_stack_ = 0, max_queue_ = 0;
};

}  // namespace fpstereo::speckle_hw
