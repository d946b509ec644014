// Design-space exploration: the resource model's block RAM against hand derivations, its
// monotonicity, the Pareto front, shards and merge, the accuracy cache and the report.
#include <catch2/catch.hpp>
#include <fmt/core.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <opencv2/imgcodecs.hpp>

#include "dse.hpp"
#include "image_io.hpp"
#include "resource_fit.hpp"
#include "resource_model.hpp"
#include "rtl_emitter.hpp"
#include "synth_command.hpp"
#include "test_support.hpp"

using namespace fpstereo;
namespace fs = std::filesystem;

namespace {

dse::MemoryEstimate mapped(int64_t words, int64_t bits) {
  dse::MemoryEstimate m;
  m.words = words;
  m.bits = bits;
  dse::map_memory(m);
  return m;
}

// A small dataset from crops of the bundled Cones pair: two pairs, ground truth included. Each test
// writes its own (ctest runs the test cases in parallel processes).
fs::path tiny_dataset(const std::string& name) {
  const fs::path dir = test::scratch_path(name);
  fs::create_directories(dir);
  const std::string ex = FPSTEREO_EXAMPLES_DIR "/cones/";
  const cv::Mat left = cv::imread(ex + "left.png", cv::IMREAD_GRAYSCALE);
  const cv::Mat right = cv::imread(ex + "right.png", cv::IMREAD_GRAYSCALE);
  const cv::Mat gt = cv::imread(ex + "gt_occ.png", cv::IMREAD_UNCHANGED);
  std::ofstream csv(dir / "pairs.csv");
  csv << "pair,left,right,gt_occ,gt_noc,noc_mask,gt_scale,gt_invalid,max_disp_px\n";
  for (int i = 0; i < 2; ++i) {
    const cv::Rect crop(100 + 150 * i, 120, 96, 40);
    const std::string n = "crop" + std::to_string(i);
    cv::imwrite((dir / (n + "_l.png")).string(), left(crop));
    cv::imwrite((dir / (n + "_r.png")).string(), right(crop));
    cv::imwrite((dir / (n + "_gt.png")).string(), gt(crop));
    csv << n << "," << n << "_l.png," << n << "_r.png," << n << "_gt.png,,,4,0,\n";
  }
  return dir;
}

// The default space with `axes` set.
dse::SpaceText space_with(const std::vector<dse::AxisText>& axes) {
  dse::SpaceText t = dse::default_space();
  for (const auto& axis : axes) dse::set_axis(t, axis);
  return t;
}

dse::SweepOptions tiny_sweep(const fs::path& cache, const std::string& data) {
  const dse::SpaceText t = space_with({{"cost", {"census", "sad"}},
                                       {"window", {"3", "5"}},
                                       {"dmax", {"16", "32"}},
                                       {"uf", {"4", "8", "32"}},  // 32 does not divide 16: skipped
                                       {"resolution", {"96x40"}},
                                       {"refine", {"none", "lr1"}},
                                       {"median", {"off", "3"}}});
  dse::SweepOptions o;
  o.space = dse::parse_space(t);
  o.datasets = {tiny_dataset(data).string()};
  o.cache_dir = cache.string();
  o.progress = false;
  return o;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path p = test::scratch_path(name);
  fs::remove_all(p);
  return p;
}

}  // namespace

TEST_CASE("block RAM of single memories as Yosys 0.23 maps them", "[dse]") {
  // 900 x 32 (census 5x5 line buffer): one RAMB36 in 1K x 36 (a RAMB18 pair would cost 258 > 257).
  CHECK(mapped(900, 32).bram36 == 1);
  CHECK(mapped(900, 32).bram18 == 0);
  // 901 x 7 (row minima): one RAMB18 in 2K x 9.
  CHECK(mapped(901, 7).bram18 == 1);
  CHECK(mapped(901, 7).bram36 == 0);
  // 14416 x 28 (a path row, uf 4, G 16): 16K x 2 per RAMB36 -> 14 of them.
  CHECK(mapped(14416, 28).bram36 == 14);
  // 28800 x 20 (cost reorder RAM): 32K x 1 per RAMB36 -> 20.
  CHECK(mapped(28800, 20).bram36 == 20);
  // 2700 x 7: 4K x 9 in one RAMB36.
  CHECK(mapped(2700, 7).bram36 == 1);
  // 16 x 224 (LR1's row-end RAM at uf 32): 16 LUTRAMs cost less than 4 RAMB36.
  CHECK(mapped(16, 224).target == "lutram");
}

