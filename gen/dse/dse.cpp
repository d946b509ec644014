#include "dse.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <system_error>
#include <thread>

#include "files.hpp"
#include "golden_model.hpp"
#include "hash.hpp"
#include "image_io.hpp"
#include "metrics.hpp"
#include "rtl_emitter.hpp"
#include "text.hpp"

namespace fs = std::filesystem;

namespace fpstereo::dse {
namespace {

// ---- axes ------------------------------------------------------------------------------------------

// The axes that set other parameters than their name.
const std::map<std::string, std::vector<std::string>>& alias_axes() {
  static const std::map<std::string, std::vector<std::string>> aliases = {{"refine", {"lr"}},
                                                                         {"resolution", {"width", "height"}}};
  return aliases;
}

// How errors name an axis: by its own flag, or as --axis NAME.
std::string axis_flag(const std::string& name) {
  for (const AxisText& axis : default_space())
    if (axis.name == name) return "--" + name;
  return "--axis " + name;
}

std::vector<Setting> settings(const std::string& axis, const std::string& value) {
  if (axis != "resolution") return {{axis_parameters(axis).front(), value}};
  const auto x = value.find('x');
  if (x == std::string::npos)
    throw InputError(fmt::format("--resolution {}: expected WIDTHxHEIGHT, e.g. 1242x374", quoted(value)));
  return {{"width", value.substr(0, x)}, {"height", value.substr(x + 1)}};
}

// Validates a value on its own: the other parameters are set to what suits any legal value (uf 1
// divides every dmax, the smallest dmax fits any width, P2 at its largest is above any P1 and P1 at
// 0 below any P2, the left-right check the right view needs is on), for a uf the smallest
// dmax it divides, and for ppc uf = dmax. So only a value that no combination could use is an
// error; the rest are skipped
// per combination.
void check_alone(const std::string& axis, const std::vector<Setting>& value) {
  StereoConfig probe;
  probe.uf = 1;
  probe.dmax = 16;
  probe.width = 8192;
  probe.p1 = 0;
  probe.p2 = 4095;
  probe.lr = LrCheck::Lr1;
  for (const Setting& s : value) set_param(probe, s.parameter, s.value);
  if (axis == "uf") probe.dmax = probe.uf * ((16 + probe.uf - 1) / probe.uf);
  if (axis == "ppc") probe.uf = probe.dmax;  // pixels per clock need uf = dmax
  validate(probe);
}

// ---- the cache -------------------------------------------------------------------------------------

nlohmann::json accuracy_json(const Accuracy& a) {
  const auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  return {{"d1_all", num(a.d1_all)},
          {"d1_noc", num(a.d1_noc)},
          {"d1_valid", num(a.d1_valid)},
          {"density", num(a.density)},
          {"pairs", a.pairs}};
}

Accuracy accuracy_from_json(const nlohmann::json& j) {
  const auto num = [&](const char* k) { return j.at(k).is_null() ? NAN : j.at(k).get<double>(); };
  return {num("d1_all"), num("d1_noc"), num("d1_valid"), num("density"), j.at("pairs").get<int>()};
}

class AccuracyCache {
 public:
  explicit AccuracyCache(fs::path dir) : dir_(std::move(dir)) {
    create_cache_directory(dir_);
    if (::access(dir_.c_str(), R_OK | W_OK | X_OK) != 0)
      throw InputError(fmt::format("cache {}: not a writable directory", quoted(dir_.string())));
  }
  fs::path path(const std::string& key, const std::string& dataset_id) const {
    const std::string text = key + '\0' + dataset_id + '\0' + FPSTEREO_VERSION;
    return dir_ / fmt::format("{:016x}.json", fnv1a64(text));
  }
  // A record that exists but does not parse is an error, not a miss: the user should know.
  // Anything but a regular file (a pipe, say) is refused at once.
  std::optional<Accuracy> load(const fs::path& p) const {
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(p, ec))) return std::nullopt;
    std::string text;
    try {
      text = read_regular_file(p, "cache record", kMaxTextFileBytes);
    } catch (const FileError& e) {
      throw InputError(e.what());
    }
    try {
      return accuracy_from_json(nlohmann::json::parse(text).at("accuracy"));
    } catch (const std::exception&) {
      throw InputError(fmt::format("cache {}: corrupt record (delete it to recompute)", quoted(p.string())));
    }
  }
  // Atomic: an interrupted sweep never leaves half a record.
  void store(const fs::path& p, const std::string& key, const Accuracy& a) const {
    const nlohmann::json j = {{"key", key}, {"accuracy", accuracy_json(a)}};
    write_file_atomically(p, j.dump(1) + "\n");
  }

