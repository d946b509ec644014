// fpstereo: run the golden model on image pairs and measure its accuracy.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>
#include <map>
#include <stdexcept>

#include "config_cli.hpp"
#include "dse_command.hpp"
#include "eval_command.hpp"
#include "files.hpp"
#include "golden_model.hpp"
#include "image_io.hpp"
#include "outputs.hpp"
#include "synth_command.hpp"
#include "text.hpp"
#include "widths.hpp"

namespace fpstereo {
namespace {

struct RunOptions {
  std::string left, right, colour, pfm;
  std::map<Plane, std::string> plane_files;  // the file each plane is written to, if asked
  std::vector<std::string> gray_pgm;         // left, right
  int jobs = 1;                              // golden-model threads for the frame
  ConfigFlags config;
};

// How a plane's file is written, by its name's extension.
std::vector<uchar> encode_plane(Plane plane, const std::string& path, const DisparityImage& words,
                                const StereoConfig& cfg) {
  switch (plane_info(plane).encoding) {
    case PlaneEncoding::Disparities:
      return encode_disparity_file(path, to_float_disparity(words, cfg));
    case PlaneEncoding::WholeDisparities: {
      StereoConfig whole = cfg;  // words without a fraction
      whole.subpixel_bits = 0;
      return encode_disparity_file(path, to_float_disparity(words, whole));
    }
    case PlaneEncoding::Levels: {
      GrayImage bytes(words.width, words.height);  // confidences are 0 .. 255
      for (size_t i = 0; i < bytes.pixels.size(); ++i) bytes.pixels[i] = uint8_t(words.pixels[i]);
      return ends_with(path, ".pgm") ? encode_pgm(bytes) : encode_gray_png(words);
    }
  }
  throw std::logic_error("encode_plane: an encoding without a writer");
}

// Every output is declared (and checked against the inputs and each other) before the work,
// computed before any is written, and committed together: a failing run leaves every previous
// output untouched.
int run_pair(const RunOptions& opt) {
  const StereoConfig cfg = opt.config.resolve();
  // The words always: the summary line counts their valid pixels.
  std::vector<Plane> planes{Plane::Disparity};
  for (const auto& [plane, path] : opt.plane_files) {
    if (path.empty()) continue;
    if (const std::string why = plane_unavailable(cfg, plane); !why.empty())
      throw ConfigError(std::string(plane_info(plane).option) + ": " + why);
    if (plane != Plane::Disparity) planes.push_back(plane);
  }
  OutputSet outputs;
  outputs.add_input(opt.left, "left image");
  outputs.add_input(opt.right, "right image");
  opt.config.declare_input(outputs);
  for (const auto& path : opt.gray_pgm) outputs.add_file(path, "--gray-pgm");
  for (const auto& [plane, path] : opt.plane_files)
    if (!path.empty()) outputs.add_file(path, plane_info(plane).option);
  for (const auto& [path, flag] : {std::pair{&opt.colour, "--colour"}, std::pair{&opt.pfm, "--pfm"}})
    if (!path->empty()) outputs.add_file(*path, flag);
  const GrayImage left = load_gray(opt.left, "left image");
  const GrayImage right = load_gray(opt.right, "right image");
  check_pair(left, right, cfg);
  const auto start = std::chrono::steady_clock::now();
  Planes result;
  try {
    result = run_golden(cfg, left, right, planes, opt.jobs);
  } catch (const std::bad_alloc&) {
    throw InputError(fmt::format("{} and {} ({}x{}): out of memory computing the disparities", quoted(opt.left),
                                 quoted(opt.right), left.width, left.height));
  }
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const cv::Mat1f disparity = to_float_disparity(result.at(Plane::Disparity), cfg);
  const auto stage = [&](const std::string& path, const std::vector<uchar>& bytes) {
    outputs.stage(path, bytes.data(), bytes.size());
  };
  if (!opt.gray_pgm.empty()) {
    stage(opt.gray_pgm[0], encode_pgm(left));
    stage(opt.gray_pgm[1], encode_pgm(right));
  }
  for (const auto& [plane, path] : opt.plane_files)
    if (!path.empty()) stage(path, encode_plane(plane, path, result.at(plane), cfg));
  if (!opt.colour.empty())
    stage(opt.colour, encode_colour_png(disparity, float(cfg.min_disp), float(cfg.min_disp + cfg.dmax - 1)));
  if (!opt.pfm.empty()) stage(opt.pfm, encode_pfm(disparity));
  outputs.commit();
  const int valid = cv::countNonZero(disparity == disparity);  // NaN != NaN
  fmt::print("{}x{}, {}, {:.1f} ms, {:.1f} % valid\n", left.width, left.height, config_tag(cfg), ms,
             100.0 * valid / double(disparity.total()));
  return 0;
}

int print_config(const ConfigFlags& flags) {
  const StereoConfig cfg = flags.resolve();
  const Widths w = derive_widths(cfg);
  fmt::print("{}", describe(cfg));
  fmt::print(
      "# derived widths (bits)\ncode = {}\ncost = {} (max {})\npath_cost = {} (max {})\n"
      "aggregated = {} (max {})\ndisparity = {}\noutput_word = {} (invalid = {})\n",
      w.code, w.cost, w.cost_max, w.path_cost, w.path_cost_max, w.aggregated, w.aggregated_max, w.disparity,
      w.output_word, w.invalid_word);
  return 0;
}

}  // namespace
}  // namespace fpstereo

