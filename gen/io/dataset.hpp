// A dataset folder with ground truth, described by its pairs.csv
// (columns pair,left,right,gt_occ,gt_noc,noc_mask,gt_scale,gt_invalid,max_disp_px; see
// the shared data README). Paths are returned joined to the dataset folder.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace fpstereo {

struct DatasetPair {
  std::string name;
  std::string left, right;
  std::string gt_occ;                 // all pixels with ground truth; empty = not available
  std::string gt_noc;                 // only pixels visible in both views; empty = not available
  std::string noc_mask;               // non-occluded where the mask is 255; empty = not available
  double gt_scale = 1;                // disparity in pixels = stored value / gt_scale
  std::string gt_invalid = "none";    // stored value meaning "no ground truth": 0, inf or none
  std::optional<double> max_disp_px;  // largest ground-truth disparity, if given

  bool has_gt() const { return !gt_occ.empty() || !gt_noc.empty(); }
  // Non-occluded ground truth is gt_noc, or gt_occ restricted to noc_mask.
  bool has_noc() const { return !gt_noc.empty() || (!gt_occ.empty() && !noc_mask.empty()); }
};

// Reads DATASET_DIR/pairs.csv. Throws InputError (one line naming the file and line) if it is
// missing, has no pairs, or a row is malformed.
std::vector<DatasetPair> read_pairs_csv(const std::string& dataset_dir);

}  // namespace fpstereo
