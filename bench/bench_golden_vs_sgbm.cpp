// Times the golden model (C2: census 7x7, dmax 128, 4 paths, median 5) against OpenCV's
// StereoSGBM (MODE_SGBM, blockSize 5, 128 disparities) on the same 1242x375 pair, both on one
// thread, and prints the ratio (target: at most 0.5); then the golden model's speed-up on two
// threads over one, with the outputs compared, beside what two cores give at the time (two
// frames at once, one per thread: on a shared VM the second core's worth varies); A6, whose LR2
// check keeps the threads to path groups, on one and two threads; and C2 with the 180-degree path
// as a fifth path, against C2. The runs alternate, so a change in the machine's load reaches all
// of them alike.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <opencv2/core/utility.hpp>
#include <random>
#include <thread>
#include <vector>

#include "golden_model.hpp"
#include "image_io.hpp"
#include "sgbm_baseline.hpp"

using namespace fpstereo;

namespace {

double time_ms(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
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
  StereoConfig with_180 = cfg;
  with_180.paths = kEveryPath;
  SgbmOptions sgbm;
  sgbm.mode = "sgbm";
  sgbm.block = 5;
  sgbm.num_disparities = cfg.dmax;

  const int runs = 9;
  const DisparityImage one_thread = run_golden(cfg, left, right);  // also the warm-up
  run_sgbm(left, right, sgbm);
  if (!(run_golden(cfg, left, right, 2) == one_thread)) {
    fmt::print(stderr, "bench: the golden model's output on two threads differs from one thread's\n");
    return 1;
  }
  const StereoConfig a6 = preset("A6");
  if (!(run_golden(a6, left, right, 2) == run_golden(a6, left, right))) {
    fmt::print(stderr, "bench: A6's output on two threads differs from one thread's\n");
    return 1;
  }
  run_golden(with_180, left, right);
  std::vector<double> golden_ms, golden2_ms, two_frames_ms, opencv_ms, a6_ms, a6_2_ms, golden180_ms;
  for (int i = 0; i < runs; ++i) {
    golden_ms.push_back(time_ms([&] { run_golden(cfg, left, right); }));
    opencv_ms.push_back(time_ms([&] { run_sgbm(left, right, sgbm); }));
    golden2_ms.push_back(time_ms([&] { run_golden(cfg, left, right, 2); }));
    two_frames_ms.push_back(time_ms([&] {
      std::thread other([&] { run_golden(cfg, left, right); });
      run_golden(cfg, left, right);
      other.join();
    }));
    a6_ms.push_back(time_ms([&] { run_golden(a6, left, right); }));
    a6_2_ms.push_back(time_ms([&] { run_golden(a6, left, right, 2); }));
    golden180_ms.push_back(time_ms([&] { run_golden(with_180, left, right); }));
  }
  const double golden = median(golden_ms), opencv = median(opencv_ms), golden2 = median(golden2_ms),
               two_frames = median(two_frames_ms), golden180 = median(golden180_ms);
  fmt::print("pair: {} ({}x{}), median of {} runs\n", left_path, left.width, left.height, runs);
  fmt::print("golden model (C2: census 7x7, dmax 128, 4 paths, median 5), 1 thread: {:8.1f} ms\n", golden);
  fmt::print("OpenCV StereoSGBM (MODE_SGBM, block 5, 128 disparities), 1 thread:   {:8.1f} ms\n", opencv);
  fmt::print("ratio golden / OpenCV: {:.2f} (target <= 0.50)\n", golden / opencv);
  fmt::print("golden model, 2 threads: {:8.1f} ms, speed-up over 1 thread {:.2f} (same output)\n", golden2,
             golden / golden2);
  fmt::print("two frames at once on two threads: {:8.1f} ms, {:.2f} times one thread's throughput "
             "(what the second core gives now)\n", two_frames, 2 * golden / two_frames);
  fmt::print("A6 (LR2, speckle filter), 1 thread {:8.1f} ms, 2 threads {:8.1f} ms, speed-up {:.2f} (same output)\n",
             median(a6_ms), median(a6_2_ms), median(a6_ms) / median(a6_2_ms));
  fmt::print("golden model, C2 with the 180-degree path (5 paths), 1 thread: {:8.1f} ms, ratio to OpenCV {:.2f}, "
             "to C2 {:.2f}\n", golden180, golden180 / opencv, golden180 / golden);
  return 0;
}
