// Naive reference model: a literal, slow transcription of docs/semantics.md.
// Every quantity is computed directly from its defining formula (full cost volume, full
// path-cost volumes, window loops everywhere). It shares no code with the golden model on
// purpose: the two are compared pixel for pixel by the tests.
#include "naive_model.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <limits>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#include "widths.hpp"

namespace fpstereo {
namespace {

// Internal marker for an invalid disparity (the output word is chosen only at the very end).
constexpr int64_t kInvalid = -1;

// Zero-extended pixel access (semantics section 1): every window reads 0 outside the image.
int64_t pixel(const GrayImage& img, int x, int y) {
  if (!img.contains(x, y)) return 0;
  return int64_t(img.at(x, y));
}

// Everything the cost functions need from one image: the raw pixels and its transforms.
struct Side {
  const GrayImage* img = nullptr;
  int width = 0;
  int height = 0;
  std::vector<std::vector<bool>> census;  // per pixel, N*N-1 bits in window raster order
  std::vector<int64_t> rank;              // per pixel
  std::vector<int64_t> mean;              // per pixel, floor(window sum / N^2)

  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  size_t index(int x, int y) const { return size_t(y) * size_t(width) + size_t(x); }

  // Census code, all zeros outside the image (needed by SHD's summation window).
  std::vector<bool> census_at(int x, int y, size_t bits) const {
    if (!inside(x, y)) return std::vector<bool>(bits, false);
    return census[index(x, y)];
  }
  int64_t rank_at(int x, int y) const { return inside(x, y) ? rank[index(x, y)] : 0; }
  int64_t mean_at(int x, int y) const { return inside(x, y) ? mean[index(x, y)] : 0; }
};

Side make_side(const GrayImage& img, int window) {
  const int r = (window - 1) / 2;
  Side s;
  s.img = &img;
  s.width = img.width;
  s.height = img.height;
  const size_t n = size_t(img.width) * size_t(img.height);
  s.census.assign(n, std::vector<bool>());
  s.rank.assign(n, 0);
  s.mean.assign(n, 0);
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const int64_t centre = pixel(img, x, y);
      std::vector<bool> code;
      int64_t rank = 0;
      int64_t sum = 0;
      // Window positions in raster order; the centre contributes to the sum only.
      for (int oy = -r; oy <= r; ++oy) {
        for (int ox = -r; ox <= r; ++ox) {
          const int64_t q = pixel(img, x + ox, y + oy);
          sum += q;
          if (ox == 0 && oy == 0) continue;
          code.push_back(centre > q);  // CT bit: 1 iff I(p) > I(q)
          if (q < centre) ++rank;      // RT: #{q : I(q) < I(p)}
        }
      }
      s.census[s.index(x, y)] = code;
      s.rank[s.index(x, y)] = rank;
      // Sum is non-negative, so integer division is the floor.
      s.mean[s.index(x, y)] = sum / (int64_t(window) * int64_t(window));
    }
  }
  return s;
}

int64_t hamming(const std::vector<bool>& a, const std::vector<bool>& b) {
  int64_t h = 0;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) ++h;
  return h;
}

// The fused cost's pixel-wise term (semantics section 2) between pixel (ax, y) of side a and
// (bx, y) of side b: the truncated difference of their intensities or horizontal gradients,
// weighted in eighths; 0 when the option is off.
int64_t fused_term(const StereoConfig& cfg, const Side& a, const Side& b, int ax, int bx, int y) {
  if (cfg.fused_weight == 0) return 0;
  auto feature = [&](const GrayImage& img, int x) {
    return cfg.fused_term == FusedTerm::Intensity ? pixel(img, x, y) : pixel(img, x + 1, y) - pixel(img, x - 1, y);
  };
  const int64_t diff = std::llabs(feature(*a.img, ax) - feature(*b.img, bx));
  return int64_t(cfg.fused_weight) * std::min<int64_t>(diff, cfg.fused_trunc) / 8;
}

