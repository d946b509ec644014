// StereoConfig: the single source of truth for every pipeline parameter.
// The golden model, the emitters, the test benches and the CLIs all read it.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fpstereo {

enum class CostFunction { Census, Rank, Sad, Zsad, Shd };
enum class LrCheck { None, Lr1, Lr2 };
// The curve fitted through the winner's and its two neighbours' aggregated costs for sub-pixel
// disparity (docs/semantics.md, section 4): two lines of equal slope, or a parabola.
enum class SubpixelFit { Equiangular, Parabola };
// The pixel-wise term of the fused matching cost (docs/semantics.md, section 2): the absolute
// difference of the two pixels' intensities, or of their horizontal gradients.
enum class FusedTerm { Intensity, Gradient };

// Aggregation path bit masks. The angle names the direction the path comes from: 0 = from the
// left (x-1, y), 45 = from the upper left (x-1, y-1), 90 = from above (x, y-1), 135 = from the
// upper right (x+1, y-1), 180 = from the right (x+1, y), computed over a row once its costs are
// known (docs/semantics.md section 3).
enum PathMask : unsigned {
  kPath0 = 1u << 0,
  kPath45 = 1u << 1,
  kPath90 = 1u << 2,
  kPath135 = 1u << 3,
  kPath180 = 1u << 4,
  // "all": the four paths the hardware streams in raster order; presets keep them.
  kAllPaths = kPath0 | kPath45 | kPath90 | kPath135,
  kEveryPath = kAllPaths | kPath180,
};

struct PathDirection {
  PathMask mask;
  int angle;
  int dx, dy;  // offset from a pixel to its predecessor on the path
};
// The five paths in a fixed order; every model iterates them in this order.
const std::vector<PathDirection>& path_directions();

// The largest speckle_size: the filter's delay and its label memories grow with it.
constexpr int kMaxSpeckleSize = 4096;
// The fused cost's weight counts eighths: its pixel-wise term is floor(k * min(diff, T) / 8).
constexpr int kFusedWeightDivisor = 8;

// Defaults are FP-Stereo's C2 configuration (census 7x7, dmax 128, uf 32, 4 paths,
// P1 = 7, P2 = 86, median 5, KITTI image size).
struct StereoConfig {
  int width = 1242;
  int height = 375;
  CostFunction cost = CostFunction::Census;
  int window = 7;      // cost window side (odd)
  int shd_window = 5;  // SHD only: side of the window the Hamming distances are summed over
  int dmax = 128;      // disparities min_disp .. min_disp + dmax - 1
  int min_disp = 0;    // the smallest disparity; words count from it (docs/semantics.md section 8)
  int uf = 32;         // disparities computed per clock (hardware unroll factor)
  // Pixels per beat of the hardware's video streams (AXI4-Stream video, UG934 samples per clock):
  // 1, 2 or 4, with uf = dmax and the width a multiple of ppc.
  int ppc = 1;
  // Fused matching cost (docs/semantics.md, section 2, the AD-Census idea): the cost plus
  // floor(fused_weight * min(|pixel-wise difference|, fused_trunc) / 8); fused_weight 0 = off.
  int fused_weight = 0;
  int fused_trunc = 20;
  FusedTerm fused_term = FusedTerm::Intensity;
  unsigned paths = kAllPaths;
  int p1 = 7;
  int p2 = 86;
  // Intensity-adaptive P2 (docs/semantics.md, section 3): along a path, P2 falls by p2_adapt / 4
  // per grey level of the base image's step from the predecessor, down to P1; 0 = constant P2.
  int p2_adapt = 0;
  // MGM-style aggregation (docs/semantics.md, section 3): each path's recursion averages the
  // terms of two causal predecessors, p - r and the one a right angle away.
  bool mgm = false;
  LrCheck lr = LrCheck::None;
  int lr_threshold = 1;  // max |D_b - D_m| that passes the left-right check
  int uniqueness = 0;    // percent; 0 = off
  int median = 5;        // median window side; 0 = off
  bool gap_interpolation = false;
  // Gap interpolation fills a run linearly between its ends where they are close (docs/semantics.md
  // section 7); set with gap-interp = linear, which also turns gap_interpolation on.
  bool gap_linear = false;
  // Speckle filter (docs/semantics.md section 5a): 4-connected regions of valid pixels whose
  // neighbours differ by at most speckle_range whole disparities, of at most speckle_size
  // pixels, become invalid (OpenCV's filterSpeckles); speckle_size 0 = off.
  int speckle_size = 0;
  int speckle_range = 2;
  int subpixel_bits = 0;  // fraction bits of the output disparity; 0 = integer disparities
  SubpixelFit subpixel_fit = SubpixelFit::Equiangular;
  // The hardware also streams the right view's disparities (the left-right check's match side).
  bool right_view = false;
  // Each output word carries the pixel's confidence (docs/semantics.md section 4) in 8 more bits.
  bool confidence = false;

  int path_count() const;
  bool operator==(const StereoConfig&) const;
  bool operator!=(const StereoConfig& o) const { return !(*this == o); }
};

// An invalid parameter or combination. what() is one line naming the parameter, the value
// and what is allowed.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws ConfigError for the first invalid value or combination.
void validate(const StereoConfig& cfg);

// Every parameter once: its name (the same as a command-line flag without "--" and as a
// config-file key), a help line, and how to set it from text and print it as text.
struct ParamSpec {
  std::string name;
  std::string help;
  void (*set)(StereoConfig&, const std::string& value);  // throws ConfigError on bad syntax
  std::string (*get)(const StereoConfig&);
};
const std::vector<ParamSpec>& param_specs();
void set_param(StereoConfig& cfg, const std::string& name, const std::string& value);

// Named presets: the FP-Stereo paper's table (S0, S1, C0 .. C4) and ours beyond it (A2 .. A6;
// A5 in the models only).
std::vector<std::string> preset_names();
StereoConfig preset(const std::string& name);  // throws ConfigError for an unknown name

// Applies a JSON (.json) or TOML (.toml) file whose keys are parameter names (and optionally
// "preset", applied first). Throws ConfigError on unknown keys, bad values or unreadable files.
void apply_config_file(StereoConfig& cfg, const std::string& path);

// The configuration a tool's flags describe, not yet validated: the preset when one was given
// (an empty name is an error, not "no preset"), then the config file when one was given, then
// each name = value.
StereoConfig compose_config(const std::optional<std::string>& preset_name, const std::string& config_file,
                            const std::map<std::string, std::string>& values);

std::string to_string(CostFunction c);
std::string to_string(LrCheck l);
std::string to_string(SubpixelFit f);
std::string to_string(FusedTerm t);
std::string paths_to_string(unsigned paths);
// "name = value" for every parameter, one per line, in param_specs() order.
std::string describe(const StereoConfig& cfg, const std::string& line_prefix = "");
// Short identifier derived from the configuration (used for module prefixes and caches).
std::string config_tag(const StereoConfig& cfg);

}  // namespace fpstereo
