#include "sgbm_baseline.hpp"

#include <fmt/core.h>

#include <opencv2/calib3d.hpp>

#include "image_io.hpp"
#include "text.hpp"

namespace fpstereo {
namespace {

constexpr int kMaxSgbmBlock = 255;

int opencv_mode(const std::string& mode) {
  if (mode == "sgbm") return cv::StereoSGBM::MODE_SGBM;
  if (mode == "3way") return cv::StereoSGBM::MODE_SGBM_3WAY;
  if (mode == "hh") return cv::StereoSGBM::MODE_HH;
  if (mode == "hh4") return cv::StereoSGBM::MODE_HH4;
  throw InputError(fmt::format("sgbm-mode = {}: expected sgbm, 3way, hh or hh4", quoted(mode)));
}

// The defaults OpenCV's documentation recommends for one channel: 8 and 32 times the block area.
int resolved_p1(const SgbmOptions& o) { return o.p1 >= 0 ? o.p1 : 8 * o.block * o.block; }
int resolved_p2(const SgbmOptions& o) { return o.p2 >= 0 ? o.p2 : 32 * o.block * o.block; }
int rounded_disparities(const SgbmOptions& o) { return (o.num_disparities + 15) / 16 * 16; }

void check_at_least(const char* name, int value, int minimum) {
  if (value < minimum) throw InputError(fmt::format("{} = {}: must be at least {}", name, value, minimum));
}

cv::Mat1b to_mat(const GrayImage& image) {
  // cv::Mat wraps the pixels without copying; StereoSGBM only reads them.
  return cv::Mat1b(image.height, image.width, const_cast<uint8_t*>(image.pixels.data()));
}

}  // namespace

void validate(const SgbmOptions& o) {
  opencv_mode(o.mode);
  // OpenCV needs an odd block; 255 bounds 32 * block^2 (the default P2) well inside an int.
  if (o.block < 1 || o.block > kMaxSgbmBlock || o.block % 2 == 0)
    throw InputError(fmt::format("sgbm-block = {}: must be an odd number from 1 to {}", o.block, kMaxSgbmBlock));
  check_at_least("sgbm-p1", o.p1, -1);
  check_at_least("sgbm-p2", o.p2, -1);
  // OpenCV would silently raise P2 to P1 + 1; an explicit error is clearer.
  if (resolved_p2(o) <= resolved_p1(o))
    throw InputError(fmt::format("sgbm-p2 = {}: must exceed P1 ({})", resolved_p2(o), resolved_p1(o)));
  if (o.uniqueness < 0 || o.uniqueness > 99)
    throw InputError(fmt::format("sgbm-uniqueness = {}: must be a percentage in 0 .. 99", o.uniqueness));
  check_at_least("sgbm-speckle-window", o.speckle_window, 0);
  check_at_least("sgbm-speckle-range", o.speckle_range, 0);
  check_at_least("sgbm-prefilter-cap", o.prefilter_cap, 1);
  check_at_least("sgbm numDisparities", o.num_disparities, 1);
}

cv::Mat1f run_sgbm(const GrayImage& left, const GrayImage& right, const SgbmOptions& o) {
  validate(o);
  auto sgbm = cv::StereoSGBM::create(o.min_disparity, rounded_disparities(o), o.block, resolved_p1(o), resolved_p2(o),
                                     o.disp12_max_diff, o.prefilter_cap, o.uniqueness, o.speckle_window,
                                     o.speckle_range, opencv_mode(o.mode));
  cv::Mat fixed_point;  // CV_16S, disparity * 16; (minDisparity - 1) * 16 where invalid
  sgbm->compute(to_mat(left), to_mat(right), fixed_point);
  cv::Mat1f disp;
  fixed_point.convertTo(disp, CV_32F, 1.0 / 16.0);
  disp.setTo(NAN, disp < float(o.min_disparity));
  return disp;
}

std::string describe(const SgbmOptions& o) {
  return fmt::format(
      "OpenCV {} StereoSGBM: mode={} block={} P1={} P2={} minDisparity={} numDisparities={} uniqueness={} disp12MaxDiff={} "
      "speckleWindow={} speckleRange={} preFilterCap={}",
      CV_VERSION, o.mode, o.block, resolved_p1(o), resolved_p2(o), o.min_disparity, rounded_disparities(o),
      o.uniqueness, o.disp12_max_diff, o.speckle_window, o.speckle_range, o.prefilter_cap);
}

}  // namespace fpstereo
