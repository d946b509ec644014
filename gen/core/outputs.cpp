#include "outputs.hpp"

#include <stdexcept>

namespace fpstereo {

const std::vector<PlaneInfo>& all_planes() {
  static const std::vector<PlaneInfo> planes = {
      {Plane::Disparity, "disparity", "--output", "the output words", PlaneEncoding::Disparities,
       "KITTI 16-bit PNG (disparity x 256, 0 = invalid; disparities 0 .. 255.99), or PFM if the name ends in "
       ".pfm"},
      {Plane::Confidence, "confidence", "--confidence-output", "each pixel's confidence", PlaneEncoding::Levels,
       "each pixel's confidence, 255 (S2 - S1) / S2 from its best and second-best aggregated costs "
       "(docs/semantics.md section 4): binary PGM if the name ends in .pgm, else an 8-bit gray PNG"},
      {Plane::Right, "right", "--right-output", "the right view's whole disparities",
       PlaneEncoding::WholeDisparities,
       "the right view's disparities (the left-right check's match side): PFM if the name ends in .pfm, else a "
       "KITTI 16-bit PNG"},
  };
  return planes;
}

const PlaneInfo& plane_info(Plane plane) {
  for (const auto& info : all_planes())
    if (info.plane == plane) return info;
  throw std::logic_error("plane_info: a plane without an entry");
}

std::string plane_unavailable(const StereoConfig& cfg, Plane plane) {
  if (plane == Plane::Right && cfg.lr == LrCheck::None)
    return "the right view needs a left-right check (lr = lr1 or lr2), whose match side it is";
  return {};
}

std::vector<Plane> output_planes(const StereoConfig& cfg) {
  std::vector<Plane> planes{Plane::Disparity};
  if (cfg.confidence) planes.push_back(Plane::Confidence);
  if (cfg.right_view) planes.push_back(Plane::Right);
  return planes;
}

}  // namespace fpstereo