namespace {

int run_command_line(int argc, char** argv) {
  using namespace fpstereo;
  CLI::App app{"fpstereo: semi-global matching golden model, accuracy evaluation"};
  app.require_subcommand(1);
  int exit_code = 0;

  RunOptions run;
  auto* run_cmd = app.add_subcommand("run", "run the golden model on one pair, write the disparity");
  run_cmd->add_option("left", run.left, "left (base) image")->required();
  run_cmd->add_option("right", run.right, "right (match) image")->required();
  for (const PlaneInfo& info : all_planes()) {
    const std::string flag = info.plane == Plane::Disparity ? std::string("-o,") + info.option : info.option;
    run_cmd->add_option(flag, run.plane_files[info.plane], info.file_help)->check(output_file_name());
    if (info.plane == Plane::Disparity) {  // the words' other renderings
      run_cmd->add_option("--colour", run.colour, "colourised PNG with a colour bar")->check(output_file_name());
      run_cmd->add_option("--pfm", run.pfm, "PFM (float disparity, inf = invalid)")->check(output_file_name());
    }
  }
  run_cmd
      ->add_option("--gray-pgm", run.gray_pgm,
                   "also write the 8-bit gray inputs the pipeline reads, as binary PGM (the input format of "
                   "the generated HLS test bench and host program)")
      ->expected(2)
      ->type_name("LEFT RIGHT")
      ->check(output_file_name());
  run_cmd
      ->add_option("--jobs", run.jobs,
                   "golden-model threads for the frame (the output is the same for any number)")
      ->check(CLI::Range(1, kMaxJobs))
      ->capture_default_str();
  run.config.add_to(*run_cmd);
  run_cmd->callback([&] { exit_code = run_pair(run); });

  ConfigFlags shown;
  auto* config_cmd = app.add_subcommand("config", "print the resolved configuration and its bit widths");
  shown.add_to(*config_cmd);
  config_cmd->callback([&] { exit_code = print_config(shown); });

  register_eval_command(app, exit_code);
  register_synth_command(app, exit_code);
  register_dse_command(app, exit_code);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return report_parse_error(app, "fpstereo", e);
  } catch (const ConfigError& e) {
    return report_error("fpstereo", std::string("invalid config: ") + e.what());
  } catch (const InputError& e) {
    return report_error("fpstereo", e.what());
  } catch (const FileError& e) {
    return report_error("fpstereo", e.what());
  } catch (const std::bad_alloc&) {  // where no input is to blame in particular
    return report_error("fpstereo", "out of memory");
  } catch (const std::exception& e) {  // e.g. fmt::print's write error on stdout
    return report_error("fpstereo", e.what());
  }
  return finish_stdout("fpstereo", exit_code);
}

}  // namespace

int main(int argc, char** argv) {
  fpstereo::start_image_codecs();
  const int exit_code = run_command_line(argc, argv);
  fpstereo::die_if_interrupted();  // a signal during synth: end by it, as without the handler
  return exit_code;
}