TEST_CASE("a RAM split in depth has a read multiplexer over its cells", "[dse]") {
  // One cell deep: no multiplexer.
  CHECK(mapped(900, 32).read_mux_bits == 0);
  CHECK(mapped(14416, 28).read_mux_bits == 0);
  CHECK(mapped(28800, 20).read_mux_bits == 0);
  // 10256 x 32 (f09's path rows, uf 4, G 16): 32 bits swizzle to 36, 1K x 36 per RAMB36 -> 11 cells
  // deep at 11 x 257 + 0.5 x 10 x 32 + 0.5 x 11 + 2 = 2994.5, below 1K x 18 RAMB18s (22 cells,
  // 3003.5) and 2K x 18 RAMB36s (12 cells); its read multiplexer picks one of 11 words of 32 bits.
  // Yosys: 150 LUTs per row RAM in f09's hierarchical synthesis.
  const dse::MemoryEstimate row = mapped(10256, 32);
  CHECK(row.bram36 == 11);
  CHECK(row.bram18 == 0);
  CHECK(row.read_mux_bits == 10 * 32);
}

// The FF terms count register bits as the Verilog declares them, so their fitted coefficient is
// near 1 (Yosys trims a few and merges equal registers): far from it, the counts no longer
// describe the Verilog.
TEST_CASE("the fitted coefficient of the register terms is near one flip-flop per counted bit", "[dse]") {
  const auto& names = dse::feature_names();
  const auto at = std::find(names.begin(), names.end(), "aggregation registers");
  REQUIRE(at != names.end());
  const double per_bit = dse::fitted_coefficients().ff[size_t(at - names.begin())];
  CHECK(per_bit > 0.9);
  CHECK(per_bit < 1.05);
}

TEST_CASE("block RAM of a whole design matches the hand derivation (and Yosys)", "[dse]") {
  // census 5x5, dmax 64, uf 4, 900x260, no median: K = 2, G = 16, 900 slots.
  // Line buffers 2 x 1, code reorder RAM 3 (2 rows x 900 slots of two 24-bit codes: 2K x 18, three
  // wide; the cost words were 20), the 45-degree path row 14 (14,416 x 28 bits: 8K x 4, seven
  // wide, two deep), the 90 and 135-degree rows 2 x 15 (14,416 x 35: their words carry the next
  // group's lane 0 too; 1K x 36, 15 deep), disparity RAM 1 -> 50 RAMB36; three row-minimum RAMs
  // -> 3 RAMB18.
  StereoConfig c;
  c.window = 5;
  c.dmax = 64;
  c.uf = 4;
  c.median = 0;
  c.width = 900;
  c.height = 260;
  const dse::ResourceEstimate e = dse::estimate(c);
  CHECK(e.bram36 == 50);
  CHECK(e.bram18 == 3);
  CHECK(e.bram36_equiv() == 51.5);
  // The same with median 5 and LR1 adds the median line buffer (900 x 28: 1 RAMB36) and the
  // completed RAM (3600 x 6: 4K x 9, 1 RAMB36); the disparity RAM grows to 3600 x 7 (still one
  // RAMB36) and the 64 x 24 row-end RAM costs less as LUTRAM (16 * 24 / 7) than as a RAMB18 (129).
  c.median = 5;
  c.lr = LrCheck::Lr1;
  const dse::ResourceEstimate lr = dse::estimate(c);
  CHECK(lr.bram36 == 52);
  CHECK(lr.bram18 == 3);
}

TEST_CASE("the fitted model grows with uf and the frame rate comes from rtl::plan", "[dse]") {
  for (const char* cost : {"census", "rank", "sad", "zsad", "shd"}) {
    double lut = 0, ff = 0;
    for (int uf : {4, 8, 16, 32}) {
      StereoConfig c;
      set_param(c, "cost", cost);
      c.uf = uf;
      const dse::ResourceEstimate e = dse::estimate(c);
      CHECK(e.lut > lut);
      CHECK(e.ff > ff);
      lut = e.lut;
      ff = e.ff;
    }
  }
  StereoConfig c2;
  const rtl::RtlDesign d = rtl::plan(c2);
  CHECK(dse::frames_per_second(d, 200) == 200e6 / double(d.cycles_per_frame));
}

