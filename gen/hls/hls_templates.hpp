// The files of hls/ (kernel library, compatibility header, templates), embedded at build time.
#pragma once

#include <map>
#include <string>

namespace fpstereo::hls {

// Path relative to hls/ -> file text.
const std::map<std::string, std::string>& templates();

}  // namespace fpstereo::hls
