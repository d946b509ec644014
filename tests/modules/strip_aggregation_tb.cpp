// fpstereo_strip_aggregation (fpstereo_strip_aggregation.v): P aggregators over strips of a row, each K steps behind the one to
// its left, with the strips' edges (docs/ppc-hardware.md). Driven with a random cost volume of
// uf = dmax costs per pixel, served from each strip's read address one step later as the cost RAM
// would, and checked against SGM over the whole frame (docs/semantics.md section 3): every pixel's
// sums S(x, y, d) of the enabled paths, each pixel exactly once, whatever strip computed it. The
// RAM rows (COST_ROWS, OUT_ROWS) are at least the frame's height here, so the read address and
// the output slot name the row itself. Random idle steps (adv low), several frames, each with its
// own size, penalties and costs. With CODES the strips read code entries {match, base} instead,
// census codes whose costs their chain cost stages compute (Hamming distance, COST_MAX where
// x - d < 0), with the match rings handed from strip to strip. With RAM the entries go through
// the strips' code RAMs (fpstereo_strip_code_reorder), each (p + 1) * K rows: written a slot of P
// pixels a step in raster order, one row a row-time, with the aggregation starting RAM_LEAD steps
// after the first write, as a front end at P pixels a clock would write them; the frame is then a
// multiple of P wide. With OUTPUT the sums go on through a winner-take-all per strip and the
// strips' disparity RAMs, read in raster order a slot of P pixels a step from kOutLead row-times
// after the aggregation's start: every pixel's word once, the lowest disparity of the least sum
// (the sums themselves are not read there: their row slots wrap within the frame). With LR1 each
// strip's LR1 match side (fpstereo_lr1_match, its state handed on from strip to strip) writes Dm of
// the match pixels its pixels complete and, at the row's last pixel, the row end: every match pixel
// of every row once, against the argmin over d of the reference S(x' + d, d) (the lowest d of the
// least), whatever strip completed it.
#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "pipe_model.hpp"
#include "strip_aggregation_sets.hpp"
#include "tb_common.hpp"

namespace {

struct StripParams {
  int P = 2, W = 40, ROW_SLOTS = 20, K = 5, SEGMENT = 4, UF = 16, COST_W = 5, COST_MAX = 24, PATH_W = 8,
      SUM_W = 10, PATHS = 15, LEVELS_PER_STAGE = 2, PATH_TREE_LAT = 2, OUT_ROWS = 16, OUT_ROW_W = 4, COST_AW = 9,
      X_W = 6, Y_W = 5, K_W = 3, COST_ROWS = 16, COST_ROW_W = 4, COST_LEAD = 1, CODES = 0, HAMMING = 1, CODE_W = 8,
      LANES_LAT = 2, RAM = 0, SLOT_ROWS = 10, SLOT_W = 4, OUTPUT = 0, DISP_W = 4, WTA_TREE_LAT = 2, LR1 = 0,
      LR1_AW = 8, LR1_LAG = 0;
};

// Steps from the first write of a frame's codes to the aggregation's start, with RAM: a write
// reaches its RAM a clock after its inputs, so the lead is at least 2. Strip 0 must read a row
// before the row (p + 1) * K later overwrites it, which bounds the lead at (K * SEGMENT - 1) / P + 1:
// measured, at P = 4, K = 5, SEGMENT = 4 a lead of 5 passes and 6 fails.
constexpr long kRamLead = 2;
// With OUTPUT, the output's start: P * K row-times after the aggregation's (the last strip's last
// chain finishes a row P * K - 1 row-times after the first strip's first chain began it) and a few
// steps for the pipeline from a chain's read address to its word at the winner-take-all. Measured
// over six seeds at P 2 and 4: 0 to 24 steps pass, -5 and 30 fail (too early for the last writes,
// too late for the row that overwrites); 12 lies in the middle.
constexpr long kOutSteps = 12;

using Volume = std::vector<std::vector<std::vector<int>>>;  // [y][x][d]

// SGM path costs summed over the enabled paths, as docs/semantics.md section 3 defines them.
Volume reference_sums(const Volume& cost, int width, int height, int dmax, int p1, int p2, int paths) {
  Volume sums(height, std::vector<std::vector<int>>(width, std::vector<int>(dmax, 0)));
  struct Dir {
    int bit, dx, dy;
  };
  const Dir dirs[] = {{1, -1, 0}, {2, -1, -1}, {4, 0, -1}, {8, 1, -1}};
  for (const Dir& r : dirs) {
    if (!(paths & r.bit)) continue;
    Volume L(height, std::vector<std::vector<int>>(width, std::vector<int>(dmax, 0)));
    for (int y = 0; y < height; ++y) {
      // The 0-degree path runs along the row; the others need only the row above.
      for (int x = 0; x < width; ++x) {
        const int px = x + r.dx, py = y + r.dy;
        const bool has_pred = px >= 0 && px < width && py >= 0;
        for (int d = 0; d < dmax; ++d) L[y][x][d] = cost[y][x][d];
        if (!has_pred) continue;
        const std::vector<int>& prev = L[py][px];
        const int m = *std::min_element(prev.begin(), prev.end());
        for (int d = 0; d < dmax; ++d) {
          int best = std::min(prev[d], m + p2);
          if (d > 0) best = std::min(best, prev[d - 1] + p1);
          if (d + 1 < dmax) best = std::min(best, prev[d + 1] + p1);
          L[y][x][d] = cost[y][x][d] + best - m;
        }
      }
    }
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int d = 0; d < dmax; ++d) sums[y][x][d] += L[y][x][d];
  }
  return sums;
}

