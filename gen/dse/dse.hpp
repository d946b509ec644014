// `fpstereo dse`: sweeps a design space, measuring accuracy with the golden model on a dataset
// (once per accuracy-distinct configuration, cached on disk) and resources and throughput with the
// fast model; finds the Pareto front and the best configurations under constraints.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "config.hpp"
#include "fpga_parts.hpp"
#include "pair_eval.hpp"
#include "resource_model.hpp"

namespace fpstereo::dse {

// ---- The design space -----------------------------------------------------------------------
// An axis is a parameter of the configuration's table (param_specs()) and its values as text, each
// applied with set_param, as a command-line flag applies it: any parameter is an axis. Two names
// set others: refine (lr) and resolution (WIDTHxHEIGHT: width and height).

// An axis as the user wrote it.
struct AxisText {
  std::string name;
  std::vector<std::string> values;
};
// The axes, outermost first: the last varies fastest.
using SpaceText = std::vector<AxisText>;

// The paper's space (768 designs): cost, window, dmax, refine, median, p2-adapt, subpixel-bits,
// resolution, uf. Each of these axes has a flag of its own (--cost, ...).
const SpaceText& default_space();
// The parameters the axis `name` sets: {name} for a parameter of the table, {"lr"} for refine,
// {"width", "height"} for resolution. Throws InputError for any other name.
std::vector<std::string> axis_parameters(const std::string& name);
// "NAME=V1,V2,..." (values separated by '/' instead when one holds commas: paths=all/0,90) as an
// axis. Throws InputError for text without '=' or an unknown name.
AxisText parse_axis(const std::string& text);
// Gives the axis that sets the same parameters as `axis` its values, or adds it before resolution
// and uf (which then still vary fastest). Throws InputError for an unknown name or an axis that
// sets only some of another's parameters (width against resolution).
void set_axis(SpaceText& space, const AxisText& axis);
// The space as flags: --NAME V1,V2 for the axes with a flag of their own, --axis NAME=V1,V2 for the
// others, in the space's order.
std::string space_flags(const SpaceText& space);

// A parameter and its value as text, applied with set_param.
struct Setting {
  std::string parameter, value;
};
// An axis parsed: for each value, the settings it makes.
struct Axis {
  std::string name;
  std::vector<std::vector<Setting>> values;
};
using Space = std::vector<Axis>;

// Checks every value on its own, with the other parameters where any legal value fits (only a
// value no combination could use is an error). Throws InputError naming the axis and value
// (e.g. "--window '4': ..."), an axis without values, or a parameter two axes set.
Space parse_space(const SpaceText& text);

struct Skipped {
  StereoConfig cfg;
  std::string reason;
};

// Every combination of the axes on top of `base`, the last axis varying fastest; invalid ones (by
// validate()) go to `skipped` with the reason.
std::vector<StereoConfig> enumerate(const Space& space, const StereoConfig& base,
                                    std::vector<Skipped>& skipped);

// What the golden model's output depends on: the configuration without width, height and uf.
std::string accuracy_key(const StereoConfig& cfg);

// Pooled over every pair (pixel counts summed): D1 in % (|err| > 3 px and > 5 %), on all pixels
// with ground truth after KITTI background filling, on the non-occluded ones where every pair has
// them (NaN otherwise), and on valid pixels only with the density.
struct Accuracy {
  double d1_all = 0, d1_noc = 0, d1_valid = 0, density = 0;
  int pairs = 0;
};

// A dataset: one folder with pairs.csv, or a folder whose subfolders have one each.
// The pairs are loaded (and checked) once by load_dataset, then again by each evaluation: memory
// does not grow with the number of pairs.
struct Dataset {
  std::vector<DatasetPair> pairs;
  int max_width = 0, max_height = 0;  // the largest images
  std::string id;  // hash of the pairs.csv files and the sizes and times of every file they name
  std::string description;
};
// Throws InputError (missing folder, no pairs.csv, unreadable images, ...).
Dataset load_dataset(const std::vector<std::string>& dirs);

// threads: the golden model's threads per pair (its paths are shared among them).
Accuracy evaluate_accuracy(const StereoConfig& cfg, const Dataset& dataset, int threads = 1);

// One full configuration of the sweep.
struct Row {
  StereoConfig cfg;
  Accuracy acc;
  ResourceEstimate model;
  std::string part;
  double lut_pct = 0, ff_pct = 0, bram_pct = 0, dsp_pct = 0;
  double resource_pct = 0;  // the largest of the four: what limits how many fit
  int64_t cycles_per_frame = 0;
  double clock_mhz = 0, fps = 0;
  bool pareto = false;
  // Yosys' figures when it was run (--yosys-front); NaN otherwise.
  double yosys_lut = NAN, yosys_ff = NAN, yosys_bram36 = NAN, yosys_dsp = NAN;
};

// Fills resources, percentages and throughput of a row from its configuration.
void fill_hardware(Row& row, const Part& part, double clock_mhz);

// Marks the rows no other row beats on D1, resource use and FPS at once (lower, lower, higher).
void mark_pareto(std::vector<Row>& rows);

struct SweepOptions {
  Space space;
  StereoConfig base;
  std::vector<std::string> datasets;
  std::string cache_dir;  // empty: cache_dir("dse")
  int shard_index = 1, shard_count = 1;
  int jobs = 2;
  double clock_mhz = 200;
  std::string part = default_part();
  bool progress = true;
};

struct SweepResult {
  std::vector<Row> rows;
  std::vector<Skipped> skipped;
  int accuracy_configs = 0, evaluated = 0, cached = 0;
  double seconds = 0;
  std::string dataset;
};

// Throws InputError (bad dataset, unreadable or corrupt cache), FileError (no cache directory) or
// ConfigError.
SweepResult sweep(const SweepOptions& options);

// "i/N" with 1 <= i <= N. Throws InputError.
std::pair<int, int> parse_shard(const std::string& text);

struct Constraints {
  std::optional<double> max_lut, max_ff, max_bram, max_dsp, min_fps;  // percent of the part; fps
  int top = 5;
};
// "30%" or "30". Throws InputError.
double parse_percent(const std::string& flag, const std::string& text);
// A finite number of at least `min` (not nan, inf or 0x10); throws InputError naming the flag.
double parse_number_at_least(const std::string& flag, const std::string& text, double min);

// The rows meeting the constraints, lowest D1 first (ties: lower resource use, then higher FPS).
std::vector<Row> recommend(const std::vector<Row>& rows, const Constraints& c);

// The configuration as flags (only the parameters that differ from the defaults; exact).
std::string config_flags(const StereoConfig& cfg);
// The fpstereo-rtl command that emits the configuration's design.
std::string rtl_command(const StereoConfig& cfg);

// CSV with one row per configuration; read back by read_csv (merge). Throws InputError.
std::string to_csv(const std::vector<Row>& rows);
std::vector<Row> read_csv(const std::string& path);

struct ReportInfo {
  std::string dataset, part, command;
  double clock_mhz = 200;
  double sweep_seconds = 0;
  Constraints constraints;
  int skipped = 0;
};
// Self-contained HTML (inline SVG, no scripts): D1 and FPS against resource use, the Pareto front,
// the recommendations.
std::string to_html(const std::vector<Row>& rows, const ReportInfo& info);

}  // namespace fpstereo::dse
