// Accuracy metrics and KITTI background filling on small hand-made maps (gen/io/metrics.hpp).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "image_io.hpp"
#include "metrics.hpp"

using namespace fpstereo;

namespace {

const float kNaN = NAN;

cv::Mat1f map_of(int rows, int cols, const std::vector<float>& values) {
  cv::Mat1f m(rows, cols);
  std::copy(values.begin(), values.end(), m.begin());
  return m;
}

// Element-wise equality where NaN equals NaN (NaN marks "no value").
bool same_map(const cv::Mat1f& a, const cv::Mat1f& b) {
  if (a.size() != b.size()) return false;
  for (int y = 0; y < a.rows; ++y)
    for (int x = 0; x < a.cols; ++x)
      if (!(a(y, x) == b(y, x) || (std::isnan(a(y, x)) && std::isnan(b(y, x))))) return false;
  return true;
}

// Ground truth and estimate, 4 wide x 3 high. Per pixel: GT -> estimate, |err|, what it counts as.
//   (0,0) 100 -> 104   4    bad-1, bad-2; NOT D1 (4 > 3 px but 4 <= 5 % of 100); NOT bad-4 (4 > 4 false)
//   (1,0) 100 -> 100   0
//   (2,0)  10 -> 14    4    D1 (4 > 3 px and 4 > 5 % of 10 = 0.5), bad-1, bad-2
//   (3,0)  10 -> NaN        no estimate: density only
//   (0,1)  50 -> 51.5  1.5  bad-1
//   (1,1) NaN -> 7          no GT: not counted at all
//   (2,1)  20 -> 20.5  0.5
//   (3,1)  20 -> NaN        no estimate
//   (0,2)  30 -> 35    5    D1 (5 > 3 and 5 > 1.5), bad-1, bad-2, bad-4
//   (1,2)  30 -> 28    2    bad-1 (2 > 1); NOT bad-2 (2 > 2 false)
//   (2,2)  40 -> 40    0
//   (3,2)  40 -> 43    3    bad-1, bad-2; NOT D1 (3 > 3 false)
// GT pixels 11, estimated 9, D1 2, bad-1 6, bad-2 4, bad-4 1, sum |err| = 4+4+1.5+0.5+5+2+3 = 20.
const cv::Mat1f kGt = map_of(3, 4, {100, 100, 10, 10, 50, kNaN, 20, 20, 30, 30, 40, 40});
const cv::Mat1f kEst = map_of(3, 4, {104, 100, 14, kNaN, 51.5f, 7, 20.5f, kNaN, 35, 28, 40, 43});

}  // namespace

TEST_CASE("count_errors counts every metric over GT pixels", "[metrics]") {
  const ErrorCounts c = count_errors(kEst, kGt);
  CHECK(c.gt_pixels == 11);
  CHECK(c.estimated == 9);
  CHECK(c.d1_outliers == 2);
  CHECK(c.bad1 == 6);
  CHECK(c.bad2 == 4);
  CHECK(c.bad4 == 1);
  CHECK(c.abs_error_sum == Approx(20.0));
  // Rates are over the 9 estimated pixels; density over the 11 GT pixels.
  CHECK(c.d1_percent() == Approx(200.0 / 9));
  CHECK(c.bad1_percent() == Approx(600.0 / 9));
  CHECK(c.bad2_percent() == Approx(400.0 / 9));
  CHECK(c.bad4_percent() == Approx(100.0 / 9));
  CHECK(c.mae_px() == Approx(20.0 / 9));
  CHECK(c.density_percent() == Approx(900.0 / 11));
}

TEST_CASE("D1 needs both the 3 px and the 5 % condition", "[metrics]") {
  // A 4 px error on a 100 px GT is within 5 %; the same error on a 10 px GT is 40 %.
  CHECK(count_errors(map_of(1, 1, {104}), map_of(1, 1, {100})).d1_outliers == 0);
  CHECK(count_errors(map_of(1, 1, {14}), map_of(1, 1, {10})).d1_outliers == 1);
  // 3 px on a small GT: above 5 % but not above 3 px.
  CHECK(count_errors(map_of(1, 1, {13}), map_of(1, 1, {10})).d1_outliers == 0);
}

