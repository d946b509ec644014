#include "stream_bench.hpp"

#include <fmt/core.h>

#include <memory>
#include <optional>
#include <random>
#include <utility>

#include "Vdut.h"
#include "verilated.h"

namespace fpstereo::tb {
namespace {

constexpr int kResetCycles = 16;
constexpr size_t kKeptProtocolErrors = 10;

// One input stream: the frames' pixels back to back in raster order. Once it offers a pixel it
// holds it until the design takes it (AXI4-Stream: no tvalid withdrawn, no data changed).
// While tvalid is low the data lines carry the inverse of the next pixel, so that a design
// sampling them without a handshake shows up as mismatches.
class AxisSource {
 public:
  AxisSource(std::vector<const GrayImage*> frames, int width, int height)
      : frames_(std::move(frames)), width_(width), frame_pixels_(size_t(width) * size_t(height)) {}

  void drive(CData& tdata, CData& tvalid, CData& tuser, CData& tlast) const {
    tvalid = valid_;
    if (next_ >= total()) return;
    const size_t p = next_ % frame_pixels_;
    const uint8_t pixel = frames_[next_ / frame_pixels_]->pixels[p];
    tdata = valid_ ? pixel : uint8_t(~pixel);
    tuser = p == 0;
    tlast = p % size_t(width_) == size_t(width_ - 1);
  }

  // After a rising edge: moves past a taken pixel; a pending pixel stays offered, otherwise the
  // next one is offered unless the source withholds it this cycle.
  void advance(bool taken, bool withhold) {
    if (taken) ++next_;
    if (valid_ && !taken) return;
    valid_ = next_ < total() && !withhold;
  }

  bool valid() const { return valid_; }
  bool withholding() const { return !valid_ && next_ < total(); }
  size_t taken() const { return next_; }
  size_t total() const { return frames_.size() * frame_pixels_; }

 private:
  std::vector<const GrayImage*> frames_;
  int width_;
  size_t frame_pixels_;
  size_t next_ = 0;
  bool valid_ = false;
};

struct OutputBeat {
  uint16_t data;
  bool user, last;
  bool operator==(const OutputBeat& o) const { return data == o.data && user == o.user && last == o.last; }
};

// Watches m_axis_disp at every rising edge: collects the pixels into frames and checks the
// stream rules (stable while stalled, tuser on each frame's first pixel, tlast at each row end,
// nothing beyond the expected pixel count).
class OutputMonitor {
 public:
  OutputMonitor(int width, int height, size_t frames, StreamRun& run)
      : width_(width),
        height_(height),
        total_(frames * size_t(width) * size_t(height)),
        run_(run),
        frame_(width, height) {}

  void observe(uint64_t cycle, bool valid, bool ready, const OutputBeat& beat) {
    check_stall(cycle, valid, beat);
    stalled_ = valid && !ready ? std::optional<OutputBeat>(beat) : std::nullopt;
    if (valid && ready) take(cycle, beat);
  }

  bool done() const { return received_ >= total_; }
  size_t received() const { return received_; }

 private:
  void check_stall(uint64_t cycle, bool valid, const OutputBeat& beat) {
    if (!stalled_ || (valid && beat == *stalled_)) return;
    if (!valid) {
      run_.protocol.add(fmt::format("cycle {}: tvalid dropped before a handshake", cycle));
      return;
    }
    run_.protocol.add(
        fmt::format("cycle {}: changed while tvalid && !tready: tdata {} -> {}, tuser {} -> {}, "
                    "tlast {} -> {}",
                    cycle, stalled_->data, beat.data, int(stalled_->user), int(beat.user),
                    int(stalled_->last), int(beat.last)));
  }

  void take(uint64_t cycle, const OutputBeat& beat) {
    if (done()) {
      run_.protocol.add(
          fmt::format("cycle {}: output beyond the expected {} pixels (tdata {})", cycle, total_, beat.data));
      return;
    }
    const size_t frame_pixels = size_t(width_) * size_t(height_);
    const size_t frame = received_ / frame_pixels;
    const int x = int(received_ % frame_pixels % size_t(width_));
    const int y = int(received_ % frame_pixels / size_t(width_));
    const bool first = x == 0 && y == 0;
    const bool row_end = x == width_ - 1;
    if (beat.user != first)
      run_.protocol.add(fmt::format("cycle {}: frame {} ({}, {}): tuser {}, expected {}", cycle, frame, x, y,
                                    int(beat.user), int(first)));
    if (beat.last != row_end)
      run_.protocol.add(fmt::format("cycle {}: frame {} ({}, {}): tlast {}, expected {}", cycle, frame, x, y,
                                    int(beat.last), int(row_end)));
    frame_.at(x, y) = beat.data;
    if (++received_ % frame_pixels == 0) {
      run_.outputs.push_back(frame_);
      run_.frame_end_cycle.push_back(cycle);
    }
  }

