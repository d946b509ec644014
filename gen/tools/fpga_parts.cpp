#include "fpga_parts.hpp"

#include <fmt/core.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "config.hpp"
#include "text.hpp"

#ifndef FPSTEREO_SOURCE_DIR
#error "FPSTEREO_SOURCE_DIR must name the source tree, where scripts/synth-yosys.sh lives (CMakeLists.txt)"
#endif

namespace fpstereo {

std::filesystem::path synth_script_path() {
  return std::filesystem::path(FPSTEREO_SOURCE_DIR) / "scripts" / "synth-yosys.sh";
}

const std::vector<Part>& parts() {
  static const std::vector<Part> table = [] {
    const std::string path = synth_script_path().string();
    std::ifstream in(path);
    if (!in) throw ConfigError("cannot read the part table in " + path);
    // The rows between part_table=" and the closing ": part family LUT FF BRAM36 DSP LUTRAM [board].
    const std::regex row(R"(^(\S+)\s+(\S+)\s+(\d+)\s+(\d+)\s+(\d+)\s+(\d+)\s+(\d+)(\s.*)?$)");
    std::vector<Part> out;
    bool inside = false;
    for (std::string line; std::getline(in, line);) {
      if (!inside) {
        inside = line == "part_table=\"";
        continue;
      }
      if (line == "\"") break;
      if (line.empty() || line[0] == '#') continue;
      std::smatch m;
      if (!std::regex_match(line, m, row))
        throw ConfigError(fmt::format("{}: malformed part row {}", path, quoted(line)));
      out.push_back({m[1], m[2], std::stoll(m[3]), std::stoll(m[4]), std::stoll(m[5]), std::stoll(m[6]),
                     std::stoll(m[7])});
    }
    if (out.empty()) throw ConfigError("no part table in " + path);
    return out;
  }();
  return table;
}

std::string default_part(const std::string& family) {
  for (const Part& p : parts())
    if (family.empty() || p.family == family) return p.name;
  throw ConfigError(fmt::format("unknown family {}", quoted(family)));
}

Part find_part(const std::string& name) {
  std::string known;
  for (const Part& p : parts()) {
    if (p.name == name) return p;
    known += (known.empty() ? "" : ", ") + p.name;
  }
  throw ConfigError(fmt::format("--part {}: unknown part (known: {})", quoted(name), known));
}

std::string part_list() {
  std::string out;
  for (const Part& p : parts()) {
    out += (out.empty() ? "" : ", ") + p.name;
    if (default_part(p.family) == p.name) out += fmt::format(" ({} default)", p.family);
  }
  return out;
}

}  // namespace fpstereo