// Cost between pixel (ax, y) of side `a` (playing the base role) and pixel (bx, y) of side `b`
// (playing the match role), straight from the table of semantics section 2. The caller has
// already handled the out-of-image match case (Cmax). The base-side volume calls this with
// (B, M, x, x-d); the LR2 match-side volume with (M, B, x', x'+d).
int64_t pair_cost(const StereoConfig& cfg, const Side& a, const Side& b, int ax, int bx, int y) {
  const int r = (cfg.window - 1) / 2;
  const size_t bits = size_t(cfg.window) * size_t(cfg.window) - 1;
  switch (cfg.cost) {
    case CostFunction::Census:
      return hamming(a.census_at(ax, y, bits), b.census_at(bx, y, bits));
    case CostFunction::Rank:
      return std::llabs(a.rank_at(ax, y) - b.rank_at(bx, y));
    case CostFunction::Sad: {
      int64_t c = 0;
      for (int oy = -r; oy <= r; ++oy)
        for (int ox = -r; ox <= r; ++ox)
          c += std::llabs(pixel(*a.img, ax + ox, y + oy) - pixel(*b.img, bx + ox, y + oy));
      return c;
    }
    case CostFunction::Zsad: {
      const int64_t ma = a.mean_at(ax, y);
      const int64_t mb = b.mean_at(bx, y);
      int64_t c = 0;
      // Positions outside the image read 0 and still have the mean subtracted.
      for (int oy = -r; oy <= r; ++oy)
        for (int ox = -r; ox <= r; ++ox)
          c += std::llabs((pixel(*a.img, ax + ox, y + oy) - ma) - (pixel(*b.img, bx + ox, y + oy) - mb));
      return c;
    }
    case CostFunction::Shd: {
      const int k = (cfg.shd_window - 1) / 2;
      const int shift = bx - ax;  // q in a's window pairs with q + shift in b
      int64_t c = 0;
      for (int qy = y - k; qy <= y + k; ++qy)
        for (int qx = ax - k; qx <= ax + k; ++qx)
          c += hamming(a.census_at(qx, qy, bits), b.census_at(qx + shift, qy, bits));
      return c;
    }
  }
  return 0;  // unreachable: every enumerator is handled above
}

// A W x H x D volume of int64 values.
struct Volume {
  int width = 0, height = 0, depth = 0;
  std::vector<int64_t> v;
  Volume(int w, int h, int d) : width(w), height(h), depth(d), v(size_t(w) * size_t(h) * size_t(d), 0) {}
  int64_t& at(int x, int y, int d) {
    return v[(size_t(y) * size_t(width) + size_t(x)) * size_t(depth) + size_t(d)];
  }
  int64_t at(int x, int y, int d) const {
    return v[(size_t(y) * size_t(width) + size_t(x)) * size_t(depth) + size_t(d)];
  }
};

// Base-side matching cost: base pixel (x, y) against match pixel (x - d, y).
Volume base_costs(const StereoConfig& cfg, const Side& base, const Side& match, int64_t cmax) {
  Volume c(base.width, base.height, cfg.dmax);
  for (int y = 0; y < base.height; ++y)
    for (int x = 0; x < base.width; ++x)
      for (int d = 0; d < cfg.dmax; ++d) {
        const int xm = x - cfg.min_disp - d;  // disparity min_disp + d
        c.at(x, y, d) = (xm < 0 || xm >= match.width)
                            ? cmax
                            : pair_cost(cfg, base, match, x, xm, y) + fused_term(cfg, base, match, x, xm, y);
      }
  return c;
}

