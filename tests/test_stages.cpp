// The stage objects (gen/pipeline/stages/): every setting belongs to a stage, every template is used
// by some configuration, and the schedule is the sum of the stages' latencies.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

#include "rtl_emitter.hpp"
#include "rtl_templates.hpp"

using namespace fpstereo;

namespace {

// Configurations that together enable every stage and every variant of one.
std::vector<StereoConfig> covering_configs() {
  std::vector<StereoConfig> out;
  for (CostFunction cost : {CostFunction::Census, CostFunction::Rank, CostFunction::Sad, CostFunction::Zsad,
                            CostFunction::Shd})
    for (LrCheck lr : {LrCheck::None, LrCheck::Lr1, LrCheck::Lr2}) {
      StereoConfig c;
      c.width = 64;
      c.height = 16;
      c.dmax = 32;
      c.uf = 8;
      c.cost = cost;
      c.shd_window = 3;
      c.lr = lr;
      c.uniqueness = lr == LrCheck::Lr1 ? 10 : 0;
      c.gap_interpolation = lr == LrCheck::Lr2;
      c.subpixel_bits = lr == LrCheck::Lr2 ? 0 : 3;
      c.right_view = lr != LrCheck::None;
      c.p2_adapt = cost != CostFunction::Shd && lr != LrCheck::Lr1 ? 4 : 0;  // the RTL has it but with SHD
      c.confidence = cost == CostFunction::Census || cost == CostFunction::Sad;
      // The fused cost where validate() allows it (not SAD, ZSAD), both terms, and off with LR1.
      const bool compares_codes = cost != CostFunction::Sad && cost != CostFunction::Zsad;
      c.fused_weight = compares_codes && lr != LrCheck::Lr1 ? 4 : 0;
      c.fused_term = lr == LrCheck::Lr2 ? FusedTerm::Gradient : FusedTerm::Intensity;
      c.speckle_size = cost == CostFunction::Census || cost == CostFunction::Rank ? 6 : 0;
      out.push_back(c);
    }
  // Beats of two pixels (uf = dmax) where the strips do not go, which the top's beat split and
  // pack serve for the one-pixel core: LR2 in a row of dmax + m, one pixel short of what its
  // strips need.
  StereoConfig beats;
  beats.width = 64;
  beats.height = 16;
  beats.dmax = beats.uf = 32;
  beats.ppc = 2;
  beats.cost = CostFunction::Sad;
  beats.lr = LrCheck::Lr2;
  beats.min_disp = 32;
  out.push_back(beats);
  // ... SHD in strips (its code windows, fpstereo_strip_code_windows, with the fused cost's
  // features beside them, and the window costs of a slot's two pixels a step,
  // fpstereo_strip_window_cost) ...
  StereoConfig window_strips = beats;
  window_strips.lr = LrCheck::None;
  window_strips.min_disp = 0;
  window_strips.cost = CostFunction::Shd;
  window_strips.shd_window = 3;
  window_strips.fused_weight = 4;
  out.push_back(window_strips);
  // ... and SAD.
  window_strips.cost = CostFunction::Sad;
  window_strips.fused_weight = 0;
  out.push_back(window_strips);
  // ... and in strips, where the core takes a beat a step (census, uniqueness, the sub-pixel fit,
  // the confidence, adaptive P2, the fused cost, min-disp, the median and gap interpolation).
  StereoConfig strips = window_strips;
  strips.cost = CostFunction::Census;
  strips.gap_interpolation = true;
  strips.confidence = true;
  strips.p2_adapt = 4;
  strips.fused_weight = 4;
  strips.min_disp = 3;
  strips.subpixel_bits = 2;
  strips.uniqueness = 10;
  strips.ppc = 4;
  strips.width = 128;
  out.push_back(strips);
  // ... and below min-disp 0 (the base entries' wait, strip 0's prefix of match entries).
  strips.min_disp = -5;
  out.push_back(strips);
  return out;
}

}  // namespace

