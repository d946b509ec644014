// StereoConfig: presets, parsing, config files, and every rejected value or combination.
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>

#include "config.hpp"

using namespace fpstereo;

namespace {

// The ConfigError message for cfg, or "" if it is valid.
std::string rejection(const StereoConfig& cfg) {
  try {
    validate(cfg);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

std::string rejection_of(const std::string& name, const std::string& value) {
  StereoConfig cfg;
  try {
    set_param(cfg, name, value);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return rejection(cfg);
}

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = "fpstereo_test_" + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST_CASE("defaults are the paper's C2 and valid", "[config]") {
  const StereoConfig c;
  CHECK(c == preset("C2"));
  CHECK(rejection(c).empty());
  CHECK(c.cost == CostFunction::Census);
  CHECK(c.window == 7);
  CHECK(c.dmax == 128);
  CHECK(c.uf == 32);
  CHECK(c.path_count() == 4);
}

TEST_CASE("presets follow the paper's table", "[config]") {
  struct Row {
    const char* name;
    int window, dmax, uf;
    LrCheck lr;
  };
  const Row table[] = {{"S0", 5, 64, 16, LrCheck::None},  {"S1", 5, 128, 32, LrCheck::None},
                       {"C0", 5, 64, 16, LrCheck::None},  {"C1", 5, 128, 32, LrCheck::None},
                       {"C2", 7, 128, 32, LrCheck::None}, {"C3", 7, 128, 32, LrCheck::Lr1},
                       {"C4", 7, 128, 32, LrCheck::Lr2}};
  for (const auto& row : table) {
    INFO(row.name);
    const StereoConfig c = preset(row.name);
    CHECK(rejection(c).empty());
    CHECK(c.cost == CostFunction::Census);
    CHECK(c.window == row.window);
    CHECK(c.dmax == row.dmax);
    CHECK(c.uf == row.uf);
    CHECK(c.lr == row.lr);
    CHECK(c.p1 == 7);
    CHECK(c.p2 == 86);
    CHECK(c.median == 5);
    CHECK(c.width == 1242);
    CHECK(c.height == 375);
  }
  CHECK_THROWS_WITH(preset("C9"), Catch::Contains("preset = 'C9'") && Catch::Contains("C4"));
}

TEST_CASE("the presets beyond the paper are C2, C3 and C4 with their four additions", "[config]") {
  for (const auto& [name, paper] : {std::pair{"A2", "C2"}, {"A3", "C3"}, {"A4", "C4"}}) {
    INFO(name);
    StereoConfig expected = preset(paper);
    expected.window = 9;
    expected.p2_adapt = 4;
    expected.median = 7;
    expected.subpixel_bits = 4;
    CHECK(preset(name) == expected);
    CHECK(rejection(preset(name)).empty());
  }
}

TEST_CASE("parameters parse from text", "[config]") {
  StereoConfig c;
  set_param(c, "cost", "SAD");
  set_param(c, "paths", "0, 90");
  set_param(c, "median", "off");
  set_param(c, "gap-interp", "on");
  set_param(c, "lr", "lr2");
  CHECK_FALSE(c.mgm);  // off by default
  set_param(c, "mgm", "on");
  CHECK(c.speckle_size == 0);  // off by default
  set_param(c, "speckle-size", "100");
  set_param(c, "speckle-range", "0");
  CHECK(c.speckle_size == 100);
  CHECK(c.speckle_range == 0);
  set_param(c, "speckle-size", "off");
  CHECK(c.speckle_size == 0);
  set_param(c, "speckle-size", "4096");
  CHECK(c.fused_weight == 0);  // off by default
  set_param(c, "fused-weight", "32");
  set_param(c, "fused-trunc", "255");
  set_param(c, "fused-term", "Gradient");
  CHECK(c.fused_weight == 32);
  CHECK(c.fused_trunc == 255);
  CHECK(c.fused_term == FusedTerm::Gradient);
  set_param(c, "fused-weight", "off");
  CHECK(c.fused_weight == 0);
  CHECK(c.cost == CostFunction::Sad);
  CHECK(c.paths == (kPath0 | kPath90));
  CHECK(c.median == 0);
  CHECK(c.gap_interpolation);
  CHECK_FALSE(c.gap_linear);
  CHECK(c.lr == LrCheck::Lr2);
  CHECK(c.mgm);
  // Every parameter prints back to text that parses to the same value (the linear fill too).
  set_param(c, "gap-interp", "linear");
  CHECK(c.gap_interpolation);
  CHECK(c.gap_linear);
  StereoConfig copy;
  for (const auto& spec : param_specs()) set_param(copy, spec.name, spec.get(c));
  CHECK(copy == c);
  set_param(c, "gap-interp", "off");  // off turns the linear fill off with it
  CHECK_FALSE(c.gap_interpolation);
  CHECK_FALSE(c.gap_linear);
}

TEST_CASE("the linear gap fill needs gap interpolation", "[config]") {
  StereoConfig c;
  c.gap_linear = true;
  CHECK_THROWS_WITH(validate(c), "gap-interp: the linear fill is a mode of gap interpolation, which is off");
  c.gap_interpolation = true;
  CHECK_NOTHROW(validate(c));
}

TEST_CASE("every invalid value is rejected with its name, value and what is allowed", "[config]") {
  struct Case {
    const char* name;
    const char* value;
    const char* expected;
  };
  const Case cases[] = {
      {"width", "4", "width = 4: must be in 16 .. 8192"},
      {"width", "12", "width = 12: must be in 16 .. 8192"},  // no dmax fits: the documented range is the rule
      {"width", "abc", "width = 'abc': expected an integer"},
      {"height", "9000", "height = 9000: must be in 4 .. 8192"},
      {"cost", "ncc", "cost = 'ncc': expected one of census rank sad zsad shd"},
      {"window", "6", "window = 6: must be an odd window side from 3 to 11"},
      {"window", "13", "window = 13: must be an odd window side from 3 to 11"},
      {"window", "1", "window = 1: must be an odd window side from 3 to 11"},
      {"dmax", "8", "dmax = 8: must be in 16 .. 256"},
      {"dmax", "512", "dmax = 512: must be in 16 .. 256"},
      {"dmax", "100", "uf = 32: must divide dmax (100)"},
      {"uf", "0", "uf = 0: must divide dmax (128)"},
      {"uf", "48", "uf = 48: must divide dmax (128)"},
      {"uf", "256", "uf = 256: must divide dmax (128)"},
      {"paths", "", "paths = '': expected a non-empty subset of 0,45,90,135,180"},
      {"paths", "0,30", "paths = '0,30': expected a comma-separated subset of 0,45,90,135,180"},
      {"paths", "0,225", "paths = '0,225': expected a comma-separated subset of 0,45,90,135,180"},
      {"paths", "180,180", "paths = '180,180': each angle at most once"},
      {"paths", "0,0", "paths = '0,0': each angle at most once"},
      {"p1", "-1", "p1 = -1: must be in 0 .. 255"},
      {"p1", "100", "p1 = 100: must not exceed p2 (86)"},
      {"p2", "5000", "p2 = 5000: must be in 0 .. 4095"},
      {"p2", "3", "p1 = 7: must not exceed p2 (3)"},
      {"lr", "lr3", "lr = 'lr3': expected one of none lr1 lr2"},
      {"lr-threshold", "16", "lr-threshold = 16: must be in 0 .. 15"},
      {"uniqueness", "100", "uniqueness = 100: must be a percentage in 0 .. 99"},
      {"median", "4", "median = 4: expected 0 (off), 3, 5 or 7"},
      {"median", "9", "median = 9: expected 0 (off), 3, 5 or 7"},
      {"gap-interp", "maybe", "gap-interp = 'maybe': expected on, off or linear"},
      {"mgm", "2", "mgm = '2': expected on or off"},
      {"speckle-size", "-1", "speckle-size = -1: must be in 0 .. 4096"},
      {"speckle-size", "4097", "speckle-size = 4097: must be in 0 .. 4096"},
      {"speckle-range", "-1", "speckle-range = -1: must be in 0 .. 128"},
      {"speckle-range", "129", "speckle-range = 129: must be in 0 .. 128"},
      {"speckle-range", "off", "speckle-range = 'off': expected an integer"},
      {"fused-weight", "-1", "fused-weight = -1: must be in 0 .. 32"},
      {"fused-weight", "33", "fused-weight = 33: must be in 0 .. 32"},
      {"fused-trunc", "0", "fused-trunc = 0: must be in 1 .. 255"},
      {"fused-trunc", "256", "fused-trunc = 256: must be in 1 .. 255"},
      {"fused-term", "census", "fused-term = 'census': expected one of intensity gradient"},
      {"paths", "0,", "paths = '0,': expected a comma-separated subset of 0,45,90,135,180"},
      {"paths", ",90", "paths = ',90': expected a comma-separated subset of 0,45,90,135,180"},
      {"dmax", "+64", "dmax = '+64': expected an integer"},
      {"dmax", " 64", "dmax = ' 64': expected an integer"},
      {"dmax", "64 ", "dmax = '64 ': expected an integer"},
      {"dmax", "0x40", "dmax = '0x40': expected an integer"},
      {"dmax", "-", "dmax = '-': expected an integer"},
      {"p1", "18446744073709551609", "p1 = '18446744073709551609': expected an integer"},
      {"shd-window", "4", "shd-window = 4: must be an odd window side from 1 to 11"},
      {"shd-window", "13", "shd-window = 13: must be an odd window side from 1 to 11"},
      {"cost", "a\nb", "cost = 'a\\nb': expected one of census rank sad zsad shd"},
  };
  for (const auto& c : cases) {
    INFO(c.name << " = " << c.value);
    CHECK(rejection_of(c.name, c.value) == c.expected);
  }
}

TEST_CASE("compose_config: a preset given as '' is an error, not the defaults", "[config]") {
  CHECK(compose_config(std::nullopt, "", {}) == StereoConfig{});
  CHECK(compose_config(std::string("C0"), "", {{"median", "3"}}).median == 3);
  CHECK_THROWS_WITH(compose_config(std::string(""), "", {}), Catch::StartsWith("preset = '': expected one of"));
}

TEST_CASE("paths: 180 is a fifth path, 'all' stays the four raster-order ones", "[config]") {
  StereoConfig c;
  set_param(c, "paths", "0, 90,180");
  CHECK(c.paths == (kPath0 | kPath90 | kPath180));
  CHECK(c.path_count() == 3);
  CHECK(paths_to_string(c.paths) == "0,90,180");
  set_param(c, "paths", "180,135,90,45,0");
  CHECK(c.paths == unsigned(kEveryPath));
  CHECK(c.path_count() == 5);
  set_param(c, "paths", "all");
  CHECK(c.paths == unsigned(kAllPaths));
  CHECK(c.path_count() == 4);
  for (const auto& name : preset_names())
    CHECK(((preset(name).paths & kPath180) == 0 || name == "A5" || name == "A7"));
  StereoConfig a7 = preset("A7");  // A5 with paths 0, 90, 180 in place of all five
  CHECK(paths_to_string(a7.paths) == "0,90,180");
  a7.paths = kEveryPath;
  CHECK(a7 == preset("A5"));
  StereoConfig a5 = preset("A5");  // A4 and the options A5 adds, nothing else
  CHECK(a5.paths == unsigned(kEveryPath));
  CHECK(a5.speckle_size == 100);
  CHECK(a5.fused_weight == 4);
  CHECK(a5.gap_linear);
  a5.paths = kAllPaths;
  CHECK(a5 == preset("A6"));  // A6 is A5 without the 180-degree path
  a5.speckle_size = 0;
  a5.fused_weight = 0;
  a5.fused_trunc = preset("A4").fused_trunc;
  a5.gap_interpolation = false;
  a5.gap_linear = false;
  CHECK(a5 == preset("A4"));
  set_param(c, "paths", "0,180");
  c.mgm = true;
  CHECK(rejection(c) == "mgm = on: not defined for the 180-degree path (paths = 0,180)");
}

TEST_CASE("invalid combinations are rejected", "[config]") {
  StereoConfig c;
  c.width = 100;  // narrower than dmax 128
  CHECK(rejection(c) == "dmax = 128: must not exceed the image width (100)");

  StereoConfig shd;
  shd.cost = CostFunction::Shd;
  shd.shd_window = 4;
  CHECK(rejection(shd) == "shd-window = 4: must be an odd window side from 1 to 11");
  shd.cost = CostFunction::Census;  // checked even when unused: a bad value is never silently kept
  CHECK(rejection(shd) == "shd-window = 4: must be an odd window side from 1 to 11");

  StereoConfig fused;
  fused.fused_weight = 8;
  for (CostFunction cost : {CostFunction::Census, CostFunction::Rank, CostFunction::Shd}) {
    fused.cost = cost;
    CHECK(rejection(fused).empty());
  }
  fused.cost = CostFunction::Sad;
  CHECK(rejection(fused) == "fused-weight = 8: needs cost census, rank or shd (sad already compares intensities)");
  fused.cost = CostFunction::Zsad;
  CHECK(rejection(fused) == "fused-weight = 8: needs cost census, rank or shd (zsad already compares intensities)");

  CHECK_THROWS_WITH(
      [] {
        StereoConfig x;
        set_param(x, "colour", "red");
      }(),
      "unknown parameter 'colour'");
}

TEST_CASE("legal dmax and uf combinations are accepted", "[config]") {
  for (int dmax : {16, 48, 96, 100, 128, 256})
    for (int uf : {1, 2, 4, 5, 8, 16, 32, 64, 128, 256}) {
      StereoConfig c;
      c.dmax = dmax;
      c.uf = uf;
      INFO(dmax << "/" << uf);
      CHECK(rejection(c).empty() == (dmax % uf == 0 && uf <= dmax));
    }
}

TEST_CASE("config files in JSON and TOML use the same names", "[config]") {
  const std::string json = write_temp(
      "a.json",
      R"({"preset": "C0", "cost": "rank", "paths": [0, 90], "gap-interp": true, "uniqueness": 15})");
  const std::string toml = write_temp(
      "a.toml", "preset = \"C0\"\ncost = \"rank\"\npaths = [0, 90]\ngap-interp = true\nuniqueness = 15\n");
  StereoConfig from_json, from_toml;
  apply_config_file(from_json, json);
  apply_config_file(from_toml, toml);
  CHECK(from_json == from_toml);
  CHECK(from_json.dmax == 64);  // from the preset
  CHECK(from_json.cost == CostFunction::Rank);
  CHECK(from_json.paths == (kPath0 | kPath90));
  CHECK(from_json.gap_interpolation);
  CHECK(from_json.uniqueness == 15);

  StereoConfig c;
  CHECK_THROWS_WITH(apply_config_file(c, write_temp("b.json", R"({"dmx": 64})")),
                    Catch::Contains("unknown parameter 'dmx'"));
  CHECK_THROWS_WITH(apply_config_file(c, write_temp("c.json", "{dmax: 64")),
                    Catch::Contains("not valid JSON"));
  CHECK_THROWS_WITH(apply_config_file(c, write_temp("d.toml", "dmax = = 3")),
                    Catch::Contains("not valid TOML"));
  CHECK_THROWS_WITH(apply_config_file(c, write_temp("e.yaml", "dmax: 3")),
                    Catch::Contains("expected a .json or .toml"));
  CHECK_THROWS_WITH(apply_config_file(c, "no/such/file.json"), Catch::Contains("cannot be read"));
  CHECK_THROWS_WITH(apply_config_file(c, write_temp("f.json", R"({"dmax": "x"})")),
                    "dmax = 'x': expected an integer");
  CHECK_THROWS_WITH(apply_config_file(c, write_temp("g.json", R"({"dmax": [64]})")),
                    Catch::Contains("dmax = [...]") && Catch::Contains("expected a single value"));
  CHECK_THROWS_WITH(apply_config_file(c, write_temp("g.toml", "dmax = [64]\n")),
                    Catch::Contains("dmax = [...]") && Catch::Contains("expected a single value"));
  CHECK_THROWS_WITH(apply_config_file(c, write_temp("h.json", R"({"paths": [[0], 90]})")),
                    Catch::Contains("paths = [[...]]"));
  CHECK_THROWS_WITH(apply_config_file(c, write_temp("i.json", R"({"dmax": 64, "dmax": 32})")),
                    Catch::Contains("key 'dmax' appears twice"));
  CHECK_THROWS_WITH(apply_config_file(c, write_temp("j.json", R"({"p1": 18446744073709551609})")),
                    "p1 = '18446744073709551609': expected an integer");
  CHECK_THROWS_WITH(apply_config_file(c, write_temp("k.json", R"({"dmax": 64.0})")),
                    "dmax = '64.0': expected an integer");
  // 100,000 levels: refused while parsing, no recursion over it.
  const std::string deep = "{\"dmax\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  CHECK_THROWS_WITH(apply_config_file(c, write_temp("l.json", deep)), Catch::Contains("nested deeper than"));
  // The TOML parser's own message quotes the input up to and with a newline (found by fpstereo-fuzz).
  try {
    apply_config_file(c, write_temp("m.toml", "window = n\np1 = 3\n"));
    FAIL("a bad float was accepted");
  } catch (const ConfigError& e) {
    CHECK_THAT(e.what(), Catch::Contains("not valid TOML"));
    CHECK(std::string(e.what()).find_first_of("\r\n") == std::string::npos);
  }
  for (const char* f : {"g.json", "g.toml", "h.json", "i.json", "j.json", "k.json", "l.json", "m.toml"})
    std::remove((std::string("fpstereo_test_") + f).c_str());
  for (const char* f : {"a.json", "a.toml", "b.json", "c.json", "d.toml", "e.yaml", "f.json"})
    std::remove((std::string("fpstereo_test_") + f).c_str());
}
