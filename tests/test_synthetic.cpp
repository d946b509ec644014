// Synthetic pairs whose disparity is known by construction (tests/test_support.hpp): the
// expected output comes from the construction, not from the model.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "golden_model.hpp"
#include "test_support.hpp"
#include "widths.hpp"

using namespace fpstereo;

namespace {

StereoConfig small_config(const char* cost, int width, int height) {
  StereoConfig c;
  set_param(c, "cost", cost);
  c.window = 5;
  c.shd_window = 3;
  c.dmax = 32;
  c.uf = 8;
  c.width = width;
  c.height = height;
  c.median = 0;
  return c;
}

// Pixels in [x_lo, x_hi) x [y_lo, y_hi) whose output differs from truth(x, y).
template <class Truth>
int wrong_pixels(const DisparityImage& out, int x_lo, int x_hi, int y_lo, int y_hi, Truth truth) {
  int wrong = 0;
  for (int y = y_lo; y < y_hi; ++y)
    for (int x = x_lo; x < x_hi; ++x) wrong += out.at(x, y) != truth(x, y);
  return wrong;
}

const char* const kCosts[] = {"census", "rank", "sad", "zsad", "shd"};

// Where a path enters a textured region from one where the true disparity has no match (the
// left border strip x < d, an occlusion), SGM keeps the old disparity for a few pixels, until the
// new one's cost advantage outgrows the P2 jump (86 here against cost gaps of ~10 per pixel).
constexpr int kSettle = 16;

// Rank values take only N*N levels, so on noise a wrong disparity often costs as little as the
// right one; single-path aggregation then errs now and then. Other costs must be exact.
int allowed_errors(const std::string& cost, int pixels) { return cost == "rank" ? pixels / 50 : 0; }

}  // namespace

TEST_CASE("a textured fronto-parallel plane is recovered exactly", "[synthetic]") {
  std::mt19937 rng(11);
  for (const char* cost : kCosts)
    for (const char* paths : {"0", "45", "90", "135", "all"})
      for (int d0 : {0, 7, 19}) {
        if (std::string(cost) == "rank" && std::string(paths) != "all") continue;  // see allowed_errors
        StereoConfig cfg = small_config(cost, 80, 24);
        set_param(cfg, "paths", paths);
        const auto [left, right] =
            test::shifted_pair(cfg.width, cfg.height, rng, [&](int, int) { return d0; });
        const DisparityImage out = run_golden(cfg, left, right);
        // Windows that see only matching texture and no zero border (at the border, census
        // codes of bright pixels saturate and tie), past the settling distance.
        const int r = cfg.window / 2 + (std::string(cost) == "shd" ? cfg.shd_window / 2 : 0);
        INFO(cost << " paths " << paths << " d0 " << d0);
        CHECK(wrong_pixels(out, d0 + r + kSettle, cfg.width - r, r, cfg.height - r,
                           [&](int, int) { return d0; }) == 0);
      }
}

TEST_CASE("the right view of a textured fronto-parallel plane is its disparity", "[synthetic]") {
  std::mt19937 rng(13);
  for (const char* lr : {"lr1", "lr2"})
    for (int d0 : {0, 7, 19}) {
      StereoConfig cfg = small_config("census", 80, 24);
      set_param(cfg, "lr", lr);
      const auto [left, right] = test::shifted_pair(cfg.width, cfg.height, rng, [&](int, int) { return d0; });
      const DisparityImage right_view = run_golden(cfg, left, right, {Plane::Right}).at(Plane::Right);
      // Right pixel x' matches left pixel x' + d0; away from the borders and past the settling
      // distance of the paths from the left.
      const int r = cfg.window / 2;
      INFO(lr << " d0 " << d0);
      CHECK(wrong_pixels(right_view, r + kSettle, cfg.width - d0 - r, r, cfg.height - r,
                         [&](int, int) { return d0; }) == 0);
    }
}

TEST_CASE("a disparity step is recovered away from the edge and its occlusion", "[synthetic]") {
  std::mt19937 rng(12);
  const int near = 14, far = 4, edge = 48;
  for (const char* cost : kCosts) {
    StereoConfig cfg = small_config(cost, 96, 24);
    const auto [left, right] =
        test::shifted_pair(cfg.width, cfg.height, rng, [&](int x, int) { return x < edge ? far : near; });
    const DisparityImage out = run_golden(cfg, left, right);
    const int margin = kSettle;
    INFO(cost);
    CHECK(wrong_pixels(out, far + margin, edge - margin, 0, cfg.height, [&](int, int) { return far; }) == 0);
    // Left of x = edge + (near - far) the near surface hides what the right camera sees.
    CHECK(wrong_pixels(out, edge + (near - far) + margin, cfg.width - margin, 0, cfg.height,
                       [&](int, int) { return near; }) == 0);
  }
}