 private:
  fs::path dir_;
};

// ---- progress ----------------------------------------------------------------------------------------

class Progress {
 public:
  Progress(int total, bool on)
      : total_(total), on_(on && total > 0), start_(std::chrono::steady_clock::now()) {}
  void step(int done) {
    if (!on_) return;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const int width = 30, filled = int(double(width) * done / total_);
    const double eta = done > 0 ? s / done * (total_ - done) : 0;
    std::cerr << fmt::format("\rfpstereo dse: [{}{}] {}/{} accuracy configurations, {:.0f} s, ETA {}  ",
                             std::string(filled, '#'), std::string(width - filled, '.'), done, total_, s,
                             done > 0 ? fmt::format("{:.0f} s", eta) : std::string("?"))
              << std::flush;
    if (done == total_) std::cerr << "\n";
  }

 private:
  int total_;
  bool on_;
  std::chrono::steady_clock::time_point start_;
};

double pct(double used, int64_t available) { return available > 0 ? 100.0 * used / double(available) : 0; }

}  // namespace

const SpaceText& default_space() {
  static const SpaceText space = {
      {"cost", {"census", "rank", "sad", "zsad"}},
      {"window", {"5", "7"}},
      {"dmax", {"64", "128"}},
      {"refine", {"none", "lr1", "lr2"}},
      {"median", {"off", "5"}},
      {"p2-adapt", {"0"}},
      {"subpixel-bits", {"0"}},
      {"resolution", {"1242x374", "900x260"}},
      {"uf", {"4", "8", "16", "32"}},
  };
  return space;
}

std::vector<std::string> axis_parameters(const std::string& name) {
  if (const auto alias = alias_axes().find(name); alias != alias_axes().end()) return alias->second;
  for (const auto& spec : param_specs())
    if (spec.name == name) return {name};
  throw InputError(fmt::format("unknown axis {}: expected a configuration parameter (--help lists them), "
                               "resolution or refine",
                               quoted(name)));
}

AxisText parse_axis(const std::string& text) {
  const auto equals = text.find('=');
  if (equals == std::string::npos)
    throw InputError(fmt::format("--axis {}: expected NAME=VALUE,VALUE,..., e.g. p1=5,7,10", quoted(text)));
  AxisText axis{text.substr(0, equals), {}};
  axis_parameters(axis.name);  // an unknown name fails here, before any value
  const std::string list = text.substr(equals + 1);
  const char separator = list.find('/') != std::string::npos ? '/' : ',';
  for (size_t at = 0; at <= list.size() && !list.empty();) {
    const size_t end = std::min(list.find(separator, at), list.size());
    axis.values.push_back(list.substr(at, end - at));
    at = end + 1;
  }
  return axis;
}

void set_axis(SpaceText& space, const AxisText& axis) {
  const std::vector<std::string> params = axis_parameters(axis.name);
  for (AxisText& other : space) {
    const std::vector<std::string> other_params = axis_parameters(other.name);
    if (other_params == params) {
      other.values = axis.values;
      return;
    }
    for (const auto& p : params)
      if (std::find(other_params.begin(), other_params.end(), p) != other_params.end())
        throw InputError(fmt::format("{}: {} is set by {} already", axis_flag(axis.name), p, axis_flag(other.name)));
  }
  const auto fastest = std::find_if(space.begin(), space.end(), [](const AxisText& a) {
    return a.name == "resolution" || a.name == "uf";
  });
  space.insert(fastest, axis);
}

std::string space_flags(const SpaceText& space) {
  std::string flags;
  for (const AxisText& axis : space) {
    const bool commas = std::any_of(axis.values.begin(), axis.values.end(),
                                    [](const std::string& v) { return v.find(',') != std::string::npos; });
    std::string list;
    for (const auto& v : axis.values) list += (list.empty() ? "" : commas ? "/" : ",") + v;
    const std::string flag = axis_flag(axis.name);
    flags += fmt::format("{}{}{}{}", flags.empty() ? "" : " ", flag, flag == "--" + axis.name ? " " : "=", list);
  }
  return flags;
}

Space parse_space(const SpaceText& text) {
  Space space;
  std::map<std::string, std::string> set_by;  // parameter -> the axis that sets it
  for (const AxisText& axis : text) {
    for (const auto& p : axis_parameters(axis.name))
      if (!set_by.emplace(p, axis.name).second)
        throw InputError(fmt::format("{}: {} is set by {} already", axis_flag(axis.name), p, axis_flag(set_by[p])));
    if (axis.values.empty()) throw InputError(fmt::format("{}: no values", axis_flag(axis.name)));
    Axis parsed{axis.name, {}};
    for (const auto& value : axis.values) {
      try {
        parsed.values.push_back(settings(axis.name, value));
        check_alone(axis.name, parsed.values.back());
      } catch (const ConfigError& e) {
        throw InputError(fmt::format("{} {}: {}", axis_flag(axis.name), quoted(value), e.what()));
      }
    }
    space.push_back(std::move(parsed));
  }
  return space;
}

