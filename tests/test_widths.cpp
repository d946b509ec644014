// Bit widths: each derived width holds the largest value the model can produce, and that value
// needs every bit (one bit fewer would overflow). The model's stages are driven to the extremes.
#include <catch2/catch.hpp>
#include <random>

#include "golden_model.hpp"
#include "golden_stages.hpp"
#include "test_support.hpp"
#include "widths.hpp"

using namespace fpstereo;

namespace {

void check_width_is_minimal(uint64_t reached, int width, uint64_t bound) {
  INFO("reached " << reached << ", width " << width << ", closed-form maximum " << bound);
  CHECK(reached <= bound);
  CHECK(reached < (uint64_t(1) << width));         // the width holds it
  CHECK(reached >= (uint64_t(1) << (width - 1)));  // one bit fewer would overflow
}

std::vector<uint32_t> cost_row(const StereoConfig& cfg, const GrayImage& base, const GrayImage& match,
                               int y) {
  golden::CostRows<uint32_t> costs(cfg, derive_widths(cfg), base, match);
  std::vector<uint32_t> row(size_t(base.width) * size_t(cfg.dmax));
  costs.compute(y, row.data());
  return row;
}

// Fills the window of side `side` centred on (cx, cy) with value(dx, dy).
template <class F>
void paint(GrayImage& img, int cx, int cy, int side, F value) {
  for (int dy = -side / 2; dy <= side / 2; ++dy)
    for (int dx = -side / 2; dx <= side / 2; ++dx) img.at(cx + dx, cy + dy) = uint8_t(value(dx, dy));
}

// A pair whose matching cost at base pixel (x0, y0), disparity d0, is as large as the cost
// function allows (see docs/semantics.md, "Bit widths").
std::pair<GrayImage, GrayImage> worst_case_pair(const StereoConfig& cfg, int x0, int y0, int d0) {
  const int n = cfg.window, k = cfg.shd_window, size = 48;
  GrayImage base(size, size, 0), match(size, size, 0);
  switch (cfg.cost) {
    case CostFunction::Census:
    case CostFunction::Rank:  // a bright centre on black against a black centre on white
      paint(base, x0, y0, n, [](int dx, int dy) { return dx == 0 && dy == 0 ? 255 : 0; });
      paint(match, x0 - d0, y0, n, [](int dx, int dy) { return dx == 0 && dy == 0 ? 0 : 255; });
      break;
    case CostFunction::Sad:
      paint(base, x0, y0, n, [](int, int) { return 255; });
      break;
    case CostFunction::Zsad: {  // (n-1)/2 pixels +255 apart, the rest -255 apart
      int i = 0;
      paint(base, x0, y0, n, [&](int, int) { return i++ < (n * n - 1) / 2 ? 255 : 0; });
      paint(match, x0 - d0, y0, n, [&](int dx, int dy) { return 255 - base.at(x0 + dx, y0 + dy); });
      break;
    }
    case CostFunction::Shd: {
      // Base: a k x k block of distinct rising values on black, so every census bit of every
      // block pixel is set exactly when the match block (falling values on white) has it clear.
      paint(match, x0 - d0, y0, k + n + 2, [](int, int) { return 255; });
      int i = 1;
      paint(base, x0, y0, k, [&](int, int) { return i++; });
      paint(match, x0 - d0, y0, k, [&](int dx, int dy) { return 255 - base.at(x0 + dx, y0 + dy); });
      break;
    }
  }
  return {base, match};
}

}  // namespace

TEST_CASE("matching cost width holds the worst case and is minimal", "[widths]") {
  for (auto cost :
       {CostFunction::Census, CostFunction::Rank, CostFunction::Sad, CostFunction::Zsad, CostFunction::Shd})
    for (int window : {3, 5, 7, 9, 11})
      for (int shd_window : {1, 3, 5, 7}) {
        if (cost != CostFunction::Shd && shd_window != 1) continue;
        StereoConfig cfg;
        cfg.cost = cost;
        cfg.window = window;
        cfg.shd_window = shd_window;
        cfg.dmax = 32;
        cfg.width = cfg.height = 48;
        validate(cfg);
        const Widths w = derive_widths(cfg);
        const int x0 = 36, y0 = 24, d0 = 20;
        const auto [base, match] = worst_case_pair(cfg, x0, y0, d0);
        const auto row = cost_row(cfg, base, match, y0);
        INFO(to_string(cost) << " window " << window << " shd-window " << shd_window);
        const uint64_t reached = row[size_t(x0) * size_t(cfg.dmax) + size_t(d0)];
        check_width_is_minimal(reached, w.cost, w.cost_max);
        if (cost != CostFunction::Zsad) CHECK(reached == w.cost_max);  // the bound is reached exactly
        // Out-of-image matches (x < d) cost exactly Cmax.
        CHECK(row[size_t(0) * size_t(cfg.dmax) + 5] == w.cost_max);
      }
}

