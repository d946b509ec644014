// fpstereo_unique_join (combinational): joins the summaries of a lower range A and the adjacent
// higher range B. Stimulus: two random ranges of 1..8 values; their summaries (unique_ref.hpp,
// from the definitions) go in, and the summary of the concatenated range must come out. The
// index of B's summary is offset by A's length, as in the tree, so indices stay global.
#include <string>
#include <vector>

#include "tb_common.hpp"
#include "unique_join_sets.hpp"
#include "unique_ref.hpp"

namespace {

struct UniqueJoinParams {
  int W = 10, IDX_W = 4;
};

// {best, all, but_first, but_last, second, index, first, last}, last at bit 0.
template <typename T>
void pack(T& port, const UniqueJoinParams& p, const modtb::UniqueSummary& s) {
  const int sw = 5 * p.W + p.IDX_W + 2;
  int top = sw;
  for (uint64_t v : {s.best, s.all, s.but_first, s.but_last, s.second}) {
    top -= p.W;
    modtb::set_bits(port, top, p.W, v);
  }
  modtb::set_bits(port, 2, p.IDX_W, s.index);
  modtb::set_bits(port, 1, 1, s.first);
  modtb::set_bits(port, 0, 1, s.last);
}

template <typename T>
modtb::UniqueSummary unpack(const T& port, const UniqueJoinParams& p) {
  const int sw = 5 * p.W + p.IDX_W + 2;
  modtb::UniqueSummary s;
  s.best = modtb::get_bits(port, sw - p.W, p.W);
  s.all = modtb::get_bits(port, sw - 2 * p.W, p.W);
  s.but_first = modtb::get_bits(port, sw - 3 * p.W, p.W);
  s.but_last = modtb::get_bits(port, sw - 4 * p.W, p.W);
  s.second = modtb::get_bits(port, sw - 5 * p.W, p.W);
  s.index = modtb::get_bits(port, 2, p.IDX_W);
  s.first = modtb::get_bits(port, 1, 1);
  s.last = modtb::get_bits(port, 0, 1);
  return s;
}

template <typename M>
int run_unique_join(const char* name, const UniqueJoinParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  const uint64_t none = modtb::mask_of(p.W);
  const int max_len = 1 << (p.IDX_W - 1);  // A and B together fit the index
  std::vector<uint64_t> a, b, ab;
  for (long cycle = 0; cycle < o.cycles; ++cycle) {
    a.resize(rng.range(1, max_len));
    b.resize(rng.range(1, max_len));
    modtb::unique_values(rng, a, p.W);
    modtb::unique_values(rng, b, p.W);
    ab = a;
    ab.insert(ab.end(), b.begin(), b.end());
    modtb::UniqueSummary sb = modtb::unique_reference(b, none);
    sb.index += a.size();
    pack(m.a, p, modtb::unique_reference(a, none));
    pack(m.b, p, sb);
    m.eval();
    const modtb::UniqueSummary want = modtb::unique_reference(ab, none);
    // first / last of a joined range: whether the winner is the joined range's first / last
    const modtb::UniqueSummary got = unpack(m.joined, p);
    const std::string at = "|A|=" + std::to_string(a.size()) + " |B|=" + std::to_string(b.size()) + " ";
    check.expect(cycle, at + "best", want.best, got.best);
    check.expect(cycle, at + "index", want.index, got.index);
    check.expect(cycle, at + "first", want.first, got.first);
    check.expect(cycle, at + "last", want.last, got.last);
    check.expect(cycle, at + "all", want.all, got.all);
    check.expect(cycle, at + "but_first", want.but_first, got.but_first);
    check.expect(cycle, at + "but_last", want.but_last, got.but_last);
    check.expect(cycle, at + "second", want.second, got.second);
  }
  return check.finish("W=" + std::to_string(p.W) + " IDX_W=" + std::to_string(p.IDX_W) +
                      ": join of two random ranges (1.." + std::to_string(max_len) +
                      " values each) equals the summary of their concatenation; " + std::to_string(o.cycles) +
                      " joins");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_unique_join, UniqueJoinParams)
MODTB_SETS(X)
#undef X

}  // namespace
