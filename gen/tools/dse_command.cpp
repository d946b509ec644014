#include "dse_command.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "config_cli.hpp"
#include "dse.hpp"
#include "files.hpp"
#include "image_io.hpp"
#include "slurm.hpp"
#include "synth_command.hpp"
#include "text.hpp"

namespace fpstereo {
namespace {

constexpr const char* kTool = "fpstereo";

// The parameters the default axes set (their flags replace the parameters' own); every other one
// is a fixed flag of the base configuration, or an axis with --axis.
bool is_default_axis_param(const std::string& name) {
  for (const auto& axis : dse::default_space()) {
    const std::vector<std::string> params = dse::axis_parameters(axis.name);
    if (std::find(params.begin(), params.end(), name) != params.end()) return true;
  }
  return false;
}

struct OutputOptions {
  std::string csv = "dse.csv", html = "dse.html", part = default_part();
  std::string max_lut, max_ff, max_bram, max_dsp, min_fps;
  int top = 5;
  bool yosys_front = false;
  int yosys_limit = 8;
};

struct DseOptions {
  std::vector<dse::AxisText> axes;  // as given: the default axes' flags, then each --axis
  std::vector<std::string> extra_axes;
  std::vector<std::string> datasets;
  std::optional<std::string> preset;
  std::string config_file, cache, shard;
  std::map<std::string, std::string> fixed;
  int jobs = 2;
  double clock_mhz = 200;
  bool progress = false;
  OutputOptions out;
};

struct MergeOptions {
  std::vector<std::string> inputs;
  OutputOptions out;
};

dse::Constraints constraints(const OutputOptions& o) {
  dse::Constraints c;
  if (!o.max_lut.empty()) c.max_lut = dse::parse_percent("--max-lut", o.max_lut);
  if (!o.max_ff.empty()) c.max_ff = dse::parse_percent("--max-ff", o.max_ff);
  if (!o.max_bram.empty()) c.max_bram = dse::parse_percent("--max-bram", o.max_bram);
  if (!o.max_dsp.empty()) c.max_dsp = dse::parse_percent("--max-dsp", o.max_dsp);
  if (!o.min_fps.empty()) c.min_fps = dse::parse_number_at_least("--min-fps", o.min_fps, 0);
  if (o.top < 1) throw InputError(fmt::format("--top {}: expected at least 1", o.top));
  if (o.yosys_limit < 1) throw InputError(fmt::format("--yosys-limit {}: expected at least 1", o.yosys_limit));
  c.top = o.top;
  return c;
}

// Declared before any work so that a bad path fails before minutes of computation; written only
// at the end, together, so a failing run leaves the previous files untouched.
void declare_outputs(OutputSet& outputs, const OutputOptions& o) {
  outputs.add_file(o.csv, "-o");
  if (!o.html.empty()) outputs.add_file(o.html, "--html");
}

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

// The default space with the axes given on the command line; an axis given twice, or both an axis
// and a fixed parameter, is an error.
dse::SpaceText space(const DseOptions& o) {
  std::vector<dse::AxisText> given = o.axes;
  for (const auto& text : o.extra_axes) given.push_back(dse::parse_axis(text));
  std::map<std::string, std::string> given_by;  // parameter -> the axis given for it
  dse::SpaceText space = dse::default_space();
  for (const auto& axis : given) {
    for (const auto& p : dse::axis_parameters(axis.name)) {
      if (const auto [first, added] = given_by.emplace(p, axis.name); !added)
        throw InputError(first->second == axis.name
                             ? fmt::format("axis {} is given twice", axis.name)
                             : fmt::format("axes {} and {} both set {}", first->second, axis.name, p));
      if (o.fixed.count(p))
        throw InputError(fmt::format("--{} and the axis {} both set {}: give one of them", p, axis.name, p));
    }
    dse::set_axis(space, axis);
  }
  return space;
}

// The sweep as a command (for the report): datasets, axes and fixed parameters.
std::string sweep_command(const DseOptions& o) {
  std::string s = "fpstereo dse " + join(o.datasets, " ") + " " + dse::space_flags(space(o));
  if (o.preset) s += " --preset " + *o.preset;
  if (!o.config_file.empty()) s += " --config " + o.config_file;
  for (const auto& [name, value] : o.fixed) s += fmt::format(" --{} {}", name, value);
  return s + fmt::format(" --part {} --clock-mhz {:g}", o.out.part, o.clock_mhz);
}

// Real Yosys figures for the front (fpstereo synth, cached by design), the lowest resource use first.
void run_yosys_front(std::vector<dse::Row>& rows, const OutputOptions& o) {
  std::vector<dse::Row*> front;
  for (auto& r : rows)
    if (r.pareto) front.push_back(&r);
  std::sort(front.begin(), front.end(),
            [](const dse::Row* a, const dse::Row* b) { return a->resource_pct < b->resource_pct; });
  if (int(front.size()) > o.yosys_limit) front.resize(size_t(o.yosys_limit));
  char self[4096];
  const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) throw InputError("cannot find the fpstereo binary for --yosys-front");
  self[n] = 0;
  int i = 0;
  for (dse::Row* r : front) {
    std::vector<std::string> args = {"nice", "-n", "10", self, "synth"};
    std::istringstream flags(dse::config_flags(r->cfg));  // "--name value" pairs, values without spaces
    for (std::string flag; flags >> flag;) args.push_back(flag);
    for (const std::string& flag : {std::string("--part"), o.part, std::string("--kv")}) args.push_back(flag);
    std::cerr << fmt::format("fpstereo dse: Yosys {}/{}: {}\n", ++i, front.size(), config_tag(r->cfg));
    std::string text;
    try {
      text = run_child_command(args);
    } catch (const SynthError& e) {
      throw InputError(fmt::format("--yosys-front: fpstereo synth failed: {}", e.what()));
    }
    const SynthReport rep = parse_kv(text);
    r->yosys_lut = double(rep.lut);
    r->yosys_ff = double(rep.ff);
    r->yosys_bram36 = rep.bram36_equiv;
    r->yosys_dsp = double(rep.dsp);
  }
}

void print_recommendations(const std::vector<dse::Row>& rows, const dse::Constraints& c) {
  const std::vector<dse::Row> best = dse::recommend(rows, c);
  std::string limits;
  const auto add = [&](const char* name, const std::optional<double>& v, const char* unit) {
    if (v) limits += fmt::format("{}{} {:g}{}", limits.empty() ? "" : ", ", name, *v, unit);
  };
  add("LUT <=", c.max_lut, " %");
  add("FF <=", c.max_ff, " %");
  add("BRAM <=", c.max_bram, " %");
  add("DSP <=", c.max_dsp, " %");
  add("fps >=", c.min_fps, "");
  fmt::print("best configurations{} (lowest D1 first):\n", limits.empty() ? "" : " with " + limits);
  if (best.empty()) fmt::print("  none meets the constraints\n");
  int i = 0;
  for (const auto& r : best) {
    fmt::print(
        "{:2}. {:<28} D1 {:6.2f} % (valid only {:.2f} %, density {:.1f} %)  LUT {:.1f} %  FF {:.1f} %  "
        "BRAM36 {:g} ({:.1f} %)  DSP {:g}  {:.1f} fps{}\n",
        ++i, config_tag(r.cfg), r.acc.d1_all, r.acc.d1_valid, r.acc.density, r.lut_pct, r.ff_pct,
        r.model.bram36_equiv(), r.bram_pct, r.model.dsp, r.fps,
        std::isfinite(r.yosys_lut) ? fmt::format("  [Yosys: {:.0f} LUT, {:.0f} FF, {:g} BRAM36]", r.yosys_lut,
                                                 r.yosys_ff, r.yosys_bram36)
                                   : std::string());
    fmt::print("    {}\n", dse::rtl_command(r.cfg));
  }
  fmt::print("resources: {}\n", dse::model_note());
}

void write_outputs(std::vector<dse::Row>& rows, const OutputOptions& o, dse::ReportInfo info, OutputSet& outputs) {
  if (o.yosys_front) run_yosys_front(rows, o);
  info.constraints = constraints(o);
  outputs.stage(o.csv, dse::to_csv(rows));
  if (!o.html.empty()) outputs.stage(o.html, dse::to_html(rows, info));
  outputs.commit();
  print_recommendations(rows, constraints(o));
}

void run_sweep(const DseOptions& o, const std::string& command) {
  dse::SweepOptions s;
  s.space = dse::parse_space(space(o));
  s.base = compose_config(o.preset, o.config_file, o.fixed);
  s.datasets = o.datasets;
  s.cache_dir = o.cache;
  if (!o.shard.empty()) std::tie(s.shard_index, s.shard_count) = dse::parse_shard(resolve_shard(o.shard));
  if (o.jobs < 1 || o.jobs > kMaxJobs)
    throw InputError(fmt::format("--jobs {}: expected 1 .. {}", o.jobs, kMaxJobs));
  s.jobs = o.jobs;
  check_clock_mhz(o.clock_mhz);
  s.clock_mhz = o.clock_mhz;
  s.part = find_part(o.out.part).name;
  s.progress = o.progress || ::isatty(STDERR_FILENO);
  constraints(o.out);  // bad constraints fail before the sweep
  if (s.datasets.empty())
    throw InputError("dse: no dataset (give a folder with pairs.csv, or one of such folders)");
  OutputSet outputs;
  if (!o.config_file.empty()) outputs.add_input(o.config_file, "config file");
  declare_outputs(outputs, o.out);

  dse::SweepResult r = dse::sweep(s);
  if (r.rows.empty() && !r.skipped.empty())
    throw InputError(fmt::format("dse: every configuration is invalid ({} skipped; the first: {}); nothing written",
                                 r.skipped.size(), r.skipped.front().reason));
  std::cerr << fmt::format(
      "fpstereo dse: {} configurations{}, {} accuracy-distinct ({} evaluated, {} cached), {} skipped as "
      "invalid, "
      "{:.1f} s\n",
      r.rows.size(), s.shard_count > 1 ? fmt::format(" in shard {}/{}", s.shard_index, s.shard_count) : "",
      r.accuracy_configs, r.evaluated, r.cached, r.skipped.size(), r.seconds);
  for (const auto& k : r.skipped)
    std::cerr << fmt::format("  skipped {}: {}\n", config_tag(k.cfg), one_line(k.reason));
  dse::ReportInfo info;
  info.dataset = r.dataset;
  info.part = s.part;
  info.command = command;
  info.clock_mhz = s.clock_mhz;
  info.sweep_seconds = r.seconds;
  info.skipped = int(r.skipped.size());
  write_outputs(r.rows, o.out, info, outputs);
  fmt::print("wrote {}{}\n", o.out.csv, o.out.html.empty() ? "" : " and " + o.out.html);
}

void run_merge(const MergeOptions& o, const std::string& command) {
  if (o.inputs.empty()) throw InputError("dse merge: no input CSV");
  constraints(o.out);
  OutputSet outputs;
  for (const auto& path : o.inputs) outputs.add_input(path, "input CSV");
  declare_outputs(outputs, o.out);
  std::vector<dse::Row> rows;
  std::map<std::string, size_t> seen;  // shards of one sweep are disjoint; repeats are dropped
  for (const auto& path : o.inputs)
    for (auto& r : dse::read_csv(path)) {
      const std::string id = dse::config_flags(r.cfg);
      if (seen.count(id)) continue;
      seen[id] = rows.size();
      rows.push_back(std::move(r));
    }
  std::string part = rows.empty() ? o.out.part : rows.front().part;
  for (const auto& r : rows)
    if (r.part != part) throw InputError(fmt::format("dse merge: rows for parts {} and {}", part, r.part));
  dse::mark_pareto(rows);
  // A shard's front is wider than the whole sweep's: its Yosys figures off the merged front go, so
  // that the merged CSV is the one a single sweep writes (with --yosys-front they come from the cache).
  for (auto& r : rows)
    if (!r.pareto) r.yosys_lut = r.yosys_ff = r.yosys_bram36 = r.yosys_dsp = NAN;
  dse::ReportInfo info;
  info.dataset = fmt::format("merged from {} CSV files", o.inputs.size());
  info.part = part;
  info.command = command;
  info.clock_mhz = rows.empty() ? 0 : rows.front().clock_mhz;
  OutputOptions out = o.out;
  out.part = part;
  write_outputs(rows, out, info, outputs);
  fmt::print("merged {} configurations; wrote {}{}\n", rows.size(), o.out.csv,
             o.out.html.empty() ? "" : " and " + o.out.html);
}

void add_output_options(CLI::App& sub, OutputOptions& o) {
  sub.add_option("-o,--csv", o.csv, "CSV output, one row per configuration")->capture_default_str();
  sub.add_option("--html", o.html, "HTML report with SVG plots ('' for none)")->capture_default_str();
  sub.add_option("--part", o.part, "FPGA part for the percentages: " + part_list())->capture_default_str();
  const std::string g = "Constraints for the recommendation";
  sub.add_option("--max-lut", o.max_lut, "at most this share of the part's LUTs, e.g. 30%")->group(g);
  sub.add_option("--max-ff", o.max_ff, "at most this share of the part's FFs")->group(g);
  sub.add_option("--max-bram", o.max_bram, "at most this share of the part's BRAM36")->group(g);
  sub.add_option("--max-dsp", o.max_dsp, "at most this share of the part's DSPs")->group(g);
  sub.add_option("--min-fps", o.min_fps, "at least this many frames per second")->group(g);
  sub.add_option("--top", o.top, "how many configurations to recommend")->group(g)->capture_default_str();
  sub.add_flag("--yosys-front", o.yosys_front,
               "also synthesise the Pareto front with Yosys (fpstereo synth, cached) and show both figures");
  sub.add_option("--yosys-limit", o.yosys_limit,
                 "with --yosys-front: at most this many designs, smallest first")
      ->capture_default_str();
}

template <class F>
void guarded(int& exit_code, F&& f) {
  try {
    f();
    exit_code = 0;
  } catch (const InputError& e) {
    exit_code = report_error(kTool, e.what());
  } catch (const ConfigError& e) {
    exit_code = report_error(kTool, e.what());
  } catch (const SynthError& e) {
    exit_code = report_error(kTool, e.what());
  } catch (const FileError& e) {
    exit_code = report_error(kTool, e.what());
  }
}

}  // namespace

