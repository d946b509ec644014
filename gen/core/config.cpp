#include "config.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <optional>
#include <nlohmann/json.hpp>

#include "files.hpp"
#include "text.hpp"
#include <sstream>

namespace fpstereo {
namespace {

[[noreturn]] void reject(const std::string& name, const std::string& value, const std::string& allowed) {
  throw ConfigError(name + " = " + value + ": " + allowed);
}

// Decimal digits with an optional '-': no sign '+', no spaces, no other base.
int parse_int(const std::string& name, const std::string& text) {
  const size_t digits = text.size() - (text.rfind('-', 0) == 0 ? 1 : 0);
  const bool plain = digits > 0 && digits <= 10 &&
                     std::all_of(text.end() - long(digits), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  const long long v = plain ? std::stoll(text) : 0;
  if (!plain || v < -1000000000LL || v > 1000000000LL) reject(name, quoted(text), "expected an integer");
  return int(v);
}

bool parse_bool(const std::string& name, const std::string& text, const char* expected = "expected on or off") {
  if (text == "on" || text == "true" || text == "1" || text == "yes") return true;
  if (text == "off" || text == "false" || text == "0" || text == "no") return false;
  reject(name, quoted(text), expected);
}

// "off" is accepted wherever 0 means off.
int parse_int_or_off(const std::string& name, const std::string& text) {
  return text == "off" ? 0 : parse_int(name, text);
}

const std::vector<std::pair<std::string, CostFunction>> kCostNames = {{"census", CostFunction::Census},
                                                                      {"rank", CostFunction::Rank},
                                                                      {"sad", CostFunction::Sad},
                                                                      {"zsad", CostFunction::Zsad},
                                                                      {"shd", CostFunction::Shd}};
const std::vector<std::pair<std::string, LrCheck>> kLrNames = {
    {"none", LrCheck::None}, {"lr1", LrCheck::Lr1}, {"lr2", LrCheck::Lr2}};
const std::vector<std::pair<std::string, SubpixelFit>> kSubpixelFitNames = {
    {"equiangular", SubpixelFit::Equiangular}, {"parabola", SubpixelFit::Parabola}};
const std::vector<std::pair<std::string, FusedTerm>> kFusedTermNames = {{"intensity", FusedTerm::Intensity},
                                                                        {"gradient", FusedTerm::Gradient}};

template <class E>
E parse_enum(const std::string& name, const std::string& text,
             const std::vector<std::pair<std::string, E>>& table) {
  std::string lower = text;
  std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
  for (const auto& [n, e] : table)
    if (n == lower) return e;
  std::string allowed = "expected one of";
  for (const auto& entry : table) allowed += " " + entry.first;
  reject(name, quoted(text), allowed);
}

template <class E>
std::string enum_name(E value, const std::vector<std::pair<std::string, E>>& table) {
  for (const auto& [n, e] : table)
    if (e == value) return n;
  return "?";
}

unsigned parse_paths(const std::string& name, const std::string& text) {
  if (text == "all") return kAllPaths;
  if (text.empty()) reject(name, quoted(text), "expected a non-empty subset of 0,45,90,135,180");
  unsigned mask = 0;
  std::vector<std::string> items(1);
  for (char c : text) {  // keeps empty items, unlike getline
    if (c == ',')
      items.emplace_back();
    else
      items.back().push_back(c);
  }
  for (std::string item : items) {
    item.erase(std::remove_if(item.begin(), item.end(), ::isspace), item.end());
    bool found = false;
    for (const auto& p : path_directions())
      if (item == std::to_string(p.angle)) {
        if (mask & p.mask) reject(name, quoted(text), "each angle at most once");
        mask |= p.mask;
        found = true;
      }
    if (!found) reject(name, quoted(text), "expected a comma-separated subset of 0,45,90,135,180");
  }
  if (mask == 0) reject(name, quoted(text), "expected a non-empty subset of 0,45,90,135,180");
  return mask;
}

void check_range(const std::string& name, int v, int lo, int hi, const std::string& what = "") {
  if (v < lo || v > hi)
    reject(name, std::to_string(v),
           "must be " + (what.empty() ? "" : what + " ") + "in " + std::to_string(lo) + " .. " +
               std::to_string(hi));
}

void check_odd_window(const std::string& name, int v, int lo, int hi) {
  if (v < lo || v > hi || v % 2 == 0)
    reject(name, std::to_string(v),
           "must be an odd window side from " + std::to_string(lo) + " to " + std::to_string(hi));
}

}  // namespace

const std::vector<PathDirection>& path_directions() {
  static const std::vector<PathDirection> dirs = {
      {kPath0, 0, -1, 0}, {kPath45, 45, -1, -1}, {kPath90, 90, 0, -1}, {kPath135, 135, 1, -1}, {kPath180, 180, 1, 0}};
  return dirs;
}

int StereoConfig::path_count() const {
  int n = 0;
  for (const auto& p : path_directions()) n += (paths & p.mask) ? 1 : 0;
  return n;
}

bool StereoConfig::operator==(const StereoConfig& o) const { return describe(*this) == describe(o); }

std::string to_string(CostFunction c) { return enum_name(c, kCostNames); }
std::string to_string(LrCheck l) { return enum_name(l, kLrNames); }
std::string to_string(SubpixelFit f) { return enum_name(f, kSubpixelFitNames); }
std::string to_string(FusedTerm t) { return enum_name(t, kFusedTermNames); }

std::string paths_to_string(unsigned paths) {
  std::string s;
  for (const auto& p : path_directions())
    if (paths & p.mask) s += (s.empty() ? "" : ",") + std::to_string(p.angle);
  return s;
}

const std::vector<ParamSpec>& param_specs() {
  static const std::vector<ParamSpec> specs = {
      {"width", "image width in pixels (the maximum the hardware accepts)",
       [](StereoConfig& c, const std::string& v) { c.width = parse_int("width", v); },
       [](const StereoConfig& c) { return std::to_string(c.width); }},
      {"height", "image height in pixels (the maximum the hardware accepts)",
       [](StereoConfig& c, const std::string& v) { c.height = parse_int("height", v); },
       [](const StereoConfig& c) { return std::to_string(c.height); }},
      {"cost", "matching cost: census, rank, sad, zsad or shd",
       [](StereoConfig& c, const std::string& v) { c.cost = parse_enum("cost", v, kCostNames); },
       [](const StereoConfig& c) { return to_string(c.cost); }},
      {"window", "cost window side: odd, 3 to 11",
       [](StereoConfig& c, const std::string& v) { c.window = parse_int("window", v); },
       [](const StereoConfig& c) { return std::to_string(c.window); }},
      {"shd-window", "SHD: side of the window Hamming distances are summed over: odd, 1 to 11",
       [](StereoConfig& c, const std::string& v) { c.shd_window = parse_int("shd-window", v); },
       [](const StereoConfig& c) { return std::to_string(c.shd_window); }},
      {"fused-weight", "fused cost: weight k of the pixel-wise term, floor(k * min(diff, fused-trunc) / 8) added to the cost; 0 or off: 0 to 32",
       [](StereoConfig& c, const std::string& v) { c.fused_weight = parse_int_or_off("fused-weight", v); },
       [](const StereoConfig& c) { return std::to_string(c.fused_weight); }},
      {"fused-trunc", "fused cost: the pixel-wise difference is truncated at this value: 1 to 255",
       [](StereoConfig& c, const std::string& v) { c.fused_trunc = parse_int("fused-trunc", v); },
       [](const StereoConfig& c) { return std::to_string(c.fused_trunc); }},
      {"fused-term", "fused cost: the pixel-wise difference, of intensities or of horizontal gradients: intensity or gradient",
       [](StereoConfig& c, const std::string& v) { c.fused_term = parse_enum("fused-term", v, kFusedTermNames); },
       [](const StereoConfig& c) { return to_string(c.fused_term); }},
      {"dmax", "disparity range (disparities 0 .. dmax-1): 16 to 256, a multiple of uf",
       [](StereoConfig& c, const std::string& v) { c.dmax = parse_int("dmax", v); },
       [](const StereoConfig& c) { return std::to_string(c.dmax); }},
      {"min-disp", "the smallest disparity searched (negative for converged cameras): -256 to 256",
       [](StereoConfig& c, const std::string& v) { c.min_disp = parse_int("min-disp", v); },
       [](const StereoConfig& c) { return std::to_string(c.min_disp); }},
      {"uf", "unroll factor: disparities per clock, a divisor of dmax",
       [](StereoConfig& c, const std::string& v) { c.uf = parse_int("uf", v); },
       [](const StereoConfig& c) { return std::to_string(c.uf); }},
      {"ppc", "pixels per beat of the hardware's video streams (UG934 samples per clock): 1, 2 or 4; needs uf = dmax and the width a multiple of ppc",
       [](StereoConfig& c, const std::string& v) { c.ppc = parse_int("ppc", v); },
       [](const StereoConfig& c) { return std::to_string(c.ppc); }},
      {"paths", "aggregation paths: comma-separated subset of 0,45,90,135,180 (180: right to left, models only), or all (= 0,45,90,135)",
       [](StereoConfig& c, const std::string& v) { c.paths = parse_paths("paths", v); },
       [](const StereoConfig& c) { return paths_to_string(c.paths); }},
      {"p1", "SGM penalty for a disparity change of 1: 0 to 255, at most p2",
       [](StereoConfig& c, const std::string& v) { c.p1 = parse_int("p1", v); },
       [](const StereoConfig& c) { return std::to_string(c.p1); }},
      {"p2", "SGM penalty for a larger disparity change: p1 to 4095",
       [](StereoConfig& c, const std::string& v) { c.p2 = parse_int("p2", v); },
       [](const StereoConfig& c) { return std::to_string(c.p2); }},
      {"p2-adapt", "adaptive P2: P2 - (k * |I(p) - I(p-r)|) / 4 along each path, at least P1; k 0 (off) to 16",
       [](StereoConfig& c, const std::string& v) { c.p2_adapt = parse_int_or_off("p2-adapt", v); },
       [](const StereoConfig& c) { return std::to_string(c.p2_adapt); }},
      {"mgm", "MGM-style aggregation: each path averages the terms of two causal predecessors: on or off",
       [](StereoConfig& c, const std::string& v) { c.mgm = parse_bool("mgm", v); },
       [](const StereoConfig& c) { return std::string(c.mgm ? "on" : "off"); }},
      {"lr", "left-right check: none, lr1 (reuse base costs) or lr2 (match side from scratch)",
       [](StereoConfig& c, const std::string& v) { c.lr = parse_enum("lr", v, kLrNames); },
       [](const StereoConfig& c) { return to_string(c.lr); }},
      {"lr-threshold", "largest |D_base - D_match| that passes the left-right check: 0 to 15",
       [](StereoConfig& c, const std::string& v) { c.lr_threshold = parse_int("lr-threshold", v); },
       [](const StereoConfig& c) { return std::to_string(c.lr_threshold); }},
      {"uniqueness", "uniqueness ratio in percent, 0 or off to disable: 0 to 99",
       [](StereoConfig& c, const std::string& v) { c.uniqueness = parse_int_or_off("uniqueness", v); },
       [](const StereoConfig& c) { return std::to_string(c.uniqueness); }},
      {"speckle-size", "speckle filter: regions of at most this many pixels become invalid (OpenCV speckleWindowSize); 0 or off: 0 to 4096",
       [](StereoConfig& c, const std::string& v) { c.speckle_size = parse_int_or_off("speckle-size", v); },
       [](const StereoConfig& c) { return std::to_string(c.speckle_size); }},
      {"speckle-range", "speckle filter: largest disparity step (whole pixels) within a region: 0 to dmax",
       [](StereoConfig& c, const std::string& v) { c.speckle_range = parse_int("speckle-range", v); },
       [](const StereoConfig& c) { return std::to_string(c.speckle_range); }},
      {"median", "median filter window: 0 or off, 3, 5 or 7",
       [](StereoConfig& c, const std::string& v) { c.median = parse_int_or_off("median", v); },
       [](const StereoConfig& c) { return std::to_string(c.median); }},
      {"gap-interp", "fill invalid pixels along the row: on (the smaller end), linear (a line between close ends) or off",
       [](StereoConfig& c, const std::string& v) {
         c.gap_linear = v == "linear";
         c.gap_interpolation = c.gap_linear || parse_bool("gap-interp", v, "expected on, off or linear");
       },
       [](const StereoConfig& c) { return std::string(c.gap_linear ? "linear" : c.gap_interpolation ? "on" : "off"); }},
      {"subpixel-bits", "fraction bits of the output disparity, 0 for whole pixels: 0 to 5",
       [](StereoConfig& c, const std::string& v) { c.subpixel_bits = parse_int("subpixel-bits", v); },
       [](const StereoConfig& c) { return std::to_string(c.subpixel_bits); }},
      {"subpixel-fit", "sub-pixel fit through the winner's and its neighbours' costs: equiangular or parabola",
       [](StereoConfig& c, const std::string& v) { c.subpixel_fit = parse_enum("subpixel-fit", v, kSubpixelFitNames); },
       [](const StereoConfig& c) { return to_string(c.subpixel_fit); }},
      {"right-view", "also stream the right image's disparities, the left-right check's match side: on or off",
       [](StereoConfig& c, const std::string& v) { c.right_view = parse_bool("right-view", v); },
       [](const StereoConfig& c) { return std::string(c.right_view ? "on" : "off"); }},
      {"confidence", "the output words also carry each pixel's 8-bit confidence: on or off",
       [](StereoConfig& c, const std::string& v) { c.confidence = parse_bool("confidence", v); },
       [](const StereoConfig& c) { return std::string(c.confidence ? "on" : "off"); }},
  };
  return specs;
}

void set_param(StereoConfig& cfg, const std::string& name, const std::string& value) {
  for (const auto& spec : param_specs())
    if (spec.name == name) return spec.set(cfg, value);
  throw ConfigError("unknown parameter " + quoted(name));
}

void validate(const StereoConfig& c) {
  check_range("width", c.width, 16, 8192);  // 16: the smallest dmax, which must fit in a row
  check_range("height", c.height, 4, 8192);
  check_odd_window("window", c.window, 3, 11);
  check_odd_window("shd-window", c.shd_window, 1, 11);  // checked even when unused: never silently wrong
  check_range("fused-weight", c.fused_weight, 0, 32);
  check_range("fused-trunc", c.fused_trunc, 1, 255);  // checked even when unused: never silently wrong
  // SAD and ZSAD sum intensity differences already; the term complements the transforms' costs.
  if (c.fused_weight != 0 && (c.cost == CostFunction::Sad || c.cost == CostFunction::Zsad))
    reject("fused-weight", std::to_string(c.fused_weight), "needs cost census, rank or shd (" + to_string(c.cost) +
                                                              " already compares intensities)");
  check_range("dmax", c.dmax, 16, 256);
  check_range("min-disp", c.min_disp, -256, 256);
  if (c.uf < 1 || c.uf > c.dmax || c.dmax % c.uf != 0)
    reject("uf", std::to_string(c.uf), "must divide dmax (" + std::to_string(c.dmax) + ")");
  if (c.dmax > c.width)
    reject("dmax", std::to_string(c.dmax),
           "must not exceed the image width (" + std::to_string(c.width) + ")");
  if (c.ppc != 1 && c.ppc != 2 && c.ppc != 4) reject("ppc", std::to_string(c.ppc), "expected 1, 2 or 4");
  if (c.ppc != 1 && c.uf != c.dmax)
    reject("ppc", std::to_string(c.ppc), "needs uf = dmax (uf " + std::to_string(c.uf) + ", dmax " + std::to_string(c.dmax) + ")");
  if (c.width % c.ppc != 0)
    reject("width", std::to_string(c.width), "must be a multiple of ppc (" + std::to_string(c.ppc) + ")");
  if ((c.paths & ~unsigned(kEveryPath)) != 0 || c.paths == 0)
    reject("paths", paths_to_string(c.paths), "expected a non-empty subset of 0,45,90,135,180");
  // MGM's second predecessor is defined for the four raster-order paths only (section 3).
  if (c.mgm && (c.paths & kPath180))
    reject("mgm", "on", "not defined for the 180-degree path (paths = " + paths_to_string(c.paths) + ")");
  check_range("p1", c.p1, 0, 255);
  check_range("p2", c.p2, 0, 4095);
  if (c.p1 > c.p2) reject("p1", std::to_string(c.p1), "must not exceed p2 (" + std::to_string(c.p2) + ")");
  check_range("p2-adapt", c.p2_adapt, 0, 16);
  check_range("lr-threshold", c.lr_threshold, 0, 15);
  check_range("uniqueness", c.uniqueness, 0, 99, "a percentage");
  // A region of at most S pixels spans at most S rows: S bounds the hardware's row delay.
  check_range("speckle-size", c.speckle_size, 0, kMaxSpeckleSize);
  check_range("speckle-range", c.speckle_range, 0, c.dmax);
  if (c.gap_linear && !c.gap_interpolation)
    throw ConfigError("gap-interp: the linear fill is a mode of gap interpolation, which is off");
  if (c.median != 0 && c.median != 3 && c.median != 5 && c.median != 7)
    reject("median", std::to_string(c.median), "expected 0 (off), 3, 5 or 7");
  check_range("subpixel-bits", c.subpixel_bits, 0, 5);
  if (c.right_view && c.lr == LrCheck::None)
    reject("right-view", "on", "needs a left-right check (lr = lr1 or lr2), whose match side it streams");
}

std::vector<std::string> preset_names() { return {"S0", "S1", "C0", "C1", "C2", "C3", "C4", "A2", "A3", "A4", "A5", "A6", "A7"}; }

StereoConfig preset(const std::string& name) {
  // All presets but A5 and A7: 4 paths, P1 = 7, P2 = 86, median 5, 1242x375 (the defaults), as in the paper.
  // S0/S1 are the paper's xfOpenCV baselines; their parameters equal C0/C1, only the
  // implementation in the paper differs.
  StereoConfig c;
  auto census = [&](int window, int dmax, int uf) {
    c.window = window;
    c.dmax = dmax;
    c.uf = uf;
  };
  if (name == "S0" || name == "C0")
    census(5, 64, 16);
  else if (name == "S1" || name == "C1")
    census(5, 128, 32);
  else if (name == "C2")
    census(7, 128, 32);
  else if (name == "C3") {
    census(7, 128, 32);
    c.lr = LrCheck::Lr1;
  } else if (name == "C4") {
    census(7, 128, 32);
    c.lr = LrCheck::Lr2;
  } else if (name == "A2" || name == "A3" || name == "A4" || name == "A5" || name == "A6" || name == "A7") {
    // Beyond the paper: C2, C3 and C4 with a 9 x 9 census, adaptive P2, a 7 x 7 median and four
    // fraction bits (docs/accuracy.md, "Accuracy beyond the paper").
    census(9, 128, 32);
    c.lr = name == "A2" ? LrCheck::None : name == "A3" ? LrCheck::Lr1 : LrCheck::Lr2;
    c.p2_adapt = 4;
    c.median = 7;
    c.subpixel_bits = 4;
    if (name == "A5" || name == "A6" || name == "A7") {
      // A6: A4 with the speckle filter (100, 2) and the fused intensity cost (k 4, T 32), the
      // best four-path setting on the tuning pairs (docs/accuracy.md, "Right-to-left path"), and
      // the linear gap fill (docs/accuracy.md, "The linear gap fill").
      // A5 adds the 180-degree path, chosen on the same pairs. A7 has paths 0, 90 and 180 instead
      // of five, better on the held-out pairs (chosen after seeing them, docs/accuracy.md, "A7").
      // Every layer runs both; the Verilog's 180-degree path takes one pixel a clock.
      if (name == "A5") c.paths = kEveryPath;
      if (name == "A7") c.paths = kPath0 | kPath90 | kPath180;
      c.speckle_size = 100;
      c.speckle_range = 2;
      c.fused_weight = 4;
      c.fused_trunc = 32;
      c.fused_term = FusedTerm::Intensity;
      c.gap_interpolation = true;
      c.gap_linear = true;
    }
  } else {
    std::string allowed = "expected one of";
    for (const auto& n : preset_names()) allowed += " " + n;
    reject("preset", quoted(name), allowed);
  }
  return c;
}

namespace {

// Deeper JSON is refused while parsing: a config file is one flat object (depth 1, arrays at 2),
// and recursion over a hostile 100,000-level document would overflow the stack.
constexpr int kMaxJsonDepth = 8;

// Only "paths" takes a list; every other parameter is one value.
bool takes_list(const std::string& key) { return key == "paths"; }

[[noreturn]] void reject_value(const std::string& key, const std::string& shown, const std::string& path) {
  throw ConfigError(key + " = " + shown + " in " + quoted(path) +
                    ": expected " + (takes_list(key) ? "a list of angles or a string" : "a single value"));
}

// A scalar as the text a command-line flag would carry; nullopt for anything else.
std::optional<std::string> json_scalar_text(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return std::string(v.get<bool>() ? "on" : "off");
  if (v.is_number_unsigned()) return std::to_string(v.get<unsigned long long>());
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  if (v.is_number_float()) return v.dump();  // rejected by the integer parser, shown as written
  return std::nullopt;
}

std::string json_value_text(const std::string& key, const nlohmann::json& v, const std::string& path) {
  if (auto text = json_scalar_text(v)) return *text;
  if (!v.is_array() || !takes_list(key)) reject_value(key, v.is_array() ? "[...]" : "{...}", path);
  std::string s;
  for (const auto& e : v) {
    const auto text = json_scalar_text(e);
    if (!text) reject_value(key, "[[...]]", path);
    s += (s.empty() ? "" : ",") + *text;
  }
  return s;
}

std::optional<std::string> toml_scalar_text(const toml::node& v) {
  if (auto s = v.as_string()) return s->get();
  if (auto b = v.as_boolean()) return std::string(b->get() ? "on" : "off");
  if (auto i = v.as_integer()) return std::to_string(i->get());
  if (auto f = v.as_floating_point()) return std::to_string(f->get());
  return std::nullopt;
}

std::string toml_value_text(const std::string& key, const toml::node& v, const std::string& path) {
  if (auto text = toml_scalar_text(v)) return *text;
  if (!v.as_array() || !takes_list(key)) reject_value(key, v.as_array() ? "[...]" : "(a table or date)", path);
  std::string s;
  for (const auto& e : *v.as_array()) {
    const auto text = toml_scalar_text(e);
    if (!text) reject_value(key, "[[...]]", path);
    s += (s.empty() ? "" : ",") + *text;
  }
  return s;
}

using Entries = std::vector<std::pair<std::string, std::string>>;

Entries json_entries(const std::string& text, const std::string& path) {
  std::vector<std::string> keys;  // of the top-level object, to refuse duplicates
  const auto limit = [&](int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    if (depth > kMaxJsonDepth)
      throw ConfigError("config file " + quoted(path) + ": nested deeper than " + std::to_string(kMaxJsonDepth) +
                        " levels");
    if (event == nlohmann::json::parse_event_t::key && depth == 1) {
      const std::string key = parsed.get<std::string>();
      if (std::find(keys.begin(), keys.end(), key) != keys.end())
        throw ConfigError("config file " + quoted(path) + ": key " + quoted(key) + " appears twice");
      keys.push_back(key);
    }
    return true;
  };
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text, limit);
  } catch (const nlohmann::json::exception& e) {
    throw ConfigError("config file " + quoted(path) + ": not valid JSON (" + one_line(e.what()) + ")");
  }
  if (!j.is_object()) throw ConfigError("config file " + quoted(path) + ": expected a JSON object");
  Entries entries;
  for (const auto& [key, value] : j.items()) entries.emplace_back(key, json_value_text(key, value, path));
  return entries;
}

Entries toml_entries(const std::string& text, const std::string& path) {
  toml::table t;
  try {
    t = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    throw ConfigError("config file " + quoted(path) + ": not valid TOML (" + one_line(std::string(e.description())) + ")");
  }
  Entries entries;
  for (const auto& [key, value] : t) {
    const std::string name(key.str());
    entries.emplace_back(name, toml_value_text(name, value, path));
  }
  return entries;
}

void apply_entries(StereoConfig& cfg, const Entries& entries, const std::string& path) {
  for (const auto& [key, value] : entries)
    if (key == "preset") cfg = preset(value);
  for (const auto& [key, value] : entries) {
    if (key == "preset") continue;
    bool known = std::any_of(param_specs().begin(), param_specs().end(),
                             [&](const ParamSpec& s) { return s.name == key; });
    if (!known) throw ConfigError("unknown parameter " + quoted(key) + " in " + quoted(path));
    set_param(cfg, key, value);
  }
}

}  // namespace