TEST_CASE("fused cost: the largest term reaches Cmax, and a gradient term is truncated and weighted", "[widths]") {
  // Census and rank's worst case also puts 255 against 0 at the centre: the intensity term's bound.
  for (auto cost : {CostFunction::Census, CostFunction::Rank})
    for (int trunc : {1, 20, 255}) {
      StereoConfig cfg;
      cfg.cost = cost;
      cfg.window = 5;
      cfg.dmax = 32;
      cfg.width = cfg.height = 48;
      cfg.fused_weight = 32;
      cfg.fused_trunc = trunc;
      validate(cfg);
      const Widths w = derive_widths(cfg);
      CHECK(w.cost_max == 24 + uint64_t(32 * trunc / 8));
      const int x0 = 36, y0 = 24, d0 = 20;
      const auto [base, match] = worst_case_pair(cfg, x0, y0, d0);
      const uint64_t reached = cost_row(cfg, base, match, y0)[size_t(x0) * size_t(cfg.dmax) + size_t(d0)];
      INFO(to_string(cost) << " fused-trunc " << trunc);
      check_width_is_minimal(reached, w.cost, w.cost_max);
      CHECK(reached == w.cost_max);
    }
  // Gradients +255 (base) and -255 (match) differ by 510; truncated at 100 and weighted 12/8: 150.
  StereoConfig cfg;
  cfg.window = 3;
  cfg.dmax = 16;
  cfg.width = cfg.height = 32;
  const int x0 = 20, y0 = 10, d0 = 6;
  GrayImage base(32, 32, 0), match(32, 32, 0);
  base.at(x0 + 1, y0) = 255;
  match.at(x0 - d0 - 1, y0) = 255;
  const uint32_t census = cost_row(cfg, base, match, y0)[size_t(x0) * size_t(cfg.dmax) + size_t(d0)];
  cfg.fused_weight = 12;
  cfg.fused_trunc = 100;
  cfg.fused_term = FusedTerm::Gradient;
  CHECK(cost_row(cfg, base, match, y0)[size_t(x0) * size_t(cfg.dmax) + size_t(d0)] == census + 150);
}

TEST_CASE("no matching cost exceeds Cmax on random images", "[widths]") {
  std::mt19937 rng(3);
  for (auto cost :
       {CostFunction::Census, CostFunction::Rank, CostFunction::Sad, CostFunction::Zsad, CostFunction::Shd}) {
    StereoConfig cfg;
    cfg.cost = cost;
    cfg.window = 5;
    cfg.shd_window = 3;
    cfg.dmax = 16;
    cfg.width = 40;
    cfg.height = 12;
    const GrayImage base = test::random_image(40, 12, rng), match = test::random_image(40, 12, rng);
    const uint64_t cost_max = derive_widths(cfg).cost_max;
    for (int y = 0; y < 12; ++y)
      for (uint32_t c : cost_row(cfg, base, match, y)) REQUIRE(c <= cost_max);
    if (cost == CostFunction::Sad || cost == CostFunction::Zsad) continue;
    for (FusedTerm term : {FusedTerm::Intensity, FusedTerm::Gradient}) {  // with the fused cost's largest term
      cfg.fused_weight = 32;
      cfg.fused_trunc = 255;
      cfg.fused_term = term;
      const uint64_t fused_max = derive_widths(cfg).cost_max;
      for (int y = 0; y < 12; ++y)
        for (uint32_t c : cost_row(cfg, base, match, y)) REQUIRE(c <= fused_max);
    }
  }
}

TEST_CASE("path cost and sum widths hold the worst case and are minimal", "[widths]") {
  // Every pixel: cost 0 at disparity 3, Cmax elsewhere. Along each path the costs of the other
  // disparities grow until the P2 jump caps them at Cmax + P2, on all paths at once. P1 is as
  // large as allowed so that the d +- 1 terms do not cap them earlier.
  for (auto [cost, window] : {std::pair{CostFunction::Census, 3},
                              {CostFunction::Census, 7},
                              {CostFunction::Rank, 5},
                              {CostFunction::Sad, 5},
                              {CostFunction::Zsad, 3}})
    for (int p2 : {0, 7, 86, 300})
      for (unsigned paths : {unsigned(kAllPaths), unsigned(kPath0), unsigned(kPath45 | kPath135), unsigned(kPath180),
                             unsigned(kEveryPath)}) {
        StereoConfig cfg;
        cfg.cost = cost;
        cfg.window = window;
        cfg.dmax = 16;
        cfg.p1 = std::min(p2, 255);
        cfg.p2 = p2;
        cfg.paths = paths;
        const Widths w = derive_widths(cfg);
        const int width = 96, height = 48;
        std::vector<uint32_t> costs(size_t(width) * 16, uint32_t(w.cost_max)), sum(costs.size());
        for (int x = 0; x < width; ++x) costs[size_t(x) * 16 + 3] = 0;
        // Adaptive P2 only lowers P2 below the configured one, so constant P2 is the worst case.
        golden::PathAggregator<uint32_t> aggregator(cfg, width, std::numeric_limits<uint32_t>::max() / 2, 0);
        const GrayImage flat(width, height);
        uint64_t max_path = 0, max_sum = 0;
        for (int y = 0; y < height; ++y) {
          aggregator.push_row(y, costs.data(), sum.data(), flat);
          max_path = std::max<uint64_t>(max_path, aggregator.max_path_cost());
          max_sum = std::max<uint64_t>(max_sum, *std::max_element(sum.begin(), sum.end()));
        }
        INFO(to_string(cost) << window << " P2 " << p2 << " paths " << paths_to_string(paths));
        CHECK(max_path == w.path_cost_max);
        CHECK(max_sum == w.aggregated_max);
        check_width_is_minimal(max_path, w.path_cost, w.path_cost_max);
        check_width_is_minimal(max_sum, w.aggregated, w.aggregated_max);
      }
}

