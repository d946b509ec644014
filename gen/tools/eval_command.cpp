#include "eval_command.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "config_cli.hpp"
#include "dataset.hpp"
#include "files.hpp"
#include "golden_model.hpp"
#include "image_io.hpp"
#include "metrics.hpp"
#include "pair_eval.hpp"
#include "sgbm_baseline.hpp"
#include "text.hpp"

namespace fpstereo {
namespace {

constexpr const char* kTool = "fpstereo";
constexpr const char* kSgbmName = "opencv-sgbm";

struct EvalOptions {
  ConfigFlags config;
  std::string dataset_dir;
  std::string baseline;
  SgbmOptions sgbm;
  std::string json_path, csv_path;
  std::vector<std::string> pair_names;
  int jobs = 1;  // golden-model threads per frame
};

struct MethodResult {
  std::string method;
  double seconds = 0;
  Scores valid_only, filled;
};

struct PairResult {
  std::string name;
  int width = 0, height = 0;
  std::vector<MethodResult> methods;
};

// ---- loading ---------------------------------------------------------------------------------

std::vector<DatasetPair> select_pairs(std::vector<DatasetPair> all, const std::vector<std::string>& names) {
  if (names.empty()) return all;
  std::vector<DatasetPair> chosen;
  for (const auto& p : all)
    if (std::find(names.begin(), names.end(), p.name) != names.end()) chosen.push_back(p);
  for (const auto& name : names) {
    const bool known =
        std::any_of(all.begin(), all.end(), [&](const DatasetPair& p) { return p.name == name; });
    if (known) continue;
    std::string available;
    for (const auto& p : all) available += (available.empty() ? "" : ", ") + p.name;
    throw InputError(fmt::format("--pairs: no pair {} in the dataset (it has {})", quoted(name), available));
  }
  return chosen;
}

void warn_if_out_of_range(const PairInputs& in) {
  const int largest = in.cfg.min_disp + in.cfg.dmax - 1;
  if (in.pair.max_disp_px && *in.pair.max_disp_px > largest)
    std::cerr << fmt::format("{}: warning: pair {} has disparities up to {} px, beyond min-disp + dmax - 1 = {}\n",
                             kTool, quoted(in.pair.name), *in.pair.max_disp_px, largest);
}

// ---- running ---------------------------------------------------------------------------------

// The baseline searches the same disparity range as the pipeline.
SgbmOptions sgbm_options(const EvalOptions& o, const StereoConfig& cfg) {
  SgbmOptions sgbm = o.sgbm;
  sgbm.min_disparity = cfg.min_disp;
  sgbm.num_disparities = cfg.dmax;
  return sgbm;
}

template <class F>
auto timed(F&& run, double& seconds) {
  const auto start = std::chrono::steady_clock::now();
  auto result = run();
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

MethodResult evaluate(const std::string& method, double seconds, const cv::Mat1f& est, const PairInputs& in) {
  return {method, seconds, score(est, in), score(kitti_fill(est), in)};
}

PairResult run_pair(const PairInputs& in, const EvalOptions& o, const std::string& label,
                    const std::string& progress) {
  PairResult result{in.pair.name, in.left.width, in.left.height, {}};
  std::cerr << progress << ": fpstereo" << std::flush;
  double seconds = 0;
  const cv::Mat1f disparity = timed([&] { return golden_disparity(in, o.jobs); }, seconds);
  std::cerr << fmt::format(" {:.2f} s", seconds) << std::flush;
  result.methods.push_back(evaluate(label, seconds, disparity, in));
  if (!o.baseline.empty()) {
    std::cerr << ", " << kSgbmName << std::flush;
    const cv::Mat1f base =
        timed([&] { return run_sgbm(in.left, in.right, sgbm_options(o, in.cfg)); }, seconds);
    std::cerr << fmt::format(" {:.2f} s", seconds) << std::flush;
    result.methods.push_back(evaluate(kSgbmName, seconds, base, in));
  }
  std::cerr << "\n";
  return result;
}

std::vector<MethodResult> overall(const std::vector<PairResult>& results) {
  std::vector<MethodResult> totals = results.front().methods;
  for (size_t i = 1; i < results.size(); ++i)
    for (size_t m = 0; m < totals.size(); ++m) {
      const MethodResult& part = results[i].methods[m];
      totals[m].seconds += part.seconds;
      pool(totals[m].valid_only.occ, part.valid_only.occ);
      pool(totals[m].valid_only.noc, part.valid_only.noc);
      pool(totals[m].filled.occ, part.filled.occ);
      pool(totals[m].filled.noc, part.filled.noc);
    }
  return totals;
}

// ---- human-readable table --------------------------------------------------------------------

constexpr int kLabelWidth = 30;

std::string pairs_text(size_t n) { return fmt::format("{} pair{}", n, n == 1 ? "" : "s"); }

std::string cell(double v) {
  return std::isfinite(v) ? fmt::format(" {:6.2f}", v) : fmt::format(" {:>6}", "-");
}

// D1 on noc and occ; bad-N, MAE and density over all ground-truth pixels (occ).
std::string metric_cells(const Scores& s) {
  const ErrorCounts none;  // every rate NaN: printed as dashes
  const ErrorCounts& occ = s.occ ? *s.occ : none;
  const ErrorCounts& noc = s.noc ? *s.noc : none;
  std::string out;
  for (double v : {noc.d1_percent(), occ.d1_percent(), occ.bad1_percent(), occ.bad2_percent(),
                   occ.bad4_percent(), occ.mae_px(), occ.density_percent()})
    out += cell(v);
  return out;
}

std::string method_row(const MethodResult& m) {
  return fmt::format("  {:<{}}{} |{} | {:7.2f}\n", m.method, kLabelWidth - 2, metric_cells(m.valid_only),
                     metric_cells(m.filled), m.seconds);
}

std::string config_summary(const StereoConfig& cfg) {
  std::string s;
  for (const auto& spec : param_specs())
    if (spec.name != "width" && spec.name != "height") s += " " + spec.name + "=" + spec.get(cfg);
  return s;
}

std::string table_header() {
  const std::string columns = " D1-noc D1-occ  bad-1  bad-2  bad-4    MAE  dens%";
  return fmt::format("{:<{}}{:-^49} |{:-^49} |\n", "", kLabelWidth, " valid pixels only ",
                     " filled (KITTI background interpolation) ") +
         fmt::format("{:<{}}{} |{} | {:>7}\n", "pair / method", kLabelWidth, columns, columns, "time s");
}

std::string format_table(const std::string& dataset, const StereoConfig& cfg, const std::string& label,
                         const EvalOptions& o, const std::vector<PairResult>& results) {
  std::string out = fmt::format("dataset {} ({})\n", one_line(dataset), pairs_text(results.size()));
  out += fmt::format("{}:{}\n", label, config_summary(cfg));
  if (!o.baseline.empty()) out += fmt::format("{}: {}\n", kSgbmName, describe(sgbm_options(o, cfg)));
  out +=
      "D1: |err| > 3 px and > 5 % of GT; bad-N: |err| > N px; bad-N, MAE, density over all GT pixels (occ);\n"
      "rates in % of the pixels with an estimate, density in % of GT pixels; '-': not available\n\n";
  out += table_header();
  for (const auto& r : results) {
    out += fmt::format("{} ({}x{})\n", r.name, r.width, r.height);
    for (const auto& m : r.methods) out += method_row(m);
  }
  out += fmt::format("overall ({}, pixel counts pooled)\n", pairs_text(results.size()));
  for (const auto& m : overall(results)) out += method_row(m);
  return out;
}

// ---- machine-readable output -----------------------------------------------------------------

nlohmann::json counts_json(const std::optional<ErrorCounts>& c) {
  if (!c) return nullptr;
  // nlohmann writes non-finite rates (no estimated pixels) as null.
  return {{"gt_pixels", c->gt_pixels},
          {"estimated", c->estimated},
          {"d1_outliers", c->d1_outliers},
          {"bad1", c->bad1},
          {"bad2", c->bad2},
          {"bad4", c->bad4},
          {"abs_error_sum", c->abs_error_sum},
          {"d1_percent", c->d1_percent()},
          {"bad1_percent", c->bad1_percent()},
          {"bad2_percent", c->bad2_percent()},
          {"bad4_percent", c->bad4_percent()},
          {"mae_px", c->mae_px()},
          {"density_percent", c->density_percent()}};
}

nlohmann::json method_json(const MethodResult& m) {
  const auto scores = [](const Scores& s) {
    return nlohmann::json{{"occ", counts_json(s.occ)}, {"noc", counts_json(s.noc)}};
  };
  return {{"method", m.method},
          {"seconds", m.seconds},
          {"valid_only", scores(m.valid_only)},
          {"filled", scores(m.filled)}};
}

std::string format_json(const std::string& dataset, const StereoConfig& cfg, const std::string& label,
                        const EvalOptions& o, const std::vector<PairResult>& results) {
  nlohmann::json config;
  for (const auto& spec : param_specs()) config[spec.name] = spec.get(cfg);
  nlohmann::json j = {
      {"dataset", dataset},
      {"fpstereo", {{"method", label}, {"config", config}}},
      {"baseline", o.baseline.empty() ? nlohmann::json(nullptr)
                                      : nlohmann::json{{"method", kSgbmName},
                                                       {"description", describe(sgbm_options(o, cfg))}}},
      {"pairs", nlohmann::json::array()},
      {"overall", nlohmann::json::array()}};
  for (const auto& r : results) {
    nlohmann::json methods = nlohmann::json::array();
    for (const auto& m : r.methods) methods.push_back(method_json(m));
    j["pairs"].push_back({{"pair", r.name}, {"width", r.width}, {"height", r.height}, {"methods", methods}});
  }
  for (const auto& m : overall(results)) j["overall"].push_back(method_json(m));
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";  // any folder name
}

std::string csv_number(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : ""; }

std::string csv_rows(const std::string& pair, const MethodResult& m) {
  std::string out;
  const auto add = [&](const char* fill, const char* region, const std::optional<ErrorCounts>& c) {
    if (!c) return;
    out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{}\n", pair, m.method, fill, region, c->gt_pixels,
                       c->estimated, csv_number(c->d1_percent()), csv_number(c->bad1_percent()),
                       csv_number(c->bad2_percent()), csv_number(c->bad4_percent()), csv_number(c->mae_px()),
                       csv_number(c->density_percent()), csv_number(m.seconds));
  };
  add("valid_only", "occ", m.valid_only.occ);
  add("valid_only", "noc", m.valid_only.noc);
  add("filled", "occ", m.filled.occ);
  add("filled", "noc", m.filled.noc);
  return out;
}

// One row per pair, method, filling and region; the pooled rows have pair "overall".
std::string format_csv(const std::vector<PairResult>& results) {
  std::string out =
      "pair,method,fill,region,gt_pixels,estimated,d1_percent,bad1_percent,bad2_percent,bad4_percent,mae_px,"
      "density_percent,seconds\n";
  for (const auto& r : results)
    for (const auto& m : r.methods) out += csv_rows(r.name, m);
  for (const auto& m : overall(results)) out += csv_rows("overall", m);
  return out;
}

// ---- the command -----------------------------------------------------------------------------

// The results go to a file, or to stdout for "-".
void write_result(OutputSet& outputs, const std::string& path, const std::string& text) {
  if (path == "-")
    std::cout << text << std::flush;
  else if (!path.empty())
    outputs.stage(path, text);
}

// The pairs are loaded and run one at a time (memory does not grow with the number of rows);
// the result files are declared before and committed together after.
void run(const EvalOptions& o) {
  const StereoConfig cfg = o.config.resolve();
  if (!o.baseline.empty() && o.baseline != kSgbmName)
    throw InputError(fmt::format("--baseline {}: expected {}", quoted(o.baseline), kSgbmName));
  if (!o.baseline.empty()) validate(o.sgbm);
  OutputSet outputs;
  o.config.declare_input(outputs);
  for (const auto& [path, flag] : {std::pair{&o.json_path, "--json"}, std::pair{&o.csv_path, "--csv"}})
    if (!path->empty() && *path != "-") outputs.add_file(*path, flag);
  const std::vector<DatasetPair> pairs = select_pairs(read_pairs_csv(o.dataset_dir), o.pair_names);
  for (const auto& p : pairs)
    for (const auto* input : {&p.left, &p.right, &p.gt_occ, &p.gt_noc, &p.noc_mask})
      if (!input->empty()) outputs.add_input(*input, "input of pair " + quoted(p.name));

  const std::string label = config_tag(cfg);
  std::vector<PairResult> results;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const PairInputs in = load_pair(pairs[i], cfg);
    warn_if_out_of_range(in);
    results.push_back(run_pair(in, o, label, fmt::format("[{}/{}] {}", i + 1, pairs.size(), pairs[i].name)));
  }