std::vector<StereoConfig> enumerate(const Space& space, const StereoConfig& base, std::vector<Skipped>& skipped) {
  std::vector<StereoConfig> out;
  if (std::any_of(space.begin(), space.end(), [](const Axis& a) { return a.values.empty(); })) return out;
  std::vector<size_t> at(space.size(), 0);  // each axis's current value, as the digits of a counter
  for (;;) {
    StereoConfig c = base;
    for (size_t i = 0; i < space.size(); ++i)
      for (const Setting& s : space[i].values[at[i]]) set_param(c, s.parameter, s.value);
    try {
      rtl::plan_geometry(c);  // validates, then refuses what the hardware generators do not build
      out.push_back(c);
    } catch (const ConfigError& e) {
      skipped.push_back({c, e.what()});
    }
    size_t axis = space.size();
    for (; axis > 0; --axis) {
      if (++at[axis - 1] < space[axis - 1].values.size()) break;
      at[axis - 1] = 0;
    }
    if (axis == 0) return out;
  }
}

std::string accuracy_key(const StereoConfig& cfg) {
  StereoConfig c = cfg;
  c.width = c.height = 0;
  c.uf = 0;
  c.ppc = 1;  // hardware only, as uf
  return describe(c);
}

Dataset load_dataset(const std::vector<std::string>& dirs) {
  if (dirs.empty()) throw InputError("no dataset given");
  Dataset ds;
  std::string identity;
  // Small enough for every pair at dmax 16; each evaluation applies its own configuration.
  StereoConfig probe;
  probe.dmax = 16;
  probe.uf = 16;
  probe.width = probe.height = 8192;
  for (const auto& dir : dirs) {
    if (!fs::is_directory(dir)) throw InputError(fmt::format("dataset {}: not a directory", quoted(dir)));
    std::vector<fs::path> sets;
    if (fs::exists(fs::path(dir) / "pairs.csv")) {
      sets.push_back(dir);
    } else {
      for (const auto& e : fs::directory_iterator(dir))
        if (e.is_directory() && fs::exists(e.path() / "pairs.csv")) sets.push_back(e.path());
      std::sort(sets.begin(), sets.end());
      if (sets.empty())
        throw InputError(fmt::format("dataset {}: no pairs.csv in it or in its subfolders", quoted(dir)));
    }
    for (const auto& set : sets) {
      const std::vector<DatasetPair> pairs = read_pairs_csv(set.string());  // refuses a pipe, say
      identity += read_regular_file(set / "pairs.csv", "pairs file", kMaxTableBytes);
      for (const DatasetPair& p : pairs) {
        const PairInputs in = load_pair(p, probe);
        ds.max_width = std::max(ds.max_width, in.left.width);
        ds.max_height = std::max(ds.max_height, in.left.height);
        ds.pairs.push_back(p);
        for (const std::string& f : {p.left, p.right, p.gt_occ, p.gt_noc, p.noc_mask}) {
          if (f.empty()) continue;
          std::error_code ec;
          const auto size = fs::file_size(f, ec);
          const auto time = fs::last_write_time(f, ec).time_since_epoch().count();
          identity += fmt::format("\n{} {} {}", f, size, time);
        }
      }
      ds.description += (ds.description.empty() ? "" : ", ") + set.string();
    }
  }
  ds.id = fmt::format("{:016x}", fnv1a64(identity));
  return ds;
}

Accuracy evaluate_accuracy(const StereoConfig& cfg, const Dataset& ds, int threads) {
  std::optional<ErrorCounts> occ_filled, noc_filled, occ_valid;
  bool first = true;
  for (const DatasetPair& pair : ds.pairs) {
    const PairInputs in = load_pair(pair, cfg);  // at the pair's own size
    const cv::Mat1f est = golden_disparity(in, threads);
    const Scores valid = score(est, in), filled = score(kitti_fill(est), in);
    if (first) {
      occ_filled = filled.occ;
      noc_filled = filled.noc;
      occ_valid = valid.occ;
      first = false;
    } else {
      pool(occ_filled, filled.occ);
      pool(noc_filled, filled.noc);
      pool(occ_valid, valid.occ);
    }
  }
  Accuracy a;
  a.pairs = int(ds.pairs.size());
  a.d1_all = occ_filled ? occ_filled->d1_percent() : NAN;
  a.d1_noc = noc_filled ? noc_filled->d1_percent() : NAN;
  a.d1_valid = occ_valid ? occ_valid->d1_percent() : NAN;
  a.density = occ_valid ? occ_valid->density_percent() : NAN;
  return a;
}

