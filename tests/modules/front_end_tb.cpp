// fpstereo_front_end (with fpstereo_window, fpstereo_window_bounds, fpstereo_slot_columns and
// their counters): the window stage at P pixels a slot, G = 1, frames that run alone. Reference,
// from the module's header: step n (a cycle with adv high, counted from the restart) is slot n mod
// ROW_SLOTS of row-time n / ROW_SLOTS; it takes the P pixels of that slot and row (in_due) while
// both lie in the frame.
// The windows that form in step n are centred on the P pixels of the slot CENTRE_LAG steps back
// (m = n - CENTRE_LAG: slot m mod ROW_SLOTS, row floor(m / ROW_SLOTS) - N / 2); window q is
// columns q .. q + N - 1 of the arrays. Checked after every step: in_due before it; the rows' and
// the columns' bounds; every window word that lies in the frame, of both images; every word of
// the arrays that entered since the restart (zeros outside the frame); the newest
// column's row bounds; and the previous step's centre on transform_x / transform_y /
// transform_slot (its row modulo COST_ROWS). Random stalls; each frame has its own size, a
// multiple of P wide, and drains a few rows past its end before the next restart.
#include <string>
#include <vector>

#include "front_end_sets.hpp"
#include "tb_common.hpp"

namespace {

struct FrontEndParams {
  int N = 5, ROW_SLOTS = 12, G = 1, COST_ROWS = 2, COST_ROW_W = 1, X_W = 4, Y_W = 5, SIGNED_Y_W = 7, G_W = 1,
      FOLLOW_WAIT = 0, P = 1;
};

long floor_div(long a, long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

template <typename M>
int run_front_end(const char* name, const FrontEndParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  const int R = p.N / 2, lag = (R + p.P - 1) / p.P, cols = p.P * (1 + lag) + R;
  long cycle = 0, steps_total = 0, frames = 0, words = 0;
  m.clk = 0;
  m.overlap = 0;
  m.next_frame = 0;
  m.eval();
  while (cycle < o.cycles || frames < 3) {
    const int width = p.P * int(rng.range(2, uint64_t(p.ROW_SLOTS)));
    const int height = int(rng.range(2, 10));
    std::vector<std::vector<int>> left(size_t(height), std::vector<int>(size_t(width), 0));
    auto right = left;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        left[size_t(y)][size_t(x)] = int(rng.bits(8));
        right[size_t(y)][size_t(x)] = int(rng.bits(8));
      }
    auto inside = [&](long y, long x) { return y >= 0 && y < height && x >= 0 && x < width; };
    m.frame_width = uint32_t(width);
    m.frame_height = uint32_t(height);
    m.restart = 1;
    m.adv = 0;
    m.eval();
    modtb::tick(m);
    ++cycle;
    m.restart = 0;
    const long steps = long(height + R + 3) * p.ROW_SLOTS;
    for (long n = 0; n < steps; ++cycle) {
      const bool adv = !rng.chance(30);
      const long slot = n % p.ROW_SLOTS, row = n / p.ROW_SLOTS;
      const bool due = slot * p.P < width && row < height;
      uint64_t in_left = rng.bits(8 * p.P), in_right = rng.bits(8 * p.P);
      if (due) {
        in_left = in_right = 0;
        for (int q = 0; q < p.P; ++q) {
          in_left |= uint64_t(left[size_t(row)][size_t(slot * p.P + q)]) << (8 * q);
          in_right |= uint64_t(right[size_t(row)][size_t(slot * p.P + q)]) << (8 * q);
        }
      }
      m.adv = adv;
      m.in_left = uint32_t(in_left);
      m.in_right = uint32_t(in_right);
      m.eval();
      const std::string at = "step " + std::to_string(n) + " (slot " + std::to_string(slot) + ", row " +
                             std::to_string(row) + ", " + std::to_string(width) + "x" + std::to_string(height) + ")";
      check.expect(cycle, at + ": in_due", due, m.in_due);
      modtb::tick(m);
      if (!adv) continue;
      // The windows of this step.
      const long centre = n - lag;
      const long cs = ((centre % p.ROW_SLOTS) + p.ROW_SLOTS) % p.ROW_SLOTS;
      const long cy = floor_div(centre, p.ROW_SLOTS) - R;
      for (int i = 0; i < p.N; ++i)
        check.expect(cycle, at + ": row_valid " + std::to_string(i), inside(cy - R + i, 0) ? 1 : 0,
                     modtb::get_bits(m.row_valid, i, 1));
      for (int j = 0; j < p.N + p.P - 1; ++j)
        check.expect(cycle, at + ": col_valid " + std::to_string(j), inside(0, cs * p.P - R + j) ? 1 : 0,
                     modtb::get_bits(m.col_valid, j, 1));
      for (int q = 0; q < p.P; ++q)
        for (int i = 0; i < p.N; ++i)
          for (int j = 0; j < p.N; ++j) {
            const long yy = cy - R + i, xx = cs * p.P + q - R + j;
            if (!inside(yy, xx)) continue;
            const int bit = (i * cols + q + j) * 8;
            const std::string what = at + ": window " + std::to_string(q) + " row " + std::to_string(i) + " col " +
                                     std::to_string(j);
            check.expect(cycle, what + " (left)", uint64_t(left[size_t(yy)][size_t(xx)]),
                         modtb::get_bits(m.window_left, bit, 8));
            check.expect(cycle, what + " (right)", uint64_t(right[size_t(yy)][size_t(xx)]),
                         modtb::get_bits(m.window_right, bit, 8));
            ++words;
          }
      // Every word of the arrays that entered since the restart: column j is the pixel P - cols + j
      // places after the step's first in raster order over the row-times, array row i is N - 1 - i
      // rows above its row; bubble slots and rows below the frame enter as zeros.
      for (int i = 0; i < p.N; ++i)
        for (int j = 0; j < cols; ++j) {
          const long place = n * p.P + p.P - cols + j, row_pixels = long(p.ROW_SLOTS) * p.P;
          const long yy = floor_div(place, row_pixels) - (p.N - 1 - i), xx = place - floor_div(place, row_pixels) * row_pixels;
          if (yy < 0) continue;  // the frame before's
          const bool in = yy < height && xx < width;
          const std::string what = at + ": array row " + std::to_string(i) + " col " + std::to_string(j);
          check.expect(cycle, what + " (left)", in ? uint64_t(left[size_t(yy)][size_t(xx)]) : 0,
                       modtb::get_bits(m.window_left, (i * cols + j) * 8, 8));
          check.expect(cycle, what + " (right)", in ? uint64_t(right[size_t(yy)][size_t(xx)]) : 0,
                       modtb::get_bits(m.window_right, (i * cols + j) * 8, 8));
        }
      const long newest_y = row - R;
      for (int i = 0; i < p.N; ++i)
        check.expect(cycle, at + ": newest_row_valid " + std::to_string(i),
                     slot * p.P < width && inside(newest_y - R + i, 0) ? 1 : 0,
                     modtb::get_bits(m.newest_row_valid, i, 1));
      // The previous step's centre.
      if (n >= 2) {
        const long before = centre - 1;
        const long bs = ((before % p.ROW_SLOTS) + p.ROW_SLOTS) % p.ROW_SLOTS;
        const long by = floor_div(before, p.ROW_SLOTS) - R;
        check.expect(cycle, at + ": transform_x", uint64_t(bs), m.transform_x);
        check.expect(cycle, at + ": transform_y", uint64_t(by) & modtb::mask_of(p.SIGNED_Y_W),
                     modtb::get_bits(m.transform_y, 0, p.SIGNED_Y_W));
        check.expect(cycle, at + ": transform_slot", uint64_t(((by % p.COST_ROWS) + p.COST_ROWS) % p.COST_ROWS),
                     m.transform_slot);
      }
      ++n;
      ++steps_total;
    }
    ++frames;
  }
  return check.finish("N=" + std::to_string(p.N) + " P=" + std::to_string(p.P) + " ROW_SLOTS=" +
                      std::to_string(p.ROW_SLOTS) + " (centres " + std::to_string(lag) + " slots back, arrays " +
                      std::to_string(cols) + " columns): " + std::to_string(frames) + " lone frames, " +
                      std::to_string(steps_total) + " steps in " + std::to_string(cycle) +
                      " cycles with random stalls; in_due, bounds, centres and " + std::to_string(words) +
                      " window words in the frame");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_front_end, FrontEndParams)
MODTB_SETS(X)
#undef X

}  // namespace
