// The Verilog backend: the plan's stages build the core (core_builder.hpp) from the building
// blocks of rtl_templates/; this writes it under an AXI4-Stream top, with the register map.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "plan.hpp"

namespace fpstereo::rtl {

// The signals of the AXI4-Lite control interface; the top's ports are s_axi_ctrl_<name>.
struct ControlPort {
  std::string name;
  bool input;  // into the core
  int bits;
};
const std::vector<ControlPort>& control_ports();

// The AXI4-Lite registers (fpstereo_control): byte offset, name, access and meaning, in address
// order. The generated C header is printed from it; the table in docs/hardware.md is checked
// against it (tests/test_register_map.cpp).
struct Register {
  uint32_t offset;
  std::string name;
  bool writable;
  std::string meaning;
};
std::vector<Register> register_map(const RtlDesign& design);
// The read-only words at 0x40 (INFO) with their names, as the design reports them.
std::vector<std::pair<std::string, uint32_t>> info_words(const RtlDesign& design);
// VERSION and CONFIG_ID as the design reports them.
uint32_t version_word();
uint32_t config_id(const RtlDesign& design);
// <prefix>_regs.h: the register map as C constants for the software that drives the core.
std::string emit_register_header(const RtlDesign& design);

struct EmittedFile {
  std::string name;  // file name, e.g. "<prefix>_top.v"
  std::string text;
};

// The top and every module it uses, the top first; each file opens with the banner.
std::vector<EmittedFile> emit(const RtlDesign& design);
// The same as one self-contained file.
std::string emit_single_file(const RtlDesign& design);

}  // namespace fpstereo::rtl