TEST_CASE("a horizontal disparity step is recovered above and below the edge", "[synthetic]") {
  std::mt19937 rng(13);
  for (const char* cost : kCosts) {
    StereoConfig cfg = small_config(cost, 80, 40);
    const auto [left, right] =
        test::shifted_pair(cfg.width, cfg.height, rng, [](int, int y) { return y < 20 ? 6 : 17; });
    const DisparityImage out = run_golden(cfg, left, right);
    const int margin = kSettle;
    INFO(cost);
    const int region = (cfg.width - 17 - 2 * margin) * (20 - margin);
    CHECK(wrong_pixels(out, 17 + margin, cfg.width - margin, 0, 20 - margin, [](int, int) { return 6; }) <=
          allowed_errors(cost, region));
    CHECK(wrong_pixels(out, 17 + margin, cfg.width - margin, 20 + margin, cfg.height,
                       [](int, int) { return 17; }) <= allowed_errors(cost, region));
  }
}

TEST_CASE("a slanted plane is recovered within one pixel almost everywhere", "[synthetic]") {
  std::mt19937 rng(14);
  auto truth = [](int x, int) { return 3 + x / 8; };  // 3 .. 14 across 96 pixels
  for (const char* cost : kCosts) {
    StereoConfig cfg = small_config(cost, 96, 24);
    const auto [left, right] = test::shifted_pair(cfg.width, cfg.height, rng, truth);
    const DisparityImage out = run_golden(cfg, left, right);
    int far_off = 0, exact = 0, total = 0;
    for (int y = 0; y < cfg.height; ++y)
      for (int x = 24; x < cfg.width - cfg.window; ++x) {
        far_off += std::abs(int(out.at(x, y)) - truth(x, y)) > 1;
        exact += out.at(x, y) == truth(x, y);
        ++total;
      }
    INFO(cost << ": " << exact << " of " << total << " exact");
    CHECK(far_off <= total / 100);
    CHECK(exact >= total * 9 / 10);
  }
}

TEST_CASE("the left-right check invalidates occluded pixels and keeps matched ones", "[synthetic]") {
  std::mt19937 rng(15);
  const int near = 14, far = 4, edge = 48;
  for (const char* lr : {"lr1", "lr2"}) {
    StereoConfig cfg = small_config("census", 96, 24);
    set_param(cfg, "lr", lr);
    const auto [left, right] =
        test::shifted_pair(cfg.width, cfg.height, rng, [&](int x, int) { return x < edge ? far : near; });
    const DisparityImage out = run_golden(cfg, left, right);
    const uint16_t invalid = derive_widths(cfg).invalid_word;
    int occluded_invalid = 0, occluded = 0;
    for (int y = 0; y < cfg.height; ++y)
      for (int x = edge + 2; x < edge + (near - far) - 2; ++x) {  // seen by the left camera only
        occluded_invalid += out.at(x, y) == invalid;
        ++occluded;
      }
    const int margin = kSettle;
    INFO(lr << ": " << occluded_invalid << " of " << occluded << " occluded pixels invalid");
    CHECK(occluded_invalid * 2 > occluded);
    CHECK(wrong_pixels(out, far + margin, edge - margin, 0, cfg.height, [&](int, int) { return far; }) == 0);
    CHECK(wrong_pixels(out, edge + (near - far) + margin, cfg.width - margin, 0, cfg.height,
                       [&](int, int) { return near; }) == 0);
    // Pixels in the left border strip (x < dmax) whose match lies left of the image are invalid.
    CHECK(out.at(2, 5) == invalid);
  }
}

TEST_CASE("gap interpolation fills invalid runs with the smaller neighbour", "[synthetic]") {
  std::mt19937 rng(16);
  StereoConfig cfg = small_config("census", 96, 24);
  cfg.lr = LrCheck::Lr2;
  const int near = 14, far = 4, edge = 48;
  const auto [left, right] =
      test::shifted_pair(cfg.width, cfg.height, rng, [&](int x, int) { return x < edge ? far : near; });
  cfg.gap_interpolation = true;
  const DisparityImage out = run_golden(cfg, left, right);
  const uint16_t invalid = derive_widths(cfg).invalid_word;
  // The occlusion sits between the far and the near surface: the smaller (background) side
  // fills it, never the foreground.
  for (int y = 0; y < cfg.height; ++y)
    for (int x = edge + 2; x < edge + (near - far) - 2; ++x) {
      INFO("(" << x << ", " << y << ")");
      CHECK(out.at(x, y) != invalid);
      CHECK(out.at(x, y) < near);
    }
}

