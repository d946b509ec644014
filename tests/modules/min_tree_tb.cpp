// fpstereo_min_tree: pipelined minimum and its index over N values. Reference: a linear scan
// keeping the first (lowest-index) minimum; latency max(1, ceil(clog2(N) / LEVELS_PER_STAGE))
// enabled steps; en low freezes the outputs.
#include <algorithm>
#include <string>
#include <vector>

#include "min_tree_sets.hpp"
#include "pipe_model.hpp"
#include "tb_common.hpp"

namespace {

struct MinTreeParams {
  int N = 8, W = 8, IDX_W = 3, LEVELS_PER_STAGE = 3;
  int LAT = 1;  // the latency the set states, which the module checks; the bench derives its own
};

struct MinResult {
  uint64_t value = 0, index = 0;
};

MinResult reference_min(const std::vector<uint64_t>& v) {
  MinResult r{v[0], 0};
  for (size_t i = 1; i < v.size(); ++i)
    if (v[i] < r.value) r = MinResult{v[i], i};
  return r;
}

int clog2(int n) {
  int b = 0;
  while ((1 << b) < n) ++b;
  return b;
}

template <typename M>
int run_min_tree(const char* name, const MinTreeParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  const int levels = p.N > 1 ? clog2(p.N) : 0;
  const int latency = std::max(1, (levels + p.LEVELS_PER_STAGE - 1) / p.LEVELS_PER_STAGE);
  modtb::EnabledPipe<MinResult> pipe(latency);
  long enabled = 0;
  std::vector<uint64_t> v(p.N);
  m.clk = 0;
  m.eval();
  for (long cycle = 0; cycle < o.cycles; ++cycle) {
    const bool en = !rng.chance(modtb::idle_percent(cycle));
    // value mix: narrow range (many ties), all equal, edges, uniform
    const unsigned mode = rng.below(4);
    const uint64_t same = rng.bits(p.W);
    for (int i = 0; i < p.N; ++i) {
      switch (mode) {
        case 0: v[i] = rng.below(3) & modtb::mask_of(p.W); break;
        case 1: v[i] = same; break;
        case 2: v[i] = modtb::edgy(rng, p.W); break;
        default: v[i] = rng.bits(p.W); break;
      }
      modtb::set_bits(m.values, i * p.W, p.W, v[i]);
    }
    m.en = en;
    m.eval();
    modtb::tick(m);
    pipe.edge(en, reference_min(v));
    enabled += en;
    if (const auto& want = pipe.out()) {
      check.expect(cycle, "min_value", want->value, modtb::get_bits(m.min_value, 0, p.W));
      check.expect(cycle, "min_index", want->index, modtb::get_bits(m.min_index, 0, p.IDX_W));
    }
  }
  return check.finish("N=" + std::to_string(p.N) + " W=" + std::to_string(p.W) + " LEVELS_PER_STAGE=" +
                      std::to_string(p.LEVELS_PER_STAGE) + ": min value and index (ties -> lower index), latency " +
                      std::to_string(latency) + ", hold while en low; " + std::to_string(o.cycles) + " cycles, " +
                      std::to_string(enabled) + " enabled");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_min_tree, MinTreeParams)
MODTB_SETS(X)
#undef X

}  // namespace
