// The speckle filter's hardware algorithm (docs/speckle-hardware.md) against the golden model:
// the cycle-level model streams frames back to back with idle clocks and must give
// golden::SpeckleFilter's words exactly, every pixel, borders included.
#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

#include "compare.hpp"
#include "golden_stages.hpp"
#include "speckle_hw_model.hpp"

using namespace fpstereo;

namespace {

constexpr uint16_t kInvalid = 4095;  // a 12-bit word's invalid value, far from the others

struct Case {
  int size, range;
  int rows;  // rows the stage holds, 0: speckle_hw::rows_held
  int clocks_per_word = 1;  // a word enters at most once every so many clocks
  std::vector<DisparityImage> frames;  // all of one width
};

struct Streamed {
  std::vector<DisparityImage> frames;
  int max_stack = 0, max_queue = 0;
  long min_slack = 0;
};

// Streams the frames back to back through the model, `idle` the chance of an idle clock before
// each word, then rows() rows of flush words to push the last rows out.
Streamed stream(const Case& c, double idle, std::mt19937& rng) {
  const int width = c.frames.front().width;
  speckle_hw::StreamingSpeckleModel model(width, c.size, c.range, kInvalid,
                                          c.rows > 0 ? c.rows : speckle_hw::rows_held(c.size, c.clocks_per_word));
  Streamed out;
  std::vector<std::pair<int, int>> row_of;  // stream row -> (frame, y)
  for (size_t f = 0; f < c.frames.size(); ++f) {
    out.frames.emplace_back(width, c.frames[f].height, uint16_t(0));
    for (int y = 0; y < c.frames[f].height; ++y) row_of.emplace_back(int(f), y);
  }
  std::bernoulli_distribution pause(idle);
  const auto take = [&](const std::optional<speckle_hw::StreamingSpeckleModel::Output>& o) {
    if (!o || o->row >= int(row_of.size())) return;
    const auto [f, y] = row_of[size_t(o->row)];
    out.frames[size_t(f)].at(o->x, y) = o->word;
  };
  const auto feed = [&](uint16_t word, bool frame_start) {
    for (int k = 1; k < c.clocks_per_word; ++k) take(model.clock(std::nullopt));
    while (pause(rng)) take(model.clock(std::nullopt));
    take(model.clock(word, frame_start));
  };
  for (const DisparityImage& frame : c.frames)
    for (int y = 0; y < frame.height; ++y)
      for (int x = 0; x < width; ++x) feed(frame.at(x, y), y == 0);
  for (int y = 0; y < model.rows(); ++y)
    for (int x = 0; x < width; ++x) feed(kInvalid, y == 0);
  out.max_stack = model.max_stack_depth();
  out.max_queue = model.max_finalise_queue();
  out.min_slack = model.min_kill_slack_rows();
  return out;
}

// Every frame through the model against golden::speckle_filter; returns the mismatching pixels.
size_t mismatches(const Case& c, double idle, std::mt19937& rng, std::string& first, Streamed* stats = nullptr) {
  const Streamed got = stream(c, idle, rng);
  if (stats != nullptr) *stats = got;
  size_t total = 0;
  for (size_t f = 0; f < c.frames.size(); ++f) {
    DisparityImage expected = c.frames[f];
    golden::speckle_filter(expected, c.size, c.range, kInvalid);
    const Comparison cmp = compare_words(expected, got.frames[f], 3);
    if (!cmp.equal() && first.empty())
      first = "frame " + std::to_string(f) + " (" + std::to_string(expected.width) + " x " +
              std::to_string(expected.height) + ", S " + std::to_string(c.size) + ", R " + std::to_string(c.range) +
              "): " + cmp.report();
    total += cmp.mismatches;
  }
  return total;
}

// --- map makers: each draws words in 0 .. 40 and leaves some pixels invalid ---

// Patches of nearly equal words, noise, holes: many small regions of all shapes.
DisparityImage blobs(int w, int h, std::mt19937& rng) {
  DisparityImage m(w, h);
  std::uniform_int_distribution<int> base(0, 40), step(-3, 3), cell(1, 6);
  std::uniform_real_distribution<double> u(0, 1);
  const int cw = cell(rng), ch = cell(rng);
  const double holes = u(rng) * 0.6, noise = u(rng) * 0.5;
  std::vector<int> patch(size_t((w / cw + 1) * (h / ch + 1)));
  for (int& p : patch) p = base(rng);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int v = patch[size_t((y / ch) * (w / cw + 1) + x / cw)];
      if (u(rng) < noise) v += step(rng);
      m.at(x, y) = u(rng) < holes ? kInvalid : uint16_t(std::clamp(v, 0, 40));
    }
  return m;
}

