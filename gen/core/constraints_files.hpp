// The files of constraints/ (the FPGA part table, the Vivado templates), embedded at build time so
// that an installed binary needs no source tree.
#pragma once

#include <map>
#include <string>

namespace fpstereo {

// Path relative to constraints/ -> file text.
const std::map<std::string, std::string>& constraints_files();

}  // namespace fpstereo