void fill_hardware(Row& row, const Part& part, double clock_mhz) {
  const rtl::RtlDesign d = rtl::plan(row.cfg);
  row.model = estimate(d);
  row.part = part.name;
  row.lut_pct = pct(row.model.lut, part.lut);
  row.ff_pct = pct(row.model.ff, part.ff);
  row.bram_pct = pct(row.model.bram36_equiv(), part.bram36);
  row.dsp_pct = pct(row.model.dsp, part.dsp);
  row.resource_pct = std::max({row.lut_pct, row.ff_pct, row.bram_pct, row.dsp_pct});
  row.cycles_per_frame = d.cycles_per_frame;
  row.clock_mhz = clock_mhz;
  row.fps = frames_per_second(d, clock_mhz);
}

void mark_pareto(std::vector<Row>& rows) {
  // D1 NaN (no ground truth) never dominates and is never on the front.
  for (auto& r : rows) {
    r.pareto = std::isfinite(r.acc.d1_all);
    if (!r.pareto) continue;
    for (const auto& o : rows) {
      if (&o == &r || !std::isfinite(o.acc.d1_all)) continue;
      const bool no_worse =
          o.acc.d1_all <= r.acc.d1_all && o.resource_pct <= r.resource_pct && o.fps >= r.fps;
      const bool better = o.acc.d1_all < r.acc.d1_all || o.resource_pct < r.resource_pct || o.fps > r.fps;
      if (no_worse && better) {
        r.pareto = false;
        break;
      }
    }
  }
}

std::pair<int, int> parse_shard(const std::string& text) {
  const auto bad = [&] {
    return InputError(fmt::format("--shard {}: expected i/N with 1 <= i <= N, e.g. 2/8", quoted(text)));
  };
  const auto slash = text.find('/');
  if (slash == std::string::npos) throw bad();
  try {
    size_t a = 0, b = 0;
    const int i = std::stoi(text.substr(0, slash), &a);
    const int n = std::stoi(text.substr(slash + 1), &b);
    if (a != slash || b != text.size() - slash - 1 || n < 1 || i < 1 || i > n) throw bad();
    return {i, n};
  } catch (const std::logic_error&) {
    throw bad();
  }
}