// A smooth texture seen with a disparity that is not whole: the right image samples the left
// one's continuous pattern at x + 7.3 (so the true disparity is 7.3 everywhere). Whole-pixel
// output errs by 0.3 px; sub-pixel output must come closer with either fit, and with SAD (whose
// costs vary smoothly with the shift) much closer. Census codes change in steps, so its fit gains
// less.
TEST_CASE("sub-pixel output recovers a fractional shift better than whole pixels", "[synthetic][subpixel]") {
  const int width = 96, height = 24;
  const double shift = 7.3;
  auto pattern = [](double x, int y) {
    return 128.0 + 50.0 * std::sin(0.61 * x + 0.9 * y) + 40.0 * std::sin(0.23 * x - 0.4 * y) +
           25.0 * std::cos(1.13 * x + 0.17 * y);
  };
  GrayImage left(width, height), right(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      left.at(x, y) = uint8_t(std::lround(pattern(x, y)));
      right.at(x, y) = uint8_t(std::lround(pattern(x + shift, y)));
    }
  auto mean_error = [&](const StereoConfig& cfg) {
    const DisparityImage out = run_golden(cfg, left, right);
    const Widths w = derive_widths(cfg);
    double sum = 0;
    int count = 0;
    for (int y = 4; y < height - 4; ++y)
      for (int x = 24; x < width - 4; ++x) {
        REQUIRE(out.at(x, y) != w.invalid_word);
        sum += std::abs(double(out.at(x, y)) / double(1 << cfg.subpixel_bits) - shift);
        ++count;
      }
    return sum / count;
  };
  for (const char* cost : {"sad", "census"}) {
    StereoConfig cfg = small_config(cost, width, height);
    const double whole = mean_error(cfg);
    CHECK(whole == Approx(0.3).margin(0.01));  // every interior pixel at 7
    cfg.subpixel_bits = 4;
    for (SubpixelFit fit : {SubpixelFit::Equiangular, SubpixelFit::Parabola}) {
      cfg.subpixel_fit = fit;
      const double fine = mean_error(cfg);
      INFO(cost << ", " << to_string(fit) << ": mean error " << fine << " px against " << whole << " whole");
      CHECK(fine < (std::string(cost) == "sad" ? 0.4 : 0.75) * whole);
    }
  }
}

TEST_CASE("confidence: high on a unique match, low where a periodic texture repeats", "[synthetic]") {
  std::mt19937 rng(14);
  // The vertical path alone: a path from the left would remember the border strip x < d, where
  // larger disparities cost Cmax, and prefer the smaller of equal matches ever after.
  StereoConfig cfg = small_config("census", 96, 24);
  set_param(cfg, "paths", "90");
  const int d0 = 9, r = cfg.window / 2;
  // Mean confidence away from the borders, where every disparity of the range has a match pixel.
  auto mean_confidence = [&](const GrayImage& left, const GrayImage& right) {
    const DisparityImage confidence = run_golden(cfg, left, right, {Plane::Confidence}).at(Plane::Confidence);
    double sum = 0;
    int n = 0;
    for (int y = r; y < cfg.height - r; ++y)
      for (int x = cfg.dmax + r; x < cfg.width - r; ++x, ++n) sum += confidence.at(x, y);
    return sum / n;
  };
  const auto [left, right] = test::shifted_pair(cfg.width, cfg.height, rng, [&](int, int) { return d0; });
  // Columns repeating every 6 pixels: disparities d0 - 6 and d0 + 6 match as well as d0.
  GrayImage periodic_right = test::random_image(cfg.width, cfg.height, rng);
  for (int y = 0; y < cfg.height; ++y)
    for (int x = 6; x < cfg.width; ++x) periodic_right.at(x, y) = periodic_right.at(x - 6, y);
  GrayImage periodic_left = periodic_right;
  for (int y = 0; y < cfg.height; ++y)
    for (int x = 0; x < cfg.width; ++x) periodic_left.at(x, y) = periodic_right.at(std::max(0, x - d0), y);
  const double unique = mean_confidence(left, right), repeated = mean_confidence(periodic_left, periodic_right);
  INFO("unique " << unique << ", repeated " << repeated);
  CHECK(unique > 128);
  CHECK(repeated < 16);
}

TEST_CASE("a negative disparity is found with min-disp, and the words count from it", "[synthetic]") {
  std::mt19937 rng(15);
  for (const char* cost : {"census", "sad"})
    for (int m : {-20, -4, 3}) {
      StereoConfig cfg = small_config(cost, 80, 24);
      cfg.min_disp = m;
      const int d0 = m + 11;  // the true disparity, index 11 of the range
      const auto [left, right] = test::shifted_pair(cfg.width, cfg.height, rng, [&](int, int) { return d0; });
      const DisparityImage out = run_golden(cfg, left, right);
      const int r = cfg.window / 2;
      // Away from the borders where the match pixel x - d0 leaves the row, and past the settling
      // distance of the paths from the left.
      INFO(cost << " min-disp " << m);
      CHECK(wrong_pixels(out, std::max(0, d0) + r + kSettle, cfg.width - std::max(0, -d0) - r, r, cfg.height - r,
                         [&](int, int) { return 11; }) == 0);
    }
}