template <typename M>
int run_strip_aggregation(const char* name, const StripParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  const int dmax = p.UF, R = p.ROW_SLOTS;
  // P1, P2 within the lanes' contract: path costs stay below 2^PATH_W (at most COST_MAX + P2).
  const int penalty_max = int(modtb::mask_of(p.PATH_W)) - p.COST_MAX;
  long cycle = 0, pixels = 0, frames = 0;
  m.clk = 0;
  m.adv = 0;
  m.restart = 1;
  m.eval();
  modtb::tick(m);
  while (cycle < o.cycles || frames < 2) {
    // A frame: its size (the last strip partly or wholly outside the run-time width at times),
    // penalties and costs.
    int width = int(rng.range(uint64_t(std::max(dmax, (p.P - 1) * R - R / 2)), uint64_t(p.W)));
    if (p.RAM != 0) width = p.P * ((width + p.P - 1) / p.P);  // whole slots (W is a multiple of P)
    const int height = int(rng.range(4, uint64_t(p.COST_ROWS)));
    const int p1 = int(rng.range(0, uint64_t(penalty_max / 4)));
    const int p2 = int(rng.range(uint64_t(p1), uint64_t(penalty_max)));
    Volume cost(height, std::vector<std::vector<int>>(width, std::vector<int>(dmax)));
    // With CODES: each pixel's base and match codes, a few values often (ties), and the costs
    // they give.
    std::vector<std::vector<uint64_t>> base(static_cast<size_t>(height), std::vector<uint64_t>(static_cast<size_t>(width)));
    auto match = base;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        base[size_t(y)][size_t(x)] = modtb::edgy(rng, p.CODE_W);
        match[size_t(y)][size_t(x)] = modtb::edgy(rng, p.CODE_W);
      }
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int d = 0; d < dmax; ++d) {
          int& c = cost[size_t(y)][size_t(x)][size_t(d)];
          if (p.CODES == 0)
            c = int(std::min<uint64_t>(modtb::edgy(rng, p.COST_W), uint64_t(p.COST_MAX)));
          else
            c = d > x ? p.COST_MAX
                      : __builtin_popcountll(base[size_t(y)][size_t(x)] ^ match[size_t(y)][size_t(x - d)]);
        }
    const Volume want = reference_sums(cost, width, height, dmax, p1, p2, p.PATHS);
    m.frame_width = width;
    m.frame_height = height;
    m.p1 = p1;
    m.p2 = p2;
    const int threshold = int(rng.range(0, 3));
    m.lr_threshold = uint32_t(threshold);
    m.overlap = 0;
    m.wrapped = 0;
    m.restart = 1;
    m.agg_on = 0;
    m.adv = 1;
    m.eval();
    modtb::tick(m);
    m.restart = 0;
    m.agg_on = p.RAM == 0;
    m.out_on = 0;
    const long out_start = (p.RAM != 0 ? kRamLead : 0) + long(p.P) * p.K * R + kOutSteps;
    std::map<std::pair<int, int>, int> read;  // (y, x) -> times, with OUTPUT
    // Every row-time until the last strip has finished the last row, and the pipeline's tail.
    const long steps = p.OUTPUT != 0 ? out_start + long(height + 1) * R + 8 : long(height + p.P * p.K + 1) * R + 32;
    std::map<std::pair<int, int>, int> seen;  // (y, x) -> times
    std::map<std::pair<int, int>, int> matched;  // with LR1: (y, x') -> times Dm(x') was written
    // Dm(x'): the least S(x' + d, d) over the d <= e whose base pixel x' + d lies in the row.
    const auto match_side = [&](int y, int xm, int e) {
      int best = 0;
      for (int d = 1; d <= e && xm + d < width; ++d)
        if (want[size_t(y)][size_t(xm + d)][size_t(d)] < want[size_t(y)][size_t(xm + best)][size_t(best)]) best = d;
      return best;
    };
    std::vector<std::vector<int>> read_q(size_t(p.P), std::vector<int>(size_t(dmax), 0));
    std::vector<uint64_t> entry_q(size_t(p.P), 0);
    for (long step = 0; step < steps;) {
      const bool adv = !rng.chance(modtb::idle_percent(cycle));
      m.adv = adv;
      if (p.RAM != 0) {
        // The front end's writes: row step / R, slot step % R.
        const long row = step / R, slot = step % R;
        const bool write = adv && row < height && slot * p.P < width;
        m.code_we = write;
        m.code_slot = uint32_t(slot);
        m.code_row = uint32_t(row % p.SLOT_ROWS);
        for (int q = 0; q < p.P && write; ++q) {
          const size_t y = size_t(row), x = size_t(slot * p.P + q);
          modtb::set_bits(m.code_data, q * 2 * p.CODE_W, 2 * p.CODE_W, match[y][x] << p.CODE_W | base[y][x]);
        }
        m.agg_on = step >= kRamLead;
      }
      m.out_on = p.OUTPUT != 0 && step >= out_start;
      m.eval();
      // The cost RAM's registered read: the word of the address at this edge, on cost_q after it.
      if (adv)
        for (int s = 0; s < p.P; ++s) {
          const uint64_t addr = modtb::get_bits(m.cost_raddr, s * p.COST_AW, p.COST_AW);
          const int y = int(addr / uint64_t(R)), x = s * R + int(addr % uint64_t(R));
          const bool inside = y < height && x < width;
          for (int d = 0; d < dmax; ++d)
            read_q[size_t(s)][size_t(d)] = inside ? cost[size_t(y)][size_t(x)][size_t(d)] : 0;
          entry_q[size_t(s)] = inside ? match[size_t(y)][size_t(x)] << p.CODE_W | base[size_t(y)][size_t(x)] : 0;
        }
      modtb::tick(m);
      ++cycle;
      if (!adv) continue;
      ++step;
      for (int s = 0; s < p.P; ++s) {
        if (p.CODES != 0) {
          modtb::set_bits(m.cost_q, s * 2 * p.CODE_W, 2 * p.CODE_W, entry_q[size_t(s)]);
          continue;
        }
        for (int d = 0; d < dmax; ++d)
          modtb::set_bits(m.cost_q, (s * dmax + d) * p.COST_W, p.COST_W, uint64_t(read_q[size_t(s)][size_t(d)]));
      }
      // The raster order's slot read in the step before (registers).
      if (p.OUTPUT != 0 && m.read_event) {
        const int y = int(m.read_y);
        for (int q = 0; q < p.P; ++q) {
          const int x = int(m.read_x) * p.P + q;
          if (x >= width) continue;
          const std::string where = "output (" + std::to_string(x) + ", " + std::to_string(y) + ")";
          if (!check.require(cycle, where + " lies in the frame", y < height)) continue;
          ++read[{y, x}];
          const std::vector<int>& s = want[size_t(y)][size_t(x)];
          const int best = int(std::min_element(s.begin(), s.end()) - s.begin());
          uint64_t expected = uint64_t(best);
          if (p.LR1 != 0) {
            // The left-right check: x' = x - D in the row and |D - Dm(x')| <= the threshold, Dm
            // over the d whose base pixel x' + d lies in the row.
            const int xm = x - best;
            const bool passes = xm >= 0 && std::abs(best - match_side(y, xm, std::min(dmax - 1, width - 1 - xm))) <= threshold;
            expected = passes ? expected : uint64_t(1) << p.DISP_W;
          }
          check.expect(cycle, where, expected, modtb::get_bits(m.read_word, q * (p.DISP_W + 1), p.DISP_W + 1));
        }
      }
      // LR1's writes of this step (combinational, from the sums' registers): a completed match
      // pixel, or the row end's match pixels width - 1 - e.
      for (int s = 0; s < p.P && p.LR1 != 0 && p.OUTPUT == 0; ++s) {
        if (modtb::get_bits(m.dm_we, s, 1)) {
          const uint64_t addr = modtb::get_bits(m.dm_waddr, s * p.LR1_AW, p.LR1_AW);
          const int y = int(addr / uint64_t(R)), xm = s * R + int(addr % uint64_t(R)) - (dmax - 1);
          const std::string where = "strip " + std::to_string(s) + " Dm(" + std::to_string(xm) + ", " + std::to_string(y) + ")";
          if (check.require(cycle, where + " lies in the frame", y < height && xm >= 0 && xm + dmax <= width)) {
            ++matched[{y, xm}];
            check.expect(cycle, where, uint64_t(match_side(y, xm, dmax - 1)),
                         modtb::get_bits(m.dm_wdata, s * p.DISP_W, p.DISP_W));
          }
        }
        if (!modtb::get_bits(m.dm_end_we, s, 1)) continue;
        const int y = int(modtb::get_bits(m.dm_end_waddr, s * p.OUT_ROW_W, p.OUT_ROW_W));
        if (!check.require(cycle, "strip " + std::to_string(s) + " row end of row " + std::to_string(y) + " in the frame",
                           y < height))
          continue;
        for (int e = 0; e < dmax; ++e) {
          const int xm = width - 1 - e;
          if (e < dmax - 1) ++matched[{y, xm}];  // e = dmax - 1 is the completed pixel's
          check.expect(cycle, "strip " + std::to_string(s) + " row end Dm(" + std::to_string(xm) + ", " + std::to_string(y) + ")",
                       uint64_t(match_side(y, xm, e)), modtb::get_bits(m.dm_end_wdata, (s * dmax + e) * p.DISP_W, p.DISP_W));
        }
      }
      // The sums of this step (registers: they changed at the edge just taken). With OUTPUT the
      // strips' row slots are modulo fewer rows than the frame's, and the output stands for them.
      for (int s = 0; s < p.P && p.OUTPUT == 0; ++s) {
        if (!modtb::get_bits(m.sums_active, s, 1)) continue;
        const int x = int(modtb::get_bits(m.sums_x, s * p.X_W, p.X_W));
        const int y = int(modtb::get_bits(m.sums_slot, s * p.OUT_ROW_W, p.OUT_ROW_W));
        const std::string where = "strip " + std::to_string(s) + " (" + std::to_string(x) + ", " + std::to_string(y) + ")";
        if (!check.require(cycle, where + " lies in the frame and the strip", x < width && y < height &&
                                                                               x >= s * R && x < (s + 1) * R))
          continue;
        ++seen[{y, x}];
        for (int d = 0; d < dmax; ++d)
          check.expect(cycle, where + " d " + std::to_string(d), uint64_t(want[size_t(y)][size_t(x)][size_t(d)]),
                       modtb::get_bits(m.sums, (s * dmax + d) * p.SUM_W, p.SUM_W));
      }
    }
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        if (p.LR1 != 0 && p.OUTPUT == 0) {
          const auto it = matched.find({y, x});
          check.require(cycle, "Dm(" + std::to_string(x) + ", " + std::to_string(y) + ") written once",
                        it != matched.end() && it->second == 1);
        }
        if (p.OUTPUT == 0) {
          const auto it = seen.find({y, x});
          check.require(cycle, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") summed once",
                        it != seen.end() && it->second == 1);
          continue;
        }
        const auto out = read.find({y, x});
        check.require(cycle, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") read once",
                      out != read.end() && out->second == 1);
      }
    pixels += long(width) * height;
    ++frames;
  }
  return check.finish(std::string(p.LR1 ? "LR1's match side, " : "") + std::string(p.OUTPUT ? "codes through the strips' RAMs to the raster disparities, " : p.RAM ? "codes through the strips' RAMs, " : p.CODES ? "codes, " : "costs, ") + "P=" + std::to_string(p.P) + " K=" + std::to_string(p.K) + " strips of " + std::to_string(R) +
                      " W=" + std::to_string(p.W) + " dmax=" + std::to_string(dmax) + " paths " +
                      std::to_string(p.PATHS) +
                      (p.OUTPUT ? ": the winner of every pixel once, in raster order, against SGM; "
                                : ": S(x, y, d) of every pixel once, against SGM; ") +
                      std::to_string(frames) + " frames, " + std::to_string(pixels) + " pixels, " +
                      std::to_string(cycle) + " cycles");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_strip_aggregation, StripParams)
MODTB_SETS(X)
#undef X

}  // namespace
