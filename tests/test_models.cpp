// The golden model against the naive model (full cost volume, explicit recursion) on many
// random configurations and images: zero mismatching pixels, borders included.
#include <catch2/catch.hpp>
#include <algorithm>
#include <limits>
#include <random>

#include "compare.hpp"
#include "golden_model.hpp"
#include "golden_stages.hpp"
#include "widths.hpp"
#include "naive_model.hpp"
#include "test_support.hpp"

using namespace fpstereo;

namespace {

template <class T>
T pick(std::mt19937& rng, std::initializer_list<T> options) {
  std::uniform_int_distribution<size_t> i(0, options.size() - 1);
  return *(options.begin() + i(rng));
}

StereoConfig random_config(std::mt19937& rng) {
  StereoConfig c;
  c.cost = pick(rng, {CostFunction::Census, CostFunction::Rank, CostFunction::Sad, CostFunction::Zsad,
                      CostFunction::Shd});
  c.window = pick(rng, {3, 5, 7});
  if (c.cost == CostFunction::Census) c.window = pick(rng, {3, 5, 7, 9, 11});  // codes over 64 bits
  c.shd_window = pick(rng, {1, 3, 5});
  if (c.cost != CostFunction::Sad && c.cost != CostFunction::Zsad) {  // the fused cost's costs
    c.fused_weight = pick(rng, {0, 0, 1, 8, 32});
    c.fused_trunc = pick(rng, {1, 20, 255});
    c.fused_term = pick(rng, {FusedTerm::Intensity, FusedTerm::Gradient});
  }
  c.dmax = pick(rng, {16, 24, 32, 48});
  c.uf = pick(rng, {1, 8, 16});
  if (c.dmax % c.uf != 0) c.uf = c.dmax;
  c.paths = std::uniform_int_distribution<unsigned>(1, kEveryPath)(rng);
  c.p1 = std::uniform_int_distribution<int>(0, 40)(rng);
  c.p2 = c.p1 + std::uniform_int_distribution<int>(0, 200)(rng);
  c.p2_adapt = pick(rng, {0, 0, 1, 4, 16});
  c.mgm = pick(rng, {false, true});
  if (c.mgm) c.paths = (c.paths & kAllPaths) != 0 ? c.paths & kAllPaths : unsigned(kPath0);  // MGM refuses 180
  c.min_disp = pick(rng, {0, 0, 3, -5, -20});
  c.lr = pick(rng, {LrCheck::None, LrCheck::Lr1, LrCheck::Lr2});
  c.lr_threshold = pick(rng, {0, 1, 2});
  c.uniqueness = pick(rng, {0, 0, 5, 15, 40});
  c.median = pick(rng, {0, 3, 5, 7});
  c.gap_interpolation = pick(rng, {false, true});
  c.gap_linear = c.gap_interpolation && pick(rng, {false, true});
  c.speckle_size = pick(rng, {0, 0, 1, 2, 5, 12, 40, 400});
  c.speckle_range = pick(rng, {0, 1, 2, 5});
  c.subpixel_bits = pick(rng, {0, 0, 1, 3, 5});
  c.subpixel_fit = pick(rng, {SubpixelFit::Equiangular, SubpixelFit::Parabola});
  c.width = c.dmax + std::uniform_int_distribution<int>(0, 24)(rng);
  c.height = std::uniform_int_distribution<int>(4, 20)(rng);
  return c;
}

// Random textures, few-level textures (many ties) and pairs with a true shift.
std::pair<GrayImage, GrayImage> random_pair(const StereoConfig& c, std::mt19937& rng) {
  switch (rng() % 3) {
    case 0:
      return {test::random_image(c.width, c.height, rng), test::random_image(c.width, c.height, rng)};
    case 1:
      return {test::random_image(c.width, c.height, rng, 3), test::random_image(c.width, c.height, rng, 3)};
    default: {
      const int d0 = int(rng() % unsigned(c.dmax));
      return test::shifted_pair(c.width, c.height, rng,
                                [&](int x, int) { return x < c.width / 2 ? d0 : d0 / 2; });
    }
  }
}

}  // namespace

TEST_CASE("golden model equals the naive model on random configurations, on 1 to 4 threads", "[models]") {
  std::mt19937 rng(20261121);
  const int cases = 400;
  for (int i = 0; i < cases; ++i) {
    const StereoConfig cfg = random_config(rng);
    validate(cfg);
    const auto [left, right] = random_pair(cfg, rng);
    // The confidences, and with a left-right check the right views (the match side's
    // disparities) as well. Both models share the frame among their threads.
    const bool views = cfg.lr != LrCheck::None;
    const int threads = 1 + i % 4;
    std::vector<Plane> planes{Plane::Disparity, Plane::Confidence};
    if (views) planes.push_back(Plane::Right);
    const Planes naive = run_naive(cfg, left, right, planes, threads);
    const Planes golden = run_golden(cfg, left, right, planes, threads);
    INFO("case " << i << ", " << threads << " threads\n" << describe(cfg));
    REQUIRE(naive.size() == planes.size());
    REQUIRE(golden.size() == planes.size());
    for (const Plane plane : planes) {
      const Comparison cmp = compare_words(naive.at(plane), golden.at(plane));
      INFO(plane_info(plane).name << ": " << cmp.report());
      REQUIRE(cmp.equal());
    }
  }
}

