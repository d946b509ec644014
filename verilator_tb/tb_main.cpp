// fpstereo-tb: streams stereo pairs through the Verilated pipeline and checks every output pixel
// against the golden model, the output stream's protocol, and the throughput.
//
// Two runs, each from reset: a throughput run (2 frames, no idle cycles, no backpressure) that
// measures latency and cycles per frame, then the checked run with the requested idle and
// backpressure probabilities. Every frame of both runs is compared pixel for pixel.
// Exit status: 0 pass, 1 mismatch or protocol error, 2 bad input, 3 timeout.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <random>

#include "compare.hpp"
#include "config_cli.hpp"
#include "golden_model.hpp"
#include "image_io.hpp"
#include "stimulus.hpp"
#include "stream_bench.hpp"
#include "widths.hpp"

#ifndef FPSTEREO_TB_CONFIG_FILE
#error "FPSTEREO_TB_CONFIG_FILE must name the config.json the RTL was generated with"
#endif

namespace fpstereo::tb {
namespace {

constexpr const char* kTool = "fpstereo-tb";
constexpr int kExitFail = 1;
constexpr int kExitTimeout = 3;

struct Options {
  std::string left, right;
  bool crop = false;
  bool random = false;
  int shift = -1;  // --shifted; -1 when not given
  int levels = 256;
  uint32_t seed = 1;
  int frames = 2;
  double idle = 0.5;
  double backpressure = 0.5;
  uint64_t timeout = 0;  // 0: derived from the configuration
  bool zero_init = false;
};

StereoConfig load_tb_config() {
  StereoConfig cfg;
  apply_config_file(cfg, FPSTEREO_TB_CONFIG_FILE);
  validate(cfg);
  return cfg;
}

// The design takes frames of exactly the configured size: an image file must have it, or be
// at least that large with --crop (which takes the top-left region).
GrayImage load_input(const std::string& path, const std::string& role, const StereoConfig& cfg, bool crop) {
  GrayImage img = load_gray(path, role);
  const bool exact = img.width == cfg.width && img.height == cfg.height;
  const bool croppable = img.width >= cfg.width && img.height >= cfg.height;
  if (exact || (crop && croppable)) return crop_top_left(img, cfg.width, cfg.height);
  throw InputError(fmt::format("{} '{}' is {}x{}, the design takes {}x{} frames{}", role, path, img.width,
                               img.height, cfg.width, cfg.height,
                               crop ? "" : " (--crop takes the top-left region of a larger image)"));
}

// The distinct pairs to stream; frame i uses pair i % size. Generated inputs give every frame
// its own pair (at least two, so that the throughput run streams two different ones).
std::vector<StereoPair> make_pairs(const Options& opt, const StereoConfig& cfg) {
  if (!opt.left.empty())
    return {{load_input(opt.left, "left image", cfg, opt.crop),
             load_input(opt.right, "right image", cfg, opt.crop)}};
  std::mt19937 rng(opt.seed);
  std::vector<StereoPair> pairs;
  for (int i = 0; i < std::max(opt.frames, 2); ++i)
    pairs.push_back(opt.shift >= 0 ? shifted_pair(cfg.width, cfg.height, opt.shift, opt.levels, rng)
                                   : random_pair(cfg.width, cfg.height, opt.levels, rng));
  return pairs;
}

std::string describe_input(const Options& opt) {
  if (!opt.left.empty())
    return fmt::format("'{}' and '{}'{}", opt.left, opt.right, opt.crop ? ", cropped" : "");
  const std::string kind =
      opt.shift >= 0 ? fmt::format("shifted pairs (disparity {})", opt.shift) : "random pairs";
  return fmt::format("{}, {} gray levels, seed {}", kind, opt.levels, opt.seed);
}

struct Totals {
  size_t frames = 0;
  size_t mismatches = 0;
  size_t protocol_errors = 0;
};

// Streams the frames, compares each output frame with the golden words of its pair and prints
// the result per frame and the protocol errors. Returns the run for its cycle counts.
StreamRun check_run(const std::string& title, const StereoConfig& cfg, const std::vector<StereoPair>& pairs,
                    const std::vector<DisparityImage>& expected, int frames, const StreamSettings& settings,
                    Totals& totals) {
  std::vector<const StereoPair*> stream;
  for (int i = 0; i < frames; ++i) stream.push_back(&pairs[size_t(i) % pairs.size()]);
  const auto start = std::chrono::steady_clock::now();
  const StreamRun run = stream_frames(cfg, stream, settings);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string span = run.frame_end_cycle.size() == size_t(frames)
                               ? fmt::format("{} cycles from the first input to the last output handshake",
                                             run.frame_end_cycle.back() - run.first_input_cycle + 1)
                               : "incomplete";
  fmt::print("{} ({} frames): {} ({} cycles simulated in {:.2f} s, {:.0f} kcycles/s)\n", title, frames, span,
             run.cycles, seconds, run.cycles / seconds / 1e3);
  for (size_t i = 0; i < run.outputs.size(); ++i) {
    const Comparison c = compare_words(expected[i % pairs.size()], run.outputs[i]);
    fmt::print("frame {}: {}\n", i, c.report());
    totals.mismatches += c.mismatches;
    ++totals.frames;
  }
  if (settings.idle > 0 || settings.backpressure > 0)
    fmt::print("stalls: left idle while tready {} cycles, right {}; output held by backpressure {} cycles\n",
               run.left_idle_while_ready, run.right_idle_while_ready, run.output_held);
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

void print_throughput(const StreamRun& run, const StereoConfig& cfg) {
  const uint64_t latency = run.frame_end_cycle[0] - run.first_input_cycle;
  const uint64_t per_frame = run.frame_end_cycle[1] - run.frame_end_cycle[0];
  const uint64_t ideal = ideal_cycles_per_frame(cfg);
  fmt::print("latency: {} cycles (first input handshake to the first frame's last output pixel)\n", latency);
  fmt::print("steady state: {} cycles per frame (between the last output pixels of frames 0 and 1)\n",
             per_frame);
  fmt::print("ideal: {} cycles per frame (W*H*dmax/uf = {}*{}*{}/{}), ratio {:.3f}\n", ideal, cfg.width,
             cfg.height, cfg.dmax, cfg.uf, double(per_frame) / double(ideal));
}

int run_bench(const Options& opt) {
  const StereoConfig cfg = load_tb_config();
  const std::vector<StereoPair> pairs = make_pairs(opt, cfg);
  const Widths widths = derive_widths(cfg);
  const int port_bits = widths.output_word <= 8 ? 8 : 16;
  fmt::print("{}: {} from {}\n", kTool, config_tag(cfg), FPSTEREO_TB_CONFIG_FILE);
  fmt::print("{}x{}, {} {}x{}, dmax {}, uf {}, paths {}, output word {} bits\n", cfg.width, cfg.height,
             to_string(cfg.cost), cfg.window, cfg.window, cfg.dmax, cfg.uf, paths_to_string(cfg.paths),
             widths.output_word);
  if (output_port_bits() != port_bits) {
    fmt::print("FAIL: m_axis_disp_tdata is held in {} bits, the contract asks for {} (output word {} bits)\n",
               output_port_bits(), port_bits, widths.output_word);
    return kExitFail;
  }

  std::vector<DisparityImage> expected;
  for (const auto& pair : pairs) expected.push_back(run_golden(cfg, pair.left, pair.right));
  fmt::print("input: {}\n", describe_input(opt));

  StreamSettings settings;
  settings.timeout = opt.timeout ? opt.timeout : 20 * ideal_cycles_per_frame(cfg) + 100000;
  settings.seed = opt.seed;
  settings.random_init = !opt.zero_init;

  Totals totals;
  const StreamRun measured =
      check_run("throughput run, no idle, no backpressure", cfg, pairs, expected, 2, settings, totals);
  if (!measured.timeout.empty()) {
    fmt::print("{}\n", measured.timeout);
    return kExitTimeout;
  }
  print_throughput(measured, cfg);

  // With neither idle cycles nor backpressure, up to two frames repeat the throughput run.
  if (opt.idle > 0 || opt.backpressure > 0 || opt.frames > 2) {
    settings.idle = opt.idle;
    settings.backpressure = opt.backpressure;
    settings.seed = opt.seed + 1;
    const std::string title =
        fmt::format("checked run, idle {}, backpressure {}", opt.idle, opt.backpressure);
    const StreamRun checked = check_run(title, cfg, pairs, expected, opt.frames, settings, totals);
    if (!checked.timeout.empty()) {
      fmt::print("{}\n", checked.timeout);
      return kExitTimeout;
    }
  }

  const bool pass = totals.mismatches == 0 && totals.protocol_errors == 0;
  fmt::print("{}: {} frames, {} mismatching pixels, {} protocol errors\n", pass ? "PASS" : "FAIL",
             totals.frames, totals.mismatches, totals.protocol_errors);
  return pass ? 0 : kExitFail;
}

}  // namespace
}  // namespace fpstereo::tb

int main(int argc, char** argv) {
  using namespace fpstereo;
  using namespace fpstereo::tb;
  CLI::App app{"fpstereo-tb: checks the Verilated SGM pipeline against the golden model, bit for bit"};
  Options opt;
  auto* left = app.add_option("--left", opt.left, "left (base) image file");
  auto* right = app.add_option("--right", opt.right, "right (match) image file");
  auto* crop = app.add_flag("--crop", opt.crop, "take the top-left region of larger images");
  auto* random =
      app.add_flag("--random", opt.random, "random texture pairs, a new one per frame (the default)");
  auto* shifted =
      app.add_option("--shifted", opt.shift,
                     "pairs with a constant disparity D: right random, left = right shifted by D px")
          ->check(CLI::Range(0, 8192));
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
  left->needs(right);
  right->needs(left);
  crop->needs(left);
  left->excludes(random)->excludes(shifted);
  shifted->excludes(random);

  try {
    app.parse(argc, argv);
    return run_bench(opt);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    return report_error(kTool, e.what());
  } catch (const ConfigError& e) {
    return report_error(kTool, std::string("invalid config: ") + e.what());
  } catch (const InputError& e) {
    return report_error(kTool, e.what());
  }
}
