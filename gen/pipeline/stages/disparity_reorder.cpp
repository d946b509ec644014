// Disparity reorder RAM: the words in chain order in, one word per slot in raster order out (the
// pixel stream). With a left-right check the reads wait lr_rows more row-times for the match side.
#include <fmt/core.h>

#include "stage_list.hpp"
#include "stage_support.hpp"

namespace fpstereo::rtl {
namespace {

class DisparityReorderStage : public Stage {
 public:
  std::string title() const override { return "disparity reorder"; }
  std::vector<std::string> knobs() const override { return {"lr"}; }
  std::string start_parameter() const override { return "OUT_START"; }
  Latency latency(const Geometry& g) const override { return {g.lr_rows, 1, 0}; }
  Latency start_offset(const Geometry& g) const override { return {g.lr_rows, 0, 0}; }
  std::vector<StageMemory> memories(const Geometry& g) const override {
    if (g.strips > 1) return {};  // the strips' disparity RAMs, in the aggregation stage's
    return {{"core.disparity_reorder.disp_ram.mem", g.disp_depth(), g.reorder_ram_bits}};
  }

  void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams& streams) const override {
    const std::string& w = streams.words;
    streams.pixels = {"read_done", "read_event", "read_x", "read_y", "read_word"};
    const bool confidence = d.cfg.confidence;
    if (d.strips > 1) {
      // The strips' disparity RAMs are read in fpstereo_strip_aggregation, a slot's P words a step
      // (with LR1 checked there, so the words leave without the whole D the check compares).
      core.text("\n  // The strips' disparity RAMs, read in raster order from step OUT_START.\n");
      start_flag(core, d, *this, "out_on");
      stream_wires(core, d, streams.pixels, int64_t(d.strips) * d.widths.output_word);
      if (confidence) strip_confidences(core, d);
      return;
    }
    core.text("\n  // Disparity reorder RAM, read in raster order from step OUT_START.\n");
    start_flag(core, d, *this, "out_on");
    stream_wires(core, d, streams.pixels, d.reorder_word_bits);
    if (confidence) core.wire("read_confidence", kConfidenceBits);
    core.wire("read_slot_row", d.out_row_bits);  // the left-right check reads with it
    core.instance("fpstereo_disparity_reorder", "disparity_reorder",
                  {{"ROW_SLOTS", num(d.row_slots)},
                   {"G", num(d.groups)},
                   {"DISP_W", num(d.reorder_ram_bits - 1)},
                   {"OUT_ROWS", num(d.out_rows)},
                   {"OUT_ROW_W", num(d.out_row_bits)},
                   {"DISP_AW", num(d.disp_addr_bits)},
                   {"EXTRA_ROWS", d.cfg.gap_interpolation ? "1" : "0"},
                   {"X_W", num(d.x_bits)},
                   {"Y_W", num(d.y_bits)},
                   {"G_W", num(d.group_bits)}},
                  {{"active", w + "_active"},
                   {"x", w + "_x"},
                   {"slot", w + "_slot"},
                   {"group", w + "_group"},
                   {"word", "{" + (confidence ? w + "_confidence, " : "") + w + "_word" +
                                (d.carries_whole ? ", " + w + "_whole}" : "}")},
                   {"read_word", confidence ? "{read_confidence, read_word}" : "read_word"}});
  }

  // The strips' words with their confidences above them, split into the slot's words and its
  // confidences (pixel 0 lowest in each).
  static void strip_confidences(CoreBuilder& core, const RtlDesign& d) {
    const int P = d.strips, word = d.widths.output_word, entry = word + kConfidenceBits;
    core.wire(kStripConfidentWords, int64_t(P) * entry);
    core.wire("read_confidence", int64_t(P) * kConfidenceBits);
    const auto words = concat_high_to_low(P, [&](int q) { return bit_field(kStripConfidentWords, q * entry, word); });
    const auto confidences = concat_high_to_low(
        P, [&](int q) { return bit_field(kStripConfidentWords, q * entry + word, entry - word); });
    core.logic(fmt::format("  assign read_word = {};\n  assign read_confidence = {};\n", words, confidences),
               {"read_word", "read_confidence"});
  }

  // ---- HLS: select_base writes raster order.
  std::string hls_calls(const RtlDesign&, HlsStreams&) const override {
    return "\n  // Disparity reorder: none, select_base writes raster order.\n";
  }
};

}  // namespace

StagePtr disparity_reorder_stage() { return std::make_shared<DisparityReorderStage>(); }

}  // namespace fpstereo::rtl
