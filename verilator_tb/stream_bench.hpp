// Streams stereo frames through the Verilated design over its AXI4-Stream ports, with random
// idle cycles on the sources and backpressure on the sink, drives its AXI4-Lite registers, and
// records what comes out and every violation of the output protocol.
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "config.hpp"
#include "image.hpp"
#include "outputs.hpp"
#include "plan.hpp"
#include "stimulus.hpp"
#include "widths.hpp"

namespace fpstereo::tb {

struct StreamSettings {
  double idle = 0;          // probability that a source withholds tvalid on a cycle
  double backpressure = 0;  // probability that the sink deasserts tready on a cycle
  uint64_t timeout = 0;     // cycles without an output handshake before giving up
  uint32_t seed = 1;        // idle and backpressure patterns, the design's initial state
  bool random_init = true;  // registers and memories start random rather than 0
  bool progress = false;    // frames done and simulated cycles per second on stderr, one updated line
};

// One input beat: tdata (ppc pixels, pixel 0 in the low byte), tuser (start of frame), tlast
// (end of row).
struct Beat {
  uint32_t data = 0;
  bool user = false, last = false;
};

// The beats of a frame in the Xilinx video convention (UG934), ppc pixels each, one stream of a
// pair.
std::vector<Beat> frame_beats(const GrayImage& image, int ppc);

struct RegisterAccess {
  uint32_t offset = 0;
  uint32_t value = 0;  // written, or read
  bool write = true;
  uint8_t response = 0;  // BRESP / RRESP
};

// What happens once the left stream has had `after_taken` beats taken: a reset (aresetn low for
// a few cycles) and register writes. An action can make the sources hold back every beat from
// index `hold_from` on, until an action with `release` has completed its writes.
struct Action {
  size_t after_taken = 0;
  std::vector<RegisterAccess> writes;
  bool reset = false;
  size_t hold_from = std::numeric_limits<size_t>::max();
  bool release = false;
};

struct StreamPlan {
  std::vector<Beat> left, right;
  // The output frames expected, in order: their sizes. An output frame cut short by a reset
  // is dropped and not counted.
  std::vector<std::pair<int, int>> output_sizes;
  std::vector<Action> actions;
  // Registers read once every output has arrived (needs the AXI4-Lite interface).
  std::vector<uint32_t> reads_at_end;
};

struct ProtocolErrors {
  size_t count = 0;
  std::vector<std::string> first;  // the first few, each "cycle C: what happened"
  void add(const std::string& message);
};

struct StreamRun {
  // Each plane's complete frames, in order, as the output streams carry them (tdata cut into the
  // streams' word nets, rtl::output_streams).
  std::map<Plane, std::vector<DisparityImage>> frames;
  // Cycles of each frame's first and last handshake on the first output stream (the words').
  std::vector<uint64_t> frame_start_cycle;
  std::vector<uint64_t> frame_end_cycle;
  uint64_t first_input_cycle = 0;  // cycle of the first input handshake on either stream
  uint64_t cycles = 0;             // cycles simulated after reset
  // How much the idle cycles and backpressure bit: cycles in which a source withheld a pixel
  // while the design was ready for it, and cycles in which an output waited for tready.
  uint64_t left_idle_while_ready = 0;
  uint64_t right_idle_while_ready = 0;
  uint64_t output_held = 0;
  std::vector<RegisterAccess> accesses;  // every register access, in order, with its result
  ProtocolErrors protocol;
  std::string timeout;  // empty unless the design stopped producing output
};

// The output streams of the design generated from cfg, as the bench watches them.
std::vector<rtl::OutputStream> output_streams(const StereoConfig& cfg);
// Width of an output stream's tdata as Verilator stores it (8, 16 or 32 bits); throws
// InputError for a port the Verilated design does not have.
int held_tdata_bits(const std::string& port);
// The design's files the bench was built with (CMake passes their paths), read when it runs: the
// configuration it was generated with, its top file (whose banner states its timing) and, with
// the AXI4-Lite control interface, its register header (else empty).
struct DesignFiles {
  std::string config, top, registers;
};
const DesignFiles& design_files();
// Whether the design has the AXI4-Lite control interface.
bool has_control();

// Resets the design, then runs the plan until every expected output pixel has arrived, the
// reads at the end are done and a drain period has shown no extra output, or until the timeout.
StreamRun stream(const StereoConfig& cfg, const StreamPlan& plan, const StreamSettings& settings);

}  // namespace fpstereo::tb
