// Times the golden model (C2: census 7x7, dmax 128, 4 paths, median 5) against OpenCV's
// StereoSGBM (MODE_SGBM, blockSize 5, 128 disparities) on the same 1242x375 pair, both on one
// thread, and prints the ratio. Target: golden model time <= 2x OpenCV's.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <opencv2/core/utility.hpp>
#include <random>
#include <vector>

#include "golden_model.hpp"
#include "image_io.hpp"
#include "sgbm_baseline.hpp"

using namespace fpstereo;

namespace {

double median_ms(int runs, const std::function<void()>& work) {
  std::vector<double> ms;
  for (int i = 0; i < runs; ++i) {
    const auto start = std::chrono::steady_clock::now();
    work();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : FPSTEREO_SHARED_DATA "/stereo/kitti2015_training_subset";
  const std::string left_path = dir + "/left/000000_10.png", right_path = dir + "/right/000000_10.png";
  if (!std::filesystem::exists(left_path)) {
    fmt::print(stderr, "bench: KITTI pair not found at {} (pass the dataset folder as argument)\n", dir);
    return 2;
  }
  const GrayImage left = load_gray(left_path, "left image"), right = load_gray(right_path, "right image");
  cv::setNumThreads(1);

  const StereoConfig cfg = preset("C2");
  check_pair(left, right, cfg);
  SgbmOptions sgbm;
  sgbm.mode = "sgbm";
  sgbm.block = 5;
  sgbm.num_disparities = cfg.dmax;

  const int runs = 5;
  run_golden(cfg, left, right);  // warm-up
  run_sgbm(left, right, sgbm);
  const double golden_ms = median_ms(runs, [&] { run_golden(cfg, left, right); });
  const double opencv_ms = median_ms(runs, [&] { run_sgbm(left, right, sgbm); });
  fmt::print("pair: {} ({}x{}), median of {} runs, one thread\n", left_path, left.width, left.height, runs);
  fmt::print("golden model (C2: census 7x7, dmax 128, 4 paths, median 5): {:8.1f} ms\n", golden_ms);
  fmt::print("OpenCV StereoSGBM (MODE_SGBM, block 5, 128 disparities):     {:8.1f} ms\n", opencv_ms);
  fmt::print("ratio golden / OpenCV: {:.2f} (target <= 2.00)\n", golden_ms / opencv_ms);
  return 0;
}