// Vertical teeth of length `tooth` hanging from a spine, or standing alone (spine invalid).
DisparityImage comb(int w, int h, std::mt19937& rng) {
  DisparityImage m(w, h, kInvalid);
  std::uniform_int_distribution<int> tooth_len(1, h), gap(1, 2), v(0, 40);
  const bool spine = rng() % 2 == 0;
  const int len = tooth_len(rng), g = gap(rng);
  for (int x = 0; x < w; ++x) {
    if (spine) m.at(x, 0) = 10;
    if (x % (g + 1) == 0)
      for (int y = 1; y < std::min(h, 1 + len); ++y) m.at(x, y) = uint16_t(rng() % 3 == 0 ? v(rng) : 10);
  }
  if (rng() % 2 == 0)  // upside down: the teeth meet at the bottom, the merges come late
    for (int y = 0; y < h / 2; ++y)
      for (int x = 0; x < w; ++x) std::swap(m.at(x, y), m.at(x, h - 1 - y));
  return m;
}

// A square spiral of one word on invalid ground, walls one pixel wide: long thin regions that turn.
DisparityImage spiral(int w, int h, std::mt19937& rng) {
  DisparityImage m(w, h, kInvalid);
  const uint16_t word = uint16_t(rng() % 41);
  int x0 = 0, y0 = 0, x1 = w - 1, y1 = h - 1;
  while (x0 <= x1 && y0 <= y1) {
    for (int x = x0; x <= x1; ++x) m.at(x, y0) = word;
    for (int y = y0; y <= y1; ++y) m.at(x1, y) = word;
    if (y1 > y0 + 1)
      for (int x = x0 + 2; x <= x1; ++x) m.at(x, y1) = word;
    if (x1 > x0 + 1)
      for (int y = y0 + 2; y <= y1; ++y) m.at(x0 + 1 < x1 ? x0 + 2 : x0, y) = word;
    x0 += 2, y0 += 2, x1 -= 2, y1 -= 2;
  }
  if (rng() % 2 == 0)  // cut the spiral in places: several regions of similar shape
    for (int k = 0; k < 4; ++k) m.at(int(rng() % unsigned(w)), int(rng() % unsigned(h))) = kInvalid;
  return m;
}

// Staircases of steps that drift by the range or just beyond it: the words decide the merges.
DisparityImage staircase(int w, int h, int range, std::mt19937& rng) {
  DisparityImage m(w, h);
  std::uniform_int_distribution<int> run(1, 5);
  const int drift = range + int(rng() % 2);
  for (int y = 0; y < h; ++y) {
    int x = 0, v = int(rng() % 10);
    const int shift = y * int(1 + rng() % 2);
    while (x < w) {
      const int len = run(rng);
      for (int k = 0; k < len && x < w; ++k, ++x)
        m.at(x, y) = (x + shift) % 7 == 0 ? kInvalid : uint16_t(std::clamp(v + ((x + shift) / 3) % 4, 0, 40));
      v += drift;
      if (v > 35) v = int(rng() % 5);
    }
  }
  return m;
}

// Columns of alternating words: every pixel its own run, bars of `len` rows ending together, the
// kill chain's worst burst.
DisparityImage bars(int w, int h, int len, int range) {
  DisparityImage m(w, h, kInvalid);
  for (int y = 0; y < std::min(h, len); ++y)
    for (int x = 0; x < w; ++x) m.at(x, y) = uint16_t(x % 2 == 0 ? 5 : 5 + range + 1);
  return m;
}

