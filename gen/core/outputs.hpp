// The planes a run produces, one entry each (docs/contributing.md, "Adding an output"): the
// golden and naive models compute them, the hardware streams them (rtl::output_streams names the
// plane each word net carries), `fpstereo run` writes them and the test benches compare them.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "config.hpp"
#include "image.hpp"

namespace fpstereo {

enum class Plane {
  Disparity,   // the output words (docs/semantics.md, "Output word")
  Confidence,  // each base pixel's confidence, 0 .. 255 (section 4)
  Right,       // the match side's whole disparities (section 5, "Right view")
};

// How a plane's words are stored in files (`fpstereo run`, the HLS test bench and host program).
enum class PlaneEncoding {
  Disparities,       // output words: disparities with their fraction, invalid where flagged
  WholeDisparities,  // whole disparities, never invalid
  Levels,            // 0 .. 255
};

struct PlaneInfo {
  Plane plane;
  const char* name;    // as files, streams' fields and messages name it
  const char* option;  // the `fpstereo run` option that writes it
  const char* what;
  PlaneEncoding encoding;
  const char* file_help;  // the files `option` writes
};

// Every plane, in the order outputs are listed.
const std::vector<PlaneInfo>& all_planes();
const PlaneInfo& plane_info(Plane plane);

// Why the configuration cannot compute the plane (the right view needs a left-right check), or
// empty if it can. The models compute any plane the configuration allows, asked or not by it.
std::string plane_unavailable(const StereoConfig& cfg, Plane plane);
// The planes the configuration's hardware outputs: the words, and the confidence and the right
// view when it is configured with them.
std::vector<Plane> output_planes(const StereoConfig& cfg);

// A run's planes.
using Planes = std::map<Plane, DisparityImage>;

}  // namespace fpstereo
