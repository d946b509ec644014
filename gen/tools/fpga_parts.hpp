// The FPGA parts whose totals `fpstereo synth` and `fpstereo dse` give percentages of. The list is
// scripts/synth-yosys.sh's table (the script also runs on its own): this reads it from there.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fpstereo {

// scripts/synth-yosys.sh in the source tree.
std::filesystem::path synth_script_path();

struct Part {
  std::string name, family;
  int64_t lut = 0, ff = 0, bram36 = 0, dsp = 0, lutram = 0;
};
// In the script's order. Throws ConfigError when the script or its table cannot be read.
const std::vector<Part>& parts();
// The first part of `family` in the table (of the whole table when `family` is empty), as the script
// picks it. Throws ConfigError for an unknown family.
std::string default_part(const std::string& family = "");
// Throws ConfigError naming the known parts when `name` is not in the table.
Part find_part(const std::string& name);
// For help texts: "xczu9eg (xcup default), xczu7ev, ...".
std::string part_list();

}  // namespace fpstereo
