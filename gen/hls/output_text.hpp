// The output-dependent text of the HLS templates (hls/templates), written from the plan's output
// streams (rtl::output_streams): the streams of the pipeline and the top, their interface pragmas,
// the memory-mapped wrapper's frames and stores, the test bench's reads and compares and the host
// program's buffers. A new output stream or word needs no template change.
#pragma once

#include <map>
#include <string>

#include "plan.hpp"

namespace fpstereo::hls {

// NAME -> text for the templates' @NAME@ placeholders (fill_template), for the templates of the top, its header, the test bench and the host program.
std::map<std::string, std::string> output_text(const rtl::Geometry& g, const std::string& top,
                                               const std::string& config);

}  // namespace fpstereo::hls
