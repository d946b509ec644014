// Left-right check (fpstereo_lr_check): three steps (the RAM reads, Dm registered, the check
// registered), against the match side's completed pixels (LR1 also its row ends).
#include <fmt/core.h>

#include <algorithm>

#include "hls_text.hpp"
#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class LrCheckStage : public Stage {
 public:
  explicit LrCheckStage(const StereoConfig& c) : row_end_(c.lr == LrCheck::Lr1) {}
  std::string title() const override { return "left-right check"; }
  std::vector<std::string> knobs() const override { return {"lr", "lr-threshold", "min-disp"}; }
  // In strips fpstereo_strip_lr_check registers the read stream first: a step more, and with the
  // right view above min-disp 0 its lookups wait.
  Latency latency(const Geometry& g) const override {
    return {0, 0, g.strips > 1 ? 4 + check_wait_slots(g) : 3};
  }
  std::vector<StageMemory> memories(const Geometry& g) const override {
    if (g.strips > 1) return {};  // in strips, the aggregation stage's (fpstereo_strip_lr_check)
    // One lookup of Dm for the check; with the right view a second one for Dm(x).
    std::vector<StageMemory> out;
    for (const std::string lookup : {"lookup", "right_view.lookup"}) {
      if (lookup != "lookup" && !g.cfg.right_view) break;
      const std::string at = "core.lr_check." + lookup;
      out.push_back({at + ".completed.mem", g.disp_depth(), g.widths.disparity});
      if (row_end_)
        out.push_back({at + ".row_end.row_end.mem", int64_t(g.out_rows) * g.groups,
                       int64_t(g.cfg.uf) * g.widths.disparity});
    }
    return out;
  }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams& streams) const override {
    // In strips fpstereo_strip_aggregation checks the words before they leave it, in this
    // stage's latency.
    if (d.strips > 1) return;
    const StereoConfig& c = d.cfg;
    const PixelStream in = streams.pixels;
    const PixelStream& out = streams.pixels = {"checked_done", "checked_event", "checked_x", "checked_y", "checked_word"};
    core.text("\n  // Left-right check.\n");
    stream_wires(core, d, out);
    core.wire("right_dm", d.widths.disparity);  // the right view reads it
    Connections ports = {{"read_done", in.done},   {"read_event", in.event}, {"read_x", in.x},
                         {"read_y", in.y},         {"read_word", in.word},   {"checked_done", out.done},
                         {"checked_event", out.event}, {"checked_x", out.x}, {"checked_y", out.y},
                         {"checked_word", out.word}, {"right_word", "right_dm"}};
    // Only LR1 has row ends to look up.
    if (!row_end_)
      ports = ports + Connections{{"row_end_we", "1'b0"},
                                  {"row_end_waddr", fmt::format("{}'d0", d.end_addr_bits)},
                                  {"row_end_wdata", fmt::format("{}'d0", c.uf * d.widths.disparity)}};
    core.instance("fpstereo_lr_check", "lr_check",
                  {{"ROW_SLOTS", num(d.row_slots)},
                   {"G", num(d.groups)},
                   {"UF", num(c.uf)},
                   {"DMAX", num(c.dmax)},
                   {"DISP_W", num(d.widths.disparity)},
                   {"REFINED_W", num(d.carries_whole ? d.widths.output_disparity : 0)},
                   {"OUT_ROWS", num(d.out_rows)},
                   {"OUT_ROW_W", num(d.out_row_bits)},
                   {"DISP_AW", num(d.disp_addr_bits)},
                   {"ROW_END", row_end_ ? "1" : "0"},
                   {"END_AW", num(d.end_addr_bits)},
                   {"RIGHT_VIEW", c.right_view ? "1" : "0"},
                   {"X_W", num(d.x_bits)},
                   {"Y_W", num(d.y_bits)},
                   {"LANE_W", num(d.lane_bits)},
                   {"MIN_DISP", num(c.min_disp)}},
                  ports);
  }

  // ---- HLS.
  std::string hls_calls(const RtlDesign&, HlsStreams& s) const override {
    const HlsStreams in = s;
    s = {"checked", ""};
    // Without the right view, right_view is never written.
    return "\n  // Left-right check.\n" + hls::stream_declarations("Word<C>", {s.base, "right_view"}) +
           fmt::format("  lr_check<C>({}, {}, {}, right_view, W, H, lr_threshold);\n", in.base, in.match, s.base);
  }
  // With min-disp m < 0 each row reads min(-m, W) of Dm ahead of its first D.
  HlsLoop hls_loop(const Geometry& g) const override {
    if (g.cfg.min_disp >= 0) return {};
    const int64_t W = g.cfg.width, H = g.cfg.height, lead = std::min<int64_t>(-g.cfg.min_disp, W);
    return {"left-right check (Dm -m pixels ahead)", "H*(W+min(-m,W))", H * (W + lead)};
  }

 private:
  bool row_end_;
};

}  // namespace

StagePtr lr_check_stage(const StereoConfig& cfg) { return std::make_shared<LrCheckStage>(cfg); }

}  // namespace fpstereo::rtl
