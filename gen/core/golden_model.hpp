// The golden model: bit-exact, integer-only, row-streaming reference of the whole pipeline.
// Its behaviour is specified in docs/semantics.md; RTL and HLS outputs must equal it.
#pragma once

#include "config.hpp"
#include "image.hpp"

namespace fpstereo {

// What a run writes besides the output words, where the caller asks for it: the right view's
// words, the match side's whole disparities (needs a left-right check; docs/semantics.md
// section 5, "Right view"), and each base pixel's confidence (section 4, "Confidence").
struct SideViews {
  DisparityImage* right = nullptr;
  DisparityImage* confidence = nullptr;
};

// Runs the full pipeline. Images must be width x height of the run (at most the configured
// size); cfg must be valid. Returns output words (docs/semantics.md, "Output word"). threads:
// how many threads the frame may use (its paths are shared among them); the output is the same
// for any number.
DisparityImage run_golden(const StereoConfig& cfg, const GrayImage& left, const GrayImage& right,
                          const SideViews& side = {}, int threads = 1);

}  // namespace fpstereo
