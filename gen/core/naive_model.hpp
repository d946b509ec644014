// A deliberately naive second implementation written straight from the paper's equations
// and docs/semantics.md: full cost volume, explicit path recursion, no shared code with the
// golden model. Used only to cross-check the golden model.
#pragma once

#include "config.hpp"
#include "golden_model.hpp"  // SideViews
#include "image.hpp"

namespace fpstereo {

// The side views as run_golden writes them.
DisparityImage run_naive(const StereoConfig& cfg, const GrayImage& left, const GrayImage& right,
                         const SideViews& side = {});

}  // namespace fpstereo