TEST_CASE("count_errors evaluates only where the mask is 255", "[metrics]") {
  // Row 0 in, row 1 out, row 2 in except (3,2) whose 128 is not 255.
  cv::Mat1b mask = (cv::Mat1b(3, 4) << 255, 255, 255, 255, 0, 0, 0, 0, 255, 255, 255, 128);
  const ErrorCounts c = count_errors(kEst, kGt, &mask);
  // Remaining pixels: (0,0) 4, (1,0) 0, (2,0) 4 D1, (3,0) no estimate, (0,2) 5 D1, (1,2) 2, (2,2) 0.
  CHECK(c.gt_pixels == 7);
  CHECK(c.estimated == 6);
  CHECK(c.d1_outliers == 2);
  CHECK(c.bad1 == 4);  // 4, 4, 5, 2
  CHECK(c.bad2 == 3);  // 4, 4, 5
  CHECK(c.bad4 == 1);  // 5
  CHECK(c.abs_error_sum == Approx(15.0));
}

TEST_CASE("ErrorCounts pool by summing counts", "[metrics]") {
  ErrorCounts total = count_errors(kEst, kGt);
  total += count_errors(map_of(1, 2, {kNaN, 10}), map_of(1, 2, {5, 20}));  // 2 GT, 1 estimate, err 10
  CHECK(total.gt_pixels == 13);
  CHECK(total.estimated == 10);
  CHECK(total.d1_outliers == 3);
  CHECK(total.bad4 == 2);
  CHECK(total.mae_px() == Approx(30.0 / 10));
}

TEST_CASE("rates without pixels are NaN, not a division by zero", "[metrics]") {
  const ErrorCounts none = count_errors(map_of(1, 2, {1, 2}), map_of(1, 2, {kNaN, kNaN}));
  CHECK(none.gt_pixels == 0);
  CHECK(std::isnan(none.d1_percent()));
  CHECK(std::isnan(none.mae_px()));
  CHECK(std::isnan(none.density_percent()));
  const ErrorCounts no_estimate = count_errors(map_of(1, 1, {kNaN}), map_of(1, 1, {3}));
  CHECK(no_estimate.density_percent() == 0.0);
  CHECK(std::isnan(no_estimate.bad1_percent()));
}

TEST_CASE("count_errors rejects maps of different sizes", "[metrics]") {
  CHECK_THROWS_AS(count_errors(map_of(1, 2, {1, 2}), map_of(2, 1, {1, 2})), InputError);
  const cv::Mat1b small_mask(1, 1, uchar(255));
  CHECK_THROWS_AS(count_errors(map_of(1, 2, {1, 2}), map_of(1, 2, {1, 2}), &small_mask), InputError);
}

TEST_CASE("kitti_fill: an interior run takes the smaller bounding value", "[metrics]") {
  // 5 | NaN NaN | 3 8  ->  min(5, 3) = 3 fills the run.
  CHECK(same_map(kitti_fill(map_of(1, 5, {5, kNaN, kNaN, 3, 8})), map_of(1, 5, {5, 3, 3, 3, 8})));
}

TEST_CASE("kitti_fill: row ends take their one valid neighbour", "[metrics]") {
  // NaN | 4 | NaN | 6 | NaN  ->  left end 4, interior min(4, 6) = 4, right end 6.
  CHECK(same_map(kitti_fill(map_of(1, 5, {kNaN, 4, kNaN, 6, kNaN})), map_of(1, 5, {4, 4, 4, 6, 6})));
}

TEST_CASE("kitti_fill: all-invalid rows at the top and bottom copy the nearest valid row", "[metrics]") {
  // Row pass: row 1 NaN 7 NaN 9 becomes 7 7 7 9 (left end 7, interior min(7, 9) = 7); rows 0
  // and 2 are all invalid and stay so, then the column pass copies row 1 up and down.
  const cv::Mat1f disp = map_of(3, 4, {kNaN, kNaN, kNaN, kNaN, kNaN, 7, kNaN, 9, kNaN, kNaN, kNaN, kNaN});
  const cv::Mat1f expected = map_of(3, 4, {7, 7, 7, 9, 7, 7, 7, 9, 7, 7, 7, 9});
  CHECK(same_map(kitti_fill(disp), expected));
  CHECK(std::isnan(disp(0, 0)));  // the input is left as it was
}

TEST_CASE("kitti_fill: an all-invalid row between valid rows stays invalid", "[metrics]") {
  // The devkit extrapolates columns only above the first and below the last valid pixel.
  const cv::Mat1f disp = map_of(3, 2, {1, 2, kNaN, kNaN, 3, 4});
  CHECK(same_map(kitti_fill(disp), disp));
}

TEST_CASE("kitti_fill: an all-invalid map stays all invalid", "[metrics]") {
  const cv::Mat1f disp(3, 4, kNaN);
  CHECK(same_map(kitti_fill(disp), disp));
}

TEST_CASE("filled metrics reach full density", "[metrics]") {
  const ErrorCounts filled = count_errors(kitti_fill(kEst), kGt);
  CHECK(filled.estimated == filled.gt_pixels);
  CHECK(filled.density_percent() == Approx(100.0));
}