// LR2 match-side cost: match pixel (x', y) against base pixel (x' + m + d, y), roles swapped.
Volume match_costs(const StereoConfig& cfg, const Side& base, const Side& match, int64_t cmax) {
  Volume c(match.width, match.height, cfg.dmax);
  for (int y = 0; y < match.height; ++y)
    for (int x = 0; x < match.width; ++x)
      for (int d = 0; d < cfg.dmax; ++d)
        c.at(x, y, d) = (x + cfg.min_disp + d < 0 || x + cfg.min_disp + d >= match.width)
                            ? cmax
                            : pair_cost(cfg, match, base, x, x + cfg.min_disp + d, y) +
                                  fused_term(cfg, match, base, x, x + cfg.min_disp + d, y);
  return c;
}

// Section 3's large-jump penalty from predecessor q to p: P2, or with adaptive P2 and a guide
// image, P2 less k/4 per grey level between I(p) and I(q), never below P1.
int64_t jump_penalty(const StereoConfig& cfg, const GrayImage* guide, int x, int y, int qx, int qy) {
  if (guide == nullptr || cfg.p2_adapt == 0) return cfg.p2;
  const int64_t step = std::llabs(int64_t(guide->at(x, y)) - int64_t(guide->at(qx, qy)));
  return std::max<int64_t>(cfg.p1, cfg.p2 - cfg.p2_adapt * step / 4);
}

// MGM's second predecessor of the path whose first is (dx, dy) (section 3): the one a right
// angle away on the causal side. Returns false for none (mgm off).
bool second_predecessor(const StereoConfig& cfg, int dx, int dy, int& sx, int& sy) {
  if (!cfg.mgm) return false;
  if (dx == -1 && dy == 0) { sx = 0; sy = -1; }         // path 0: (x, y-1)
  else if (dx == -1 && dy == -1) { sx = 1; sy = -1; }   // path 45: (x+1, y-1)
  else if (dx == 0 && dy == -1) { sx = -1; sy = 0; }    // path 90: (x-1, y)
  else { sx = -1; sy = -1; }                            // path 135: (x-1, y-1)
  return true;
}

// One path's L_r volume by explicit recursion (section 3). Rows top to bottom, and within a row
// away from a predecessor in the same row: left to right, but right to left for the 180-degree
// path, whose predecessor is (x+1, y); the others lie in the row above.
// With mgm, L_r = C + floor((T1 + T2) / 2) over the predecessors in the image (one: its T).
Volume path_costs(const StereoConfig& cfg, const Volume& c, const GrayImage* guide, int dx, int dy) {
  const int w = c.width, h = c.height, D = c.depth;
  Volume l(w, h, D);
  auto in_image = [&](int qx, int qy) { return qx >= 0 && qy >= 0 && qx < w && qy < h; };
  // The predecessor term min(L(q,d), L(q,d-1)+P1, L(q,d+1)+P1, min L(q) + P2) - min L(q).
  auto term = [&](int x, int y, int qx, int qy, int d) {
    int64_t m = std::numeric_limits<int64_t>::max();
    for (int i = 0; i < D; ++i) m = std::min(m, l.at(qx, qy, i));
    int64_t best = l.at(qx, qy, d);
    if (d >= 1) best = std::min(best, l.at(qx, qy, d - 1) + int64_t(cfg.p1));
    if (d <= D - 2) best = std::min(best, l.at(qx, qy, d + 1) + int64_t(cfg.p1));
    best = std::min(best, m + jump_penalty(cfg, guide, x, y, qx, qy));
    return best - m;
  };
  int sx = 0, sy = 0;
  const bool mgm = second_predecessor(cfg, dx, dy, sx, sy);
  const bool right_to_left = dy == 0 && dx > 0;
  for (int y = 0; y < h; ++y) {
    for (int i = 0; i < w; ++i) {
      const int x = right_to_left ? w - 1 - i : i;
      const bool first = in_image(x + dx, y + dy);
      const bool second = mgm && in_image(x + sx, y + sy);
      for (int d = 0; d < D; ++d) {
        int64_t add = 0;
        if (first && second)
          add = (term(x, y, x + dx, y + dy, d) + term(x, y, x + sx, y + sy, d)) / 2;
        else if (first)
          add = term(x, y, x + dx, y + dy, d);
        else if (second)
          add = term(x, y, x + sx, y + sy, d);
        l.at(x, y, d) = c.at(x, y, d) + add;
      }
    }
  }
  return l;
}

