// fpstereo_sum_tree: the sum of N unsigned values modulo 2^SUM_W. Reference: the sum in 64 bits,
// masked. With REGISTER_LEVEL 0 the sum follows the values in the same cycle; otherwise it comes
// one enabled edge later and holds while en is low.
#include <string>
#include <vector>

#include "pipe_model.hpp"
#include "sum_tree_sets.hpp"
#include "tb_common.hpp"

namespace {

struct SumTreeParams {
  int N = 7, IN_W = 8, SUM_W = 11, REGISTER_LEVEL = 0;
};

template <typename M>
int run_sum_tree(const char* name, const SumTreeParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  const bool registered = p.REGISTER_LEVEL > 0;
  modtb::EnabledPipe<uint64_t> pipe(1);
  long enabled = 0;
  std::vector<uint64_t> v(p.N);
  m.clk = 0;
  m.eval();
  for (long cycle = 0; cycle < o.cycles; ++cycle) {
    const bool en = !rng.chance(modtb::idle_percent(cycle));
    // value mix: all at the maximum (the widest carries), edges, uniform
    const unsigned mode = rng.below(3);
    uint64_t sum = 0;
    for (int i = 0; i < p.N; ++i) {
      v[i] = mode == 0 ? modtb::mask_of(p.IN_W) : mode == 1 ? modtb::edgy(rng, p.IN_W) : rng.bits(p.IN_W);
      modtb::set_bits(m.values, i * p.IN_W, p.IN_W, v[i]);
      sum += v[i];
    }
    sum &= modtb::mask_of(p.SUM_W);
    m.en = en;
    m.eval();
    if (!registered) check.expect(cycle, "sum", sum, modtb::get_bits(m.sum, 0, p.SUM_W));
    modtb::tick(m);
    pipe.edge(en, sum);
    enabled += en;
    if (registered && pipe.out()) check.expect(cycle, "sum", *pipe.out(), modtb::get_bits(m.sum, 0, p.SUM_W));
  }
  return check.finish("N=" + std::to_string(p.N) + " IN_W=" + std::to_string(p.IN_W) + " SUM_W=" +
                      std::to_string(p.SUM_W) + " REGISTER_LEVEL=" + std::to_string(p.REGISTER_LEVEL) +
                      ": the sum modulo 2^SUM_W, " + (registered ? "one enabled edge later" : "combinational") +
                      "; " + std::to_string(o.cycles) + " cycles, " + std::to_string(enabled) + " enabled");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_sum_tree, SumTreeParams)
MODTB_SETS(X)
#undef X

}  // namespace