TEST_CASE("golden model in column bands of 2 to 4 threads equals the naive model", "[models]") {
  // The threads share each row by columns (golden_model.cpp, "Column bands"). The images are
  // narrow, so the bands (4 to 8 of them) are narrower than dmax: the left-right check reads sums
  // and LR2's match side reads costs several bands away.
  std::mt19937 rng(20261126);
  for (int i = 0; i < 120; ++i) {
    const StereoConfig cfg = random_config(rng);
    validate(cfg);
    const auto [left, right] = random_pair(cfg, rng);
    const int threads = 2 + i % 3;
    std::vector<Plane> planes{Plane::Disparity, Plane::Confidence};
    if (cfg.lr != LrCheck::None) planes.push_back(Plane::Right);
    const Planes naive = run_naive(cfg, left, right, planes, threads);
    const Planes golden = run_golden(cfg, left, right, planes, threads);
    INFO("case " << i << ", " << threads << " threads\n" << describe(cfg));
    for (const Plane plane : planes) {
      const Comparison cmp = compare_words(naive.at(plane), golden.at(plane));
      INFO(plane_info(plane).name << ": " << cmp.report());
      REQUIRE(cmp.equal());
    }
  }
}

TEST_CASE("golden model equals the naive model for each option alone", "[models]") {
  std::mt19937 rng(7);
  StereoConfig base;
  base.width = 48;
  base.height = 12;
  base.dmax = 16;
  base.uf = 4;
  base.median = 0;
  std::vector<std::pair<std::string, StereoConfig>> variants;
  for (const auto& spec : {std::pair<const char*, const char*>{"cost", "census"},
                           {"cost", "rank"},
                           {"cost", "sad"},
                           {"cost", "zsad"},
                           {"cost", "shd"},
                           {"paths", "0"},
                           {"paths", "45"},
                           {"paths", "90"},
                           {"paths", "135"},
                           {"paths", "180"},
                           {"paths", "0,45,90,135,180"},
                           {"lr", "lr1"},
                           {"lr", "lr2"},
                           {"uniqueness", "20"},
                           {"median", "3"},
                           {"median", "5"},
                           {"median", "7"},
                           {"gap-interp", "on"},
                           {"gap-interp", "linear"},
                           {"speckle-size", "6"},
                           {"fused-weight", "8"},
                           {"subpixel-bits", "4"},
                           {"p2-adapt", "6"},
                           {"mgm", "on"},
                           {"min-disp", "2"},
                           {"min-disp", "-7"}}) {
    StereoConfig c = base;
    set_param(c, spec.first, spec.second);
    variants.emplace_back(std::string(spec.first) + "=" + spec.second, c);
  }
  for (const char* paths : {"0", "45", "90", "135"}) {
    StereoConfig c = base;
    c.mgm = true;
    c.p2_adapt = 6;
    set_param(c, "paths", paths);
    variants.emplace_back(std::string("mgm=on p2-adapt=6 paths=") + paths, c);
  }
  for (const char* lr : {"lr1", "lr2"}) {
    // The 180-degree path with adaptive P2, on both sides of the left-right check.
    StereoConfig c = base;
    set_param(c, "paths", "0,90,180");
    set_param(c, "lr", lr);
    c.p2_adapt = 6;
    variants.emplace_back(std::string("paths=0,90,180 p2-adapt=6 lr=") + lr, c);
  }
  StereoConfig parabola = base;
  parabola.subpixel_bits = 2;
  parabola.subpixel_fit = SubpixelFit::Parabola;
  variants.emplace_back("subpixel-bits=2 subpixel-fit=parabola", parabola);
  for (const char* cost : {"census", "rank", "shd"}) {
    // The largest gradient term, on both sides of LR2 (the match side's costs from scratch).
    StereoConfig fused = base;
    set_param(fused, "cost", cost);
    fused.fused_weight = 32;
    fused.fused_trunc = 255;
    fused.fused_term = FusedTerm::Gradient;
    fused.lr = LrCheck::Lr2;
    variants.emplace_back(std::string("cost=") + cost + " fused-weight=32 fused-trunc=255 fused-term=gradient lr=lr2", fused);
  }
  for (const auto& [name, cfg] : variants) {
    const auto [left, right] =
        test::shifted_pair(cfg.width, cfg.height, rng, [](int x, int) { return x < 24 ? 3 : 9; });
    const Comparison cmp = compare_words(run_naive(cfg, left, right).at(Plane::Disparity), run_golden(cfg, left, right));
    INFO(name << ": " << cmp.report());
    CHECK(cmp.equal());
  }
}

