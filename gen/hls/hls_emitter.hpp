// The HLS emitter: the Vitis HLS C++ of a configuration (hls/): a config header with every
// constant the kernels are templated on, thin top functions with the interface pragmas, the
// kernel library, a C-simulation test bench, a host program, a Makefile and run_hls.tcl.
#pragma once

#include <string>
#include <vector>

#include "config.hpp"

namespace fpstereo::hls {

struct HlsOptions {
  std::string part = "xczu9eg-ffvb1156-2-e";  // ZCU102
  double clock_mhz = 300;
};

struct HlsFile {
  std::string name;
  std::string text;
};

// The top function's name: the configuration tag plus "_top" (as the RTL's top module).
std::string top_name(const StereoConfig& cfg);

// Every file of the HLS project, each opening with the banner. Throws ConfigError for an invalid
// configuration and std::invalid_argument for a bad part or clock.
std::vector<HlsFile> emit(const StereoConfig& cfg, const HlsOptions& options);

}  // namespace fpstereo::hls