TEST_CASE("LR2 in strips counts the match side's costs again, the one-pixel core does not", "[dse]") {
  // In strips LR2's match side computes its costs itself (census and rank in its chain costs, the
  // window costs in a second instance with the images swapped); at one pixel a clock it reads the
  // base side's.
  const auto term = [](const StereoConfig& c, const std::string& name) {
    const auto& names = dse::feature_names();
    const auto at = std::find(names.begin(), names.end(), name);
    REQUIRE(at != names.end());
    return dse::features(rtl::plan(c))[size_t(at - names.begin())];
  };
  for (const char* cost : {"census", "rank", "sad", "zsad", "shd"})
    for (int ppc : {1, 2}) {
      StereoConfig c;
      c.width = 96;
      c.height = 16;
      c.dmax = c.uf = 16;
      c.ppc = ppc;
      set_param(c, "cost", cost);
      c.shd_window = 3;
      StereoConfig with_lr2 = c;
      with_lr2.lr = LrCheck::Lr2;
      REQUIRE(rtl::plan(with_lr2).strips == ppc);
      INFO(cost << " at ppc " << ppc);
      const double sides = ppc > 1 ? 2.0 : 1.0;
      for (const std::string name : {"code cost lanes", "pixel cost lanes", "match ring", "ZSAD lanes"})
        CHECK(term(with_lr2, name) == sides * term(c, name));
      CHECK(term(with_lr2, "match ring") > 0);
    }
}

TEST_CASE("non-negative least squares recovers exact coefficients and clamps negative ones", "[dse]") {
  const std::vector<std::vector<double>> a = {{1, 1, 0}, {1, 2, 1}, {1, 3, 0}, {1, 4, 2}, {1, 5, 1}};
  std::vector<double> b;
  for (const auto& r : a) b.push_back(10 + 3 * r[1] + 0.5 * r[2]);
  const std::vector<double> x = dse::fit_nonnegative(a, b, std::vector<double>(a.size(), 1.0));
  CHECK(std::abs(x[0] - 10) < 1e-6);
  CHECK(std::abs(x[1] - 3) < 1e-6);
  CHECK(std::abs(x[2] - 0.5) < 1e-6);
  std::vector<double> neg;
  for (const auto& r : a) neg.push_back(10 + 3 * r[1] - 2 * r[2]);
  for (double v : dse::fit_nonnegative(a, neg, std::vector<double>(a.size(), 1.0))) CHECK(v >= 0);
}

TEST_CASE("the Pareto front of a synthetic set", "[dse]") {
  const auto row = [](double d1, double res, double fps) {
    dse::Row r;
    r.acc.d1_all = d1;
    r.resource_pct = res;
    r.fps = fps;
    return r;
  };
  std::vector<dse::Row> rows = {
      row(10, 10, 100),  // front: best D1
      row(12, 5, 100),   // front: cheaper
      row(12, 10, 100),  // dominated by the first
      row(12, 10, 200),  // front: fastest
      row(11, 10, 100),  // dominated by the first
      row(10, 10, 100),  // equal to the first: neither dominates, both on the front
      row(NAN, 1, 999),  // no accuracy: never on the front
  };
  dse::mark_pareto(rows);
  const std::vector<bool> expected = {true, true, false, true, false, true, false};
  for (size_t i = 0; i < rows.size(); ++i) CHECK(rows[i].pareto == expected[i]);
}

TEST_CASE("axes, shards and constraints reject bad values", "[dse]") {
  CHECK_THROWS_AS(dse::parse_space(space_with({{"window", {"4"}}})), InputError);
  CHECK_THROWS_AS(dse::parse_space(space_with({{"cost", {"ncc"}}})), InputError);
  CHECK_THROWS_AS(dse::parse_space(space_with({{"resolution", {"1242*374"}}})), InputError);
  CHECK_THROWS_AS(dse::parse_space(space_with({{"p2-adapt", {"17"}}})), InputError);
  CHECK_THROWS_AS(dse::parse_space(space_with({{"subpixel-bits", {"6"}}})), InputError);
  CHECK_THROWS_AS(dse::parse_space(space_with({{"uniqueness", {"100"}}})), InputError);
  CHECK_THROWS_AS(dse::parse_space(space_with({{"median", {}}})), InputError);
  // Unknown names, and two axes on one parameter.
  CHECK_THROWS_AS(dse::parse_space({{"speed", {"1"}}}), InputError);
  CHECK_THROWS_AS(dse::parse_space({{"refine", {"none"}}, {"lr", {"lr1"}}}), InputError);
  CHECK_THROWS_AS(dse::parse_space({{"resolution", {"640x480"}}, {"height", {"200"}}}), InputError);
  dse::SpaceText t = dse::default_space();
  CHECK_THROWS_AS(dse::set_axis(t, {"width", {"640"}}), InputError);  // only half of resolution
  CHECK_THROWS_AS(dse::set_axis(t, {"speed", {"1"}}), InputError);
  CHECK(t.size() == dse::default_space().size());
  CHECK(dse::parse_shard("2/8") == std::make_pair(2, 8));
  for (const char* bad : {"0/2", "3/2", "2", "a/b", "1/0", "1/2x"})
    CHECK_THROWS_AS(dse::parse_shard(bad), InputError);
  CHECK(dse::parse_percent("--max-lut", "30%") == 30);
  CHECK_THROWS_AS(dse::parse_percent("--max-lut", "lots"), InputError);
  CHECK_THROWS_AS(find_part("xc9000"), ConfigError);
  CHECK(find_part("xczu9eg").lut == 274080);
}

