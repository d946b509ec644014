// Accuracy of a disparity map against ground truth, KITTI and Middlebury style. Maps are
// cv::Mat1f in pixels; a non-finite value (NaN) means "no value" in estimates and ground truth.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

namespace fpstereo {

// The KITTI development kit's background interpolation: per row, every invalid run between two
// valid pixels takes the smaller of the two and runs at a row end take the one neighbour
// (fill_row_gaps); then per column, invalid pixels above the first / below the last valid one
// take its value. An all-invalid map, or an invalid row between valid ones, stays invalid.
cv::Mat1f kitti_fill(const cv::Mat1f& disp);

// Pixel counts over the evaluated pixels; sums, so that pairs can be pooled with +=.
// err = estimate - ground truth, only where both exist.
struct ErrorCounts {
  int64_t gt_pixels = 0;     // pixels with ground truth (inside the mask)
  int64_t estimated = 0;     // of those, pixels with a valid estimate
  int64_t d1_outliers = 0;   // estimated pixels with |err| > 3 px and |err| > 5 % of GT (KITTI D1)
  int64_t bad1 = 0;          // estimated pixels with |err| > 1 px
  int64_t bad2 = 0;          // estimated pixels with |err| > 2 px
  int64_t bad4 = 0;          // estimated pixels with |err| > 4 px
  double abs_error_sum = 0;  // sum of |err| over estimated pixels, in px

  // Rates over the estimated pixels (NaN if there are none), except density.
  double d1_percent() const;       // D1 outliers, % of estimated pixels
  double bad1_percent() const;     // |err| > 1 px, % of estimated pixels
  double bad2_percent() const;     // |err| > 2 px, % of estimated pixels
  double bad4_percent() const;     // |err| > 4 px, % of estimated pixels
  double mae_px() const;           // mean |err| over estimated pixels, px
  double density_percent() const;  // estimated pixels, % of GT pixels (NaN without GT)

  ErrorCounts& operator+=(const ErrorCounts& o);
};

// Counts over the pixels with finite ground truth (and mask == 255 where a mask is given).
// Invalid estimates count only towards density: on a raw estimate this gives the "valid-only"
// metrics, on kitti_fill(estimate) the "filled" ones. Throws InputError if sizes differ.
ErrorCounts count_errors(const cv::Mat1f& est, const cv::Mat1f& gt, const cv::Mat1b* mask = nullptr);

}  // namespace fpstereo
