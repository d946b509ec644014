// fpstereo-tb: streams stereo pairs through the Verilated pipeline and checks every output pixel
// against the golden model, the output stream's protocol, the throughput and the status registers.
//
// Runs, each from reset: a throughput run (4 frames back to back, no idle cycles, no backpressure)
// that measures latency and cycles per frame, fails unless they are exactly what the design states
// in its banner (check_timing), and tries writes the control interface must refuse;
// the checked run with the requested idle and backpressure probabilities and run-time settings
// (--set, written during frame 0, in effect from frame 1); then one run per framing fault
// (--fault). Every frame a fault does not truncate is compared pixel for pixel.
// Exit status: 0 pass, 1 mismatch, protocol, register or timing error, 2 bad input, 3 timeout.
#include <fmt/core.h>
#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <fstream>
#include <map>
#include <optional>
#include <random>
#include <regex>

#include "compare.hpp"
#include "config_cli.hpp"
#include "golden_model.hpp"
#include "image_io.hpp"
#include "stimulus.hpp"
#include "stream_bench.hpp"
#include "widths.hpp"

namespace fpstereo::tb {
namespace {

constexpr const char* kTool = "fpstereo-tb";
constexpr int kExitFail = 1;
constexpr int kExitTimeout = 3;

// The framing faults --fault injects into the second of four frames (docs/architecture.md,
// "Robust video input", says how the design answers each).
const std::vector<std::string> kFaults = {"early-eol",   "late-eol",   "missing-sof", "repeated-sof",
                                          "short-frame", "long-frame", "reset",       "disable"};

struct Options {
  std::string left, right;
  bool crop = false;
  int upscale = 1;
  bool random = false;
  int shift = -1;  // --shifted; -1 when not given
  int levels = 256;
  uint32_t seed = 1;
  int frames = 2;
  double idle = 0.5;
  double backpressure = 0.5;
  uint64_t timeout = 0;  // 0: derived from the configuration
  bool zero_init = false;
  std::vector<std::string> settings;  // --set name=value
  std::vector<std::string> faults;
  std::string fault_stream = "both";
};

StereoConfig load_tb_config() {
  StereoConfig cfg;
  apply_config_file(cfg, design_files().config);
  validate(cfg);
  return cfg;
}

// ---- The timing the design states, in the banner comment its files open with (the generator's
// "Initiation interval" and "Latency" lines): read from the top's file when the bench runs, so
// that the bench checks what the design says, not a figure it would compute itself.
struct StatedTiming {
  std::optional<uint64_t> cycles_per_frame;      // "expected cycles per frame without stalls: N"
  std::optional<uint64_t> first_output_latency;  // "Latency without stalls from the first input
                                                 // handshake to the first output handshake: N cycles"
};

StatedTiming read_stated_timing(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("cannot read '{}', the design's top file", path));
  static const std::regex cycles(R"(expected cycles per frame without stalls: (\d+)\b)");
  static const std::regex latency(
      R"(from the first input handshake to the first output handshake: (\d+) cycles)");
  StatedTiming stated;
  std::string line;
  std::smatch m;
  while (std::getline(in, line) && line.rfind("//", 0) == 0) {  // the banner: the leading comment
    if (std::regex_search(line, m, cycles)) stated.cycles_per_frame = std::stoull(m[1]);
    if (std::regex_search(line, m, latency)) stated.first_output_latency = std::stoull(m[1]);
  }
  return stated;
}

// ---- The AXI4-Lite registers as the generator wrote them in <prefix>_regs.h (offsets, and the
// values the design must report), read when the bench runs, like the configuration.
class RegisterMap {
 public:
  explicit RegisterMap(const std::string& path) {
    if (path.empty()) return;  // no control interface
    std::ifstream in(path);
    if (!in) throw InputError(fmt::format("cannot read '{}', the design's register header", path));
    static const std::regex guard(R"(^#ifndef ([A-Z0-9_]+)_REGS_H$)");
    static const std::regex define(R"(^#define ([A-Z0-9_]+) +(0x[0-9A-Fa-f]+|[0-9]+)u\b)");
    std::string line, prefix;
    std::smatch m;
    while (std::getline(in, line)) {
      if (std::regex_search(line, m, guard)) prefix = m[1].str() + "_";
      if (!prefix.empty() && std::regex_search(line, m, define) && m[1].str().rfind(prefix, 0) == 0)
        values_[m[1].str().substr(prefix.size())] = uint32_t(std::stoul(m[2].str(), nullptr, 0));
    }
    if (values_.empty()) throw InputError(fmt::format("'{}' defines no registers", path));
  }
  uint32_t operator()(const std::string& name) const {
    const auto found = values_.find(name);
    if (found == values_.end()) throw InputError("the register header does not define " + name);
    return found->second;
  }

