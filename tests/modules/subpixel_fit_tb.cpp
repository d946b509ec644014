// fpstereo_subpixel_fit: the winner d refined to units of 2^-K from the sums a, b, c at d - 1, d,
// d + 1 (docs/semantics.md, section 4). Reference: the offset f in -2^K .. 2^K nearest to
// delta * 2^K, delta = (a - c) / (2e), halves away from zero, found by trying every f on the
// cross-multiplied distance; d * 2^K at the ends of the range. Inputs keep a > b <= c, as a
// first minimum does, except at the ends, where a or c is arbitrary. Latency K + 3 enabled edges.
#include <cstdlib>
#include <string>

#include "pipe_model.hpp"
#include "subpixel_fit_sets.hpp"
#include "tb_common.hpp"

namespace {

struct SubpixelFitParams {
  int DMAX = 64, DISP_W = 6, SUM_W = 10, K = 4, EQUIANGULAR = 1, OUT_W = 10;
};

uint64_t reference_fit(const SubpixelFitParams& p, int64_t d, int64_t a, int64_t b, int64_t c) {
  const int64_t scale = int64_t(1) << p.K;
  if (d == 0 || d == p.DMAX - 1) return uint64_t(d * scale);
  const int64_t e = p.EQUIANGULAR ? std::max(a, c) - b : a + c - 2 * b;
  auto distance = [&](int64_t f) { return std::llabs(f * 2 * e - (a - c) * scale); };
  int64_t best = 0;
  for (int64_t f = -scale; f <= scale; ++f)
    if (distance(f) < distance(best) || (distance(f) == distance(best) && std::llabs(f) > std::llabs(best))) best = f;
  return uint64_t(d * scale + best);
}

template <typename M>
int run_subpixel_fit(const char* name, const SubpixelFitParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  modtb::EnabledPipe<uint64_t> pipe(p.K + 3);
  const uint64_t sum_max = modtb::mask_of(p.SUM_W);
  long enabled = 0;
  m.clk = 0;
  m.eval();
  for (long cycle = 0; cycle < o.cycles; ++cycle) {
    const bool en = !rng.chance(modtb::idle_percent(cycle));
    // d: often at or next to the ends; sums: small gaps (offsets near +-1/2 and ties), large ones
    // and the extremes of the width
    const unsigned where = rng.below(4);
    const int64_t d = where == 0 ? 0 : where == 1 ? p.DMAX - 1 : where == 2 ? 1 + rng.below(2) : rng.below(unsigned(p.DMAX));
    const bool narrow = rng.chance(50);
    const int64_t b = rng.chance(10) ? 0 : int64_t(rng.below(unsigned(sum_max / 2)));
    auto above = [&](int64_t low) {
      const uint64_t room = sum_max - uint64_t(low);
      return low + int64_t(narrow ? rng.below(unsigned(std::min<uint64_t>(room, 4)) + 1) : rng.below(unsigned(room) + 1));
    };
    int64_t a = std::min<int64_t>(above(b) + 1, int64_t(sum_max));
    if (a == b) a = b + 1;  // b <= sum_max / 2 leaves room
    int64_t c = above(b);
    if (d == 0) a = int64_t(rng.bits(p.SUM_W));
    if (d == p.DMAX - 1) c = int64_t(rng.bits(p.SUM_W));
    m.d = uint32_t(d);
    m.left = uint32_t(a);
    m.best = uint32_t(b);
    m.right = uint32_t(c);
    m.en = en;
    m.eval();
    modtb::tick(m);
    pipe.edge(en, reference_fit(p, d, a, b, c));
    enabled += en;
    if (const auto& want = pipe.out()) check.expect(cycle, "refined", *want, modtb::get_bits(m.refined, 0, p.OUT_W));
  }
  return check.finish("DMAX=" + std::to_string(p.DMAX) + " SUM_W=" + std::to_string(p.SUM_W) + " K=" +
                      std::to_string(p.K) + (p.EQUIANGULAR ? " equiangular" : " parabola") +
                      ": refined disparity, latency " + std::to_string(p.K + 3) + ", hold while en low; " +
                      std::to_string(o.cycles) + " cycles, " + std::to_string(enabled) + " enabled");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_subpixel_fit, SubpixelFitParams)
MODTB_SETS(X)
#undef X

}  // namespace
