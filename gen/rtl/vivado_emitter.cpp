#include "vivado_emitter.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <map>
#include <stdexcept>

#include "constraints_files.hpp"
#include "text.hpp"
#include "widths.hpp"

namespace fpstereo::rtl {
namespace {

// rtl_emitter's names: emit() writes the top as "<prefix>_top" into "<prefix>_top.v".
std::string top_module_name(const RtlDesign& d) { return d.prefix + "_top"; }
std::string xdc_file_name(const RtlDesign& d) { return d.prefix + ".xdc"; }

// One IP per configuration (its name is the module prefix), so several coexist in one repository.
constexpr const char* kIpVendor = "fpstereo";
constexpr const char* kIpLibrary = "fpstereo";

// IP-XACT versions are MAJOR.MINOR: the generator's version without its patch level.
std::string ip_version() {
  const std::string version = FPSTEREO_VERSION;
  return version.substr(0, version.find('.', version.find('.') + 1));
}

std::string ip_vlnv(const RtlDesign& d) {
  return fmt::format("{}:{}:{}:{}", kIpVendor, kIpLibrary, d.prefix, ip_version());
}

// The top's AXI4-Stream interfaces as top_module() declares them; the tests check that the top
// has exactly these ports.
struct Stream {
  std::string name;
  bool slave;  // the core receives on it
};
std::vector<Stream> streams(const RtlDesign& d) {
  std::vector<Stream> s = {{"s_axis_left", true}, {"s_axis_right", true}, {"m_axis_disp", false}};
  if (d.cfg.right_view) s.push_back({"m_axis_disp_right", false});
  return s;
}
const std::vector<std::string> kStreamSignals = {"tdata", "tvalid", "tready", "tuser", "tlast"};

std::string port_name(const Stream& stream, const std::string& signal) { return stream.name + "_" + signal; }
// tready runs against the data.
bool is_core_input(const Stream& stream, const std::string& signal) {
  return (signal == "tready") != stream.slave;
}

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : separator) + item;
  return text;
}

// `text` as one Tcl word (also as a list element): bare when plain, else double-quoted with the
// characters Tcl would substitute escaped.
std::string tcl_word(const std::string& text) {
  const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::strchr("_-.,:/+=", c) != nullptr;
  });
  if (plain) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (std::strchr("\\\"$[]{}", c) != nullptr) quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

// A Tcl list of `items`, one per line, for a `set NAME {...}` that people read.
std::string tcl_block(const std::vector<std::string>& items) {
  std::string text = "{\n";
  for (const auto& item : items) text += "  " + item + "\n";
  return text + "}";
}

// constraints/templates/<name>, embedded.
const std::string& vivado_template(const std::string& name) {
  const auto& files = constraints_files();
  const auto it = files.find("templates/" + name);
  if (it == files.end()) throw std::logic_error("constraints/templates/" + name + " was not embedded");
  return it->second;
}

// The banner's and the names' values, in every template.
std::map<std::string, std::string> common_values(const RtlDesign& d) {
  std::string configuration = describe(d.cfg, "#   ");
  configuration.pop_back();  // the template ends the line
  return {{"PREFIX", d.prefix},
          {"VERSION", FPSTEREO_VERSION},
          {"CONFIGURATION", configuration},
          {"TOP", top_module_name(d)},
          {"XDC", xdc_file_name(d)},
          {"IP_VLNV", ip_vlnv(d)},
          {"DEFAULT_PART", kDefaultPart}};
}

// ---- XDC -------------------------------------------------------------------------------------

// A port in get_ports: the whole bus for tdata.
std::string xdc_port(const Stream& stream, const std::string& signal) {
  return port_name(stream, signal) + (signal == "tdata" ? "[*]" : "");
}

std::string port_delay(const char* command, const std::vector<std::string>& ports) {
  const std::string list = ports.size() == 1 ? ports[0] : "{" + join(ports, " ") + "}";
  return fmt::format("{} -clock [get_clocks aclk] 0.000 [get_ports {}]", command, list);
}

// The control interface's ports: s_axi_ctrl_<signal>, buses with [*].
constexpr const char* kControlInterface = "s_axi_ctrl";
std::string control_port(const ControlPort& port) { return std::string(kControlInterface) + "_" + port.name; }