TEST_CASE("mgm: paths 0 and 90 are one recursion, and so are 45 and 135", "[models]") {
  // With mgm the paths 0 and 90 both read (x-1, y) and (x, y-1), the paths 45 and 135 both
  // (x-1, y-1) and (x+1, y-1): four paths are two, counted twice (section 3).
  std::mt19937 rng(3);
  StereoConfig c;
  c.width = 64;
  c.height = 16;
  c.dmax = 32;
  c.uf = 8;
  c.median = 0;
  c.mgm = true;
  c.p2_adapt = 4;
  c.subpixel_bits = 3;
  const auto [left, right] = test::shifted_pair(c.width, c.height, rng, [](int x, int y) { return (x + y) / 8; });
  auto run = [&](const char* paths) {
    StereoConfig cfg = c;
    set_param(cfg, "paths", paths);
    return run_golden(cfg, left, right);
  };
  CHECK(compare_words(run("0"), run("90")).equal());
  CHECK(compare_words(run("45"), run("135")).equal());
  CHECK(compare_words(run("0,45"), run("all")).equal());
  c.mgm = false;
  CHECK_FALSE(compare_words(run("0"), run("90")).equal());
}

TEST_CASE("mgm: path costs stay within Cmax + P2, the width of section 'Bit widths'", "[models]") {
  // Cost 0 at disparity 3, Cmax elsewhere: the other disparities' path costs grow to Cmax + P2
  // (both predecessor terms capped at P2, and their mean too), never beyond.
  for (int p2 : {0, 7, 86, 301}) {
    StereoConfig cfg;
    cfg.window = 5;
    cfg.dmax = 16;
    cfg.uf = 16;
    cfg.p1 = std::min(p2, 255);
    cfg.p2 = p2;
    cfg.mgm = true;
    const Widths w = derive_widths(cfg);
    const int width = 64, height = 32;
    std::vector<uint32_t> costs(size_t(width) * 16, uint32_t(w.cost_max)), sum(costs.size());
    for (int x = 0; x < width; ++x) costs[size_t(x) * 16 + 3] = 0;
    golden::PathAggregator<uint32_t> aggregator(cfg, width, std::numeric_limits<uint32_t>::max() / 2, 0);
    const GrayImage flat(width, height);
    uint64_t max_path = 0, max_sum = 0;
    for (int y = 0; y < height; ++y) {
      aggregator.push_row(y, costs.data(), sum.data(), flat);
      max_path = std::max<uint64_t>(max_path, aggregator.max_path_cost());
      max_sum = std::max<uint64_t>(max_sum, *std::max_element(sum.begin(), sum.end()));
    }
    INFO("P2 " << p2);
    CHECK(max_path == w.path_cost_max);
    CHECK(max_sum == w.aggregated_max);
  }
}

TEST_CASE("the 180-degree path is the 0-degree path of the mirrored row", "[models]") {
  // Section 3: L_180 runs from the row's last pixel leftwards against (x + 1, y), with adaptive P2
  // on the pair (x, x + 1); mirroring the row's costs and guide turns it into L_0.
  std::mt19937 rng(180);
  const int width = 37, height = 5, dmax = 16;
  StereoConfig cfg;
  cfg.dmax = dmax;
  cfg.uf = 16;
  cfg.p1 = 9;
  cfg.p2 = 70;
  StereoConfig mirrored_cfg = cfg;
  cfg.paths = kPath180;
  mirrored_cfg.paths = kPath0;
  const GrayImage guide = test::random_image(width, height, rng);
  GrayImage mirrored_guide(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) mirrored_guide.at(width - 1 - x, y) = guide.at(x, y);
  const uint32_t sentinel = std::numeric_limits<uint32_t>::max() / 2;
  golden::PathAggregator<uint32_t> path180(cfg, width, sentinel, 8), path0(mirrored_cfg, width, sentinel, 8);
  std::vector<uint32_t> cost(size_t(width) * dmax), mirrored_cost(cost.size()), sum(cost.size()), mirrored_sum(cost.size());
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x)
      for (int d = 0; d < dmax; ++d) {
        const uint32_t c = uint32_t(rng() % 49);
        cost[size_t(x * dmax + d)] = c;
        mirrored_cost[size_t((width - 1 - x) * dmax + d)] = c;
      }
    path180.push_row(y, cost.data(), sum.data(), guide);
    path0.push_row(y, mirrored_cost.data(), mirrored_sum.data(), mirrored_guide);
    for (int x = 0; x < width; ++x)
      for (int d = 0; d < dmax; ++d) {
        INFO("row " << y << " pixel " << x << " disparity " << d);
        REQUIRE(sum[size_t(x * dmax + d)] == mirrored_sum[size_t((width - 1 - x) * dmax + d)]);
      }
  }
}

TEST_CASE("the comparison reports the first mismatches with coordinates", "[models]") {
  DisparityImage a(4, 2, 3), b = a;
  b.at(2, 1) = 5;
  b.at(0, 0) = 128;
  const Comparison c = compare_words(a, b);
  CHECK(c.mismatches == 2);
  CHECK(c.report() == "2 mismatching pixels\n  (0, 0): expected 3, got 128\n  (2, 1): expected 3, got 5");
  CHECK(compare_words(a, a).equal());
  CHECK_FALSE(compare_words(a, DisparityImage(4, 3)).equal());
}