// S = sum of L_r over the enabled paths; guide (or none) is the image adaptive P2 follows.
// Up to `threads` paths at a time, each on its own thread.
Volume aggregate(const StereoConfig& cfg, const Volume& c, const GrayImage* guide, int threads) {
  std::vector<PathDirection> paths;
  for (const PathDirection& p : path_directions())
    if (cfg.paths & p.mask) paths.push_back(p);
  Volume s(c.width, c.height, c.depth);
  const size_t group = size_t(std::max(1, threads));
  for (size_t first = 0; first < paths.size(); first += group) {
    const size_t n = std::min(group, paths.size() - first);
    std::vector<Volume> l(n, Volume(0, 0, 0));
    std::vector<std::exception_ptr> errors(n);
    auto run = [&](size_t i) {
      try {
        l[i] = path_costs(cfg, c, guide, paths[first + i].dx, paths[first + i].dy);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    };
    std::vector<std::thread> helpers;
    for (size_t i = 1; i < n; ++i) {
      try {
        helpers.emplace_back(run, i);
      } catch (const std::system_error&) {  // no thread to be had: this one does it
        run(i);
      }
    }
    run(0);
    for (auto& helper : helpers) helper.join();
    for (size_t i = 0; i < n; ++i) {
      if (errors[i]) std::rethrow_exception(errors[i]);
      for (size_t k = 0; k < s.v.size(); ++k) s.v[k] += l[i].v[k];
    }
  }
  return s;
}

// Smallest d with the minimal S(x, y, d) (ties to the smaller disparity).
int64_t wta(const Volume& s, int x, int y) {
  int64_t best_d = 0;
  for (int d = 1; d < s.depth; ++d)
    if (s.at(x, y, d) < s.at(x, y, int(best_d))) best_d = d;
  return best_d;
}

// A disparity map during refinement: a disparity per pixel, or kInvalid.
struct DispMap {
  int width = 0, height = 0;
  std::vector<int64_t> v;
  DispMap(int w, int h) : width(w), height(h), v(size_t(w) * size_t(h), kInvalid) {}
  int64_t& at(int x, int y) { return v[size_t(y) * size_t(width) + size_t(x)]; }
  int64_t at(int x, int y) const { return v[size_t(y) * size_t(width) + size_t(x)]; }
};

// Section 4: invalid iff S2 * (100 - u) < S1 * 100, S2 = min over |d - D| >= 2.
void apply_uniqueness(const StereoConfig& cfg, const Volume& sum, DispMap& disp) {
  const int64_t u = cfg.uniqueness;
  const int64_t none = std::numeric_limits<int64_t>::max();
  for (int y = 0; y < disp.height; ++y) {
    for (int x = 0; x < disp.width; ++x) {
      const int64_t D = disp.at(x, y);
      const int64_t s1 = sum.at(x, y, int(D));
      // dmax >= 16 (validate), so the set |d - D| >= 2 is never empty; if it were, S2 is
      // taken as infinite and the pixel stays valid.
      int64_t s2 = none;
      for (int d = 0; d < sum.depth; ++d)
        if (std::llabs(int64_t(d) - D) >= 2) s2 = std::min(s2, sum.at(x, y, d));
      if (s2 != none && s2 * (100 - u) < s1 * 100) disp.at(x, y) = kInvalid;
    }
  }
}

// Section 4, confidence: 255 (S2 - S1) / S2 rounded down, S2 the best sum two or more
// disparities from the winner D; 0 when S2 is 0.
DisparityImage confidence(const Volume& sum, const DispMap& winners) {
  DisparityImage out(winners.width, winners.height);
  for (int y = 0; y < winners.height; ++y)
    for (int x = 0; x < winners.width; ++x) {
      const int64_t D = winners.at(x, y), s1 = sum.at(x, y, int(D));
      int64_t s2 = std::numeric_limits<int64_t>::max();
      for (int d = 0; d < sum.depth; ++d)
        if (d <= D - 2 || d >= D + 2) s2 = std::min(s2, sum.at(x, y, d));
      out.at(x, y) = uint16_t(s2 == 0 ? 0 : 255 * (s2 - s1) / s2);
    }
  return out;
}

// LR1: Dm(x') = smallest d minimising S(x' + m + d, y, d) over d with x' + m + d in the row.
DispMap lr1_match_disparities(const Volume& sum, int m) {
  DispMap dm(sum.width, sum.height);
  for (int y = 0; y < sum.height; ++y) {
    for (int xm = 0; xm < sum.width; ++xm) {
      // Over the d whose base pixel x' + m + d lies in the row; 0 when none does.
      int64_t best_d = -1;
      for (int d = 0; d < sum.depth; ++d) {
        const int x = xm + m + d;
        if (x < 0 || x >= sum.width) continue;
        if (best_d < 0 || sum.at(x, y, d) < sum.at(xm + m + int(best_d), y, int(best_d))) best_d = d;
      }
      dm.at(xm, y) = best_d < 0 ? 0 : best_d;
    }
  }
  return dm;
}

// LR2: match-side cost with the roles swapped, its own aggregation with constant P2, plain WTA.
DispMap lr2_match_disparities(const StereoConfig& cfg, const Side& base, const Side& match, int64_t cmax,
                              int threads) {
  const Volume msum = aggregate(cfg, match_costs(cfg, base, match, cmax), nullptr, threads);
  DispMap dm(msum.width, msum.height);
  for (int y = 0; y < msum.height; ++y)
    for (int xm = 0; xm < msum.width; ++xm) dm.at(xm, y) = wta(msum, xm, y);
  return dm;
}

// Section 5: compare each still-valid base disparity with Dm at x' = x - D.
void apply_lr_check(const StereoConfig& cfg, const DispMap& dm, DispMap& disp) {
  for (int y = 0; y < disp.height; ++y) {
    for (int x = 0; x < disp.width; ++x) {
      const int64_t D = disp.at(x, y);
      if (D == kInvalid) continue;
      const int64_t xm = int64_t(x) - cfg.min_disp - D;
      if (xm < 0 || xm >= disp.width || std::llabs(D - dm.at(int(xm), y)) > int64_t(cfg.lr_threshold))
        disp.at(x, y) = kInvalid;
    }
  }
}

// Section 4, sub-pixel: each valid D becomes D * 2^k + f, f the integer nearest to
// delta * 2^k (ties away from zero), delta = (a - c) / (2 e) with a, b, c the sums at D - 1, D,
// D + 1 and e = max(a, c) - b (equiangular) or a + c - 2b (parabola); f = 0 at D = 0 and
// D = dmax - 1. Found by trying every f in -2^k .. 2^k on the cross-multiplied distance.
// k = 0 keeps D as it is (no rounding to a neighbour).
void refine_subpixel(const StereoConfig& cfg, const Volume& sum, DispMap& disp) {
  if (cfg.subpixel_bits == 0) return;
  const int64_t scale = int64_t(1) << cfg.subpixel_bits;
  for (int y = 0; y < disp.height; ++y) {
    for (int x = 0; x < disp.width; ++x) {
      const int64_t D = disp.at(x, y);
      if (D == kInvalid) continue;
      int64_t best_f = 0;
      if (D > 0 && D < sum.depth - 1) {
        const int64_t a = sum.at(x, y, int(D) - 1), b = sum.at(x, y, int(D)), c = sum.at(x, y, int(D) + 1);
        const int64_t e = cfg.subpixel_fit == SubpixelFit::Equiangular ? std::max(a, c) - b : a + c - 2 * b;
        // |f - delta * 2^k| * 2e, compared as integers
        auto distance = [&](int64_t f) { return std::llabs(f * 2 * e - (a - c) * scale); };
        for (int64_t f = -scale; f <= scale; ++f)
          if (distance(f) < distance(best_f) || (distance(f) == distance(best_f) && std::llabs(f) > std::llabs(best_f)))
            best_f = f;
      }
      disp.at(x, y) = D * scale + best_f;
    }
  }
}

// Section 5a: flood-fill every 4-connected region of valid pixels whose neighbours differ by at
// most `range` (in the map's units) from an explicit stack; a region of at most `size` pixels
// becomes invalid.
void remove_speckles(DispMap& disp, int size, int64_t range) {
  const int W = disp.width, H = disp.height;
  std::vector<bool> visited(size_t(W) * size_t(H), false);
  auto index = [&](int x, int y) { return size_t(y) * size_t(W) + size_t(x); };
  const int steps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (int sy = 0; sy < H; ++sy)
    for (int sx = 0; sx < W; ++sx) {
      if (disp.at(sx, sy) == kInvalid || visited[index(sx, sy)]) continue;
      std::vector<std::pair<int, int>> region{{sx, sy}}, stack{{sx, sy}};
      visited[index(sx, sy)] = true;
      while (!stack.empty()) {
        const auto [x, y] = stack.back();
        stack.pop_back();
        for (const auto& step : steps) {
          const int nx = x + step[0], ny = y + step[1];
          if (nx < 0 || ny < 0 || nx >= W || ny >= H || visited[index(nx, ny)] || disp.at(nx, ny) == kInvalid) continue;
          if (std::abs(disp.at(nx, ny) - disp.at(x, y)) > range) continue;
          visited[index(nx, ny)] = true;
          region.emplace_back(nx, ny);
          stack.emplace_back(nx, ny);
        }
      }
      if (int64_t(region.size()) <= size)
        for (const auto& [x, y] : region) disp.at(x, y) = kInvalid;
    }
}

// Section 6: lower median of the valid in-image window values; invalid centres stay invalid.
DispMap median_filter(const DispMap& in, int side) {
  const int k = (side - 1) / 2;
  DispMap out(in.width, in.height);
  for (int y = 0; y < in.height; ++y) {
    for (int x = 0; x < in.width; ++x) {
      if (in.at(x, y) == kInvalid) continue;  // filling holes is gap interpolation's job
      std::vector<int64_t> values;
      for (int qy = y - k; qy <= y + k; ++qy)
        for (int qx = x - k; qx <= x + k; ++qx)
          if (qx >= 0 && qy >= 0 && qx < in.width && qy < in.height && in.at(qx, qy) != kInvalid)
            values.push_back(in.at(qx, qy));
      std::sort(values.begin(), values.end());  // non-empty: the centre is valid
      out.at(x, y) = values[(values.size() - 1) / 2];
    }
  }
  return out;
}

// Section 7: fill each maximal invalid run of a row from the valid pixels bounding it; with
// `linear`, a run whose bounding values are close is filled along the straight line between
// them (`unit` values a pixel).
void gap_interpolate(DispMap& disp, bool linear, int64_t unit) {
  for (int y = 0; y < disp.height; ++y) {
    int x = 0;
    while (x < disp.width) {
      if (disp.at(x, y) != kInvalid) {
        ++x;
        continue;
      }
      const int run_start = x;
      while (x < disp.width && disp.at(x, y) == kInvalid) ++x;
      const int run_end = x;  // one past the run
      const bool has_left = run_start > 0;
      const bool has_right = run_end < disp.width;
      if (!has_left && !has_right) continue;  // whole row invalid: stays invalid
      if (linear && has_left && has_right) {
        const int64_t a = disp.at(run_start - 1, y), b = disp.at(run_end, y);
        const int64_t span = run_end - (run_start - 1);  // from one valid pixel to the other
        // |b - a| <= 4 + span / 8 pixels, in values
        if (8 * (a > b ? a - b : b - a) <= (32 + span) * unit) {
          for (int i = run_start; i < run_end; ++i) {
            const int64_t t = i - (run_start - 1);  // steps from the left valid pixel
            // a + (b - a) t / span, rounded half up, over non-negative terms
            disp.at(i, y) = (a * (span - t) + b * t + span / 2) / span;
          }
          continue;
        }
      }
      int64_t fill = 0;
      if (has_left && has_right)
        fill = std::min(disp.at(run_start - 1, y), disp.at(run_end, y));
      else if (has_left)
        fill = disp.at(run_start - 1, y);
      else
        fill = disp.at(run_end, y);
      for (int i = run_start; i < run_end; ++i) disp.at(i, y) = fill;
    }
  }
}

}  // namespace

