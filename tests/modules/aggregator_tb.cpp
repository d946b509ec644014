// fpstereo_aggregator (fpstereo_aggregator.v) alone, one strip: K interleaved chains over a row of
// G groups of UF disparities a pixel, served cost words from the read address one step later as
// the cost RAM would, against SGM path costs written from docs/semantics.md section 3: every
// pixel's sums S(x, y, d) of the enabled raster paths once, or with MIRROR the 180-degree path's
// L(x, y, d) (from the row's end, each pixel against (x + 1, y)). With PENALTIES each cost word
// carries random P2 fields above its costs: the raster paths take their own pixel's field, the
// 180-degree path the 0-degree field of x + 1. The RAM's rows (COST_ROWS, OUT_ROWS) hold a whole
// frame, so that addresses and slots name the rows. Random idle steps (adv low), several frames,
// each with its own size, penalties and costs.
#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "aggregator_sets.hpp"
#include "pipe_model.hpp"
#include "tb_common.hpp"

namespace {

struct AggregatorParams {
  int W = 20, ROW_SLOTS = 20, K = 2, SEGMENT = 10, G = 4, UF = 4, COST_W = 5, COST_MAX = 24, PATH_W = 8,
      SUM_W = 10, PATHS = 15, PENALTIES = 0, LEVELS_PER_STAGE = 2, PATH_TREE_LAT = 1, OUT_ROWS = 16,
      OUT_ROW_W = 4, COST_AW = 9, X_W = 5, Y_W = 5, G_W = 2, K_W = 1, COST_ROWS = 16, COST_ROW_W = 4,
      MIRROR = 0;
};

using Volume = std::vector<std::vector<std::vector<int>>>;  // [y][x][d]
using Fields = std::vector<std::vector<std::vector<int>>>;  // [y][x][field]: the word's P2 fields

// The path costs of one direction (dx, dy), the predecessor (x + dx, y + dy); p2_of(y, x) is the
// P2 of pixel (x, y) against its predecessor.
template <typename P2Of>
Volume path_costs(const Volume& cost, int width, int height, int dmax, int p1, int dx, int dy, P2Of p2_of) {
  Volume L(height, std::vector<std::vector<int>>(width, std::vector<int>(dmax, 0)));
  for (int y = 0; y < height; ++y)
    for (int i = 0; i < width; ++i) {
      const int x = dx > 0 ? width - 1 - i : i;  // along the path: the predecessor first
      const int px = x + dx, py = y + dy;
      L[y][x] = cost[y][x];
      if (px < 0 || px >= width || py < 0) continue;
      const std::vector<int>& prev = L[py][px];
      const int m = *std::min_element(prev.begin(), prev.end()), p2 = p2_of(y, x);
      for (int d = 0; d < dmax; ++d) {
        int best = std::min(prev[d], m + p2);
        if (d > 0) best = std::min(best, prev[d - 1] + p1);
        if (d + 1 < dmax) best = std::min(best, prev[d + 1] + p1);
        L[y][x][d] = cost[y][x][d] + best - m;
      }
    }
  return L;
}

// What the module delivers: the sums of the enabled raster paths, or with MIRROR the 180-degree
// path's costs.
Volume reference(const AggregatorParams& p, const Volume& cost, const Fields& fields, int width, int height,
                 int p1, int p2) {
  const int dmax = p.G * p.UF;
  if (p.MIRROR != 0)
    return path_costs(cost, width, height, dmax, p1, 1, 0, [&](int y, int x) {
      return p.PENALTIES != 0 ? fields[size_t(y)][size_t(x + 1)][0] : p2;
    });
  Volume sums(height, std::vector<std::vector<int>>(width, std::vector<int>(dmax, 0)));
  struct Dir {
    int bit, dx, dy;
  };
  const Dir dirs[] = {{1, -1, 0}, {2, -1, -1}, {4, 0, -1}, {8, 1, -1}};
  int field = 0;
  for (const Dir& r : dirs) {
    if (!(p.PATHS & r.bit)) continue;
    const Volume L = path_costs(cost, width, height, dmax, p1, r.dx, r.dy, [&](int y, int x) {
      return p.PENALTIES != 0 ? fields[size_t(y)][size_t(x)][size_t(field)] : p2;
    });
    ++field;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int d = 0; d < dmax; ++d) sums[y][x][d] += L[y][x][d];
  }
  return sums;
}

