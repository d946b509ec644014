#include "metrics.hpp"

#include <fmt/core.h>

#include <cmath>

#include "gap_fill.hpp"
#include "image_io.hpp"

namespace fpstereo {
namespace {

bool has_value(float d) { return std::isfinite(d); }

double percent(int64_t part, int64_t whole) { return whole > 0 ? 100.0 * double(part) / double(whole) : NAN; }

// Copies the first valid value of column x (walking from `from` by `step`) over the invalid
// pixels before it: the column pass of the devkit's interpolation, one direction.
void extrapolate_column(cv::Mat1f& disp, int x, int from, int step) {
  for (int y = from; y >= 0 && y < disp.rows; y += step) {
    if (!has_value(disp(y, x))) continue;
    for (int fill = from; fill != y; fill += step) disp(fill, x) = disp(y, x);
    return;
  }
}

void require_same_size(const cv::Mat& a, const cv::Mat& b, const char* what_b) {
  if (a.size() != b.size())
    throw InputError(
        fmt::format("estimate is {}x{} but the {} is {}x{}", a.cols, a.rows, what_b, b.cols, b.rows));
}

}  // namespace

cv::Mat1f kitti_fill(const cv::Mat1f& disp) {
  cv::Mat1f filled = disp.clone();
  for (int y = 0; y < filled.rows; ++y) fill_row_gaps(filled[y], filled.cols, has_value);
  for (int x = 0; x < filled.cols; ++x) {
    extrapolate_column(filled, x, 0, +1);
    extrapolate_column(filled, x, filled.rows - 1, -1);
  }
  return filled;
}

double ErrorCounts::d1_percent() const { return percent(d1_outliers, estimated); }
double ErrorCounts::bad1_percent() const { return percent(bad1, estimated); }
double ErrorCounts::bad2_percent() const { return percent(bad2, estimated); }
double ErrorCounts::bad4_percent() const { return percent(bad4, estimated); }
double ErrorCounts::mae_px() const { return estimated > 0 ? abs_error_sum / double(estimated) : NAN; }
double ErrorCounts::density_percent() const { return percent(estimated, gt_pixels); }

ErrorCounts& ErrorCounts::operator+=(const ErrorCounts& o) {
  gt_pixels += o.gt_pixels;
  estimated += o.estimated;
  d1_outliers += o.d1_outliers;
  bad1 += o.bad1;
  bad2 += o.bad2;
  bad4 += o.bad4;
  abs_error_sum += o.abs_error_sum;
  return *this;
}

ErrorCounts count_errors(const cv::Mat1f& est, const cv::Mat1f& gt, const cv::Mat1b* mask) {
  require_same_size(est, gt, "ground truth");
  if (mask) require_same_size(est, *mask, "mask");
  ErrorCounts c;
  for (int y = 0; y < gt.rows; ++y)
    for (int x = 0; x < gt.cols; ++x) {
      const float truth = gt(y, x), estimate = est(y, x);
      if (!has_value(truth) || (mask && (*mask)(y, x) != 255)) continue;
      ++c.gt_pixels;
      if (!has_value(estimate)) continue;
      ++c.estimated;
      const double err = std::abs(double(estimate) - double(truth));
      c.d1_outliers += err > 3.0 && err > 0.05 * std::abs(double(truth));
      c.bad1 += err > 1.0;
      c.bad2 += err > 2.0;
      c.bad4 += err > 4.0;
      c.abs_error_sum += err;
    }
  return c;
}

}  // namespace fpstereo
