// fpstereo_unique_tree: the uniqueness summaries of N sums (best, index, first, last, all,
// but_first, but_last, second). Reference: unique_ref.hpp, straight from the definitions over
// all N values (not a tree); latency max(1, ceil(clog2(N) / LEVELS_PER_STAGE)) enabled steps.
#include <algorithm>
#include <string>
#include <vector>

#include "pipe_model.hpp"
#include "tb_common.hpp"
#include "unique_ref.hpp"
#include "unique_tree_sets.hpp"

namespace {

struct UniqueTreeParams {
  int N = 8, W = 10, IDX_W = 3, LEVELS_PER_STAGE = 3;
  int LAT = 1;  // the latency the set states, which the module checks; the bench derives its own
};

int clog2(int n) {
  int b = 0;
  while ((1 << b) < n) ++b;
  return b;
}

template <typename M>
int run_unique_tree(const char* name, const UniqueTreeParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  const int levels = p.N > 1 ? clog2(p.N) : 0;
  const int latency = std::max(1, (levels + p.LEVELS_PER_STAGE - 1) / p.LEVELS_PER_STAGE);
  const uint64_t none = modtb::mask_of(p.W);
  modtb::EnabledPipe<modtb::UniqueSummary> pipe(latency);
  std::vector<uint64_t> v(p.N);
  long enabled = 0;
  m.clk = 0;
  m.eval();
  for (long cycle = 0; cycle < o.cycles; ++cycle) {
    const bool en = !rng.chance(modtb::idle_percent(cycle));
    modtb::unique_values(rng, v, p.W);
    for (int i = 0; i < p.N; ++i) modtb::set_bits(m.values, i * p.W, p.W, v[i]);
    m.en = en;
    m.eval();
    modtb::tick(m);
    pipe.edge(en, modtb::unique_reference(v, none));
    enabled += en;
    if (const auto& want = pipe.out()) {
      check.expect(cycle, "best", want->best, modtb::get_bits(m.best, 0, p.W));
      check.expect(cycle, "index", want->index, modtb::get_bits(m.index, 0, p.IDX_W));
      check.expect(cycle, "first", want->first, m.first);
      check.expect(cycle, "last", want->last, m.last);
      check.expect(cycle, "all", want->all, modtb::get_bits(m.all, 0, p.W));
      check.expect(cycle, "but_first", want->but_first, modtb::get_bits(m.but_first, 0, p.W));
      check.expect(cycle, "but_last", want->but_last, modtb::get_bits(m.but_last, 0, p.W));
      check.expect(cycle, "second", want->second, modtb::get_bits(m.second, 0, p.W));
    }
  }
  return check.finish("N=" + std::to_string(p.N) + " W=" + std::to_string(p.W) + " LEVELS_PER_STAGE=" +
                      std::to_string(p.LEVELS_PER_STAGE) +
                      ": best/index/first/last/all/but_first/but_last/second, latency " + std::to_string(latency) +
                      ", hold while en low; " + std::to_string(o.cycles) + " cycles, " + std::to_string(enabled) +
                      " enabled");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_unique_tree, UniqueTreeParams)
MODTB_SETS(X)
#undef X

}  // namespace
