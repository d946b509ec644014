// Gap interpolation (fpstereo_gap_fill), one row behind its input; with strips a slot's P words a step.
#include <fmt/core.h>

#include "hls_text.hpp"
#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class GapStage : public Stage {
 public:
  std::string title() const override { return "gap interpolation"; }
  std::vector<std::string> knobs() const override { return {"gap-interp"}; }
  // The linear fill adds its divider: two steps of operands and a step a quotient bit.
  Latency latency(const Geometry& g) const override {
    return {1, 0, 4 + (g.cfg.gap_linear ? 2 + (g.widths.output_word - 1) : 0)};
  }
  // Two rows of the slots' words with their last runs' first pixels, and of the runs' right
  // neighbours by first pixel (with the linear fill, with the neighbours' pixels).
  std::vector<StageMemory> memories(const Geometry& g) const override {
    return {{"core.gap.words.mem", 2 * int64_t(g.cfg.width) / g.strips,
             int64_t(g.strips) * g.widths.output_word + g.x_bits},
            {"core.gap.right_neighbours.mem", 2 * int64_t(g.cfg.width),
             g.widths.output_word + (g.cfg.gap_linear ? g.x_bits : 0)}};
  }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams& streams) const override {
    const PixelStream in = streams.pixels;
    const PixelStream& out = streams.pixels = {"", "gap_event", "gap_x", "gap_y", "gap_word"};
    core.text("\n  // Gap interpolation.\n");
    stream_wires(core, d, out, d.widths.output_word * d.strips);
    core.instance("fpstereo_gap_fill", "gap",
                  {{"W", num(d.cfg.width)},
                   {"WORD_W", num(d.widths.output_word)},
                   {"X_W", num(d.x_bits)},
                   {"Y_W", num(d.y_bits)},
                   {"P", num(d.strips)},
                   {"LINEAR", d.cfg.gap_linear ? "1" : "0"},
                   {"UNIT_LOG", num(d.cfg.subpixel_bits)}},
                  Connections{{"in_event", in.event}} + stream_connections(in, out));
  }

  // ---- HLS: one row behind its input.
  std::string hls_calls(const RtlDesign&, HlsStreams& s) const override {
    const std::string in = s.base;
    s.base = "filled";
    return "\n  // Gap interpolation.\n" + hls::stream_declarations("Word<C>", {s.base}) +
           fmt::format("  gap_fill<C>({}, {}, W, H);\n", in, s.base);
  }
  int hls_fill_rows(const Geometry&) const override { return 1; }
};

}  // namespace

StagePtr gap_stage() { return std::make_shared<GapStage>(); }

}  // namespace fpstereo::rtl