void register_dse_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<DseOptions>();
  auto m = std::make_shared<MergeOptions>();
  CLI::App* sub = app.add_subcommand(
      "dse",
      "Design-space exploration: accuracy (golden model on a dataset) against resources (fast model) and "
      "frame "
      "rate for every combination of the axes; CSV, HTML report, Pareto front, best configurations under "
      "constraints");
  sub->add_option("DATASET", o->datasets,
                  "folder with pairs.csv, or a folder of such folders (every subset is used)")
      ->type_name("DIR");
  const std::string axes = "Axes (comma-separated values)";
  // The default axes' own flags; their help is the parameter's (refine's is lr's).
  const auto parameter_help = [](const std::string& name) {
    for (const auto& spec : param_specs())
      if (spec.name == name) return spec.help;
    return std::string();
  };
  for (const auto& axis : dse::default_space()) {
    const std::string help = axis.name == "resolution" ? "largest image sizes, WIDTHxHEIGHT"
                                                       : parameter_help(dse::axis_parameters(axis.name).front());
    sub->add_option_function<std::vector<std::string>>(
           "--" + axis.name, [o, name = axis.name](const std::vector<std::string>& v) { o->axes.push_back({name, v}); },
           help + " [" + join(axis.values, ",") + "]")
        ->delimiter(',')
        ->group(axes);
  }
  sub->add_option("--axis", o->extra_axes,
                  "any other parameter as an axis, NAME=V1,V2,... (values separated by / when they hold commas: "
                  "paths=all/0,90); repeatable. Each axis varies slower than resolution and uf")
      ->type_name("NAME=VALUES")
      ->group(axes);
  const std::string base = "Fixed parameters (every configuration)";
  sub->add_option_function<std::string>(
         "--preset", [o](const std::string& v) { o->preset = v; }, "start from a named configuration")
      ->group(base);
  sub->add_option("--config", o->config_file, "JSON or TOML file with parameter names as keys")->group(base);
  for (const auto& spec : param_specs()) {
    if (is_default_axis_param(spec.name)) continue;
    sub->add_option_function<std::string>(
           "--" + spec.name, [o, name = spec.name](const std::string& v) { o->fixed[name] = v; },
           spec.help + " [C2: " + spec.get(StereoConfig{}) + "]")
        ->group(base);
  }
  sub->add_option("--clock-mhz", o->clock_mhz, "clock for the frame rate")->check(decimal_number())->capture_default_str();
  sub->add_option("--cache", o->cache, "accuracy cache [" + cache_dir_rule("dse") + "]");
  sub->add_option("--jobs", o->jobs, "golden-model threads")->capture_default_str();
  sub->add_option(
      "--shard", o->shard,
      "evaluate only shard i of N (1 <= i <= N) and write its partial CSV; combine with dse merge. auto: this "
      "Slurm array task's place in its array (docs/cluster.md)");
  sub->add_flag("--progress", o->progress, "progress bar even when stderr is not a terminal");
  add_output_options(*sub, o->out);
  sub->footer(
      "Accuracy depends on every parameter but the resolution and uf; each such configuration runs once on "
      "the dataset at its own image size and is cached, so an interrupted sweep resumes. Resolution and uf "
      "set resources and frame rate.");

  CLI::App* merge =
      sub->add_subcommand("merge", "Combine the CSVs of a sharded sweep into one CSV and report");
  merge->add_option("CSV", m->inputs, "partial CSVs written by dse --shard")->required();
  add_output_options(*merge, m->out);

  sub->callback([o, merge, &exit_code] {
    if (merge->parsed()) return;
    guarded(exit_code, [&] { run_sweep(*o, sweep_command(*o)); });
  });
  merge->callback([m, &exit_code] {
    guarded(exit_code, [&] { run_merge(*m, "fpstereo dse merge " + join(m->inputs, " ")); });
  });
}

}  // namespace fpstereo