// One value on every default axis but those the test sweeps.
dse::SpaceText single_design_space() {
  return space_with({{"cost", {"census"}},
                     {"window", {"5"}},
                     {"dmax", {"64"}},
                     {"uf", {"16"}},
                     {"resolution", {"320x96"}},
                     {"refine", {"none"}},
                     {"median", {"5"}}});
}

TEST_CASE("the adaptive P2 and sub-pixel axes reach every configuration", "[dse]") {
  dse::SpaceText t = single_design_space();
  dse::set_axis(t, {"p2-adapt", {"off", "4"}});
  dse::set_axis(t, {"subpixel-bits", {"0", "3"}});
  std::vector<dse::Skipped> skipped;
  const std::vector<StereoConfig> configs = dse::enumerate(dse::parse_space(t), StereoConfig{}, skipped);
  CHECK(skipped.empty());
  std::set<std::pair<int, int>> seen;
  for (const auto& c : configs) seen.insert({c.p2_adapt, c.subpixel_bits});
  CHECK(seen == std::set<std::pair<int, int>>{{0, 0}, {0, 3}, {4, 0}, {4, 3}});
  CHECK(configs.size() == 4);
  // Each is a distinct accuracy key, and the flags name both axes.
  std::set<std::string> keys;
  for (const auto& c : configs) keys.insert(dse::accuracy_key(c));
  CHECK(keys.size() == 4);
  const std::string flags = dse::config_flags(configs.back());
  CHECK(flags.find("--p2-adapt 4 ") != std::string::npos);
  CHECK(flags.find("--subpixel-bits 3") != std::string::npos);
}

TEST_CASE("any parameter of the table is an axis, set through the table like its flag", "[dse]") {
  // Parameters the DSE names nowhere: uniqueness, confidence, p1 and paths (whose values hold commas).
  dse::SpaceText t = single_design_space();
  for (const char* text : {"uniqueness=0,15", "confidence=off/on", "p1=5,9", "paths=all/0,90"})
    dse::set_axis(t, dse::parse_axis(text));
  // Each goes in before resolution and uf, after the axes given before it.
  std::vector<std::string> names;
  for (const auto& axis : t) names.push_back(axis.name);
  CHECK(names == std::vector<std::string>{"cost", "window", "dmax", "refine", "median", "p2-adapt", "subpixel-bits",
                                          "uniqueness", "confidence", "p1", "paths", "resolution", "uf"});
  std::vector<dse::Skipped> skipped;
  const std::vector<StereoConfig> configs = dse::enumerate(dse::parse_space(t), StereoConfig{}, skipped);
  CHECK(skipped.empty());
  REQUIRE(configs.size() == 16);
  // In the order of a counter whose last digit is paths: every combination once.
  size_t i = 0;
  for (int uniqueness : {0, 15})
    for (bool confidence : {false, true})
      for (int p1 : {5, 9})
        for (unsigned paths : {unsigned(kAllPaths), unsigned(kPath0 | kPath90)}) {
          StereoConfig expected;
          set_param(expected, "cost", "census");
          expected.window = 5;
          expected.dmax = 64;
          expected.uf = 16;
          expected.width = 320;
          expected.height = 96;
          expected.uniqueness = uniqueness;
          expected.confidence = confidence;
          expected.p1 = p1;
          expected.paths = paths;
          CHECK(configs[i++] == expected);
        }
  CHECK(dse::config_flags(configs.back()).find("--paths 0,90 --p1 9") != std::string::npos);
  CHECK(dse::space_flags(t).find("--subpixel-bits 0 --axis uniqueness=0,15 --axis confidence=off,on --axis p1=5,9 "
                                 "--axis paths=all/0,90 --resolution 320x96 --uf 16") != std::string::npos);
  // Every parameter of the table: a one-value axis at its default is the default design (width
  // and height belong to resolution, lr is refine's parameter).
  for (const auto& spec : param_specs()) {
    dse::SpaceText one = single_design_space();
    const dse::AxisText axis{spec.name, {spec.get(StereoConfig{})}};
    if (spec.name == "width" || spec.name == "height") {
      CHECK_THROWS_AS(dse::set_axis(one, axis), InputError);
      continue;
    }
    dse::set_axis(one, axis);
    std::vector<dse::Skipped> none;
    CHECK(dse::enumerate(dse::parse_space(one), StereoConfig{}, none).size() == 1);
  }
}

