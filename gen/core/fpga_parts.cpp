#include "fpga_parts.hpp"

#include <regex>
#include <sstream>

#include "config.hpp"
#include "constraints_files.hpp"
#include "text.hpp"

namespace fpstereo {
namespace {

constexpr const char* kPartTable = "fpga_parts.txt";

}  // namespace

const std::string& part_table_text() { return constraints_files().at(kPartTable); }

const std::vector<Part>& parts() {
  static const std::vector<Part> table = [] {
    const std::string where = std::string("constraints/") + kPartTable;
    // part family LUT FF BRAM36 DSP LUTRAM URAM [boards]; '#' starts a comment line.
    const std::regex row(R"(^\s*(\S+)\s+(\S+)\s+(\d+)\s+(\d+)\s+(\d+)\s+(\d+)\s+(\d+)\s+(\d+)(\s.*)?$)");
    std::vector<Part> out;
    std::istringstream in(part_table_text());
    for (std::string line; std::getline(in, line);) {
      const size_t first = line.find_first_not_of(" \t");
      if (first == std::string::npos || line[first] == '#') continue;  // as the script's awk skips them
      std::smatch m;
      if (!std::regex_match(line, m, row))
        throw ConfigError(where + ": malformed part row " + quoted(line));
      out.push_back({m[1], m[2], std::stoll(m[3]), std::stoll(m[4]), std::stoll(m[5]), std::stoll(m[6]),
                     std::stoll(m[7]), std::stoll(m[8])});
    }
    if (out.empty()) throw ConfigError("no parts in " + where);
    return out;
  }();
  return table;
}

std::string default_part(const std::string& family) {
  for (const Part& p : parts())
    if (family.empty() || p.family == family) return p.name;
  throw ConfigError("unknown family " + quoted(family));
}

Part find_part(const std::string& name) {
  std::string known;
  for (const Part& p : parts()) {
    if (p.name == name) return p;
    known += (known.empty() ? "" : ", ") + p.name;
  }
  throw ConfigError("--part " + quoted(name) + ": unknown part (known: " + known + ")");
}

std::string part_list() {
  std::string out;
  for (const Part& p : parts()) {
    out += (out.empty() ? "" : ", ") + p.name;
    if (default_part(p.family) == p.name) out += " (" + p.family + " default)";
  }
  return out;
}

}  // namespace fpstereo
