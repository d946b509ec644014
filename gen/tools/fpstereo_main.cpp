// fpstereo: run the golden model on image pairs and measure its accuracy.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>

#include "config_cli.hpp"
#include "dse_command.hpp"
#include "eval_command.hpp"
#include "files.hpp"
#include "golden_model.hpp"
#include "image_io.hpp"
#include "synth_command.hpp"
#include "text.hpp"
#include "widths.hpp"

namespace fpstereo {
namespace {

struct RunOptions {
  std::string left, right, output, colour, pfm, right_output, confidence;
  std::vector<std::string> gray_pgm;  // left, right
  ConfigFlags config;
};

// Every output is declared (and checked against the inputs and each other) before the work,
// computed before any is written, and committed together: a failing run leaves every previous
// output untouched.
int run_pair(const RunOptions& opt) {
  const StereoConfig cfg = opt.config.resolve();
  if (!opt.right_output.empty() && cfg.lr == LrCheck::None)
    throw ConfigError("--right-output needs a left-right check (lr = lr1 or lr2), whose match side it writes");
  OutputSet outputs;
  outputs.add_input(opt.left, "left image");
  outputs.add_input(opt.right, "right image");
  opt.config.declare_input(outputs);
  const std::pair<const std::string*, const char*> named[] = {
      {&opt.output, "--output"}, {&opt.colour, "--colour"}, {&opt.pfm, "--pfm"},
      {&opt.right_output, "--right-output"}, {&opt.confidence, "--confidence-output"}};
  for (const auto& path : opt.gray_pgm) outputs.add_file(path, "--gray-pgm");
  for (const auto& [path, flag] : named)
    if (!path->empty()) outputs.add_file(*path, flag);
  const GrayImage left = load_gray(opt.left, "left image");
  const GrayImage right = load_gray(opt.right, "right image");
  check_pair(left, right, cfg);
  const auto start = std::chrono::steady_clock::now();
  DisparityImage right_words, confidence;
  const DisparityImage words =
      run_golden(cfg, left, right,
                 {opt.right_output.empty() ? nullptr : &right_words, opt.confidence.empty() ? nullptr : &confidence});
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const cv::Mat1f disparity = to_float_disparity(words, cfg);
  const auto stage = [&](const std::string& path, const std::vector<uchar>& bytes) {
    outputs.stage(path, bytes.data(), bytes.size());
  };
  if (!opt.gray_pgm.empty()) {
    stage(opt.gray_pgm[0], encode_pgm(left));
    stage(opt.gray_pgm[1], encode_pgm(right));
  }
  if (!opt.output.empty()) stage(opt.output, encode_disparity_file(opt.output, disparity));
  if (!opt.colour.empty())
    stage(opt.colour, encode_colour_png(disparity, float(cfg.min_disp), float(cfg.min_disp + cfg.dmax - 1)));
  if (!opt.pfm.empty()) stage(opt.pfm, encode_pfm(disparity));
  if (!opt.right_output.empty()) {
    StereoConfig whole = cfg;  // the right view's words are whole disparities
    whole.subpixel_bits = 0;
    stage(opt.right_output, encode_disparity_file(opt.right_output, to_float_disparity(right_words, whole)));
  }
  if (!opt.confidence.empty()) {
    GrayImage bytes(confidence.width, confidence.height);  // confidences are 0 .. 255
    for (size_t i = 0; i < bytes.pixels.size(); ++i) bytes.pixels[i] = uint8_t(confidence.pixels[i]);
    stage(opt.confidence, ends_with(opt.confidence, ".pgm") ? encode_pgm(bytes) : encode_gray_png(confidence));
  }
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
  run_cmd->add_option("-o,--output", run.output, "KITTI 16-bit PNG (disparity x 256, 0 = invalid; disparities 0 .. 255.99), or PFM if the name ends in .pfm");
  run_cmd->add_option("--colour", run.colour, "colourised PNG with a colour bar");
  run_cmd->add_option("--pfm", run.pfm, "PFM (float disparity, inf = invalid)");
  run_cmd->add_option("--right-output", run.right_output,
                      "the right view's disparities (the left-right check's match side): PFM if the name ends in "
                      ".pfm, else a KITTI 16-bit PNG");
  run_cmd->add_option("--confidence-output", run.confidence,
                      "each pixel's confidence, 255 (S2 - S1) / S2 from its best and second-best aggregated costs "
                      "(docs/semantics.md section 4): binary PGM if the name ends in .pgm, else an 8-bit gray PNG");
  run_cmd
      ->add_option("--gray-pgm", run.gray_pgm,
                   "also write the 8-bit gray inputs the pipeline reads, as binary PGM (the input format of "
                   "the generated HLS test bench and host program)")
      ->expected(2)
      ->type_name("LEFT RIGHT");
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
  } catch (const std::exception& e) {  // e.g. fmt::print's write error on stdout
    return report_error("fpstereo", e.what());
  }
  return finish_stdout("fpstereo", exit_code);
}

}  // namespace

int main(int argc, char** argv) {
  const int exit_code = run_command_line(argc, argv);
  fpstereo::die_if_interrupted();  // a signal during synth: end by it, as without the handler
  return exit_code;
}
