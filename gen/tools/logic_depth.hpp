// Logic depth of a mapped Xilinx netlist (Yosys write_json after synth_xilinx): the LUT levels of
// every register-to-register path, and the deepest paths with their start and end registers, so
// the engineer who pipelines a design knows where the deep logic is.
//
// What counts, per cell on a path:
//   LUT1..LUT6, INV                       1 LUT level (INV becomes a LUT1, as synth-yosys.sh counts it)
//   LUTRAM and SRL reads (RAM64M8, SRL16E ...): 1 LUT level from the read address to the data out,
//                                         and their contents start paths like a register's
//   MUXF7/F8/F9                           0 (a LUT6 pair plus MUXF7 is abc9's one LUT7), 1 with carry/MUXF
//   CARRY4/CARRY8                         0, 1 with carry/MUXF per cell; bit j depends on bits 0..j
//   IBUF, OBUF, BUFG                      0 (wires)
// Anything else (FDRE, RAMB18E2, DSP48E2, unknown types) ends and starts paths: its outputs start
// them, its inputs other than clocks end them. Top-level ports start and end paths too.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace fpstereo {

// A netlist that cannot be analysed (malformed JSON, no top module, a combinational loop); what()
// is one line.
class LogicDepthError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One path. Start: a register ("core.agg.sum_q[3]"), another cell's output pin ("cell/PIN[2]") or
// an input port. End: the same with the pin it enters ("core.agg.min_q[0]/CE"), or an output port.
struct LogicPath {
  int levels = 0;             // LUT levels
  int levels_with_carry = 0;  // LUT levels plus CARRY and MUXF cells
  std::string start, end;
};

struct LogicDepth {
  int levels = 0;             // deepest path by LUT levels
  int levels_with_carry = 0;  // deepest path by LUT levels plus carry/MUXF cells (may be another path)
  // Deepest by LUT levels (ties: with carry), one path per end register (a bus counts once), at
  // most the number asked for.
  std::vector<LogicPath> worst;
  LogicPath worst_with_carry;  // deepest by levels_with_carry (ties: LUT levels)
};

// Analyses the top module of a Yosys JSON netlist (the module with attribute top, else the only
// module with cells). Linear in the netlist's size. Throws LogicDepthError.
LogicDepth analyse_logic_depth(const std::string& yosys_json, size_t max_paths);

}  // namespace fpstereo
