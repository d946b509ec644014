// fpstereo_speckle: the speckle filter's streaming stage (docs/speckle-hardware.md) against
// golden::speckle_filter (docs/semantics.md section 5a). Frames of random heights (some shorter
// than the rows the stage holds) stream back to back, words held until taken, idle clocks in
// stretches; ROWS rows of invalid words push the last frame out. Every word of every frame must
// equal the golden model's, borders included.
#include <string>
#include <vector>

#include "golden_stages.hpp"
#include "speckle_sets.hpp"
#include "tb_common.hpp"

namespace {

struct SpeckleParams {
  int W = 32, S = 8, R = 2, WORD_W = 8;
};

using fpstereo::DisparityImage;

// A frame where a label's parent is the label just before it, which the row-end resolution
// resolves while that label's root is being written (its forward): row 1's labels 1 and 2 join
// label 0; in row 2 label 1 is a root, and label 2 starts at (4, 2), which keeps label 2, before it
// joins label 1's set at (5, 2); row 3 reads label 2 at (4, 3). A stale root for label 2 (label
// 1's of row 1, i.e. 0) sends row 3 to the lone pixel at (0, 2) instead of the region of 18
// pixels, more than the S of any set, which keeps all of it. Needs w >= 8.
DisparityImage forwarded_root_frame(int w, uint16_t invalid) {
  DisparityImage m(w, 5, invalid);
  for (int x = 0; x < 8; ++x) m.at(x, 0) = 10;
  for (int x : {0, 2, 3, 5, 6, 7}) m.at(x, 1) = 10;
  m.at(0, 2) = 30;
  for (int x : {2, 4, 5}) m.at(x, 2) = 10;
  m.at(4, 3) = 10;
  return m;
}

// A frame of words in 0 .. 40 (or below the invalid word) with invalid pixels, in one of the
// shapes of tests/test_speckle_hw_model.cpp: patches with noise and holes, bars of single-pixel
// runs, nested arches, combs, and arches and cups of about S pixels (one leg joins the other's
// set on the stack: the parent pointers and the counts decide).
DisparityImage random_frame(int w, int h, int size, int range, uint16_t invalid, modtb::Rng& rng) {
  DisparityImage m(w, h, invalid);
  const int top = std::min(40, int(invalid) - 1 - range - 1);
  switch (rng.below(5)) {
    case 0: {
      const int cell = int(rng.range(1, 5)), holes = int(rng.below(60)), noise = int(rng.below(50));
      std::vector<int> patch(size_t((w / cell + 1) * (h / cell + 1)));
      for (int& p : patch) p = int(rng.below(uint64_t(top) + 1));
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          int v = patch[size_t((y / cell) * (w / cell + 1) + x / cell)];
          if (rng.chance(unsigned(noise))) v += int(rng.below(7)) - 3;
          if (!rng.chance(unsigned(holes))) m.at(x, y) = uint16_t(std::clamp(v, 0, top));
        }
      break;
    }
    case 1: {
      const int len = int(rng.range(1, uint64_t(h)));
      for (int y = 0; y < len; ++y)
        for (int x = 0; x < w; ++x) m.at(x, y) = uint16_t(x % 2 == 0 ? 1 : 1 + range + 1);
      break;
    }
    case 2: {
      const int legs_end = h / 2, depth = std::min(w / 4, legs_end / 2);
      for (int k = 0; k < depth; ++k) {
        const int left = 2 * k, right = w - 1 - 2 * k;
        for (int x = left; x <= right; ++x) m.at(x, 2 * k) = 10;
        for (int y = 2 * k + 1; y <= legs_end; ++y) m.at(left, y) = m.at(right, y) = 10;
      }
      for (int y = legs_end + 1; y < h; ++y)
        for (int x = 0; x < w; ++x)
          if (rng.chance(50)) m.at(x, y) = uint16_t(rng.chance(30) ? 30 : 10);
      break;
    }
    case 3: {
      for (int n = int(rng.range(1, 8)); n > 0; --n) {
        const int legs = int(rng.range(1, uint64_t(std::max(1, size / 2)))), bar = int(rng.range(2, 6));
        const int x0 = int(rng.below(uint64_t(w))), y0 = int(rng.below(uint64_t(h)));
        const bool cup = rng.chance(50);
        const uint16_t v = uint16_t(rng.below(uint64_t(top) + 1));
        for (int k = 0; k < bar; ++k)
          if (m.contains(x0 + k, cup ? y0 + legs : y0)) m.at(x0 + k, cup ? y0 + legs : y0) = v;
        for (int k = 0; k < legs; ++k)
          for (int leg : {x0, x0 + bar - 1})
            if (m.contains(leg, cup ? y0 + k : y0 + 1 + k)) m.at(leg, cup ? y0 + k : y0 + 1 + k) = v;
      }
      break;
    }
    default: {
      const int len = int(rng.range(1, uint64_t(h))), gap = int(rng.range(1, 2));
      for (int x = 0; x < w; ++x) {
        if (rng.chance(50)) m.at(x, h - 1) = 10;
        if (x % (gap + 1) == 0)
          for (int y = std::max(0, h - 1 - len); y < h - 1; ++y) m.at(x, y) = uint16_t(rng.chance(30) ? 20 : 10);
      }
      break;
    }
  }
  return m;
}

