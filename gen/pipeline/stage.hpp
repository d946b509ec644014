// A stage of the pipeline (docs/architecture.md, "Stages"; docs/contributing.md, "Adding a
// stage"): it knows its latency in the core's time base and the memories it instantiates, both from
// the plan's geometry, adds its nets, logic and instances to the core (core_builder.hpp) and its
// kernel calls to the HLS pipeline. plan() chains the stages; the banner, the INFO registers, the
// resource model and the DSE read the one plan they make. One file a stage, in stages/.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "config.hpp"

namespace fpstereo::rtl {

class CoreBuilder;
struct Geometry;
struct RtlDesign;

// A time in the core's time base: row-times of R slots, slots of G steps, and steps.
struct Latency {
  int64_t rows = 0, slots = 0, steps = 0;
  Latency operator+(const Latency& o) const { return {rows + o.rows, slots + o.slots, steps + o.steps}; }
  int64_t in_steps(int64_t row_slots, int64_t groups) const { return (rows * row_slots + slots) * groups + steps; }
};

// Cycles from the step that pushes a frame's last pixel to the next frame's step 0 when the next
// frame is waiting: the push itself, the cycle in which the idle core is started and the one in
// which the sequencer starts (fpstereo_sequencer). The output stage's latency ends with them.
constexpr int64_t kStepsAfterPush = 3;

// When G = 1 the window stage decides whether the next frame follows on in the row-time's last
// slot, and a frame that follows on reaches the core this many cycles too late for that: the
// framing stage rests a cycle after the frame before's last pixel, starts the frame, and the
// sequencer offers it (next_frame) a cycle later. The row-time's spare slots (R - W) cover part
// of it and the window stage holds the pipeline (adv low) for the rest, once per frame
// (Geometry::follow_wait; the test bench's timing check finds a cycle less too few). With G >= 2
// the decision comes G - 1 steps after the last pixel's, which covers it.
constexpr int kFollowCycles = 2;
// With several pixels per beat the beat's register (fpstereo_beat_split) delays a frame that runs
// alone by a cycle.
constexpr int kBeatSplitCycles = 1;

// A RAM a stage instantiates: its name as Yosys gives it after flattening the top
// ("core.cost_reorder.cost_ram.mem"), its shape and whether its read is registered (block RAM)
// or asynchronous (distributed RAM).
struct StageMemory {
  std::string name;
  int64_t words = 0;
  int64_t bits = 0;
  bool sync_read = true;
};

// The streams between the core's stages, by the names of their nets. Up to the disparity reorder
// RAM, the words in chain order: nets <words>_active, _x, _slot, _group, _word (and _whole when
// the geometry carries_whole), one a pixel in its last group's step. After it, the pixel stream
// in raster order: done in the step after each slot's word (empty once the stream has left the slot
// schedule), event for the frame's pixels, their position and word. Each stage reads the streams
// it is handed and names the ones it drives after itself.
struct PixelStream {
  std::string done, event, x, y, word;
};
struct CoreStreams {
  std::string words;
  PixelStream pixels;
};

// The HLS side (gen/hls): the names of the hls::streams between the kernel calls of the generated
// pipeline, the base side's and, beside it, the match side's (the right image's pixels and
// windows, the costs LR2's match side regroups, the match-side disparities). Each stage reads
// them and names the streams its calls write; the pipeline's function provides left_in,
// right_in, out (the video streams), W, H (the clamped frame), p1, p2, uniqueness and
// lr_threshold, and works in namespace fpstereo_hls with the configuration struct as C.
struct HlsStreams {
  std::string base, match;
};

// A loop of a stage's HLS kernels with its iterations per frame at the configured size.
struct HlsLoop {
  std::string what, formula;  // "aggregation (two interleaved chains)", "(H+1)*2*ceil(W/2)*dmax/uf"
  int64_t iterations = 0;
};

class Stage {
 public:
  virtual ~Stage() = default;
  // What the stage is, for the banner and the docs ("cost reorder").
  virtual std::string title() const = 0;
  // The configuration parameters (param_specs names) that shape the stage.
  virtual std::vector<std::string> knobs() const = 0;
  // Steps from the first word of the stage's input stream to the first of its output stream.
  virtual Latency latency(const Geometry& g) const = 0;
  // Stages with a schedule of their own start it start_offset after their input starts; the
  // core compares the step counter with that sum, the localparam named start_parameter().
  virtual std::string start_parameter() const { return ""; }
  virtual Latency start_offset(const Geometry&) const { return {}; }
  virtual std::vector<StageMemory> memories(const Geometry&) const { return {}; }
  // Its part of the core: the nets it drives, its logic and its instances; it reads the streams
  // and replaces those it drives.
  virtual void core_verilog(const RtlDesign& d, CoreBuilder& core, CoreStreams& streams) const = 0;

  // The HLS side. Its part of the pipeline's body: declarations of the streams it writes (with
  // their STREAM pragmas) and its kernel calls, or a comment naming the kernel that does its work.
  virtual std::string hls_calls(const RtlDesign& d, HlsStreams& streams) const = 0;
  // Its kernels' longest loop, at II = 1, if it may bound the frame time: empty for stages without
  // kernels of their own and for those whose loops (W*H, W*H*dmax/uf, (H+1)*W) never exceed the
  // aggregation's. And the rows by which its kernels delay the stream (the fill latency).
  virtual HlsLoop hls_loop(const Geometry&) const { return {}; }
  virtual int hls_fill_rows(const Geometry&) const { return 0; }
};

using StagePtr = std::shared_ptr<const Stage>;

// The stages of a configuration in the order data flows through them; stages that run beside
// the main stream (the match side of the left-right check) follow the stage they read from and
// add no latency to the stream.
std::vector<StagePtr> pipeline_stages(const StereoConfig& cfg);

}  // namespace fpstereo::rtl
