// A deliberately naive second implementation written straight from the paper's equations
// and docs/semantics.md: full cost volume, explicit path recursion, no shared code with the
// golden model. Used only to cross-check the golden model.
#pragma once

#include <vector>

#include "config.hpp"
#include "image.hpp"
#include "outputs.hpp"

namespace fpstereo {

// The planes asked for, as run_golden computes them.
Planes run_naive(const StereoConfig& cfg, const GrayImage& left, const GrayImage& right,
                 const std::vector<Plane>& planes = {Plane::Disparity});

}  // namespace fpstereo