TEST_CASE("every configuration parameter is owned by a stage", "[stages]") {
  std::set<std::string> owned;
  for (const auto& cfg : covering_configs())
    for (const auto& stage : rtl::plan(cfg).stages)
      for (const auto& knob : stage->knobs()) owned.insert(knob);
  for (const auto& spec : param_specs()) {
    INFO("parameter " << spec.name);
    CHECK(owned.count(spec.name) == 1);
  }
  for (const auto& knob : owned) {
    INFO("knob " << knob);
    CHECK(std::any_of(param_specs().begin(), param_specs().end(),
                      [&](const ParamSpec& s) { return s.name == knob; }));
  }
}

TEST_CASE("every template is used by some configuration", "[stages]") {
  std::set<std::string> used;
  for (const auto& cfg : covering_configs()) {
    const rtl::RtlDesign d = rtl::plan(cfg);
    for (const auto& file : rtl::emit(d))
      for (const auto& [name, text] : rtl::templates())
        if (file.name == d.prefix + name.substr(std::string("fpstereo").size()) + ".v") used.insert(name);
  }
  for (const auto& [name, text] : rtl::templates()) {
    INFO("template " << name);
    CHECK(used.count(name) == 1U);
  }
}

TEST_CASE("the schedule is the sum of the stages' latencies", "[stages]") {
  for (const auto& cfg : covering_configs()) {
    const rtl::RtlDesign d = rtl::plan(cfg);
    int64_t sum = 0;
    for (const auto& stage : d.stages) sum += stage->latency(d).in_steps(d.row_slots, d.groups);
    // With strips a step takes a slot of P pixels.
    const int64_t last_pixel = (int64_t(cfg.height) - 1) * d.row_slots + cfg.width / d.strips - 1;
    INFO(config_tag(cfg));
    // A row-time is the width in whole segments, without bubble slots; with strips, P strips of
    // whole segments and whole slots, the last one not empty.
    if (d.strips == 1) {
      CHECK(d.row_slots == d.chains * ((cfg.width + d.chains - 1) / d.chains));
    } else {
      CHECK(d.strips == cfg.ppc);
      CHECK(d.row_slots == d.chains * d.segment);
      CHECK(d.row_slots % d.strips == 0);
      CHECK(int64_t(d.strips) * d.row_slots >= cfg.width);
      CHECK(int64_t(d.strips - 1) * d.row_slots < cfg.width);
    }
    // With several pixels per beat split for the one-pixel core, the beat's register delays the
    // frame's first pixel a cycle.
    const int beat = cfg.ppc > 1 && d.strips == 1 ? rtl::kBeatSplitCycles : 0;
    // At G = 1 a frame that may be followed waits at its end for what the row's spare slots and
    // the beat's other pixels do not cover of the next frame's way in (with strips a slot is a beat).
    const int64_t spare =
        d.strips > 1 ? d.row_slots - cfg.width / d.strips : d.row_slots - cfg.width + cfg.ppc - 1;
    const int64_t wait = d.groups == 1 ? std::max<int64_t>(0, rtl::kFollowCycles - spare) : 0;
    CHECK(d.follow_wait == wait);
    const bool follows_on = cfg.height >= d.overlap_height;
    CHECK(d.lone_frame_cycles == sum + last_pixel * d.groups + beat + (follows_on ? wait : 0));
    // Back to back, a frame takes its row-times and the wait, once it is taller than the drain.
    const int64_t rows_cycles = int64_t(cfg.height) * d.row_slots * d.groups;
    CHECK(d.cycles_per_frame == (follows_on ? rows_cycles + wait : d.lone_frame_cycles));
    // Frames follow on when taller than the drain, up to the push of pixel (0, 0) (the output
    // stage's last kStepsAfterPush steps come after it), by two row-times.
    const int64_t push_first = sum - rtl::kStepsAfterPush;
    CHECK(d.overlap_height * d.row_slots * d.groups >= push_first + 2 * d.row_slots * d.groups);
    // Every stage with a schedule of its own has its start step, and only those.
    for (const auto& stage : d.stages)
      CHECK(d.start_steps.count(stage->start_parameter()) == (stage->start_parameter().empty() ? 0u : 1u));
  }
}
