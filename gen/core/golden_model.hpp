// The golden model: bit-exact, integer-only, row-streaming reference of the whole pipeline.
// Its behaviour is specified in docs/semantics.md; RTL and HLS outputs must equal it.
#pragma once

#include "config.hpp"
#include "image.hpp"

namespace fpstereo {

// Runs the full pipeline. Images must be width x height of the run (at most the configured
// size); cfg must be valid. Returns output words (docs/semantics.md, "Output word"). With
// right_view, which needs a left-right check, also the right view's words: the match side's
// whole disparities (section 5, "Right view").
DisparityImage run_golden(const StereoConfig& cfg, const GrayImage& left, const GrayImage& right,
                          DisparityImage* right_view = nullptr);

}  // namespace fpstereo