SweepResult sweep(const SweepOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  SweepResult result;
  const Part part = find_part(o.part);
  const Dataset ds = load_dataset(o.datasets);
  result.dataset = ds.description;
  std::vector<StereoConfig> configs;
  for (const StereoConfig& c : enumerate(o.space, o.base, result.skipped))
    if (c.width < ds.max_width || c.height < ds.max_height)  // its hardware would refuse the images
      result.skipped.push_back({c, fmt::format("resolution {}x{} is smaller than the dataset's largest images, {}x{}",
                                               c.width, c.height, ds.max_width, ds.max_height)});
    else
      configs.push_back(c);

  // Accuracy groups in first-seen order; a shard takes every N-th group, so the shards of one
  // sweep partition it and each evaluates a disjoint set of golden runs.
  std::vector<std::string> keys;
  std::map<std::string, std::vector<StereoConfig>> members;
  for (const auto& c : configs) {
    const std::string key = accuracy_key(c);
    if (!members.count(key)) keys.push_back(key);
    members[key].push_back(c);
  }
  std::vector<std::string> mine;
  for (size_t i = 0; i < keys.size(); ++i)
    if (int(i % size_t(o.shard_count)) == o.shard_index - 1) mine.push_back(keys[i]);
  result.accuracy_configs = int(mine.size());

  const AccuracyCache cache(o.cache_dir.empty() ? cache_dir("dse") : fs::path(o.cache_dir));

  // Cache hits first (cheap, and a corrupt record fails before any work), then the misses on
  // o.jobs threads: one configuration per thread, and the threads beyond the configurations
  // shared among their frames.
  std::map<std::string, Accuracy> accuracy;
  std::vector<std::string> todo;
  for (const auto& key : mine) {
    if (auto hit = cache.load(cache.path(key, ds.id))) {
      accuracy[key] = *hit;
      result.cached++;
    } else {
      todo.push_back(key);
    }
  }
  // Costs differ tenfold between configurations (ZSAD, LR2 and dmax 128 are slow) and the axes
  // enumerate them in blocks: a fixed shuffle makes the average rate, and so the ETA, honest.
  std::shuffle(todo.begin(), todo.end(), std::mt19937(12345));
  Progress progress(int(mine.size()), o.progress);
  std::atomic<size_t> next{0};
  std::atomic<int> done{result.cached};
  std::mutex lock;
  std::string error;
  progress.step(done);
  const int workers = std::clamp(int(todo.size()), 1, std::max(1, o.jobs));
  const int frame_threads = std::max(1, o.jobs / workers);
  const auto worker = [&] {
    for (size_t i; (i = next++) < todo.size();) {
      try {
        const std::string& key = todo[i];
        const Accuracy a = evaluate_accuracy(members[key].front(), ds, frame_threads);
        std::lock_guard<std::mutex> g(lock);
        // Under the lock: write_file_atomically stages its temporaries in one process-wide list
        // (the signal handler's), which two threads must not change at once.
        cache.store(cache.path(key, ds.id), key, a);
        accuracy[key] = a;
        result.evaluated++;
        progress.step(++done);
      } catch (const std::exception& e) {
        std::lock_guard<std::mutex> g(lock);
        if (error.empty()) error = e.what();
        next = todo.size();
      }
    }
  };
  std::vector<std::thread> threads;
  try {
    for (int t = 1; t < workers; ++t) threads.emplace_back(worker);
  } catch (const std::system_error& e) {  // the threads started so far do the work
    std::cerr << fmt::format("fpstereo dse: warning: {} of {} threads started: {}\n", threads.size() + 1, workers,
                             e.what());
  }
  worker();
  for (auto& t : threads) t.join();
  if (!error.empty()) throw InputError(error);

  for (const auto& key : mine)
    for (const auto& c : members[key]) {
      Row r;
      r.cfg = c;
      r.acc = accuracy[key];
      fill_hardware(r, part, o.clock_mhz);
      result.rows.push_back(std::move(r));
    }
  mark_pareto(result.rows);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

double parse_percent(const std::string& flag, const std::string& text) {
  std::string t = text;
  if (!t.empty() && t.back() == '%') t.pop_back();
  if (const std::optional<double> v = parse_decimal(t); v && *v >= 0) return *v;
  throw InputError(fmt::format("{} {}: expected a percentage such as 30% or 30", flag, quoted(text)));
}

double parse_number_at_least(const std::string& flag, const std::string& text, double min) {
  if (const std::optional<double> v = parse_decimal(text); v && *v >= min) return *v;
  throw InputError(fmt::format("{} {}: expected a number of at least {:g}", flag, quoted(text), min));
}

std::vector<Row> recommend(const std::vector<Row>& rows, const Constraints& c) {
  std::vector<Row> ok;
  for (const auto& r : rows) {
    if (!std::isfinite(r.acc.d1_all)) continue;
    if (c.max_lut && r.lut_pct > *c.max_lut) continue;
    if (c.max_ff && r.ff_pct > *c.max_ff) continue;
    if (c.max_bram && r.bram_pct > *c.max_bram) continue;
    if (c.max_dsp && r.dsp_pct > *c.max_dsp) continue;
    if (c.min_fps && r.fps < *c.min_fps) continue;
    ok.push_back(r);
  }
  std::stable_sort(ok.begin(), ok.end(), [](const Row& a, const Row& b) {
    if (a.acc.d1_all != b.acc.d1_all) return a.acc.d1_all < b.acc.d1_all;
    if (a.resource_pct != b.resource_pct) return a.resource_pct < b.resource_pct;
    return a.fps > b.fps;
  });
  if (int(ok.size()) > c.top) ok.resize(size_t(std::max(0, c.top)));
  return ok;
}

std::string config_flags(const StereoConfig& cfg) {
  const StereoConfig defaults;
  std::string out;
  for (const auto& spec : param_specs()) {
    const std::string v = spec.get(cfg);
    // The parameters of the default axes (width and height among them) always appear, so the
    // command reads on its own.
    const bool shown = std::any_of(default_space().begin(), default_space().end(), [&](const AxisText& axis) {
      const std::vector<std::string> params = axis_parameters(axis.name);
      return std::find(params.begin(), params.end(), spec.name) != params.end();
    });
    if (shown || v != spec.get(defaults))
      out += fmt::format("{}--{} {}", out.empty() ? "" : " ", spec.name, v);
  }
  return out;
}

std::string rtl_command(const StereoConfig& cfg) {
  return fmt::format("fpstereo-rtl {} -o {}", config_flags(cfg), config_tag(cfg));
}

}  // namespace fpstereo::dse
