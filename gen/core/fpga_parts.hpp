// The FPGA parts whose totals `fpstereo synth` and `fpstereo dse` give percentages of: the table
// constraints/fpga_parts.txt, embedded in the binary; scripts/synth-yosys.sh reads the same file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fpstereo {

struct Part {
  std::string name, family;
  int64_t lut = 0, ff = 0, bram36 = 0, dsp = 0, lutram = 0, uram = 0;
};
// The table's text as embedded (what the synthesis script reads, so part of its cache key).
const std::string& part_table_text();
// In the table's order. Throws ConfigError when a row is malformed or the table is empty.
const std::vector<Part>& parts();
// The first part of `family` in the table (of the whole table when `family` is empty), as the script
// picks it. Throws ConfigError for an unknown family.
std::string default_part(const std::string& family = "");
// Throws ConfigError naming the known parts when `name` is not in the table.
Part find_part(const std::string& name);
// For help texts: "xczu9eg (xcup default), xczu7ev, ...".
std::string part_list();

}  // namespace fpstereo
