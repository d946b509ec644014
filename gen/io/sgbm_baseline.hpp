// OpenCV's StereoSGBM as an accuracy baseline, run on the same gray images as the pipeline.
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "image.hpp"

namespace fpstereo {

// cv::StereoSGBM parameters; eval sets min_disparity and num_disparities to the pipeline's range.
struct SgbmOptions {
  std::string mode = "sgbm";  // sgbm, 3way, hh or hh4
  int block = 5;              // odd block side
  int p1 = -1;                // -1: 8 * block^2
  int p2 = -1;                // -1: 32 * block^2
  int uniqueness = 10;        // percent
  int disp12_max_diff = 1;    // negative: no left-right check
  int speckle_window = 0;     // 0: no speckle filter
  int speckle_range = 2;
  int prefilter_cap = 63;
  int min_disparity = 0;
  int num_disparities = 128;  // rounded up to a multiple of 16
};

// Throws InputError naming the first bad option ("sgbm-block = 4: ...").
void validate(const SgbmOptions& o);

// Disparities in pixels (1/16 px steps), NaN where StereoSGBM found none. Validates `o` first.
cv::Mat1f run_sgbm(const GrayImage& left, const GrayImage& right, const SgbmOptions& o);

// One line with every parameter as OpenCV receives it (P1/P2 resolved, numDisparities rounded).
std::string describe(const SgbmOptions& o);

}  // namespace fpstereo