// One line a direction and interface, the last without its newline.
std::string port_delays(const RtlDesign& d) {
  std::vector<std::string> lines = {port_delay("set_input_delay", {"aresetn"})};
  for (const auto& stream : streams(d)) {
    std::vector<std::string> inputs, outputs;
    for (const auto& signal : kStreamSignals)
      (is_core_input(stream, signal) ? inputs : outputs).push_back(xdc_port(stream, signal));
    lines.push_back(port_delay("set_input_delay", inputs));
    lines.push_back(port_delay("set_output_delay", outputs));
  }
  if (d.options.control) {
    std::vector<std::string> inputs, outputs;
    for (const auto& port : control_ports())
      (port.input ? inputs : outputs).push_back(control_port(port) + (port.bits > 1 ? "[*]" : ""));
    lines.push_back(port_delay("set_input_delay", inputs));
    lines.push_back(port_delay("set_output_delay", outputs));
  }
  return join(lines, "\n");
}

// ---- package_ip.tcl ---------------------------------------------------------------------------

// A configuration value shown, read-only, in the IP's customisation dialog.
struct GuiParameter {
  std::string name;  // IP user parameter
  std::string display_name;
  std::string value;
  std::string tooltip;
};

// "shd-window" -> "SHD_WINDOW": user parameter names are identifiers.
std::string parameter_name(const std::string& flag) {
  std::string name = flag;
  for (char& c : name) c = c == '-' ? '_' : char(std::toupper(static_cast<unsigned char>(c)));
  return name;
}

std::vector<GuiParameter> gui_parameters(const RtlDesign& d) {
  std::vector<GuiParameter> parameters;
  for (const auto& spec : param_specs())
    parameters.push_back({parameter_name(spec.name), spec.name, spec.get(d.cfg), spec.help});
  parameters.push_back(
      {"M_AXIS_DISP_TDATA_WIDTH", "m_axis_disp tdata width", std::to_string(d.output_bits * d.cfg.ppc),
       "bits of an output beat: ppc words, pixel 0 lowest, each the disparity with the invalid flag above it, "
       "zero-extended"});
  parameters.push_back({"SAMPLES_PER_CLOCK", "samples per clock", std::to_string(d.cfg.ppc),
                        "pixels per beat on every AXI4-Stream video interface (UG934), pixel 0 in the lowest bits"});
  parameters.push_back({"CYCLES_PER_FRAME", "cycles per frame", std::to_string(d.cycles_per_frame),
                        "clock cycles from a frame's first input to its last output without stalls"});
  return parameters;
}

