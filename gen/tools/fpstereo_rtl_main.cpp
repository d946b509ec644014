// fpstereo-rtl: emit the Verilog of a configuration.
//   fpstereo-rtl --dmax 128 --uf 32 > top.v       one self-contained file
//   fpstereo-rtl --preset C2 -o DIR                one file per module, filelist.f, config.json, the
//                                                  register map <prefix>_regs.h and the Vivado files
//                                                  (constraints/README.md)
//   fpstereo-rtl --emit hls --preset C2 -o DIR     the Vitis HLS C++ project (hls/, docs/hls.md)
#include <CLI/CLI.hpp>
#include <cerrno>
#include <iostream>
#include <nlohmann/json.hpp>

#include "config_cli.hpp"
#include "files.hpp"
#include "hls_emitter.hpp"
#include "rtl_emitter.hpp"
#include "text.hpp"
#include "vivado_emitter.hpp"

namespace fpstereo {
namespace {

// Everything is emitted before anything is written, into a fresh directory swapped in whole:
// a bad clock or a full disk leaves the previous directory as it was.
void write_directory(const rtl::RtlDesign& design, OutputSet& outputs, const std::string& dir, double clock_mhz) {
  const auto verilog = rtl::emit(design);
  std::vector<std::string> names;
  for (const auto& file : verilog) names.push_back(file.name);
  const auto vivado = rtl::emit_vivado_files(design, names, clock_mhz);
  std::string filelist;
  for (const auto& file : verilog) {
    outputs.stage_in_directory(dir, file.name, file.text);
    filelist += file.name + "\n";
  }
  outputs.stage_in_directory(dir, "filelist.f", filelist);
  for (const auto& file : vivado) outputs.stage_in_directory(dir, file.name, file.text);
  if (design.options.control)
    outputs.stage_in_directory(dir, design.prefix + "_regs.h", rtl::emit_register_header(design));
  nlohmann::ordered_json config;
  for (const auto& spec : param_specs()) config[spec.name] = spec.get(design.cfg);
  outputs.stage_in_directory(dir, "config.json", config.dump(2) + "\n");
}

void write_hls_directory(const StereoConfig& cfg, const hls::HlsOptions& options, OutputSet& outputs,
                         const std::string& dir) {
  for (const auto& file : hls::emit(cfg, options)) outputs.stage_in_directory(dir, file.name, file.text);
}

}  // namespace
}  // namespace fpstereo

int main(int argc, char** argv) {
  using namespace fpstereo;
  CLI::App app{"fpstereo-rtl: emit the synthesizable Verilog of an SGM stereo pipeline"};
  ConfigFlags flags;
  flags.add_to(app);
  std::string out_dir;
  app.add_option("-o,--output-dir", out_dir,
                 "write one file per module, filelist.f, config.json and the Vivado files here");
  rtl::RtlOptions options;
  bool no_axi_lite = false;
  app.add_flag("--no-axi-lite", no_axi_lite,
               "no AXI4-Lite control interface: the settings are the generated ones, nothing is counted");
  double clock_mhz = 300;
  app.add_option(
         "--clock-mhz", clock_mhz,
         "with -o: target clock of the out-of-context XDC (or of run_hls.tcl with --emit hls), in MHz")
      ->check(decimal_number())
      ->capture_default_str();
  std::string emit = "verilog";
  app.add_option("--emit", emit, "verilog, or hls: the Vitis HLS C++ project (needs -o)")
      ->capture_default_str();
  hls::HlsOptions hls_options;
  CLI::Option* part = app.add_option("--part", hls_options.part, "with --emit hls: the part run_hls.tcl targets")
                          ->capture_default_str();
  try {
    app.parse(argc, argv);
    check_clock_mhz(clock_mhz);  // a bad clock is an error with or without -o
    if (emit != "verilog" && emit != "hls")
      return report_error("fpstereo-rtl", "--emit " + quoted(emit) + ": expected verilog or hls");
    if (emit == "hls" && out_dir.empty())
      return report_error("fpstereo-rtl", "--emit hls writes a directory: give -o DIR");
    // The Verilog names no part (the block design takes the project's): a --part would be lost.
    if (emit == "verilog" && part->count() > 0)
      return report_error("fpstereo-rtl", "--part is for --emit hls (run_hls.tcl's part); the Verilog names none");
    OutputSet outputs;
    flags.declare_input(outputs);
    if (!out_dir.empty()) outputs.add_directory(out_dir, "-o directory");
    if (emit == "hls") {
      hls_options.clock_mhz = clock_mhz;
      write_hls_directory(flags.resolve(), hls_options, outputs, out_dir);
    } else {
      options.control = !no_axi_lite;
      const rtl::RtlDesign design = rtl::plan(flags.resolve(), options);
      if (out_dir.empty()) {
        errno = 0;
        std::cout << rtl::emit_single_file(design) << std::flush;
        // The reason now, while errno still holds the failed write's (finish_stdout only sees the state).
        if (!std::cout) return report_stdout_error("fpstereo-rtl", errno);
      } else
        write_directory(design, outputs, out_dir, clock_mhz);
    }
    outputs.commit();
  } catch (const CLI::ParseError& e) {
    return report_parse_error(app, "fpstereo-rtl", e);
  } catch (const ConfigError& e) {
    return report_error("fpstereo-rtl", std::string("invalid config: ") + e.what());
  } catch (const std::exception& e) {
    return report_error("fpstereo-rtl", e.what());
  }
  return finish_stdout("fpstereo-rtl", 0);
}
