// Streams stereo frames through the Verilated design over its AXI4-Stream ports, with random
// idle cycles on the sources and backpressure on the sink, and records what comes out and every
// violation of the output protocol.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "config.hpp"
#include "image.hpp"
#include "stimulus.hpp"

namespace fpstereo::tb {

struct StreamSettings {
  double idle = 0;          // probability that a source withholds tvalid on a cycle
  double backpressure = 0;  // probability that the sink deasserts tready on a cycle
  uint64_t timeout = 0;     // cycles without an output handshake before giving up
  uint32_t seed = 1;        // idle and backpressure patterns, the design's initial state
  bool random_init = true;  // registers and memories start random rather than 0
};

struct ProtocolErrors {
  size_t count = 0;
  std::vector<std::string> first;  // the first few, each "cycle C: what happened"
  void add(const std::string& message);
};

struct StreamRun {
  std::vector<DisparityImage> outputs;    // the complete output frames, in order
  std::vector<uint64_t> frame_end_cycle;  // cycle of each frame's last output handshake
  uint64_t first_input_cycle = 0;         // cycle of the first input handshake on either stream
  uint64_t cycles = 0;                    // cycles simulated after reset
  // How much the idle cycles and backpressure bit: cycles in which a source withheld a pixel
  // while the design was ready for it, and cycles in which an output waited for tready.
  uint64_t left_idle_while_ready = 0;
  uint64_t right_idle_while_ready = 0;
  uint64_t output_held = 0;
  ProtocolErrors protocol;
  std::string timeout;  // empty unless the design stopped producing output
};

// Width of the design's m_axis_disp_tdata as Verilator stores it: 8 or 16 (or more) bits.
int output_port_bits();

// Resets the design, then streams `frames` back to back on both inputs (cfg.width x
// cfg.height each, tuser on a frame's first pixel, tlast at each row end) until every output
// pixel has arrived and a drain period has shown no extra output, or until the timeout.
StreamRun stream_frames(const StereoConfig& cfg, const std::vector<const StereoPair*>& frames,
                        const StreamSettings& settings);

}  // namespace fpstereo::tb