template <typename M>
int run_speckle(const char* name, const SpeckleParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  const uint16_t invalid = uint16_t(modtb::mask_of(p.WORD_W));
  const int rows_held = p.S + 2 + (p.S + 3) / 4;

  // The stream: frames back to back, then rows_held rows of invalid words.
  std::vector<DisparityImage> frames;
  struct Word {
    uint16_t word;
    bool first;
  };
  std::vector<Word> stream;
  long words_wanted = o.cycles * 10;
  frames.push_back(forwarded_root_frame(p.W, invalid));
  for (int y = 0; y < frames.back().height; ++y)
    for (int x = 0; x < p.W; ++x) stream.push_back({frames.back().at(x, y), x == 0 && y == 0});
  while (long(stream.size()) < words_wanted) {
    const int h = int(rng.range(1, 40));
    frames.push_back(random_frame(p.W, h, p.S, p.R, invalid, rng));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < p.W; ++x) stream.push_back({frames.back().at(x, y), x == 0 && y == 0});
  }
  const size_t image_words = stream.size();
  for (int y = 0; y < rows_held; ++y)
    for (int x = 0; x < p.W; ++x) stream.push_back({invalid, x == 0 && y == 0});

  std::vector<uint16_t> got;
  got.reserve(image_words);
  m.rst = 1;
  m.in_valid = 0;
  m.clk = 0;
  m.eval();
  modtb::tick(m);
  modtb::tick(m);
  m.rst = 0;
  long cycle = 0, idle = 0;
  unsigned idle_share = 0;
  for (size_t next = 0; next < stream.size(); ++cycle) {
    if (cycle % 500 == 0) idle_share = unsigned(rng.below(4)) * 20;  // stretches of 0 .. 60 % idle
    if (!m.in_valid && !rng.chance(idle_share)) {
      m.in_valid = 1;
      m.in_word = stream[next].word;
      m.in_first = stream[next].first;
    }
    idle += !m.in_valid;
    m.eval();
    const bool taken = m.in_valid && m.in_ready;
    modtb::tick(m);
    if (taken) {
      m.in_valid = 0;
      ++next;
    }
    if (m.out_valid && got.size() < image_words) got.push_back(uint16_t(m.out_word));
  }
  for (int k = 0; k < 8; ++k, ++cycle) {  // the last word's exit
    m.eval();
    modtb::tick(m);
    if (m.out_valid && got.size() < image_words) got.push_back(uint16_t(m.out_word));
  }
  check.expect(cycle, "words out", image_words, got.size());

  size_t at = 0, removed = 0;
  for (size_t f = 0; f < frames.size(); ++f) {
    DisparityImage expected = frames[f];
    fpstereo::golden::speckle_filter(expected, p.S, p.R, invalid);
    for (int y = 0; y < expected.height; ++y)
      for (int x = 0; x < expected.width; ++x, ++at)
        removed += expected.at(x, y) != frames[f].at(x, y);
    at -= size_t(expected.width) * size_t(expected.height);
    for (int y = 0; y < expected.height; ++y)
      for (int x = 0; x < expected.width; ++x, ++at)
        check.expect(cycle, "frame " + std::to_string(f) + " (" + std::to_string(x) + ", " + std::to_string(y) + ")",
                     expected.at(x, y), at < got.size() ? got[at] : invalid + 1U);
  }
  return check.finish("W=" + std::to_string(p.W) + " S=" + std::to_string(p.S) + " R=" + std::to_string(p.R) +
                      " WORD_W=" + std::to_string(p.WORD_W) + ": golden::speckle_filter word for word, " +
                      std::to_string(frames.size()) + " frames back to back (" + std::to_string(removed) +
                      " pixels removed), " + std::to_string(cycle) +
                      " cycles, " + std::to_string(idle) + " idle");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_speckle, SpeckleParams)
MODTB_SETS(X)
#undef X

}  // namespace