TEST_CASE("the pixels-per-clock axis: one accuracy run for its values, the strips' frame rate", "[dse]") {
  // ppc needs uf = dmax: accepted as an axis, skipped where uf is below dmax.
  dse::SpaceText t = single_design_space();
  dse::set_axis(t, {"uf", {"16", "64"}});
  dse::set_axis(t, dse::parse_axis("ppc=1,2,4"));
  std::vector<dse::Skipped> skipped;
  const std::vector<StereoConfig> configs = dse::enumerate(dse::parse_space(t), StereoConfig{}, skipped);
  REQUIRE(configs.size() == 4);  // uf 16 at ppc 1, uf 64 at ppc 1, 2, 4
  CHECK(skipped.size() == 2);
  std::set<std::string> keys;
  std::map<int, double> fps;
  for (const auto& c : configs) {
    keys.insert(dse::accuracy_key(c));
    if (c.uf == 64) fps[c.ppc] = dse::frames_per_second(rtl::plan(c), 200);
  }
  CHECK(keys.size() == 1);  // ppc, like uf, leaves the output as it is
  // 320 wide, census 5 with the median: in strips, so about ppc times the frames of ppc 1.
  REQUIRE(fps.size() == 3);
  CHECK(fps[2] > 1.9 * fps[1]);
  CHECK(fps[4] > 3.5 * fps[1]);
}

TEST_CASE("a value is refused only when no combination could use it", "[dse]") {
  // p1 200 exceeds the default p2 (86) but not every p2: it is skipped per combination.
  dse::SpaceText t = single_design_space();
  dse::set_axis(t, dse::parse_axis("p1=7,200"));
  std::vector<dse::Skipped> skipped;
  const std::vector<StereoConfig> configs = dse::enumerate(dse::parse_space(t), StereoConfig{}, skipped);
  REQUIRE(configs.size() == 1);
  REQUIRE(skipped.size() == 1);
  CHECK(skipped[0].reason.find("p1") != std::string::npos);
  dse::set_axis(t, dse::parse_axis("p2=86,255"));
  skipped.clear();
  CHECK(dse::enumerate(dse::parse_space(t), StereoConfig{}, skipped).size() == 3);
  CHECK(skipped.size() == 1);
  // The right view needs a left-right check: an axis of its own on, skipped without one.
  dse::set_axis(t, dse::parse_axis("right-view=off,on"));
  CHECK_NOTHROW(dse::parse_space(t));
  CHECK_THROWS_AS(dse::parse_axis("p1"), InputError);
  CHECK_THROWS_AS(dse::parse_axis("speed=1"), InputError);
  CHECK(dse::parse_axis("p1=").values.empty());
}

TEST_CASE("a combination the hardware generators refuse is skipped with their reason", "[dse]") {
  // The Verilog's 180-degree path needs a raster-order path beside it: no accuracy run is spent
  // on the 180-degree path alone.
  dse::SpaceText t = single_design_space();
  dse::set_axis(t, dse::parse_axis("paths=all/180"));
  std::vector<dse::Skipped> skipped;
  const std::vector<StereoConfig> configs = dse::enumerate(dse::parse_space(t), StereoConfig{}, skipped);
  REQUIRE(configs.size() == 1);
  CHECK(configs[0].paths == unsigned(kAllPaths));
  REQUIRE(skipped.size() == 1);
  CHECK(skipped[0].reason.find("needs a raster-order path beside the 180-degree one") != std::string::npos);
}