void remove_speckles(DisparityImage& words, int size, int range, uint16_t invalid) {
  DispMap disp(words.width, words.height);
  for (int y = 0; y < words.height; ++y)
    for (int x = 0; x < words.width; ++x)
      if (words.at(x, y) != invalid) disp.at(x, y) = words.at(x, y);
  remove_speckles(disp, size, range);
  for (int y = 0; y < words.height; ++y)
    for (int x = 0; x < words.width; ++x) words.at(x, y) = disp.at(x, y) == kInvalid ? invalid : uint16_t(disp.at(x, y));
}

Planes run_naive(const StereoConfig& cfg, const GrayImage& left, const GrayImage& right,
                 const std::vector<Plane>& planes, int threads) {
  for (const Plane plane : planes)
    if (const std::string why = plane_unavailable(cfg, plane); !why.empty())
      throw std::invalid_argument("run_naive: " + why);
  const auto wanted = [&](Plane plane) { return std::find(planes.begin(), planes.end(), plane) != planes.end(); };
  Planes out;
  // The run's size is the images' size (the caller checked left and right agree).
  const int W = left.width, H = left.height;
  const Widths widths = derive_widths(cfg);
  const int64_t cmax = int64_t(widths.cost_max);

  const Side base = make_side(left, cfg.window);
  const Side match = make_side(right, cfg.window);

  // Cost, aggregation, winner-take-all.
  const Volume sum = aggregate(cfg, base_costs(cfg, base, match, cmax), &left, threads);
  DispMap disp(W, H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) disp.at(x, y) = wta(sum, x, y);

  if (wanted(Plane::Confidence)) out[Plane::Confidence] = confidence(sum, disp);
  if (cfg.uniqueness > 0) apply_uniqueness(cfg, sum, disp);

  if (cfg.lr != LrCheck::None) {
    const DispMap dm = cfg.lr == LrCheck::Lr1 ? lr1_match_disparities(sum, cfg.min_disp)
                                              : lr2_match_disparities(cfg, base, match, cmax, threads);
    apply_lr_check(cfg, dm, disp);
    if (wanted(Plane::Right)) {
      DisparityImage& view = out[Plane::Right] = DisparityImage(W, H);
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) view.at(x, y) = uint16_t(dm.at(x, y));
    }
  }

  refine_subpixel(cfg, sum, disp);

  if (cfg.speckle_size > 0) remove_speckles(disp, cfg.speckle_size, int64_t(cfg.speckle_range) << cfg.subpixel_bits);

  if (cfg.median > 0) disp = median_filter(disp, cfg.median);

  if (cfg.gap_interpolation) gap_interpolate(disp, cfg.gap_linear, int64_t(1) << cfg.subpixel_bits);

  // Output words: the disparity, or the invalid flag alone.
  if (wanted(Plane::Disparity)) {
    DisparityImage& words = out[Plane::Disparity] = DisparityImage(W, H, widths.invalid_word);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        if (disp.at(x, y) != kInvalid) words.at(x, y) = uint16_t(disp.at(x, y));
  }
  return out;
}

}  // namespace fpstereo