 private:
  std::map<std::string, uint32_t> values_;
};

// The offset or value the register header gives `name`.
uint32_t reg(const std::string& name) {
  static const RegisterMap map(design_files().registers);
  return map(name);
}

// ---- Run-time settings (--set): each is a register and the configuration field it stands for.
struct Setting {
  const char* name;
  uint32_t offset;
  int StereoConfig::*field;
};

std::vector<Setting> settings_table() {
  if (!has_control()) return {};
  return {{"p1", reg("P1"), &StereoConfig::p1},
          {"p2", reg("P2"), &StereoConfig::p2},
          {"uniqueness", reg("UNIQUENESS"), &StereoConfig::uniqueness},
          {"lr-threshold", reg("LR_THRESHOLD"), &StereoConfig::lr_threshold},
          {"width", reg("WIDTH"), &StereoConfig::width},
          {"height", reg("HEIGHT"), &StereoConfig::height}};
}

// The register writes of --set, in an order that keeps P1 <= P2 throughout, and the
// configuration the golden model runs with after them. Throws InputError for what the design
// cannot take.
std::pair<std::vector<RegisterAccess>, StereoConfig> parse_settings(const std::vector<std::string>& items,
                                                                    const StereoConfig& cfg) {
  if (!items.empty() && !has_control())
    throw InputError(
        "--set needs the AXI4-Lite control interface (the design was generated with --no-axi-lite)");
  StereoConfig after = cfg;
  std::map<std::string, uint32_t> values;
  const auto table = settings_table();
  for (const auto& item : items) {
    const auto eq = item.find('=');
    const std::string name = item.substr(0, eq);
    const auto it =
        std::find_if(table.begin(), table.end(), [&](const Setting& s) { return name == s.name; });
    if (eq == std::string::npos || it == table.end())
      throw InputError(
          fmt::format("--set '{}': expected NAME=VALUE with NAME one of p1, p2, uniqueness, "
                      "lr-threshold, width, height",
                      item));
    int value = 0;
    try {
      size_t used = 0;
      value = std::stoi(item.substr(eq + 1), &used);
      if (used != item.size() - eq - 1) throw std::invalid_argument("trailing text");
    } catch (const std::exception&) {
      throw InputError(fmt::format("--set '{}': the value is not an integer", item));
    }
    after.*(it->field) = value;
    values[name] = uint32_t(value);
  }
  try {
    validate(after);
  } catch (const ConfigError& e) {
    throw InputError(fmt::format("--set: the settings are not a valid configuration: {}", e.what()));
  }
  if (after.width > cfg.width || after.height > cfg.height)
    throw InputError(fmt::format("--set: the design takes frames up to {}x{}", cfg.width, cfg.height));
  if (after.p2 > cfg.p2) throw InputError(fmt::format("--set: p2 is at most {} in this design", cfg.p2));
  if (values.count("uniqueness") && cfg.uniqueness == 0)
    throw InputError("--set uniqueness: the design was generated without the uniqueness check");
  if (values.count("lr-threshold") && cfg.lr == LrCheck::None)
    throw InputError("--set lr-threshold: the design was generated without a left-right check");
  // Lowering P2 below the current P1 needs P1 first; otherwise P2 goes first.
  std::vector<std::string> order = {"width", "height", "uniqueness", "lr-threshold"};
  if (after.p2 < cfg.p1)
    order.insert(order.begin(), {"p1", "p2"});
  else
    order.insert(order.begin(), {"p2", "p1"});
  std::vector<RegisterAccess> writes;
  for (const auto& name : order)
    if (values.count(name)) {
      const auto it =
          std::find_if(table.begin(), table.end(), [&](const Setting& s) { return name == s.name; });
      writes.push_back({it->offset, values[name], true});
    }
  return {writes, after};
}

// The design takes frames of at most the configured size: an image file (enlarged --upscale
// times) must have the frame's size, or be at least that large with --crop (which takes the
// top-left region).
GrayImage load_input(const std::string& path, const std::string& role, int width, int height, bool crop,
                     int factor) {
  GrayImage img = load_gray(path, role);
  if (factor > 1) img = upscale(img, factor);
  const bool exact = img.width == width && img.height == height;
  const bool croppable = img.width >= width && img.height >= height;
  if (exact || (crop && croppable)) return crop_top_left(img, width, height);
  throw InputError(fmt::format("{} '{}' is {}x{}{}, the frames are {}x{}{}", role, path, img.width,
                               img.height, factor > 1 ? fmt::format(" upscaled {}x", factor) : "", width,
                               height, crop ? "" : " (--crop takes the top-left region of a larger image)"));
}

// The distinct pairs of a frame size; frame i uses pair i % size. Generated inputs give every
// frame its own pair (at least four, so that the throughput run and a fault run stream
// different ones).
std::vector<StereoPair> make_pairs(const Options& opt, int width, int height, uint32_t seed) {
  if (!opt.left.empty())
    return {{load_input(opt.left, "left image", width, height, opt.crop, opt.upscale),
             load_input(opt.right, "right image", width, height, opt.crop, opt.upscale)}};
  std::mt19937 rng(seed);
  std::vector<StereoPair> pairs;
  for (int i = 0; i < std::max(opt.frames, 4); ++i)
    pairs.push_back(opt.shift >= 0 ? shifted_pair(width, height, opt.shift, opt.levels, rng)
                                   : random_pair(width, height, opt.levels, rng));
  return pairs;
}

std::string describe_input(const Options& opt) {
  if (!opt.left.empty())
    return fmt::format("'{}' and '{}'{}{}", opt.left, opt.right,
                       opt.upscale > 1 ? fmt::format(", upscaled {}x", opt.upscale) : "",
                       opt.crop ? ", cropped" : "");
  const std::string kind =
      opt.shift >= 0 ? fmt::format("shifted pairs (disparity {})", opt.shift) : "random pairs";
  return fmt::format("{}, {} gray levels, seed {}", kind, opt.levels, opt.seed);
}

// ---- A run: what goes in, and what must come out.
struct Run {
  explicit Run(std::string run_title) : title(std::move(run_title)) {}
  std::string title;
  StreamPlan plan;
  // Per output frame, the golden model's planes of the design's outputs; none: not compared.
  std::vector<std::optional<Planes>> expected;
  std::vector<std::pair<uint32_t, uint32_t>> registers;  // (offset, value) expected at the end
  std::vector<std::string> register_names;
};

void add_frame(Run& run, const StereoPair& pair, const StereoConfig& cfg) {
  const auto left = frame_beats(pair.left, cfg.ppc), right = frame_beats(pair.right, cfg.ppc);
  run.plan.left.insert(run.plan.left.end(), left.begin(), left.end());
  run.plan.right.insert(run.plan.right.end(), right.begin(), right.end());
  run.plan.output_sizes.push_back({cfg.width, cfg.height});
  run.expected.push_back(run_golden(cfg, pair.left, pair.right, output_planes(cfg)));
}

// The register `name` must read `value` once every output has arrived.
void expect_register(Run& run, const std::string& name, uint32_t value) {
  const uint32_t offset = reg(name);
  run.plan.reads_at_end.push_back(offset);
  run.registers.push_back({offset, value});
  run.register_names.push_back(name);
}

// The status counters a run must end with (a reset in the run clears them).
void expect_counters(Run& run, uint32_t done, uint32_t dropped, uint32_t truncated, uint32_t errors,
                     uint32_t rejected) {
  if (!has_control()) return;
  expect_register(run, "FRAMES_DONE", done);
  expect_register(run, "FRAMES_DROPPED", dropped);
  expect_register(run, "FRAMES_TRUNCATED", truncated);
  expect_register(run, "PROTOCOL_ERRORS", errors);
  expect_register(run, "REJECTED_WRITES", rejected);
}

// Frames of the throughput run: the steady state is measured over the last three.
constexpr int kThroughputFrames = 4;

// Clean frames back to back. With the control interface, also writes the design must refuse (out
// of range, breaking P1 <= P2, read-only), and reads of what the design says it is.
Run throughput_run(const StereoConfig& cfg, const std::vector<StereoPair>& pairs) {
  Run run{"throughput run, no idle, no backpressure"};
  for (int i = 0; i < kThroughputFrames; ++i) add_frame(run, pairs[i % pairs.size()], cfg);
  uint32_t refused = 0;
  if (has_control()) {
    std::vector<RegisterAccess> bad = {
        {reg("WIDTH"), uint32_t(cfg.width) + 1}, {reg("HEIGHT"), 0}, {reg("P1"), uint32_t(cfg.p2) + 1},
        {reg("P2"), uint32_t(cfg.p2) + 1},       {reg("STATUS"), 1}, {reg("FRAMES_DONE"), 0}};
    // With several pixels per beat, a width in range that is not a whole number of beats.
    if (cfg.ppc > 1) bad.push_back({reg("WIDTH"), uint32_t(cfg.width - cfg.ppc - 1)});
    run.plan.actions.push_back({0, bad});
    refused = uint32_t(bad.size());
    expect_register(run, "VERSION", reg("VERSION_VALUE"));
    expect_register(run, "CONFIG_ID", reg("CONFIG_ID_VALUE"));
    expect_register(run, "MAX_WIDTH", reg("MAX_WIDTH_VALUE"));
    expect_register(run, "MAX_HEIGHT", reg("MAX_HEIGHT_VALUE"));
    expect_register(run, "DMAX", uint32_t(cfg.dmax));
    expect_register(run, "UF", uint32_t(cfg.uf));
    expect_register(run, "CYCLES_PER_FRAME", reg("CYCLES_PER_FRAME_VALUE"));
    expect_register(run, "PIXELS_PER_BEAT", uint32_t(cfg.ppc));
    expect_register(run, "WIDTH", uint32_t(cfg.width));
    expect_register(run, "P2", uint32_t(cfg.p2));
  }
  expect_counters(run, kThroughputFrames, 0, 0, 0, refused);
  return run;
}

// `frames` frames; settings written during frame 0 hold from frame 1 on.
Run checked_run(const Options& opt, const StereoConfig& cfg, const std::vector<StereoPair>& pairs,
                const std::vector<RegisterAccess>& writes, const StereoConfig& after,
                const std::vector<StereoPair>& pairs_after) {
  Run run{fmt::format("checked run, idle {}, backpressure {}", opt.idle, opt.backpressure)};
  for (int i = 0; i < opt.frames; ++i) {
    const bool changed = i > 0 && !writes.empty();
    const auto& source = changed ? pairs_after : pairs;
    add_frame(run, source[size_t(i) % source.size()], changed ? after : cfg);
  }
  if (!writes.empty()) {
    run.title += ", settings from frame 1:";
    for (const auto& item : opt.settings) run.title += " " + item;
    run.plan.actions.push_back({1, writes});
  }
  expect_counters(run, uint32_t(opt.frames), 0, 0, 0, 0);
  return run;
}

// Four frames A F B C, the fault in F (on one or both streams).
Run fault_run(const std::string& fault, const Options& opt, const StereoConfig& cfg,
              const std::vector<StereoPair>& pairs) {
  const bool in_beats = fault != "reset" && fault != "disable";
  Run run{fmt::format(
      "fault run: {}{}, idle {}, backpressure {}", fault,
      in_beats ? " on " + opt.fault_stream + (opt.fault_stream == "both" ? " streams" : " stream") : "",
      opt.idle, opt.backpressure)};
  // Faults are placed in beats: a row is w beats of ppc pixels.
  const int w = cfg.width / cfg.ppc, h = cfg.height;
  const size_t frame = size_t(w) * size_t(h);
  const auto& pa = pairs[0 % pairs.size()];
  const auto& pf = pairs[1 % pairs.size()];
  const auto& pb = pairs[2 % pairs.size()];
  const auto& pc = pairs[3 % pairs.size()];
  const Planes golden_f = run_golden(cfg, pf.left, pf.right, output_planes(cfg));

  add_frame(run, pa, cfg);
  // F, and what the design makes of it: output frames (checked or not) and counter deltas.
  auto inject = [&](std::vector<Beat> beats) {
    const size_t middle_row = size_t(h / 2) * size_t(w);
    if (fault == "early-eol") {  // row h/2 ends 3 pixels early
      beats.erase(beats.begin() + long(middle_row + w - 3), beats.begin() + long(middle_row + w));
      beats[middle_row + w - 4].last = true;
    } else if (fault == "late-eol") {  // row h/2 runs 3 pixels long
      beats[middle_row + w - 1].last = false;
      std::vector<Beat> extra(3, Beat{0x5a, false, false});
      extra.back().last = true;
      beats.insert(beats.begin() + long(middle_row + w), extra.begin(), extra.end());
    } else if (fault == "missing-sof") {
      beats[0].user = false;
    } else if (fault == "repeated-sof") {  // a second start of frame at row h/2
      beats[middle_row].user = true;
    } else if (fault == "short-frame") {  // two rows missing
      beats.resize(frame - 2 * size_t(w));
    } else if (fault == "long-frame") {  // two rows too many
      for (size_t i = 0; i < 2 * size_t(w); ++i) beats.push_back(beats[frame - 2 * size_t(w) + i]);
    }
    return beats;
  };
  auto left_f = frame_beats(pf.left, cfg.ppc), right_f = frame_beats(pf.right, cfg.ppc);
  if (opt.fault_stream != "right") left_f = inject(left_f);
  if (opt.fault_stream != "left") right_f = inject(right_f);
  const size_t a_beats = run.plan.left.size();
  run.plan.left.insert(run.plan.left.end(), left_f.begin(), left_f.end());
  run.plan.right.insert(run.plan.right.end(), right_f.begin(), right_f.end());
  const size_t f_beats = left_f.size();

  // Output frames from F, and the counters at the end (docs/architecture.md).
  uint32_t done = 4, dropped = 0, truncated = 0, errors = 0;
  auto unchecked = [&](int count) {
    for (int i = 0; i < count; ++i) {
      run.plan.output_sizes.push_back({cfg.width, h});
      run.expected.push_back(std::nullopt);
    }
  };
  if (fault == "early-eol" || fault == "late-eol" || fault == "short-frame") {
    unchecked(1);
    truncated = errors = 1;
  } else if (fault == "repeated-sof" && opt.fault_stream == "both") {
    unchecked(2);  // F up to the second start, then from it to B's start
    done = 5;
    truncated = errors = 2;
  } else if (fault == "repeated-sof") {
    // On one stream: F is truncated there; the other stream skips the rest of F, half a frame,
    // so the second start's frame is skipped as its counterpart.
    unchecked(1);
    truncated = errors = 1;
  } else if (fault == "missing-sof") {
    done = 3;
    errors = 1;
  } else if (fault == "long-frame") {
    run.plan.output_sizes.push_back({cfg.width, h});
    run.expected.push_back(golden_f);  // F itself is complete; its extra rows are skipped
    errors = 1;
  } else if (fault == "reset") {
    // aresetn as F's last row begins: F's output is cut short, the counters start again, the
    // rest of F is skipped (one error), B and C follow. A is complete by then even where F
    // follows A on: frames overlap only where the drain is at least two rows shorter than a frame.
    run.plan.actions.push_back({a_beats + f_beats - size_t(w), {}, true});
    done = 2;
    errors = 1;
  } else if (fault == "disable") {
    // CONTROL.enable = 0 during A; F is skipped; enable = 1 before B is offered.
    // Not at A's first beat taken: the input register slices take two beats of a stream before
    // the framing stage sees its start, and the right stream may not have offered its start yet,
    // so a write then can land before A starts, and the design rightly skips A as well as F.
    // Half-way through A's left beats, A has started.
    run.plan.actions.push_back({a_beats / 2, {{reg("CONTROL"), 0}}, false, a_beats + f_beats});
    run.plan.actions.push_back({a_beats + f_beats, {{reg("CONTROL"), 1}}, false, a_beats + f_beats, true});
    done = 3;
    dropped = 1;
  }
  add_frame(run, pb, cfg);
  add_frame(run, pc, cfg);
  expect_counters(run, done, dropped, truncated, errors, 0);
  return run;
}

struct Totals {
  size_t frames = 0;
  size_t mismatches = 0;
  size_t protocol_errors = 0;
  size_t register_errors = 0;
  size_t timing_errors = 0;
};

// Streams the run, compares each output frame with its golden words, the register accesses with
// what they must return, and prints the result per frame and the protocol errors.
StreamRun check_run(const Run& run_spec, const StereoConfig& cfg, const StreamSettings& settings,
                    Totals& totals) {
  const auto start = std::chrono::steady_clock::now();
  const StreamRun run = stream(cfg, run_spec.plan, settings);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const size_t frames = run_spec.plan.output_sizes.size();
  const std::string span = run.frame_end_cycle.size() == frames && frames > 0
                               ? fmt::format("{} cycles from the first input to the last output handshake",
                                             run.frame_end_cycle.back() - run.first_input_cycle + 1)
                               : "incomplete";
  fmt::print("{} ({} output frames): {} ({} cycles simulated in {:.2f} s, {:.0f} kcycles/s)\n",
             run_spec.title, frames, span, run.cycles, seconds, run.cycles / seconds / 1e3);
  // Each plane of the outputs: as many frames as the words, each equal to its golden plane.
  const std::vector<Plane> planes = output_planes(cfg);
  const auto frames_of = [&](Plane plane) -> const std::vector<DisparityImage>& {
    static const std::vector<DisparityImage> none;
    const auto found = run.frames.find(plane);
    return found == run.frames.end() ? none : found->second;
  };
  for (const Plane plane : planes) {
    const std::vector<DisparityImage>& got = frames_of(plane);
    // Messages name the planes besides the words: "<plane>, frame 2: ...".
    const std::string name = plane == Plane::Disparity ? "" : std::string(plane_info(plane).name) + ", ";
    if (got.size() != frames_of(Plane::Disparity).size()) {
      fmt::print("{}: {} frames, expected {}\n", plane_info(plane).name, got.size(),
                 frames_of(Plane::Disparity).size());
      ++totals.mismatches;
    }
    for (size_t i = 0; i < got.size() && i < run_spec.expected.size(); ++i) {
      if (!run_spec.expected[i]) {
        if (plane == Plane::Disparity)
          fmt::print("frame {}: truncated by the fault, framing checked only\n", i);
        continue;
      }
      const Comparison c = compare_words(run_spec.expected[i]->at(plane), got[i]);
      fmt::print("{}frame {}: {}\n", name, i, c.report());
      totals.mismatches += c.mismatches + (c.size_matches ? 0 : 1);
      ++totals.frames;
    }
  }
  if (settings.idle > 0 || settings.backpressure > 0)
    fmt::print("stalls: left idle while tready {} cycles, right {}; output held by backpressure {} cycles\n",
               run.left_idle_while_ready, run.right_idle_while_ready, run.output_held);
  // Writes answer OKAY unless the run meant them to be refused (the reads at the end follow
  // every write); reads return what the run expects.
  size_t reads = 0;
  std::string register_report;
  for (const auto& access : run.accesses) {
    if (access.write) continue;
    if (reads < run_spec.registers.size()) {
      const auto& [offset, value] = run_spec.registers[reads];
      if (access.offset != offset || access.value != value || access.response != 0) {
        register_report +=
            fmt::format(" {}={} (expected {})", run_spec.register_names[reads], access.value, value);
        ++totals.register_errors;
      } else {
        register_report += fmt::format(" {}={}", run_spec.register_names[reads], access.value);
      }
    }
    ++reads;
  }
  if (reads != run_spec.registers.size()) {
    register_report += fmt::format(" ({} of {} reads done)", reads, run_spec.registers.size());
    ++totals.register_errors;
  }
  if (!run_spec.registers.empty()) fmt::print("registers:{}\n", register_report);
  size_t refused = 0;
  for (const auto& access : run.accesses) refused += access.write && access.response != 0;
  if (refused) fmt::print("writes refused (SLVERR): {}\n", refused);
  fmt::print("protocol errors: {}\n", run.protocol.count);
  for (const auto& e : run.protocol.first) fmt::print("  {}\n", e);
  if (run.protocol.count > run.protocol.first.size()) fmt::print("  ...\n");
  totals.protocol_errors += run.protocol.count;
  return run;
}

// One pixel per dmax/uf cycles, no bubbles.
uint64_t ideal_cycles_per_frame(const StereoConfig& cfg) {
  return uint64_t(cfg.width) * uint64_t(cfg.height) * uint64_t(cfg.dmax / cfg.uf);
}

// Prints the throughput run's timing and checks it against what the design states, exactly:
//   cycles per frame: between the last output handshakes of consecutive frames, each of the three
//     intervals of the four frames (steady state; the sources never withhold a pixel and the sink
//     is always ready, so the design alone sets it), equal to the banner's "expected cycles per
//     frame without stalls";
//   first-output latency: from the cycle of the first input handshake (either stream; cycles
//     counted at the rising edge) to the cycle of frame 0's first output handshake, equal to the
//     banner's "Latency from the first input handshake to the first output handshake".
// Returns the number of timing errors, each printed as a FAIL line.
size_t check_timing(const StreamRun& run, const StereoConfig& cfg, const StatedTiming& stated) {
  const size_t frames = kThroughputFrames;
  if (run.frame_start_cycle.size() < frames || run.frame_end_cycle.size() < frames) {
    fmt::print("FAIL: the throughput run did not complete {} frames, nothing to measure\n", frames);
    return 1;
  }
  const uint64_t first_output = run.frame_start_cycle[0] - run.first_input_cycle;
  const uint64_t latency = run.frame_end_cycle[0] - run.first_input_cycle;
  std::vector<uint64_t> intervals;
  for (size_t i = 1; i < frames; ++i)
    intervals.push_back(run.frame_end_cycle[i] - run.frame_end_cycle[i - 1]);
  const uint64_t per_frame = (run.frame_end_cycle[frames - 1] - run.frame_end_cycle[0]) / (frames - 1);
  const uint64_t ideal = ideal_cycles_per_frame(cfg);
  fmt::print("first output: {} cycles (first input handshake to the first frame's first output pixel)\n",
             first_output);
  fmt::print("latency: {} cycles (first input handshake to the first frame's last output pixel)\n", latency);
  fmt::print("steady state: {} cycles per frame over frames 0 to {} (intervals {})\n", per_frame, frames - 1,
             fmt::join(intervals, ", "));
  fmt::print("ideal: {} cycles per frame (W*H*dmax/uf = {}*{}*{}/{}), ratio {:.4f}\n", ideal, cfg.width,
             cfg.height, cfg.dmax, cfg.uf, double(per_frame) / double(ideal));
  size_t errors = 0;
  const bool uniform =
      std::all_of(intervals.begin(), intervals.end(), [&](uint64_t i) { return i == per_frame; });
  if (!stated.cycles_per_frame) {
    fmt::print(
        "FAIL: the design does not state its cycles per frame (no 'expected cycles per frame without "
        "stalls: N' in the banner of {})\n",
        design_files().top);
    ++errors;
  } else if (!uniform) {
    fmt::print("FAIL: the frames ended {} cycles apart, not at one steady interval\n",
               fmt::join(intervals, ", "));
    ++errors;
  } else if (per_frame != *stated.cycles_per_frame) {
    fmt::print("FAIL: measured {} cycles per frame, the design states {}\n", per_frame,
               *stated.cycles_per_frame);
    ++errors;
  }
  if (!stated.first_output_latency) {
    fmt::print(
        "FAIL: the design does not state its first-output latency (no 'Latency from the first input "
        "handshake ...' in the banner of {})\n",
        design_files().top);
    ++errors;
  } else if (first_output != *stated.first_output_latency) {
    fmt::print("FAIL: measured a first-output latency of {} cycles, the design states {}\n", first_output,
               *stated.first_output_latency);
    ++errors;
  }
  // The register map states the figure too (CYCLES_PER_FRAME, read back in the run above).
  if (has_control() && stated.cycles_per_frame && *stated.cycles_per_frame != reg("CYCLES_PER_FRAME_VALUE")) {
    fmt::print("FAIL: the banner states {} cycles per frame, the register map {}\n", *stated.cycles_per_frame,
               reg("CYCLES_PER_FRAME_VALUE"));
    ++errors;
  }
  if (errors == 0)
    fmt::print("timing: as the design states ({} cycles per frame, first-output latency {} cycles)\n",
               per_frame, first_output);
  return errors;
}

int run_bench(const Options& opt) {
  const StereoConfig cfg = load_tb_config();
  const StatedTiming stated = read_stated_timing(design_files().top);
  const Widths widths = derive_widths(cfg);
  fmt::print("{}: {} from {}\n", kTool, config_tag(cfg), design_files().config);
  fmt::print("{}x{}, {} {}x{}, dmax {}, uf {}, paths {}, output word {} bits, {} pixel(s) per beat, control {}\n",
             cfg.width, cfg.height, to_string(cfg.cost), cfg.window, cfg.window, cfg.dmax, cfg.uf,
             paths_to_string(cfg.paths), widths.output_word, cfg.ppc, has_control() ? "AXI4-Lite" : "none");
  // Each output stream's tdata as the list lays it out; Verilator holds 24 bits in 32, 48 in 64
  // and more in 32-bit words.
  for (const auto& stream : output_streams(cfg)) {
    const int bits = stream.tdata_bits();
    const int held = bits <= 8 ? 8 : bits <= 16 ? 16 : bits <= 32 ? 32 : bits <= 64 ? 64 : 32 * ((bits + 31) / 32);
    if (held_tdata_bits(stream.port) != held) {
      fmt::print("FAIL: {}_tdata is held in {} bits, the output list asks for {} ({} bits)\n", stream.port,
                 held_tdata_bits(stream.port), held, bits);
      return kExitFail;
    }
  }
  std::vector<std::string> faults = opt.faults;
  if (std::find(faults.begin(), faults.end(), "all") != faults.end()) {
    faults = kFaults;
    if (!has_control()) faults.pop_back();  // "disable" needs the control interface
  }
  if (std::find(faults.begin(), faults.end(), "disable") != faults.end() && !has_control())
    throw InputError("--fault disable needs the AXI4-Lite control interface");
  const auto [writes, after] = parse_settings(opt.settings, cfg);
  const std::vector<StereoPair> pairs = make_pairs(opt, cfg.width, cfg.height, opt.seed);
  const std::vector<StereoPair> pairs_after =
      writes.empty() ? pairs : make_pairs(opt, after.width, after.height, opt.seed + 7);
  fmt::print("input: {}\n", describe_input(opt));

  StreamSettings settings;
  settings.timeout = opt.timeout ? opt.timeout : 20 * ideal_cycles_per_frame(cfg) + 100000;
  settings.seed = opt.seed;
  settings.random_init = !opt.zero_init;
  settings.progress = ::isatty(STDERR_FILENO);  // in a script, only the report

  Totals totals;
  const StreamRun measured = check_run(throughput_run(cfg, pairs), cfg, settings, totals);
  if (!measured.timeout.empty()) {
    fmt::print("{}\n", measured.timeout);
    return kExitTimeout;
  }
  totals.timing_errors += check_timing(measured, cfg, stated);

  // With neither idle cycles nor backpressure, up to four plain frames repeat the throughput run.
  std::vector<Run> runs;
  if (opt.idle > 0 || opt.backpressure > 0 || opt.frames > kThroughputFrames || !writes.empty())
    runs.push_back(checked_run(opt, cfg, pairs, writes, after, pairs_after));
  for (const auto& fault : faults) runs.push_back(fault_run(fault, opt, cfg, pairs));
  settings.idle = opt.idle;
  settings.backpressure = opt.backpressure;
  for (const auto& run : runs) {
    ++settings.seed;
    const StreamRun checked = check_run(run, cfg, settings, totals);
    if (!checked.timeout.empty()) {
      fmt::print("{}\n", checked.timeout);
      return kExitTimeout;
    }
  }

  const bool pass = totals.mismatches == 0 && totals.protocol_errors == 0 && totals.register_errors == 0 &&
                    totals.timing_errors == 0;
  fmt::print(
      "{}: {} frames compared, {} mismatching pixels, {} protocol errors, {} register errors, {} timing "
      "errors\n",
      pass ? "PASS" : "FAIL", totals.frames, totals.mismatches, totals.protocol_errors,
      totals.register_errors, totals.timing_errors);
  return pass ? 0 : kExitFail;
}

}  // namespace
}  // namespace fpstereo::tb

