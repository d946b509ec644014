#include "pair_eval.hpp"

#include <fmt/core.h>

#include "golden_model.hpp"
#include "image_io.hpp"
#include "text.hpp"

namespace fpstereo {
namespace {

cv::Mat1f read_gt(const std::string& path, const PairInputs& in) {
  cv::Mat1f gt = read_disparity(path, in.pair.gt_scale, in.pair.gt_invalid);
  if (gt.cols != in.left.width || gt.rows != in.left.height)
    throw InputError(fmt::format("ground truth {} is {}x{} but the images are {}x{}", quoted(path), gt.cols,
                                 gt.rows, in.left.width, in.left.height));
  return gt;
}

cv::Mat1b read_mask(const std::string& path, const PairInputs& in) {
  const GrayImage mask = load_gray(path, "noc mask");
  if (mask.width != in.left.width || mask.height != in.left.height)
    throw InputError(fmt::format("noc mask {} is {}x{} but the images are {}x{}", quoted(path), mask.width,
                                 mask.height, in.left.width, in.left.height));
  return cv::Mat1b(mask.height, mask.width, const_cast<uint8_t*>(mask.pixels.data())).clone();
}

std::optional<ErrorCounts> score_region(const cv::Mat1f& est, const std::optional<Region>& region) {
  if (!region) return std::nullopt;
  return count_errors(est, region->gt, region->mask.empty() ? nullptr : &region->mask);
}

}  // namespace

StereoConfig config_for_pair(const StereoConfig& cfg, const PairInputs& in) {
  StereoConfig run = cfg;
  run.width = in.left.width;
  run.height = in.left.height;
  run.ppc = 1;  // the hardware's beats: the models ignore them, and a pair's width need not be whole beats
  try {
    check_pair(in.left, in.right, run);
    validate(run);
  } catch (const std::runtime_error& e) {
    throw InputError(fmt::format("pair {}: {}", quoted(in.pair.name), e.what()));
  }
  return run;
}

PairInputs load_pair(const DatasetPair& pair, const StereoConfig& cfg) {
  PairInputs in;
  in.pair = pair;
  in.left = load_gray(pair.left, "left image");
  in.right = load_gray(pair.right, "right image");
  in.cfg = config_for_pair(cfg, in);
  if (!pair.gt_occ.empty()) in.occ = Region{read_gt(pair.gt_occ, in), {}};
  const cv::Mat1b mask = pair.noc_mask.empty() ? cv::Mat1b() : read_mask(pair.noc_mask, in);
  if (!pair.gt_noc.empty())
    in.noc = Region{read_gt(pair.gt_noc, in), mask};
  else if (in.occ && !mask.empty())
    in.noc = Region{in.occ->gt, mask};
  return in;
}

cv::Mat1f golden_disparity(const PairInputs& in, int threads) {
  try {
    return to_float_disparity(run_golden(in.cfg, in.left, in.right, threads), in.cfg);
  } catch (const std::bad_alloc&) {
    throw InputError(fmt::format("pair {} ({}x{}): out of memory computing its disparities", quoted(in.pair.name),
                                 in.left.width, in.left.height));
  }
}

Scores score(const cv::Mat1f& est, const PairInputs& in) {
  return {score_region(est, in.occ), score_region(est, in.noc)};
}

void pool(std::optional<ErrorCounts>& total, const std::optional<ErrorCounts>& part) {
  if (total && part)
    *total += *part;
  else
    total.reset();
}

}  // namespace fpstereo
