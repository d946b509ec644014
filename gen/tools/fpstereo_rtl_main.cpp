// fpstereo-rtl: emit the Verilog of a configuration.
//   fpstereo-rtl --dmax 128 --uf 32 > top.v       one self-contained file
//   fpstereo-rtl --preset C2 -o DIR                one file per module, filelist.f, config.json, the
//                                                  register map <prefix>_regs.h and the Vivado files
//                                                  (constraints/README.md)
//   fpstereo-rtl --emit hls --preset C2 -o DIR     the Vitis HLS C++ project (hls/, docs/hls.md)
#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "config_cli.hpp"
#include "hls_emitter.hpp"
#include "rtl_emitter.hpp"
#include "text.hpp"
#include "vivado_emitter.hpp"

namespace fpstereo {
namespace {

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + quoted(path.string()));
}

void write_directory(const rtl::RtlDesign& design, const std::filesystem::path& dir, double clock_mhz) {
  // Everything is emitted before anything is written: a bad clock leaves no directory behind.
  const auto verilog = rtl::emit(design);
  std::vector<std::string> names;
  for (const auto& file : verilog) names.push_back(file.name);
  const auto vivado = rtl::emit_vivado_files(design, names, clock_mhz);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create directory " + quoted(dir.string()) + ": " + ec.message());
  std::string filelist;
  for (const auto& file : verilog) {
    write_file(dir / file.name, file.text);
    filelist += file.name + "\n";
  }
  write_file(dir / "filelist.f", filelist);
  for (const auto& file : vivado) write_file(dir / file.name, file.text);
  if (design.options.control) write_file(dir / (design.prefix + "_regs.h"), rtl::emit_register_header(design));
  nlohmann::ordered_json config;
  for (const auto& spec : param_specs()) config[spec.name] = spec.get(design.cfg);
  write_file(dir / "config.json", config.dump(2) + "\n");
}

void write_hls_directory(const StereoConfig& cfg, const hls::HlsOptions& options,
                         const std::filesystem::path& dir) {
  const auto files = hls::emit(cfg, options);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create directory " + quoted(dir.string()) + ": " + ec.message());
  for (const auto& file : files) write_file(dir / file.name, file.text);
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
      ->capture_default_str();
  std::string emit = "verilog";
  app.add_option("--emit", emit, "verilog, or hls: the Vitis HLS C++ project (needs -o)")
      ->capture_default_str();
  hls::HlsOptions hls_options;
  app.add_option("--part", hls_options.part, "with --emit hls: the part run_hls.tcl targets")
      ->capture_default_str();
  try {
    app.parse(argc, argv);
    rtl::clock_period_ns(clock_mhz);  // a bad clock is an error with or without -o
    if (emit != "verilog" && emit != "hls")
      return report_error("fpstereo-rtl", "--emit " + quoted(emit) + ": expected verilog or hls");
    if (emit == "hls") {
      if (out_dir.empty()) return report_error("fpstereo-rtl", "--emit hls writes a directory: give -o DIR");
      hls_options.clock_mhz = clock_mhz;
      write_hls_directory(flags.resolve(), hls_options, out_dir);
      return 0;
    }
    options.control = !no_axi_lite;
    const rtl::RtlDesign design = rtl::plan(flags.resolve(), options);
    if (out_dir.empty())
      std::cout << rtl::emit_single_file(design);
    else
      write_directory(design, out_dir, clock_mhz);
  } catch (const CLI::ParseError& e) {
    return report_parse_error(app, "fpstereo-rtl", e);
  } catch (const ConfigError& e) {
    return report_error("fpstereo-rtl", std::string("invalid config: ") + e.what());
  } catch (const std::exception& e) {
    return report_error("fpstereo-rtl", e.what());
  }
  return finish_stdout("fpstereo-rtl", 0);
}