template <typename M>
int run_aggregator(const char* name, const AggregatorParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  const int dmax = p.G * p.UF, R = p.ROW_SLOTS;
  // P1, P2 within the lanes' contract: path costs stay below 2^PATH_W (at most COST_MAX + P2).
  const int penalty_max = int(modtb::mask_of(p.PATH_W)) - p.COST_MAX;
  long cycle = 0, pixels = 0, frames = 0;
  m.clk = 0;
  m.adv = 0;
  m.restart = 1;
  m.eval();
  modtb::tick(m);
  while (cycle < o.cycles || frames < 3) {
    const int width = int(rng.range(uint64_t(std::max(3, R / 2)), uint64_t(p.W)));
    const int height = int(rng.range(2, uint64_t(std::min(p.COST_ROWS, p.OUT_ROWS))));
    const int p1 = int(rng.range(0, uint64_t(penalty_max / 4)));
    const int p2 = int(rng.range(uint64_t(p1), uint64_t(penalty_max)));
    Volume cost(height, std::vector<std::vector<int>>(width, std::vector<int>(dmax)));
    Fields fields(height, std::vector<std::vector<int>>(width, std::vector<int>(size_t(std::max(1, p.PENALTIES)))));
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        for (int d = 0; d < dmax; ++d)
          cost[y][x][d] = int(std::min<uint64_t>(modtb::edgy(rng, p.COST_W), uint64_t(p.COST_MAX)));
        for (int& f : fields[y][x]) f = int(rng.range(uint64_t(p1), uint64_t(p2)));
      }
    const Volume want = reference(p, cost, fields, width, height, p1, p2);
    m.frame_width = width;
    m.frame_height = height;
    m.p1 = p1;
    m.p2 = p2;
    m.overlap = 0;
    m.wrapped = 0;
    m.restart = 1;
    m.agg_on = 0;
    m.adv = 1;
    m.eval();
    modtb::tick(m);
    m.restart = 0;
    m.agg_on = 1;
    // Every row-time until the last chain has finished the last row, and the pipeline's tail.
    const long steps = long(height + p.K) * R * p.G + 32;
    std::map<std::pair<int, int>, int> seen;  // (y, x) -> groups delivered
    std::vector<uint64_t> word_q(size_t(p.UF + p.PENALTIES), 0);
    for (long step = 0; step < steps;) {
      const bool adv = !rng.chance(modtb::idle_percent(cycle));
      m.adv = adv;
      m.eval();
      // The cost RAM's registered read: the word at this edge's address, on cost_q after it.
      if (adv) {
        const uint64_t addr = m.cost_raddr;
        const int y = int(addr / uint64_t(R * p.G)), x = int(addr / uint64_t(p.G) % uint64_t(R)),
                  g = int(addr % uint64_t(p.G));
        const bool inside = y < height && x < width;
        for (int l = 0; l < p.UF; ++l) word_q[size_t(l)] = inside ? uint64_t(cost[y][x][g * p.UF + l]) : 0;
        for (int f = 0; f < p.PENALTIES; ++f)
          word_q[size_t(p.UF + f)] = inside ? uint64_t(fields[y][x][size_t(f)]) : 0;
      }
      modtb::tick(m);
      ++cycle;
      if (!adv) continue;
      ++step;
      for (int l = 0; l < p.UF; ++l) modtb::set_bits(m.cost_q, l * p.COST_W, p.COST_W, word_q[size_t(l)]);
      for (int f = 0; f < p.PENALTIES; ++f)
        modtb::set_bits(m.cost_q, p.UF * p.COST_W + f * p.PATH_W, p.PATH_W, word_q[size_t(p.UF + f)]);
      // The sums of this step (registers: they changed at the edge just taken).
      if (!m.sums_active) continue;
      const int x = int(m.sums_x), y = int(m.sums_slot), g = int(m.sums_group);
      const std::string where = "(" + std::to_string(x) + ", " + std::to_string(y) + ") group " + std::to_string(g);
      if (!check.require(cycle, where + " lies in the frame", x < width && y < height && g < p.G)) continue;
      ++seen[{y, x}];
      for (int l = 0; l < p.UF; ++l)
        check.expect(cycle, where + " lane " + std::to_string(l), uint64_t(want[y][x][g * p.UF + l]),
                     modtb::get_bits(m.sums, l * p.SUM_W, p.SUM_W));
    }
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const auto it = seen.find({y, x});
        check.require(cycle, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") summed once",
                      it != seen.end() && it->second == p.G);
      }
    pixels += long(width) * height;
    ++frames;
  }
  return check.finish(std::string(p.MIRROR ? "the 180-degree path" : "paths " + std::to_string(p.PATHS)) +
                      (p.PENALTIES ? " with P2 fields" : "") + ", K=" + std::to_string(p.K) + " G=" +
                      std::to_string(p.G) + " UF=" + std::to_string(p.UF) + " W=" + std::to_string(p.W) +
                      ": every pixel's groups once, against SGM; " + std::to_string(frames) + " frames, " +
                      std::to_string(pixels) + " pixels, " + std::to_string(cycle) + " cycles");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_aggregator, AggregatorParams)
MODTB_SETS(X)
#undef X

}  // namespace
