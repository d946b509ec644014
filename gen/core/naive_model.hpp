// A deliberately naive second implementation written straight from the paper's equations
// and docs/semantics.md: full cost volume, explicit path recursion, no shared code with the
// golden model. Used only to cross-check the golden model.
#pragma once

#include <vector>

#include "config.hpp"
#include "image.hpp"
#include "outputs.hpp"

namespace fpstereo {

// The planes asked for, as run_golden computes them; threads: how many paths are aggregated at
// once (the output does not depend on it).
Planes run_naive(const StereoConfig& cfg, const GrayImage& left, const GrayImage& right,
                 const std::vector<Plane>& planes = {Plane::Disparity}, int threads = 1);

// Section 5a alone on a map of words (invalid: the invalid word), for the tests' hand-made maps.
void remove_speckles(DisparityImage& words, int size, int range, uint16_t invalid);

}  // namespace fpstereo
