// Speckle filter (fpstereo_speckle_stage around fpstereo_speckle, docs/speckle-hardware.md): every
// slot's word enters the filter, and the word of the same slot speckle_rows rows earlier leaves
// with the next slot's word, registered: speckle_rows rows, one slot and one step behind. The HLS
// path runs the kernel speckle_filter (hls/fpstereo_hls.hpp).
#include <fmt/core.h>

#include "hls_text.hpp"
#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class SpeckleStage : public Stage {
 public:
  std::string title() const override { return "speckle filter"; }
  std::vector<std::string> knobs() const override { return {"speckle-size", "speckle-range"}; }
  Latency latency(const Geometry& g) const override { return {g.speckle_rows, 1, 1}; }
  // fpstereo_speckle's memories at W = row_slots (docs/speckle-hardware.md, "Memories").
  std::vector<StageMemory> memories(const Geometry& g) const override {
    const int64_t W = g.row_slots, positions = int64_t(g.speckle_rows) * W;
    const int x_w = clog2(W), run_w = clog2(positions), count_w = clog2(g.cfg.speckle_size + 2);
    const int64_t labels = int64_t(2) << x_w, stack_depth = (W + 1) / 2;
    const std::string at = "core.speckle.filter.";
    return {{at + "words_mem.mem", positions, g.widths.output_word},
            {at + "kill_mem.mem", positions, 1},
            {at + "next_mem.mem", positions, run_w},
            {at + "linked_mem.mem", positions, 1},  // whether a run's link is one
            {at + "above_mem.mem", W, g.widths.output_word + 1 + x_w},
            {at + "parent_mem.mem", labels, x_w},
            {at + "root_res_mem.mem", W, x_w},
            {at + "root_mem.mem", W, x_w},
            {at + "cls_mem.mem", labels, count_w + x_w + 2 * run_w + 1},
            {at + "stack_mem.mem", stack_depth, 3 * x_w + count_w + 2 * run_w}};
  }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams& streams) const override {
    const PixelStream in = streams.pixels;
    const PixelStream& out = streams.pixels = {"speckle_done", "speckle_event", "speckle_x", "speckle_y", "speckle_word"};
    core.text("\n  // Speckle filter.\n");
    stream_wires(core, d, out);
    core.instance("fpstereo_speckle_stage", "speckle",
                  {{"ROW_SLOTS", num(d.row_slots)},
                   {"G", num(d.groups)},
                   {"S", num(d.cfg.speckle_size)},
                   {"R", num(int64_t(d.cfg.speckle_range) << d.cfg.subpixel_bits)},
                   {"ROWS", num(d.speckle_rows)},
                   {"DISP_W", num(d.widths.output_disparity)},
                   {"EXTRA_ROWS", d.cfg.gap_interpolation ? "1" : "0"},
                   {"X_W", num(d.x_bits)},
                   {"Y_W", num(d.y_bits)},
                   {"SIGNED_Y_W", num(d.signed_y_bits)}},
                  Connections{{"in_done", in.done}, {"out_done", out.done}} + stream_connections(in, out));
  }

  // ---- HLS: the models' one-pass labelling (speckle_filter), S rows behind its input.
  std::string hls_calls(const RtlDesign&, HlsStreams& s) const override {
    const std::string in = s.base;
    s.base = "despeckled";
    return "\n  // Speckle filter.\n" + hls::stream_declarations("Word<C>", {s.base}) +
           fmt::format("  speckle_filter<C>({}, {}, W, H);\n", in, s.base);
  }
  HlsLoop hls_loop(const Geometry& g) const override {
    const int64_t S = g.cfg.speckle_size;
    return {"speckle filter (each with a root search)", "(H+S)*W", (int64_t(g.cfg.height) + S) * g.cfg.width};
  }
  int hls_fill_rows(const Geometry& g) const override { return g.cfg.speckle_size; }
};

}  // namespace

StagePtr speckle_stage() { return std::make_shared<SpeckleStage>(); }

}  // namespace fpstereo::rtl