bool is_integer(const std::string& text) {
  return !text.empty() && std::all_of(text.begin(), text.end(),
                                      [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

std::string gui_parameter_entry(const GuiParameter& p) {
  return "{" +
         join({p.name, tcl_word(p.display_name), tcl_word(p.value), is_integer(p.value) ? "long" : "string",
               tcl_word(p.tooltip)},
              " ") +
         "}";
}

// "width 1242, height 375, ...": the configuration on the one line an IP description has.
std::string configuration_line(const StereoConfig& cfg) {
  std::vector<std::string> items;
  for (const auto& spec : param_specs()) items.push_back(spec.name + " " + spec.get(cfg));
  return join(items, ", ");
}

std::string control_entry(const RtlDesign& d) {
  if (!d.options.control) return "{}";
  std::vector<std::string> ports;
  for (const auto& port : control_ports()) ports.push_back(control_port(port));
  return tcl_block({std::string(kControlInterface) + " {" + join(ports, " ") + "}"});
}

// ---- block_design.tcl -------------------------------------------------------------------------

int disparity_bytes(const RtlDesign& d) { return d.output_bits / 8; }
// The VDMA line buffers (in stream words, ppc pixels each): the smallest power of two the IP
// offers that holds a row.
int line_buffer_depth(const RtlDesign& d) {
  int depth = 128;
  while (depth < d.cfg.width / d.cfg.ppc && depth < 32768) depth *= 2;
  return depth;
}

}  // namespace

std::string clock_period_ns(double clock_mhz) {
  // Also rejects NaN and infinity; XDC periods have 3 decimals, so 0.000 is no period either.
  if (!(clock_mhz > 0 && 1000.0 / clock_mhz >= 0.0005))
    throw std::invalid_argument(fmt::format("clock-mhz = {}: expected a positive frequency", clock_mhz));
  return fmt::format("{:.3f}", 1000.0 / clock_mhz);
}

std::string emit_xdc(const RtlDesign& d, double clock_mhz) {
  auto values = common_values(d);
  values.insert({{"CLOCK_MHZ", fmt::format("{}", clock_mhz)},
                 {"PERIOD", clock_period_ns(clock_mhz)},
                 {"PORT_DELAYS", port_delays(d)}});
  return fill_template(vivado_template("core.xdc.in"), values);
}

std::string emit_package_ip_tcl(const RtlDesign& d, const std::vector<std::string>& files, double clock_mhz) {
  std::vector<std::string> sources, stream_entries, parameter_entries;
  for (const auto& file : files) sources.push_back(tcl_word(file));
  for (const auto& stream : streams(d)) {
    std::vector<std::string> ports;
    for (const auto& signal : kStreamSignals) ports.push_back(port_name(stream, signal));
    stream_entries.push_back(stream.name + " {" + join(ports, " ") + "}");
  }
  for (const auto& parameter : gui_parameters(d)) parameter_entries.push_back(gui_parameter_entry(parameter));
  const std::string description = fmt::format(
      "Semi-global matching stereo pipeline, bit-exact with the fpstereo golden model. AXI4-Stream: left and "
      "right 8-bit pixels in, {}-bit disparity words out, {} per beat; one pixel every {} cycles. Configuration: {}. "
      "Out-of-context constraint: {} MHz.",
      d.output_bits, d.cfg.ppc, d.groups, configuration_line(d.cfg), clock_mhz);
  auto values = common_values(d);
  values.insert({{"CLOCK_MHZ", fmt::format("{}", clock_mhz)},
                 {"PERIOD", clock_period_ns(clock_mhz)},
                 {"SOURCES", tcl_block(sources)},
                 {"IP_VENDOR", kIpVendor},
                 {"IP_LIBRARY", kIpLibrary},
                 {"IP_VERSION", ip_version()},
                 {"DISPLAY_NAME", tcl_word("fpstereo SGM stereo " + d.prefix)},
                 {"DESCRIPTION", tcl_word(description)},
                 {"STREAMS", tcl_block(stream_entries)},
                 {"CONTROL", control_entry(d)},
                 {"GUI_PARAMETERS", tcl_block(parameter_entries)}});
  return fill_template(vivado_template("package_ip.tcl.in"), values);
}

std::string emit_block_design_tcl(const RtlDesign& d) {
  const bool control = d.options.control;
  auto values = common_values(d);
  values.insert(
      {{"RIGHT_VIEW_PATH",
        d.cfg.right_view ? "\n#   and stereo -> m_axis_disp_right -> vdma_disp_right (S2MM) -> DDR, 8-bit words" : ""},
       {"CONTROL_REGISTERS", control ? " and the core's (s_axi_ctrl)" : ""},
       {"WIDTH", std::to_string(d.cfg.width)},
       {"HEIGHT", std::to_string(d.cfg.height)},
       {"DISPARITY_BYTES", std::to_string(disparity_bytes(d))},
       {"ROW_BYTES", std::to_string(int64_t(d.cfg.width) * disparity_bytes(d))},
       {"FRAME_SIZE", control ? "write the core's WIDTH and HEIGHT registers to match."
                              : "without the control interface the size is fixed."},
       {"DISPARITY_BITS", std::to_string(d.output_bits)},
       {"PPC", std::to_string(d.cfg.ppc)},
       {"LINE_BUFFER", std::to_string(line_buffer_depth(d))},
       {"CONTROL", control ? kControlInterface : "{}"},
       {"RIGHT_VIEW", d.cfg.right_view ? "1" : "0"}});
  return fill_template(vivado_template("block_design.tcl.in"), values);
}

std::vector<EmittedFile> emit_vivado_files(const RtlDesign& d, const std::vector<std::string>& files,
                                           double clock_mhz) {
  return {{xdc_file_name(d), emit_xdc(d, clock_mhz)},
          {"package_ip.tcl", emit_package_ip_tcl(d, files, clock_mhz)},
          {"block_design.tcl", emit_block_design_tcl(d)}};
}

}  // namespace fpstereo::rtl