int main(int argc, char** argv) {
  using namespace fpstereo;
  using namespace fpstereo::tb;
  start_image_codecs();  // its registry built as the program starts (image_io.hpp)
  CLI::App app{"fpstereo-tb: checks the Verilated SGM pipeline against the golden model, bit for bit"};
  Options opt;
  auto* left = app.add_option("--left", opt.left, "left (base) image file");
  auto* right = app.add_option("--right", opt.right, "right (match) image file");
  auto* crop = app.add_flag("--crop", opt.crop, "take the top-left region of larger images");
  auto* upscale = app.add_option("--upscale", opt.upscale, "enlarge the images N times (bilinear) first")
                      ->check(CLI::Range(1, 16));
  auto* random =
      app.add_flag("--random", opt.random, "random texture pairs, a new one per frame (the default)");
  auto* shifted =
      app.add_option("--shifted", opt.shift,
                     "pairs with a constant disparity D: right random, left = right shifted by D px")
          ->check(CLI::Range(0, 8192));
  auto* levels =
      app.add_option("--levels", opt.levels, "gray levels of generated textures (few levels: many ties)")
          ->capture_default_str()
          ->check(CLI::Range(2, 256));
  app.add_option("--seed", opt.seed, "seed of generated pairs, idle and backpressure patterns, initial state")
      ->capture_default_str();
  app.add_option("--frames", opt.frames, "frames streamed back to back in the checked run")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  app.add_option("--idle", opt.idle, "probability that a source withholds tvalid on a cycle")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--backpressure", opt.backpressure, "probability that the sink deasserts tready on a cycle")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--timeout", opt.timeout,
                 "cycles without an output handshake before giving up [20 * W*H*dmax/uf + 100000]")
      ->check(CLI::Range(uint64_t(1), uint64_t(1) << 48));
  app.add_flag("--zero-init", opt.zero_init, "start registers and memories at 0 instead of random values");
  app.add_option(
         "--set", opt.settings,
         "run-time setting NAME=VALUE written over AXI4-Lite during frame 0 of the checked run, in effect "
         "from frame 1 (p1, p2, uniqueness, lr-threshold, width, height; repeatable)")
      ->delimiter(',');
  std::vector<std::string> fault_names = kFaults;
  fault_names.push_back("all");
  auto* fault = app.add_option(
                       "--fault", opt.faults,
                       "a run of four frames with a framing fault in the second, per fault given: " +
                           [&] {
                             std::string all;
                             for (const auto& f : fault_names) all += (all.empty() ? "" : ", ") + f;
                             return all;
                           }())
                    ->delimiter(',')
                    ->check(CLI::IsMember(fault_names));
  app.add_option("--fault-stream", opt.fault_stream, "the stream(s) the fault is injected into")
      ->capture_default_str()
      ->check(CLI::IsMember({"both", "left", "right"}))
      ->needs(fault);
  left->needs(right);
  right->needs(left);
  crop->needs(left);
  upscale->needs(left);
  left->excludes(random)->excludes(shifted)->excludes(levels);  // real images have their own levels
  shifted->excludes(random);

  try {
    app.parse(argc, argv);
    return run_bench(opt);
  } catch (const CLI::ParseError& e) {
    return report_parse_error(app, kTool, e);
  } catch (const ConfigError& e) {
    return report_error(kTool, std::string("invalid config: ") + e.what());
  } catch (const InputError& e) {
    return report_error(kTool, e.what());
  }
}