TEST_CASE("the axes enumerate in the old nested loops' order: cost outermost, uf fastest", "[dse]") {
  const dse::SpaceText t = space_with({{"cost", {"census", "sad"}},
                                       {"window", {"3", "5"}},
                                       {"dmax", {"32", "64"}},
                                       {"refine", {"none", "lr1"}},
                                       {"median", {"off", "3"}},
                                       {"p2-adapt", {"0", "4"}},
                                       {"subpixel-bits", {"0", "2"}},
                                       {"resolution", {"96x40", "128x48"}},
                                       {"uf", {"8", "16"}}});
  std::vector<dse::Skipped> skipped;
  const std::vector<StereoConfig> configs = dse::enumerate(dse::parse_space(t), StereoConfig{}, skipped);
  CHECK(skipped.empty());
  REQUIRE(configs.size() == 512);
  size_t i = 0;
  for (CostFunction cost : {CostFunction::Census, CostFunction::Sad})
    for (int window : {3, 5})
      for (int dmax : {32, 64})
        for (LrCheck lr : {LrCheck::None, LrCheck::Lr1})
          for (int median : {0, 3})
            for (int adapt : {0, 4})
              for (int subpixel : {0, 2})
                for (const auto& [w, h] : {std::pair{96, 40}, std::pair{128, 48}})
                  for (int uf : {8, 16}) {
                    const StereoConfig& c = configs[i++];
                    CHECK((c.cost == cost && c.window == window && c.dmax == dmax && c.lr == lr &&
                           c.median == median && c.p2_adapt == adapt && c.subpixel_bits == subpixel &&
                           c.width == w && c.height == h && c.uf == uf));
                  }
}

TEST_CASE("a tiny sweep: skipped combinations, one golden run per accuracy key, resume from the cache",
          "[dse]") {
  const fs::path cache = fresh_dir("fpstereo_test_dse_cache");
  dse::SweepOptions o = tiny_sweep(cache, "fpstereo_test_dse_data");
  const dse::SweepResult first = dse::sweep(o);
  // 2 costs x 2 windows x 2 dmax x 2 refine x 2 median = 32 accuracy keys; uf 32 is skipped for
  // dmax 16 (x 16 configurations), so 32 * 3 - 16 = 80 rows.
  CHECK(first.accuracy_configs == 32);
  CHECK(first.evaluated == 32);
  CHECK(first.cached == 0);
  CHECK(first.rows.size() == 80);
  CHECK(first.skipped.size() == 16);
  // Configurations that differ only in uf share their accuracy.
  for (const auto& a : first.rows)
    for (const auto& b : first.rows)
      if (dse::accuracy_key(a.cfg) == dse::accuracy_key(b.cfg)) CHECK(a.acc.d1_all == b.acc.d1_all);
  const dse::SweepResult second = dse::sweep(o);
  CHECK(second.evaluated == 0);
  CHECK(second.cached == 32);
  REQUIRE(second.rows.size() == first.rows.size());
  for (size_t i = 0; i < first.rows.size(); ++i) CHECK(second.rows[i].acc.d1_all == first.rows[i].acc.d1_all);

  SECTION("shards merged equal the full sweep") {
    std::vector<dse::Row> merged;
    for (int i = 1; i <= 3; ++i) {
      dse::SweepOptions s = o;
      s.cache_dir = fresh_dir("fpstereo_test_dse_shard" + std::to_string(i)).string();
      s.shard_index = i;
      s.shard_count = 3;
      const fs::path csv =
          test::scratch_path("fpstereo_test_dse_shard" + std::to_string(i) + ".csv");
      std::ofstream(csv) << dse::to_csv(dse::sweep(s).rows);
      for (auto& r : dse::read_csv(csv.string())) merged.push_back(r);
    }
    dse::mark_pareto(merged);
    REQUIRE(merged.size() == first.rows.size());
    std::map<std::string, const dse::Row*> full;
    for (const auto& r : first.rows) full[dse::config_flags(r.cfg)] = &r;
    for (const auto& r : merged) {
      const dse::Row* f = full.at(dse::config_flags(r.cfg));
      CHECK(std::abs(r.acc.d1_all - f->acc.d1_all) < 1e-4);
      CHECK(r.pareto == f->pareto);
      CHECK(std::abs(r.model.lut - f->model.lut) < 1);
      CHECK(r.model.bram36_equiv() == f->model.bram36_equiv());
      CHECK(r.cycles_per_frame == f->cycles_per_frame);
    }
  }

  SECTION("the report and the recommendation") {
    dse::ReportInfo info;
    info.part = "xczu9eg";
    info.constraints.min_fps = 1000;
    info.constraints.top = 3;
    const std::string html = dse::to_html(first.rows, info);
    CHECK(html.find("<svg") != std::string::npos);
    CHECK(html.find("Pareto front") != std::string::npos);
    CHECK(html.find("<script") == std::string::npos);
    // Which figures are the fast model's, and how far it was from Yosys.
    CHECK(html.find(dse::model_note()) != std::string::npos);
    const std::vector<dse::Row> best = dse::recommend(first.rows, info.constraints);
    REQUIRE(best.size() == 3);
    for (const auto& r : best) CHECK(r.fps >= 1000);
    CHECK(best[0].acc.d1_all <= best[1].acc.d1_all);
    CHECK(dse::rtl_command(best[0].cfg).rfind("fpstereo-rtl --width 96 --height 40 --cost ", 0) == 0);
  }
}

