// The hand-written Verilog building blocks of rtl_templates/, embedded at build time.
#pragma once

#include <map>
#include <string>

namespace fpstereo::rtl {

// Module name (file name without .v) -> file text.
const std::map<std::string, std::string>& templates();

}  // namespace fpstereo::rtl