namespace {

// The largest disparity, dmax - 1, is produced by a pair shifted by that much: the golden
// model's output on one, with the configuration it ran.
std::pair<StereoConfig, DisparityImage> run_largest_shift(int dmax, int subpixel_bits, std::mt19937& rng) {
  StereoConfig cfg;
  cfg.dmax = dmax;
  cfg.uf = dmax;
  cfg.width = dmax + 40;
  cfg.height = 16;
  cfg.median = 0;
  cfg.subpixel_bits = subpixel_bits;
  const auto [left, right] = test::shifted_pair(cfg.width, cfg.height, rng, [&](int, int) { return dmax - 1; });
  return {cfg, run_golden(cfg, left, right)};
}

}  // namespace

TEST_CASE("disparity and output word widths", "[widths]") {
  std::mt19937 rng(5);
  for (int dmax : {16, 48, 100, 128, 256}) {
    const auto [cfg, out] = run_largest_shift(dmax, 0, rng);
    const Widths w = derive_widths(cfg);
    const uint16_t largest = *std::max_element(out.pixels.begin(), out.pixels.end());
    INFO("dmax " << dmax);
    CHECK(largest == dmax - 1);
    check_width_is_minimal(largest, w.disparity, uint64_t(dmax - 1));
    CHECK(w.output_word == w.disparity + 1);
    CHECK(w.invalid_word == (1u << w.disparity));
    CHECK(w.invalid_word > dmax - 1);
    CHECK(w.invalid_word < (1u << w.output_word));
  }
  StereoConfig c2;
  CHECK(derive_widths(c2).output_word == 8);  // dmax 128: 7 disparity bits and the flag
}

TEST_CASE("sub-pixel output widths", "[widths][subpixel]") {
  // The largest output is (dmax - 1) * 2^k: the last disparity has no right neighbour, so its
  // fraction is 0 (docs/semantics.md, section 4).
  std::mt19937 rng(6);
  for (int bits : {1, 3, 5})
    for (int dmax : {16, 100, 256}) {
      const auto [cfg, out] = run_largest_shift(dmax, bits, rng);
      const Widths w = derive_widths(cfg);
      uint16_t largest = 0;
      for (uint16_t v : out.pixels)
        if (v != w.invalid_word) largest = std::max(largest, v);
      INFO("dmax " << dmax << ", " << bits << " fraction bits");
      CHECK(largest == (dmax - 1) << bits);
      check_width_is_minimal(largest, w.output_disparity, uint64_t(dmax - 1) << bits);
      StereoConfig whole = cfg;
      whole.subpixel_bits = 0;
      CHECK(w.disparity == derive_widths(whole).disparity);  // the winner-take-all's stays
      CHECK(w.output_word == w.output_disparity + 1);
      CHECK(w.invalid_word == (1u << w.output_disparity));
    }
  StereoConfig c2;
  c2.subpixel_bits = 4;
  CHECK(derive_widths(c2).output_word == 12);  // dmax 128: 127 * 16 = 2032 in 11 bits, and the flag
}

TEST_CASE("closed-form widths of the paper's C2 configuration", "[widths]") {
  // Census 7x7: 48-bit codes, costs 0..48 (6 bits), paths 48 + 86 = 134 (8 bits),
  // sums 4 * 134 = 536 (10 bits), uniqueness product 53600 (16 bits).
  const Widths w = derive_widths(preset("C2"));
  CHECK(w.code == 48);
  CHECK(w.cost == 6);
  CHECK(w.path_cost == 8);
  CHECK(w.aggregated == 10);
  CHECK(w.disparity == 7);
  CHECK(w.uniqueness_product == 16);
  CHECK(bits_for(0) == 1);
  CHECK(bits_for(1) == 1);
  CHECK(bits_for(255) == 8);
  CHECK(bits_for(256) == 9);
}