  // Machine-readable output on stdout moves the table to stderr, so stdout stays parseable.
  const bool stdout_taken = o.json_path == "-" || o.csv_path == "-";
  const std::string json_text = o.json_path.empty() ? "" : format_json(o.dataset_dir, cfg, label, o, results);
  const std::string csv_text = o.csv_path.empty() ? "" : format_csv(results);
  (stdout_taken ? std::cerr : std::cout) << format_table(o.dataset_dir, cfg, label, o, results) << std::flush;
  write_result(outputs, o.json_path, json_text);
  write_result(outputs, o.csv_path, csv_text);
  outputs.commit();
}

void add_sgbm_flags(CLI::App& sub, EvalOptions& o) {
  const std::string group = "OpenCV StereoSGBM baseline, with --baseline opencv-sgbm (numDisparities = dmax)";
  const auto add = [&](const std::string& flag, auto& value, const std::string& help) {
    sub.add_option(flag, value, help)->default_val(value)->group(group);
  };
  add("--sgbm-mode", o.sgbm.mode, "sgbm, 3way, hh or hh4");
  add("--sgbm-block", o.sgbm.block, "block side, odd");
  add("--sgbm-p1", o.sgbm.p1, "P1; -1: 8 * block^2");
  add("--sgbm-p2", o.sgbm.p2, "P2; -1: 32 * block^2");
  add("--sgbm-uniqueness", o.sgbm.uniqueness, "uniqueness ratio, percent");
  add("--sgbm-disp12maxdiff", o.sgbm.disp12_max_diff, "left-right check threshold in px; negative: off");
  add("--sgbm-speckle-window", o.sgbm.speckle_window, "speckle filter window in pixels; 0: off");
  add("--sgbm-speckle-range", o.sgbm.speckle_range, "speckle filter disparity range");
  add("--sgbm-prefilter-cap", o.sgbm.prefilter_cap, "prefilter clipping value");
}

}  // namespace

