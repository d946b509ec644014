// fpstereo_window (with its line buffer fpstereo_ram_sdp): an N x N window over a raster stream.
// Reference: per column, the last N-1 words that entered it; on a shift with word w at column c
// the window moves one column left and its new right column is, top (oldest) to bottom, the
// words N-1 .. 1 rows above w in column c, then w. Columns run 0 .. ROW_SLOTS-1 and wrap; idle
// cycles (shift low) carry random col / next_col / word and must change nothing. Window entries
// whose words never entered (power-up) are not compared.
#include <optional>
#include <string>
#include <vector>

#include "tb_common.hpp"
#include "window_sets.hpp"

namespace {

struct WindowParams {
  int N = 7, WORD_W = 8, ROW_SLOTS = 64, ADDR_W = 6;
};

template <typename M>
int run_window(const char* name, const WindowParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  using Word = std::optional<uint64_t>;
  // above[c][k]: the word k + 1 rows above the next one to enter column c
  std::vector<std::vector<Word>> above(p.ROW_SLOTS, std::vector<Word>(p.N - 1));
  std::vector<Word> window(p.N * p.N);  // row i, column j at i * N + j
  int col = 0;
  long shifts = 0, compared = 0;
  m.clk = 0;
  m.shift = 0;
  m.eval();
  for (long cycle = 0; cycle < o.cycles; ++cycle) {
    const bool shift = !rng.chance(cycle % 1000 < 300 ? 0 : 40);
    const uint64_t word = rng.bits(p.WORD_W);
    m.shift = shift;
    m.word = word;
    if (shift) {
      m.col = col;
      m.next_col = (col + 1) % p.ROW_SLOTS;
    } else {
      m.col = rng.bits(p.ADDR_W) % p.ROW_SLOTS;
      m.next_col = rng.bits(p.ADDR_W) % p.ROW_SLOTS;
    }
    m.eval();
    modtb::tick(m);
    if (shift) {
      for (int i = 0; i < p.N; ++i) {
        for (int j = 0; j < p.N - 1; ++j) window[i * p.N + j] = window[i * p.N + j + 1];
        window[i * p.N + p.N - 1] = i == p.N - 1 ? Word(word) : above[col][p.N - 2 - i];
      }
      auto& column = above[col];
      for (int k = p.N - 2; k > 0; --k) column[k] = column[k - 1];
      column[0] = word;
      col = (col + 1) % p.ROW_SLOTS;
      ++shifts;
    }
    for (int i = 0; i < p.N; ++i)
      for (int j = 0; j < p.N; ++j)
        if (const Word& want = window[i * p.N + j]) {
          ++compared;
          check.expect(cycle, "window row " + std::to_string(i) + " col " + std::to_string(j), *want,
                       modtb::get_bits(m.window, (i * p.N + j) * p.WORD_W, p.WORD_W));
        }
  }
  return check.finish("N=" + std::to_string(p.N) + " WORD_W=" + std::to_string(p.WORD_W) + " ROW_SLOTS=" +
                      std::to_string(p.ROW_SLOTS) + ": every window word after each cycle (" +
                      std::to_string(compared) + " words), " + std::to_string(shifts) + " shifts (" +
                      std::to_string(shifts / p.ROW_SLOTS) + " rows) in " + std::to_string(o.cycles) +
                      " cycles, idle cycles with random col/next_col/word");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_window, WindowParams)
MODTB_SETS(X)
#undef X

}  // namespace
