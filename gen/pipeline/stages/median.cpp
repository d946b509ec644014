// Median filter (fpstereo_median): its window's newest word is rm rows and rm slots past the
// centre (with strips, ceil(rm / P) slots: P medians a slot); the selection takes three steps per
// word bit, and a step each for the window and the result.
#include <fmt/core.h>

#include "hls_text.hpp"
#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class MedianStage : public Stage {
 public:
  std::string title() const override { return "median filter"; }
  std::vector<std::string> knobs() const override { return {"median"}; }
  Latency latency(const Geometry& g) const override {
    const int rm = g.cfg.median / 2;
    return {rm, (rm + g.strips - 1) / g.strips, 2 + 3 * g.widths.output_word};
  }
  std::vector<StageMemory> memories(const Geometry& g) const override {
    return {{"core.median.line_window.line_buffer.mem", g.row_slots,
             int64_t(g.cfg.median - 1) * g.widths.output_word * g.strips}};
  }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams& streams) const override {
    const PixelStream in = streams.pixels;
    const PixelStream& out = streams.pixels = {"", "median_event", "median_x", "median_y", "median_word"};
    core.text("\n  // Median filter.\n");
    stream_wires(core, d, out, d.widths.output_word * d.strips);
    core.instance("fpstereo_median", "median",
                  {{"M", num(d.cfg.median)},
                   {"ROW_SLOTS", num(d.row_slots)},
                   {"DISP_W", num(d.widths.output_disparity)},
                   {"EXTRA_ROWS", d.cfg.gap_interpolation ? "1" : "0"},
                   {"X_W", num(d.x_bits)},
                   {"Y_W", num(d.y_bits)},
                   {"SIGNED_Y_W", num(d.signed_y_bits)},
                   {"P", num(d.strips)}},
                  Connections{{"in_done", in.done}} + stream_connections(in, out));
  }

  // ---- HLS: the median window (positions outside the image invalid) and the selection.
  std::string hls_calls(const RtlDesign&, HlsStreams& s) const override {
    using hls::stream_declarations;
    const std::string in = s.base;
    s.base = "filtered";
    return "\n  // Median filter.\n" + stream_declarations("Window<Word<C>, C::kMedian>", {"median_windows"}) +
           stream_declarations("Word<C>", {s.base}) +
           fmt::format("  window_stage<Word<C>, C::kMedian, C::kMaxWidth>({}, median_windows, W, H, "
                       "Word<C>(C::kInvalidWord));\n",
                       in) +
           fmt::format("  median_stage<C>(median_windows, {}, W, H);\n", s.base);
  }
  HlsLoop hls_loop(const Geometry& g) const override { return hls_window_loop(g, "median window", g.cfg.median / 2); }
  int hls_fill_rows(const Geometry& g) const override { return g.cfg.median / 2; }
};

}  // namespace

StagePtr median_stage() { return std::make_shared<MedianStage>(); }

}  // namespace fpstereo::rtl