void register_eval_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<EvalOptions>();
  CLI::App* sub = app.add_subcommand(
      "eval",
      "Accuracy on a dataset with ground truth (a folder with pairs.csv): D1, bad-1/2/4, MAE and density, "
      "on valid pixels only and after KITTI background filling, optionally against OpenCV's StereoSGBM");
  sub->add_option("DATASET_DIR", o->dataset_dir, "dataset folder containing pairs.csv")
      ->required()
      ->type_name("DIR");
  o->config.add_to(*sub);
  sub->add_option("--baseline", o->baseline, "also evaluate a baseline: opencv-sgbm")->type_name("NAME");
  add_sgbm_flags(*sub, *o);
  sub->add_option("--json", o->json_path, "write all results as JSON to FILE ('-': stdout)")
      ->type_name("FILE")
      ->check(output_file_name());
  sub->add_option("--csv", o->csv_path, "write all results as CSV to FILE ('-': stdout)")
      ->type_name("FILE")
      ->check(output_file_name());
  sub->add_option("--pairs", o->pair_names, "evaluate only these pairs (comma-separated names)")
      ->delimiter(',')
      ->type_name("NAME");
  sub->add_option("--jobs", o->jobs, "golden-model threads per frame (the disparities do not depend on it)")
      ->check(CLI::Range(1, kMaxJobs))
      ->capture_default_str();
  sub->footer(
      "Each pair runs at its own image size: --width/--height are the hardware's maximum and do not change "
      "accuracy, so they are not applied here. A table goes to stdout (to stderr if --json or --csv is '-'), "
      "progress to stderr.");
  sub->callback([o, &exit_code] {
    try {
      run(*o);
      exit_code = 0;
    } catch (const InputError& e) {
      exit_code = report_error(kTool, e.what());
    } catch (const ConfigError& e) {
      exit_code = report_error(kTool, e.what());
    } catch (const FileError& e) {
      exit_code = report_error(kTool, e.what());
    }
  });
}

}  // namespace fpstereo
