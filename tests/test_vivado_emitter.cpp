// The Vivado integration files (gen/rtl/vivado_emitter): each names the generated top, the stream
// and control ports listed in the XDC and the packaging script are exactly the ones the top
// declares (with the directions it declares), every Verilog file is packaged, the clock period and the part are the
// requested ones, and nothing belongs to another configuration. Tcl syntax is checked separately
// with tclsh (tcl_syntax.cmake); nothing here runs Vivado.
#include <fmt/core.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "rtl_emitter.hpp"
#include "vivado_emitter.hpp"

using namespace fpstereo;

namespace {

// dmax 256: the output word is 9 bits, so m_axis_disp_tdata is 16 bits wide.
StereoConfig wide_output_config() {
  StereoConfig cfg;
  cfg.width = 260;
  cfg.height = 6;
  cfg.dmax = 256;
  cfg.uf = 64;
  cfg.window = 3;
  cfg.median = 0;
  return cfg;
}

struct Generated {
  rtl::RtlDesign design;
  std::vector<rtl::EmittedFile> verilog;
  std::vector<std::string> verilog_names;
  std::string xdc, package_ip, block_design;
};

Generated generate(const StereoConfig& cfg, double clock_mhz = 300, bool control = true) {
  rtl::RtlOptions options;
  options.control = control;
  Generated g{rtl::plan(cfg, options), {}, {}, "", "", ""};
  g.verilog = rtl::emit(g.design);
  for (const auto& file : g.verilog) g.verilog_names.push_back(file.name);
  const auto files = rtl::emit_vivado_files(g.design, g.verilog_names, clock_mhz);
  REQUIRE(files.size() == 3);
  CHECK(files[0].name == g.design.prefix + ".xdc");
  CHECK(files[1].name == "package_ip.tcl");
  CHECK(files[2].name == "block_design.tcl");
  g.xdc = files[0].text;
  g.package_ip = files[1].text;
  g.block_design = files[2].text;
  return g;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// "input" or "output" for every stream (s_axis_*, m_axis_*) and control (s_axi_ctrl_*) port the
// top module declares.
std::map<std::string, std::string> top_interface_ports(const std::string& top_text) {
  static const std::regex declaration(R"((input|output)\s+wire\s+(?:\[\d+:0\]\s+)?([sm]_axis_\w+|s_axi_ctrl_\w+))");
  std::map<std::string, std::string> ports;
  for (std::sregex_iterator it(top_text.begin(), top_text.end(), declaration), end; it != end; ++it)
    ports[(*it)[2]] = (*it)[1];
  return ports;
}

std::set<std::string> interface_ports_named_in(const std::string& text) {
  static const std::regex port(R"(\b(?:[sm]_axis_[a-z]+_t[a-z]+|s_axi_ctrl_[a-z]+)\b)");
  std::set<std::string> ports;
  for (std::sregex_iterator it(text.begin(), text.end(), port), end; it != end; ++it) ports.insert(it->str());
  return ports;
}

std::set<std::string> keys(const std::map<std::string, std::string>& map) {
  std::set<std::string> result;
  for (const auto& entry : map) result.insert(entry.first);
  return result;
}

void check_files_of(const Generated& g) {
  const std::string top = g.design.prefix + "_top";
  INFO("configuration " << g.design.prefix);
  REQUIRE(g.verilog.front().name == top + ".v");
  REQUIRE(contains(g.verilog.front().text, "module " + top + " ("));
  const auto ports = top_interface_ports(g.verilog.front().text);
  // tdata, tvalid, tready, tuser, tlast of three streams; the 17 signals of AXI4-Lite
  const bool control = g.design.options.control;
  REQUIRE(ports.size() == (control ? 15 + 17 : 15));

  for (const std::string* text : {&g.xdc, &g.package_ip, &g.block_design}) {
    CHECK(contains(*text, top));
    CHECK(contains(*text, "Verified here: syntax checked with tclsh; not run in Vivado."));
  }

  // XDC: the clock, then every stream port timed in its own direction.
  CHECK(contains(g.xdc, "create_clock -name aclk -period 3.333 [get_ports aclk]\n"));
  CHECK(interface_ports_named_in(g.xdc) == keys(ports));
  std::istringstream lines(g.xdc);
  for (std::string line; std::getline(lines, line);) {
    const bool input = line.rfind("set_input_delay", 0) == 0, output = line.rfind("set_output_delay", 0) == 0;
    for (const auto& port : interface_ports_named_in(line)) {
      INFO(line);
      CHECK((input || output));
      CHECK(ports.at(port) == (input ? "input" : "output"));
    }
  }
  for (const char* exception : {"set_false_path", "set_multicycle_path", "set_max_delay", "set_clock_groups"})
    CHECK_FALSE(contains(g.xdc, exception));

  // package_ip.tcl: every Verilog file, the XDC, the stream ports and the default part.
  for (const auto& name : g.verilog_names) CHECK(contains(g.package_ip, "\n  " + name + "\n"));
  CHECK(contains(g.package_ip, "set xdc " + g.design.prefix + ".xdc\n"));
  CHECK(contains(g.package_ip, "set top " + top + "\n"));
  CHECK(interface_ports_named_in(g.package_ip) == keys(ports));
  CHECK(contains(g.package_ip, "set default_part xczu9eg-ffvb1156-2-e\n"));
  CHECK(contains(g.package_ip, "3.333 ns"));
  CHECK(contains(g.package_ip, "ipx::infer_bus_interfaces xilinx.com:interface:axis_rtl:1.0 $core"));
  CHECK(contains(g.package_ip, "ACTIVE_LOW"));
  CHECK(contains(g.package_ip, fmt::format("M_AXIS_DISP_TDATA_WIDTH \"m_axis_disp tdata width\" {} long",
                                           g.design.output_bits * g.design.cfg.ppc)));
  CHECK(contains(g.package_ip, fmt::format("SAMPLES_PER_CLOCK \"samples per clock\" {} long", g.design.cfg.ppc)));
  CHECK(contains(g.package_ip, control ? "set control {\n  s_axi_ctrl {s_axi_ctrl_awaddr" : "set control {}\n"));
  CHECK(contains(g.package_ip, "ipx::infer_bus_interfaces xilinx.com:interface:aximm_rtl:1.0 $core"));
  CHECK(contains(g.package_ip, "set_property slave_memory_map_ref $name $busif"));

  // block_design.tcl: the packaged IP, its three stream interfaces and the DMA widths.
  CHECK(contains(g.block_design, "set ip_vlnv fpstereo:fpstereo:" + g.design.prefix + ":"));
  CHECK(contains(g.block_design, "set default_part xczu9eg-ffvb1156-2-e\n"));
  for (const char* busif : {"stereo/s_axis_left]", "stereo/s_axis_right]", "stereo/m_axis_disp]"})
    CHECK(contains(g.block_design, busif));
  CHECK(contains(g.block_design, fmt::format("set ppc {}\n", g.design.cfg.ppc)));
  CHECK(contains(g.block_design, "set pixel_bits [expr {8 * $ppc}]\n"));
  CHECK(contains(g.block_design, fmt::format("set disparity_bits [expr {{{} * $ppc}}]\n", g.design.output_bits)));
  CHECK(contains(g.block_design, control ? "set control s_axi_ctrl\n" : "set control {}\n"));
  CHECK(contains(g.block_design, "Slave /stereo/$control"));
  // The VDMA gives the core the tuser and per-row tlast it checks (a plain AXI DMA would not).
  CHECK(contains(g.block_design, "xilinx.com:ip:axi_vdma"));
  CHECK_FALSE(contains(g.block_design, "xilinx.com:ip:axi_dma "));
}

}  // namespace

TEST_CASE("Vivado files reference the generated top, its ports, its files, the period and the part") {
  const Generated c2 = generate(preset("C2"));
  CHECK(c2.design.output_bits == 8);
  check_files_of(c2);
  const Generated wide = generate(wide_output_config());
  CHECK(wide.design.output_bits == 16);
  check_files_of(wide);
  const Generated fixed = generate(preset("C2"), 300, false);
  check_files_of(fixed);
  StereoConfig four = preset("C2");  // four pixels per beat: 32-bit input and output beats
  four.uf = four.dmax;
  four.ppc = 4;
  four.width = 1240;
  const Generated beats = generate(four);
  CHECK(beats.design.output_bits == 8);
  check_files_of(beats);
  CHECK_FALSE(contains(fixed.xdc, "s_axi_ctrl"));
}

TEST_CASE("Vivado files of different configurations name different modules") {
  const Generated c2 = generate(preset("C2")), wide = generate(wide_output_config());
  REQUIRE(c2.design.prefix != wide.design.prefix);
  for (const std::string* text : {&c2.xdc, &c2.package_ip, &c2.block_design}) {
    CHECK(contains(*text, c2.design.prefix));
    CHECK_FALSE(contains(*text, wide.design.prefix));
  }
  for (const std::string* text : {&wide.xdc, &wide.package_ip, &wide.block_design}) {
    CHECK(contains(*text, wide.design.prefix));
    CHECK_FALSE(contains(*text, c2.design.prefix));
  }
}

TEST_CASE("the XDC period follows the clock, to 3 decimals") {
  const rtl::RtlDesign d = rtl::plan(preset("C2"));
  CHECK(contains(rtl::emit_xdc(d, 250), "-period 4.000 [get_ports aclk]"));
  CHECK(contains(rtl::emit_xdc(d, 333.33), "-period 3.000 [get_ports aclk]"));
  CHECK(contains(rtl::emit_xdc(d, 150), "-period 6.667 [get_ports aclk]"));
  for (double bad : {0.0, -100.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    INFO("clock " << bad);
    CHECK_THROWS_AS(rtl::emit_xdc(d, bad), std::invalid_argument);
    CHECK_THROWS_AS(rtl::emit_package_ip_tcl(d, {}, bad), std::invalid_argument);
  }
}
