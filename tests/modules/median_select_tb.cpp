// fpstereo_median_select: median of an M x M window of disparity words (docs/semantics.md
// section 6, words as in section 8). Reference: an invalid centre gives the invalid word
// 1 << DISP_W; otherwise the used words (centre by its flag; others inside the image by
// row_valid / col_valid and with flag 0) are sorted and v_((k-1)/2) is the result. Latency
// 3 * WORD_W enabled steps; en low holds.
#include <algorithm>
#include <string>
#include <vector>

#include "median_select_sets.hpp"
#include "pipe_model.hpp"
#include "tb_common.hpp"

namespace {

struct MedianParams {
  int M = 5, WORD_W = 8;
};

template <typename M>
int run_median_select(const char* name, const MedianParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  const int n = p.M * p.M, disp_w = p.WORD_W - 1, centre = (p.M / 2) * p.M + p.M / 2;
  const uint64_t invalid = uint64_t{1} << disp_w;
  modtb::EnabledPipe<uint64_t> pipe(3 * p.WORD_W);
  std::vector<uint64_t> words(n), used;
  long enabled = 0, invalid_centres = 0;
  m.clk = 0;
  m.eval();
  for (long cycle = 0; cycle < o.cycles; ++cycle) {
    const bool en = !rng.chance(modtb::idle_percent(cycle));
    // disparities: narrow range (ties) or full; invalid words with a varying share
    const bool narrow = rng.chance(40);
    const unsigned invalid_share = static_cast<unsigned>(rng.below(4)) * 25;
    for (int e = 0; e < n; ++e) {
      words[e] = rng.chance(invalid_share) ? invalid : (narrow ? rng.below(3) : rng.bits(disp_w));
      modtb::set_bits(m.window, e * p.WORD_W, p.WORD_W, words[e]);
    }
    // rows / columns inside the image: mostly all, else a border pattern, sometimes any mask
    uint64_t rows = modtb::mask_of(p.M), cols = modtb::mask_of(p.M);
    switch (rng.below(4)) {
      case 0: break;
      case 1: rows &= modtb::mask_of(p.M) << rng.below(p.M / 2 + 1); cols >>= rng.below(p.M / 2 + 1); break;
      case 2: cols &= modtb::mask_of(p.M) << rng.below(p.M / 2 + 1); rows >>= rng.below(p.M / 2 + 1); break;
      default: rows = rng.bits(p.M); cols = rng.bits(p.M); break;
    }
    m.row_valid = rows;
    m.col_valid = cols;
    uint64_t want = invalid;
    if (words[centre] != invalid) {
      used.clear();
      for (int e = 0; e < n; ++e) {
        const bool inside = e == centre || (((rows >> (e / p.M)) & 1) && ((cols >> (e % p.M)) & 1));
        if (inside && words[e] != invalid) used.push_back(words[e]);
      }
      std::sort(used.begin(), used.end());
      want = used[(used.size() - 1) / 2];
    } else {
      invalid_centres += en;
    }
    m.en = en;
    m.eval();
    modtb::tick(m);
    pipe.edge(en, want);
    enabled += en;
    if (const auto& w = pipe.out()) check.expect(cycle, "median", *w, modtb::get_bits(m.median, 0, p.WORD_W));
  }
  return check.finish("M=" + std::to_string(p.M) + " WORD_W=" + std::to_string(p.WORD_W) +
                      ": lower median of the used words, invalid centre -> invalid word, latency " +
                      std::to_string(3 * p.WORD_W) + ", hold while en low; " + std::to_string(o.cycles) + " cycles, " +
                      std::to_string(enabled) + " enabled (" + std::to_string(invalid_centres) + " invalid centres)");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_median_select, MedianParams)
MODTB_SETS(X)
#undef X

}  // namespace