TEST_CASE("a corrupt cache record is an error, not a silent recomputation", "[dse]") {
  const fs::path cache = fresh_dir("fpstereo_test_dse_corrupt");
  dse::SweepOptions o = tiny_sweep(cache, "fpstereo_test_dse_corrupt_data");
  o.space = dse::parse_space(space_with({{"cost", {"census"}},
                                         {"window", {"3"}},
                                         {"dmax", {"16"}},
                                         {"uf", {"4", "8", "32"}},
                                         {"resolution", {"96x40"}},
                                         {"refine", {"none"}},
                                         {"median", {"off"}}}));
  dse::sweep(o);
  for (const auto& e : fs::directory_iterator(cache)) std::ofstream(e.path()) << "{ not json";
  CHECK_THROWS_AS(dse::sweep(o), InputError);
}

TEST_CASE("every CSV column reads back what was written", "[dse]") {
  dse::Row row;
  row.cfg = preset("C3");
  row.cfg.p2_adapt = 4;
  row.cfg.subpixel_bits = 2;
  row.acc = {12.3456, 10.5, 4.25, 80.125, 3};
  row.model.lut = 12345;
  row.model.ff = 23456;
  row.model.bram36 = 17;
  row.model.bram18 = 1;
  row.model.dsp = 3;
  row.part = "xck26";
  row.lut_pct = 10.125;
  row.ff_pct = 5.5;
  row.bram_pct = 12.25;
  row.dsp_pct = 0.25;
  row.resource_pct = 12.25;
  row.cycles_per_frame = 7571380;
  row.clock_mhz = 250;
  row.fps = 33.5;
  row.pareto = true;
  row.yosys_lut = 12000;
  row.yosys_ff = 23000;
  row.yosys_bram36 = 16.5;
  const fs::path csv = test::scratch_path("fpstereo_test_dse_columns.csv");
  dse::Row blank;
  blank.part = "xck26";  // every row names a known part
  const std::string text = dse::to_csv({row, blank});
  std::ofstream(csv) << text;
  const std::vector<dse::Row> back = dse::read_csv(csv.string());
  REQUIRE(back.size() == 2);
  CHECK(dse::to_csv(back) == text);
  CHECK(describe(back[0].cfg) == describe(row.cfg));
  CHECK(back[0].model.bram36 == 17);
  CHECK(back[0].model.bram18 == 1);
  CHECK(std::isnan(back[0].yosys_dsp));
}

