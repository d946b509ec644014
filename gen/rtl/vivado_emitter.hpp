// Vivado integration files for a generated design: an out-of-context XDC, a script that packages
// the core as IP, and an example Zynq UltraScale+ block design around it (constraints/README.md).
// Nothing here has run in Vivado: the Tcl and XDC are checked for syntax with tclsh only.
#pragma once

#include <string>
#include <vector>

#include "rtl_emitter.hpp"

namespace fpstereo::rtl {

// The part both scripts target unless the user names another (ZCU102's MPSoC).
inline constexpr const char* kDefaultPart = "xczu9eg-ffvb1156-2-e";

// Constraints for the core out of context: the aclk clock at clock_mhz, the stream ports and the
// reset timed against it. Throws std::invalid_argument unless clock_mhz is positive and finite.
std::string emit_xdc(const RtlDesign& d, double clock_mhz);
// The clock period in ns as the XDC writes it; throws std::invalid_argument, one line, unless
// clock_mhz is positive and finite.
std::string clock_period_ns(double clock_mhz);

// `vivado -mode batch -source package_ip.tcl [-tclargs PART]` in the output directory: packages the
// top and `files` (emit()'s file names) with the XDC as an IP in ip/.
std::string emit_package_ip_tcl(const RtlDesign& d, const std::vector<std::string>& files, double clock_mhz);

// `vivado -mode batch -source block_design.tcl [-tclargs PART [BOARD_PART]]` after package_ip.tcl:
// a Zynq UltraScale+ block design feeding the packaged core from DDR through AXI DMAs.
std::string emit_block_design_tcl(const RtlDesign& d);

// The three files above under their names in the output directory: "<prefix>.xdc",
// "package_ip.tcl" and "block_design.tcl".
std::vector<EmittedFile> emit_vivado_files(const RtlDesign& d, const std::vector<std::string>& files,
                                           double clock_mhz);

}  // namespace fpstereo::rtl
