#include "stage_list.hpp"

namespace fpstereo::rtl {

std::vector<StagePtr> pipeline_stages(const StereoConfig& c) {
  std::vector<StagePtr> stages = {framing_stage(), window_stage(c), cost_stage(c), cost_reorder_stage()};
  if (c.lr == LrCheck::Lr2) stages.push_back(lr2_match_stage());
  stages.push_back(aggregation_stage());
  if (c.lr == LrCheck::Lr1) stages.push_back(lr1_match_stage());
  stages.push_back(wta_stage(c));
  if (c.subpixel_bits != 0) stages.push_back(subpixel_stage());
  if (c.confidence) stages.push_back(confidence_stage());
  stages.push_back(disparity_reorder_stage());
  if (c.lr != LrCheck::None) stages.push_back(lr_check_stage(c));
  if (c.right_view) stages.push_back(right_view_stage());
  if (c.speckle_size != 0) stages.push_back(speckle_stage());
  if (c.median != 0) stages.push_back(median_stage());
  if (c.gap_interpolation) stages.push_back(gap_stage());
  stages.push_back(output_stage());
  return stages;
}

}  // namespace fpstereo::rtl