TEST_CASE("dse CSV: a bad cell is an error naming the file, line and column", "[dse]") {
  dse::Row row;
  row.cfg = preset("C2");
  row.part = "xck26";
  row.model.bram36 = 3;
  const std::string text = dse::to_csv({row});
  const std::string header = text.substr(0, text.find('\n'));
  std::vector<std::string> names, cells;
  std::stringstream hs(header);
  for (std::string n; std::getline(hs, n, ',');) names.push_back(n);
  const std::string line = text.substr(header.size() + 1, text.size() - header.size() - 2);
  std::stringstream ls(line);
  for (std::string c; std::getline(ls, c, ',');) cells.push_back(c);
  if (line.back() == ',') cells.emplace_back();
  REQUIRE(cells.size() == names.size());
  const fs::path csv = test::scratch_path("fpstereo_test_dse_bad_cell.csv");
  const auto error_with = [&](const std::string& column, const std::string& value) {
    std::vector<std::string> changed = cells;
    changed[size_t(std::find(names.begin(), names.end(), column) - names.begin())] = value;
    std::string out = header + "\n";
    for (size_t i = 0; i < changed.size(); ++i) out += (i ? "," : "") + changed[i];
    std::ofstream(csv) << out << "\n";
    try {
      dse::read_csv(csv.string());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string at = "'" + csv.string() + "' line 2, column ";
  CHECK(error_with("bram36", "-2147483648") == at + "bram36: '-2147483648' is not a number from 0 to 1e+09");
  CHECK(error_with("bram36", "1e300") == at + "bram36: '1e300' is not a number from 0 to 1e+09");
  CHECK(error_with("lut", "nan") == at + "lut: 'nan' is not a number from 0 to 1e+09");
  CHECK(error_with("fps", "inf") == at + "fps: 'inf' is not a number from 0 to 1e+09");
  CHECK(error_with("lut", "12x") == at + "lut: '12x' is not a number from 0 to 1e+09");
  CHECK(error_with("cycles_per_frame", "1.5") == at + "cycles_per_frame: '1.5' is not a whole number from 0 to 1e+09");
  CHECK_THAT(error_with("part", "xc9000"), Catch::StartsWith(at + "part: ") && Catch::Contains("xc9000"));
  CHECK(error_with("flags", "") == at + "flags: empty, expected the configuration's flags");
  CHECK(error_with("bram36", "3").empty());
  fs::remove(csv);
}

TEST_CASE("the Verilog hash follows the emitted Verilog", "[dse]") {
  StereoConfig a, b;
  b.dmax = 64;
  CHECK(verilog_hash(a) == verilog_hash(StereoConfig{}));
  CHECK(verilog_hash(a) != verilog_hash(b));
  CHECK(verilog_hash(a).size() == 16);
}

// The committed model is the fit of the committed Yosys results: a recollection without a refit,
// a hand edit of the coefficients or of the data, or a configuration without a result fails here.
// Stale results (the generator emits other Verilog for them now) only warn: every Verilog change
// makes rows stale, and recollecting takes hours of Yosys (bench_resource_model --fail-on-stale,
// ctest -L resource-data, is the strict check); the bench and the DSE's report name them.
TEST_CASE("the resource model is the fit of the committed Yosys results and names their stale rows", "[dse]") {
  const std::string dir = std::string(FPSTEREO_SOURCE_DIR) + "/bench/";
  std::vector<dse::YosysRow> rows = dse::read_fit_configs(dir + "resource_fit_configs.txt");
  dse::read_fit_data(dir + "resource_fit_data.csv", rows);
  size_t fit_rows = 0, heldout_rows = 0;
  for (const auto& r : rows) {
    INFO("row " << r.name);
    CHECK(r.have_yosys);
    CHECK(r.verilog_hash.size() == 16);
    fit_rows += r.role == "fit";
    heldout_rows += r.role == "heldout";
  }
  // At least as many fit designs as coefficients per resource, and designs to check them on.
  CHECK(fit_rows >= dse::group_names().size());
  CHECK(heldout_rows >= 2);

  const dse::Coefficients refitted = dse::refit(rows), &committed = dse::fitted_coefficients();
  const auto same = [](const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
      if (std::abs(a[i] - b[i]) > 1e-5 * std::max(1.0, std::abs(a[i]))) return false;
    return true;
  };
  CHECK(same(refitted.lut, committed.lut));
  CHECK(same(refitted.ff, committed.ff));
  CHECK(same(refitted.dsp, committed.dsp));

  const dse::FitProvenance& p = dse::fit_provenance();
  REQUIRE(p.records.size() == rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    CHECK(rows[i].name == p.records[i].name);
    CHECK(rows[i].role == p.records[i].role);
    CHECK(rows[i].flags == p.records[i].flags);
    CHECK(rows[i].verilog_hash == p.records[i].verilog_hash);
  }
  const dse::ErrorSummary h = dse::summarise(rows, "heldout", committed);
  CHECK(h.designs == p.heldout.designs);
  CHECK(h.bram_exact == p.heldout.bram_exact);
  CHECK(h.lut_mean == Approx(p.heldout.lut_mean).margin(0.005));
  CHECK(h.lut_max == Approx(p.heldout.lut_max).margin(0.005));
  CHECK(h.ff_mean == Approx(p.heldout.ff_mean).margin(0.005));
  CHECK(h.ff_max == Approx(p.heldout.ff_max).margin(0.005));

  // The report's staleness is the rows': what the DSE says about its model holds.
  std::vector<std::string> stale;
  for (const auto& r : rows)
    if (dse::is_stale(r)) stale.push_back(r.name);
  CHECK(dse::stale_records() == stale);
  const std::string note = dse::model_note();
  CHECK_THAT(note, Catch::Contains(fmt::format("{} held-out designs", h.designs)));
  if (stale.empty()) {
    CHECK_THAT(note, Catch::Contains("Every one of those Yosys results is of the Verilog the generator emits today"));
  } else {
    CHECK_THAT(note, Catch::Contains(fmt::format("Stale: {} of the {}", stale.size(), rows.size())));
    std::string names;
    for (const auto& n : stale) names += " " + n;
    WARN(stale.size() << " of " << rows.size() << " rows of bench/resource_fit_data.csv are stale (the generator "
                      "emits other Verilog for them now):" << names << "; rerun build/bench/bench_resource_model "
                      "--collect, then --refit --write gen/dse/resource_coefficients.inc");
  }
}