void apply_config_file(StereoConfig& cfg, const std::string& path) {
  std::string text;
  try {
    text = read_regular_file(path, "config file", kMaxTextFileBytes);
  } catch (const FileError& e) {
    throw ConfigError(e.what());
  }
  if (!ends_with(path, ".json") && !ends_with(path, ".toml"))
    throw ConfigError("config file " + quoted(path) + ": expected a .json or .toml file");
  apply_entries(cfg, ends_with(path, ".json") ? json_entries(text, path) : toml_entries(text, path), path);
}

StereoConfig compose_config(const std::optional<std::string>& preset_name, const std::string& config_file,
                            const std::map<std::string, std::string>& values) {
  StereoConfig cfg = preset_name ? preset(*preset_name) : StereoConfig{};
  if (!config_file.empty()) apply_config_file(cfg, config_file);
  for (const auto& [name, value] : values) set_param(cfg, name, value);
  return cfg;
}

std::string describe(const StereoConfig& cfg, const std::string& line_prefix) {
  std::string s;
  for (const auto& spec : param_specs()) s += line_prefix + spec.name + " = " + spec.get(cfg) + "\n";
  return s;
}

std::string config_tag(const StereoConfig& cfg) {
  // FNV-1a over the full description: stable across runs and platforms.
  uint32_t h = 2166136261u;
  for (char ch : describe(cfg)) h = (h ^ uint8_t(ch)) * 16777619u;
  char hex[9];
  std::snprintf(hex, sizeof hex, "%08x", h);
  return "fps_" + to_string(cfg.cost) + std::to_string(cfg.window) + "_d" + std::to_string(cfg.dmax) + "u" +
         std::to_string(cfg.uf) + "_" + std::string(hex, 6);
}

}  // namespace fpstereo
