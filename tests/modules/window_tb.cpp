// fpstereo_window (with its line buffer fpstereo_ram_sdp): a window N rows high and COLS columns
// wide over a raster stream of P words a slot. Reference: per column, the last N-1 words that entered it; on a shift
// with words w_0 .. w_{P-1} at slot c (columns c * P + q) the window moves P columns left and its
// new right columns q are, top (oldest) to bottom, the words N-1 .. 1 rows above w_q in column
// c * P + q, then w_q. Slots run 0 .. ROW_SLOTS-1 and wrap; idle cycles (shift low) carry random
// col / next_col / words and must change nothing. Window entries whose words never entered
// (power-up) are not compared.
#include <optional>
#include <string>
#include <vector>

#include "tb_common.hpp"
#include "window_sets.hpp"

namespace {

struct WindowParams {
  int N = 7, WORD_W = 8, P = 1, COLS = 0, ROW_SLOTS = 64, ADDR_W = 6;  // COLS 0: N + P - 1
};

template <typename M>
int run_window(const char* name, const WindowParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  using Word = std::optional<uint64_t>;
  const int C = p.COLS != 0 ? p.COLS : p.N + p.P - 1;  // window columns
  // above[x][k]: the word k + 1 rows above the next one to enter column x
  std::vector<std::vector<Word>> above(size_t(p.ROW_SLOTS * p.P), std::vector<Word>(size_t(p.N - 1)));
  std::vector<Word> window(size_t(p.N * C));  // row i, column j at i * C + j
  int col = 0;
  long shifts = 0, compared = 0;
  m.clk = 0;
  m.shift = 0;
  m.eval();
  for (long cycle = 0; cycle < o.cycles; ++cycle) {
    const bool shift = !rng.chance(cycle % 1000 < 300 ? 0 : 40);
    std::vector<uint64_t> words(size_t(p.P));
    uint64_t packed = 0;
    for (int q = 0; q < p.P; ++q) {
      words[size_t(q)] = rng.bits(p.WORD_W);
      packed |= words[size_t(q)] << (q * p.WORD_W);
    }
    m.shift = shift;
    m.word = packed;
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
        for (int j = 0; j < C - p.P; ++j) window[size_t(i * C + j)] = window[size_t(i * C + j + p.P)];
        for (int q = 0; q < p.P; ++q)
          window[size_t(i * C + C - p.P + q)] =
              i == p.N - 1 ? Word(words[size_t(q)]) : above[size_t(col * p.P + q)][size_t(p.N - 2 - i)];
      }
      for (int q = 0; q < p.P; ++q) {
        auto& column = above[size_t(col * p.P + q)];
        for (int k = p.N - 2; k > 0; --k) column[size_t(k)] = column[size_t(k - 1)];
        column[0] = words[size_t(q)];
      }
      col = (col + 1) % p.ROW_SLOTS;
      ++shifts;
    }
    for (int i = 0; i < p.N; ++i)
      for (int j = 0; j < C; ++j)
        if (const Word& want = window[size_t(i * C + j)]) {
          ++compared;
          check.expect(cycle, "window row " + std::to_string(i) + " col " + std::to_string(j), *want,
                       modtb::get_bits(m.window, (i * C + j) * p.WORD_W, p.WORD_W));
        }
  }
  return check.finish("N=" + std::to_string(p.N) + " WORD_W=" + std::to_string(p.WORD_W) + " P=" +
                      std::to_string(p.P) + " COLS=" + std::to_string(C) + " ROW_SLOTS=" + std::to_string(p.ROW_SLOTS) +
                      ": every window word after each cycle (" + std::to_string(compared) + " words), " +
                      std::to_string(shifts) + " shifts (" + std::to_string(shifts / p.ROW_SLOTS) + " rows) in " +
                      std::to_string(o.cycles) + " cycles, idle cycles with random col/next_col/words");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_window, WindowParams)
MODTB_SETS(X)
#undef X

}  // namespace
