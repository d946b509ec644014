// A deliberately naive second implementation written straight from the paper's equations
// and docs/semantics.md: full cost volume, explicit path recursion, no shared code with the
// golden model. Used only to cross-check the golden model.
#pragma once

#include "config.hpp"
#include "image.hpp"

namespace fpstereo {

// With right_view (a left-right check needed), also the match side's disparities.
DisparityImage run_naive(const StereoConfig& cfg, const GrayImage& left, const GrayImage& right,
                         DisparityImage* right_view = nullptr);

}  // namespace fpstereo
