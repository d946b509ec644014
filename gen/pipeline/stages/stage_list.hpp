// The stages of a configuration, one file each in this folder, in the order data flows through
// them (docs/architecture.md, "Stages").
#pragma once

#include <vector>

#include "config.hpp"
#include "stage.hpp"

namespace fpstereo::rtl {

// Stages that run beside the main stream (the match side of the left-right check, the right
// view) follow the stage they read from and add no latency to the stream.
std::vector<StagePtr> pipeline_stages(const StereoConfig& cfg);

StagePtr framing_stage();
StagePtr window_stage(const StereoConfig& cfg);
StagePtr cost_stage(const StereoConfig& cfg);
StagePtr cost_reorder_stage();
StagePtr lr2_match_stage();
StagePtr aggregation_stage();
StagePtr lr1_match_stage();
StagePtr wta_stage(const StereoConfig& cfg);
StagePtr subpixel_stage();
StagePtr confidence_stage();
StagePtr disparity_reorder_stage();
StagePtr lr_check_stage(const StereoConfig& cfg);
StagePtr right_view_stage();
StagePtr speckle_stage();
StagePtr median_stage();
StagePtr gap_stage();
StagePtr output_stage();

}  // namespace fpstereo::rtl
