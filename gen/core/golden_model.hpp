// The golden model: bit-exact, integer-only, row-streaming reference of the whole pipeline.
// Its behaviour is specified in docs/semantics.md; RTL and HLS outputs must equal it.
#pragma once

#include <vector>

#include "config.hpp"
#include "image.hpp"
#include "outputs.hpp"

namespace fpstereo {

// Runs the full pipeline and returns the planes asked for (outputs.hpp; each must be available to
// the configuration, else std::invalid_argument). Images must be width x height of the run (at
// most the configured size); cfg must be valid. threads: how many threads the frame may use (they
// share its rows by columns); the output is the same for any number.
Planes run_golden(const StereoConfig& cfg, const GrayImage& left, const GrayImage& right,
                  const std::vector<Plane>& planes, int threads = 1);
// The output words alone (docs/semantics.md, "Output word").
DisparityImage run_golden(const StereoConfig& cfg, const GrayImage& left, const GrayImage& right, int threads = 1);

}  // namespace fpstereo
