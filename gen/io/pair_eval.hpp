// One dataset pair loaded for scoring (images, ground truth, noc region) and the scores of a
// disparity map against it. Shared by `fpstereo eval` and `fpstereo dse`.
#pragma once

#include <opencv2/core.hpp>
#include <optional>

#include "config.hpp"
#include "dataset.hpp"
#include "image.hpp"
#include "metrics.hpp"

namespace fpstereo {

// Ground truth over one set of pixels: all pixels with GT (occ) or the non-occluded ones (noc).
struct Region {
  cv::Mat1f gt;
  cv::Mat1b mask;  // empty: every pixel with ground truth
};

// Everything a pair needs, loaded and checked before any model runs, so bad input fails fast.
struct PairInputs {
  DatasetPair pair;
  GrayImage left, right;
  StereoConfig cfg;  // the run's configuration: the pair's own image size
  std::optional<Region> occ, noc;
};

struct Scores {
  std::optional<ErrorCounts> occ, noc;
};

// The configured width/height are the hardware's maximum; accuracy does not depend on them, so
// every pair runs at its own size. Throws InputError naming the pair if `cfg` cannot run on it.
StereoConfig config_for_pair(const StereoConfig& cfg, const PairInputs& in);

// Loads and checks the images and ground truth. Throws InputError.
PairInputs load_pair(const DatasetPair& pair, const StereoConfig& cfg);

// The golden model's disparities of the pair, as floats (to_float_disparity); an allocation
// failure is an InputError naming the pair.
cv::Mat1f golden_disparity(const PairInputs& in, int threads = 1);

Scores score(const cv::Mat1f& est, const PairInputs& in);

// Adds `part` into `total`; a region missing from either leaves the total without it (a pool over
// a subset of the pairs would not be comparable).
void pool(std::optional<ErrorCounts>& total, const std::optional<ErrorCounts>& part);

}  // namespace fpstereo