  int width_, height_;
  size_t total_;
  StreamRun& run_;
  DisparityImage frame_;
  size_t received_ = 0;
  std::optional<OutputBeat> stalled_;  // the beat offered without tready at the previous edge
};

std::string timeout_message(uint64_t cycles, const OutputMonitor& out, size_t expected,
                            const AxisSource& left, const AxisSource& right) {
  return fmt::format(
      "timeout: no output handshake for {} cycles; {} of {} output pixels received, inputs taken: "
      "left {} of {}, right {} of {}",
      cycles, out.received(), expected, left.taken(), left.total(), right.taken(), right.total());
}

}  // namespace

void ProtocolErrors::add(const std::string& message) {
  if (first.size() < kKeptProtocolErrors) first.push_back(message);
  ++count;
}

int output_port_bits() { return int(8 * sizeof(std::declval<Vdut&>().m_axis_disp_tdata)); }

StreamRun stream_frames(const StereoConfig& cfg, const std::vector<const StereoPair*>& frames,
                        const StreamSettings& settings) {
  auto context = std::make_unique<VerilatedContext>();
  context->randReset(settings.random_init ? 2 : 0);
  context->randSeed(int(settings.seed));
  auto dut = std::make_unique<Vdut>(context.get(), "dut");

  std::vector<const GrayImage*> lefts, rights;
  for (const StereoPair* pair : frames) {
    lefts.push_back(&pair->left);
    rights.push_back(&pair->right);
  }
  AxisSource left(lefts, cfg.width, cfg.height);
  AxisSource right(rights, cfg.width, cfg.height);
  StreamRun run;
  OutputMonitor monitor(cfg.width, cfg.height, frames.size(), run);
  const size_t expected_pixels = left.total();

  std::mt19937 rng(settings.seed);
  std::uniform_real_distribution<double> chance(0.0, 1.0);
  auto withhold = [&] { return settings.idle > 0 && chance(rng) < settings.idle; };
  auto sink_ready = [&] { return !(settings.backpressure > 0 && chance(rng) < settings.backpressure); };

  // Inputs change at the falling edge, half a cycle away from the rising edge that samples them.
  auto half_cycle = [&](bool clock) {
    dut->aclk = clock;
    dut->eval();
    context->timeInc(1);
  };

  dut->aresetn = 0;
  dut->s_axis_left_tvalid = dut->s_axis_right_tvalid = 0;
  dut->m_axis_disp_tready = 0;
  for (int i = 0; i < kResetCycles; ++i) {
    half_cycle(false);
    half_cycle(true);
  }
  dut->aresetn = 1;
  left.advance(false, withhold());
  right.advance(false, withhold());
  bool ready = sink_ready();

  // Once every pixel is out, keep watching long enough for a spurious extra row to show.
  const uint64_t drain_cycles = 2 * uint64_t(cfg.width) * uint64_t(cfg.dmax / cfg.uf) + 100;
  bool seen_input = false;
  uint64_t last_progress = 0;  // cycle of the last output handshake (or reset)
  uint64_t cycle = 0;
  for (;; ++cycle) {
    left.drive(dut->s_axis_left_tdata, dut->s_axis_left_tvalid, dut->s_axis_left_tuser,
               dut->s_axis_left_tlast);
    right.drive(dut->s_axis_right_tdata, dut->s_axis_right_tvalid, dut->s_axis_right_tuser,
                dut->s_axis_right_tlast);
    dut->m_axis_disp_tready = ready;
    half_cycle(false);

    const bool left_taken = left.valid() && dut->s_axis_left_tready;
    const bool right_taken = right.valid() && dut->s_axis_right_tready;
    const bool output_valid = dut->m_axis_disp_tvalid;
    run.left_idle_while_ready += left.withholding() && dut->s_axis_left_tready;
    run.right_idle_while_ready += right.withholding() && dut->s_axis_right_tready;
    run.output_held += output_valid && !ready;
    if ((left_taken || right_taken) && !seen_input) {
      seen_input = true;
      run.first_input_cycle = cycle;
    }
    monitor.observe(
        cycle, output_valid, ready,
        {uint16_t(dut->m_axis_disp_tdata), bool(dut->m_axis_disp_tuser), bool(dut->m_axis_disp_tlast)});
    half_cycle(true);

    if (output_valid && ready) last_progress = cycle;
    if (monitor.done() && cycle >= run.frame_end_cycle.back() + drain_cycles) break;
    if (!monitor.done() && cycle - last_progress >= settings.timeout) {
      run.timeout = timeout_message(cycle - last_progress, monitor, expected_pixels, left, right);
      break;
    }
    left.advance(left_taken, withhold());
    right.advance(right_taken, withhold());
    ready = sink_ready();
  }
  run.cycles = cycle + 1;
  dut->final();
  return run;
}

}  // namespace fpstereo::tb