// Nested arches (a bar on two legs, one inside the other) over noise: below the legs the row
// meets each arch's left leg first (the stack grows as deep as the arches are nested) and its
// right leg last (the arches close one a pixel while the noise ends runs).
DisparityImage arches(int w, int h, std::mt19937& rng) {
  DisparityImage m(w, h, kInvalid);
  const int legs_end = h / 2, depth = std::min(w / 4, legs_end / 2);
  for (int k = 0; k < depth; ++k) {
    const int left = 2 * k, right = w - 1 - 2 * k;
    for (int x = left; x <= right; ++x) m.at(x, 2 * k) = 10;
    for (int y = 2 * k + 1; y <= legs_end; ++y) m.at(left, y) = m.at(right, y) = 10;
  }
  for (int y = legs_end + 1; y < h; ++y)
    for (int x = 0; x < w; ++x) m.at(x, y) = rng() % 2 == 0 ? kInvalid : uint16_t(rng() % 3 == 0 ? 30 : 10);
  return m;
}

DisparityImage checker(int w, int h, std::mt19937& rng) {
  DisparityImage m(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m.at(x, y) = rng() % 5 == 0 ? kInvalid : uint16_t((x + y) % 2 == 0 ? 0 : 20);
  return m;
}

Case random_case(std::mt19937& rng) {
  std::uniform_int_distribution<int> width(16, 64), height(8, 40), size(1, 30), r(0, 3), frames(1, 3), kind(0, 6);
  Case c{};
  c.size = size(rng);
  c.range = r(rng) << (rng() % 3);  // R = r << sub-pixel bits
  const int w = width(rng);
  for (int f = frames(rng); f > 0; --f) {
    const int h = height(rng);
    switch (kind(rng)) {
      case 0: c.frames.push_back(comb(w, h, rng)); break;
      case 1: c.frames.push_back(spiral(w, h, rng)); break;
      case 2: c.frames.push_back(staircase(w, h, c.range, rng)); break;
      case 3: c.frames.push_back(checker(w, h, rng)); break;
      case 4: c.frames.push_back(arches(w, h, rng)); break;
      default: c.frames.push_back(blobs(w, h, rng)); break;
    }
  }
  return c;
}

}  // namespace

TEST_CASE("speckle hardware model: random and adversarial maps give golden::SpeckleFilter's words", "[speckle_hw]") {
  std::mt19937 rng(29);
  size_t total = 0, cases = 0;
  std::string first;
  int max_stack = 0, max_queue = 0;
  long min_slack = 1L << 40;
  for (int i = 0; i < 3000; ++i) {
    Case c = random_case(rng);
    c.clocks_per_word = i % 4 == 3 ? 1 + int(rng() % 4) : 1;
    Streamed stats;
    total += mismatches(c, i % 3 == 0 ? 0.0 : 0.3, rng, first, &stats);
    max_stack = std::max(max_stack, stats.max_stack);
    max_queue = std::max(max_queue, stats.max_queue);
    min_slack = std::min(min_slack, stats.min_slack);
    ++cases;
  }
  INFO(first);
  CHECK(total == 0);
  INFO("cases " << cases << ", deepest stack " << max_stack << ", longest finalisation queue " << max_queue
                << ", fewest rows of slack at a kill " << min_slack);
  CHECK(min_slack >= 1);
  WARN("cases " << cases << ", deepest stack " << max_stack << ", longest finalisation queue " << max_queue
                << ", fewest rows of slack at a kill " << min_slack);
}

TEST_CASE("speckle hardware model: the kill chain's worst burst is drained in time", "[speckle_hw]") {
  std::mt19937 rng(7);
  for (int size : {1, 2, 3, 5, 8, 13, 30})
    for (int width : {16, 33, 64})
      for (int clocks_per_word : {1, 2, 4}) {
        // Single-pixel runs in bars of S rows, all closing in the same row, frame after frame.
        Case c{size, 1, 0, clocks_per_word, {}};
        for (int f = 0; f < 3; ++f) c.frames.push_back(bars(width, size + 1, size, 1));
        std::string first;
        Streamed stats;
        INFO("S " << size << ", width " << width << ", clocks a word " << clocks_per_word);
        CHECK(mismatches(c, 0.0, rng, first, &stats) == 0);
        INFO(first);
        CHECK(stats.min_slack >= 1);
      }
}
