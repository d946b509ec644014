// fpstereo_path_lanes: one SGM path step for UF lanes (docs/semantics.md section 3):
//   L(d) = C(d) + min(P(d), P(d-1) + P1, P(d+1) + P1, m + P2) - m, or C(d) without predecessor,
// where a neighbour outside the disparity range (prev_below / prev_above all ones) is left out
// of the minimum. Stimulus within the module's contract: m = prev_min is the minimum of the whole
// predecessor, so at most Cmax, and every predecessor cost lies in m .. Cmax + P2; P1, P2 at most
// the path cost's maximum minus Cmax. One register stage; en low holds.
#include <algorithm>
#include <string>
#include <vector>

#include "path_lanes_sets.hpp"
#include "pipe_model.hpp"
#include "tb_common.hpp"

namespace {

struct PathLanesParams {
  int UF = 32, COST_W = 6, PATH_W = 8;
};

template <typename M>
int run_path_lanes(const char* name, const PathLanesParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  const uint64_t cmax = modtb::mask_of(p.COST_W), ones = modtb::mask_of(p.PATH_W);
  const uint64_t penalty_max = ones - cmax;
  modtb::EnabledPipe<std::vector<uint64_t>> pipe(2);
  std::vector<uint64_t> cost(p.UF), prev(p.UF), want(p.UF);
  uint64_t p1 = 0, p2 = 0;
  long enabled = 0, without_pred = 0, missing_neighbour = 0;
  auto penalty = [&] {
    switch (rng.below(4)) {
      case 0: return uint64_t{0};
      case 1: return penalty_max;
      default: return rng.range(0, penalty_max);
    }
  };
  m.clk = 0;
  m.eval();
  for (long cycle = 0; cycle < o.cycles; ++cycle) {
    const bool en = !rng.chance(modtb::idle_percent(cycle));
    if (cycle % 100 == 0) {  // penalties are settings: they change rarely
      p1 = penalty();
      p2 = penalty();
    }
    const uint64_t mprev = rng.chance(30) ? (rng.chance(50) ? 0 : cmax) : rng.range(0, cmax);
    const uint64_t lmax = cmax + p2;
    auto path_value = [&] { return rng.chance(40) ? std::min(lmax, mprev + rng.below(3)) : rng.range(mprev, lmax); };
    for (int l = 0; l < p.UF; ++l) {
      cost[l] = modtb::edgy(rng, p.COST_W);
      prev[l] = path_value();
    }
    const bool has_below = !rng.chance(30), has_above = !rng.chance(30);
    const uint64_t below = has_below ? path_value() : ones, above = has_above ? path_value() : ones;
    const bool has_pred = !rng.chance(15);
    for (int l = 0; l < p.UF; ++l) {
      if (!has_pred) {
        want[l] = cost[l];
        continue;
      }
      uint64_t best = std::min(prev[l], mprev + p2);
      if (l > 0) best = std::min(best, prev[l - 1] + p1);
      else if (has_below) best = std::min(best, below + p1);
      if (l < p.UF - 1) best = std::min(best, prev[l + 1] + p1);
      else if (has_above) best = std::min(best, above + p1);
      want[l] = cost[l] + best - mprev;
    }
    m.p1 = p1;
    m.p2 = p2;
    m.has_pred = has_pred;
    m.prev_below = below;
    m.prev_above = above;
    m.prev_min = mprev;
    for (int l = 0; l < p.UF; ++l) {
      modtb::set_bits(m.cost, l * p.COST_W, p.COST_W, cost[l]);
      modtb::set_bits(m.prev, l * p.PATH_W, p.PATH_W, prev[l]);
    }
    m.en = en;
    m.eval();
    modtb::tick(m);
    pipe.edge(en, want);
    if (en) {
      ++enabled;
      without_pred += !has_pred;
      missing_neighbour += !has_below || !has_above;
    }
    if (const auto& w = pipe.out())
      for (int l = 0; l < p.UF; ++l)
        check.expect(cycle, "lane " + std::to_string(l), (*w)[l], modtb::get_bits(m.path, l * p.PATH_W, p.PATH_W));
  }
  return check.finish("UF=" + std::to_string(p.UF) + " COST_W=" + std::to_string(p.COST_W) + " PATH_W=" +
                      std::to_string(p.PATH_W) + ": L(d) per lane, latency 2, hold while en low; " +
                      std::to_string(o.cycles) + " cycles, " + std::to_string(enabled) + " enabled (" +
                      std::to_string(without_pred) + " without predecessor, " + std::to_string(missing_neighbour) +
                      " with a missing neighbour)");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_path_lanes, PathLanesParams)
MODTB_SETS(X)
#undef X

}  // namespace
