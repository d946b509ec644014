#include "stream_bench.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <type_traits>
#include <chrono>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <random>
#include <utility>

#include "Vdut.h"
#include "image_io.hpp"  // InputError
#include "verilated.h"

namespace fpstereo::tb {
namespace {

constexpr int kResetCycles = 16;
constexpr size_t kKeptProtocolErrors = 10;

// One input stream: a list of beats. Once it offers a beat it holds it until the design takes it
// (AXI4-Stream: no tvalid withdrawn, no data changed). While tvalid is low the data lines carry
// the inverse of the next pixel, so that a design sampling them without a handshake shows up as
// mismatches.
class AxisSource {
 public:
  explicit AxisSource(const std::vector<Beat>& beats) : beats_(beats) {}

  // tdata is CData, SData or IData: 1, 2 or 4 pixels.
  template <class Data>
  void drive(Data& tdata, CData& tvalid, CData& tuser, CData& tlast) const {
    tvalid = valid_;
    if (next_ >= beats_.size()) return;
    const Beat& b = beats_[next_];
    tdata = Data(valid_ ? b.data : ~b.data);
    tuser = b.user;
    tlast = b.last;
  }

  // After a rising edge: moves past a taken beat; a pending beat stays offered, otherwise the
  // next one is offered unless the source withholds it this cycle or it lies at or beyond
  // `hold_from`.
  void advance(bool taken, bool withhold, size_t hold_from) {
    if (taken) ++next_;
    if (valid_ && !taken) return;
    valid_ = next_ < beats_.size() && !withhold && next_ < hold_from;
  }

  bool valid() const { return valid_; }
  bool withholding() const { return !valid_ && next_ < beats_.size(); }
  size_t taken() const { return next_; }
  size_t total() const { return beats_.size(); }

 private:
  const std::vector<Beat>& beats_;
  size_t next_ = 0;
  bool valid_ = false;
};

// tdata in 32-bit words, the lowest first: up to 4 pixels of 24 bits.
struct OutputBeat {
  std::array<uint32_t, 4> data{};
  bool user, last;
  bool operator==(const OutputBeat& o) const { return data == o.data && user == o.user && last == o.last; }
  // bits lsb .. lsb + n - 1 of tdata (n <= 32)
  uint32_t bits(int lsb, int n) const {
    const uint64_t pair = data[size_t(lsb / 32)] | (lsb / 32 + 1 < 4 ? uint64_t(data[size_t(lsb / 32 + 1)]) << 32 : 0);
    return uint32_t((pair >> (lsb % 32)) & ((uint64_t(1) << n) - 1));
  }
  std::string hex() const {
    std::string s;
    for (size_t i = data.size(); i-- > 0;) s += fmt::format("{:08x}", data[i]);
    return "0x" + s;
  }
};

// tdata as Verilator holds it: CData, SData, IData, QData or VlWide.
template <class Data>
std::array<uint32_t, 4> tdata_words(const Data& tdata) {
  std::array<uint32_t, 4> words{};
  if constexpr (std::is_integral_v<Data>) {
    words[0] = uint32_t(uint64_t(tdata));
    words[1] = uint32_t(uint64_t(tdata) >> 32);
  } else {
    constexpr size_t held = sizeof(tdata) / sizeof(tdata[0]);
    for (size_t i = 0; i < words.size() && i < held; ++i) words[i] = tdata[i];
  }
  return words;
}

// An output port of the Verilated design: reads its beat, drives its tready.
struct OutputPort {
  std::function<bool()> valid;
  std::function<OutputBeat()> beat;
  std::function<void(bool)> set_ready;
};

template <class Data>
OutputPort port_of(Data& tdata, CData& tvalid, CData& tuser, CData& tlast, CData& tready) {
  return {[&] { return bool(tvalid); },
          [&] {
            return OutputBeat{tdata_words(tdata), bool(tuser), bool(tlast)};
          },
          [&](bool ready) { tready = ready; }};
}

// The design's output ports: output_ports.inc has a FPSTEREO_TB_PORT(<name>) line for each one the
// top declares (verilator_tb/CMakeLists.txt writes it).
OutputPort output_port(Vdut& dut, const std::string& port) {
#define FPSTEREO_TB_PORT(NAME)                                                              \
  if (port == #NAME)                                                                        \
    return port_of(dut.NAME##_tdata, dut.NAME##_tvalid, dut.NAME##_tuser, dut.NAME##_tlast, \
                   dut.NAME##_tready);
#include "output_ports.inc"
#undef FPSTEREO_TB_PORT
  throw InputError("the design has no output port " + port + ", which its output list names");
}

// Watches an output stream at every rising edge: cuts tdata into its pixels and each pixel into
// the stream's word nets, collects each net's plane into frames of the expected sizes and checks
// the stream rules (stable while stalled, tuser on the beat of each frame's first pixel, tlast on
// the beat of each row's last, the bits of tdata outside the words zero, nothing beyond the
// expected frames).
class OutputMonitor {
 public:
  OutputMonitor(const rtl::OutputStream& stream, const std::vector<std::pair<int, int>>& sizes,
                std::map<Plane, std::vector<DisparityImage>>& frames, std::vector<uint64_t>& start_cycle,
                std::vector<uint64_t>& end_cycle, ProtocolErrors& protocol)
      : stream_(stream),
        sizes_(sizes),
        frames_(frames),
        start_cycle_(start_cycle),
        end_cycle_(end_cycle),
        protocol_(protocol) {
    for (const auto& word : stream_.words) outside_words_ &= ~(mask(word.bits) << word.lsb);
    outside_words_ &= mask(stream_.pixel_bits);
    start_frame();
  }

  void observe(uint64_t cycle, bool valid, bool ready, const OutputBeat& beat) {
    check_stall(cycle, valid, beat);
    stalled_ = valid && !ready ? std::optional<OutputBeat>(beat) : std::nullopt;
    if (valid && ready) take(cycle, beat);
  }

  // The design was reset: a frame in progress will not be completed.
  void reset() {
    stalled_.reset();
    if (in_frame_ > 0) start_cycle_.pop_back();
    received_ -= in_frame_;
    in_frame_ = 0;
  }

  bool done() const { return frames_done_ >= sizes_.size(); }
  size_t received() const { return received_; }
  size_t expected() const {
    size_t total = 0;
    for (const auto& [w, h] : sizes_) total += size_t(w) * size_t(h);
    return total;
  }

 private:
  static uint64_t mask(int bits) { return (uint64_t(1) << bits) - 1; }

  void start_frame() {
    if (done()) return;
    for (const auto& word : stream_.words)
      frame_[word.plane] = DisparityImage(sizes_[frames_done_].first, sizes_[frames_done_].second);
  }

  void check_stall(uint64_t cycle, bool valid, const OutputBeat& beat) {
    if (!stalled_ || (valid && beat == *stalled_)) return;
    if (!valid) {
      protocol_.add(fmt::format("cycle {}: {}: tvalid dropped before a handshake", cycle, stream_.port));
      return;
    }
    protocol_.add(
        fmt::format("cycle {}: {}: changed while tvalid && !tready: tdata {} -> {}, tuser {} -> {}, "
                    "tlast {} -> {}",
                    cycle, stream_.port, stalled_->hex(), beat.hex(), int(stalled_->user), int(beat.user),
                    int(stalled_->last), int(beat.last)));
  }

  void take(uint64_t cycle, const OutputBeat& beat) {
    if (done()) {
      protocol_.add(fmt::format("cycle {}: {}: output beyond the expected {} frames (tdata {})", cycle,
                                stream_.port, sizes_.size(), beat.hex()));
      return;
    }
    const int width = sizes_[frames_done_].first;
    const int x = int(in_frame_ % size_t(width));
    const int y = int(in_frame_ / size_t(width));
    const bool first = x == 0 && y == 0;
    const bool row_end = x + stream_.pixels == width;
    if (beat.user != first)
      protocol_.add(fmt::format("cycle {}: {}: frame {} ({}, {}): tuser {}, expected {}", cycle, stream_.port,
                                frames_done_, x, y, int(beat.user), int(first)));
    if (beat.last != row_end)
      protocol_.add(fmt::format("cycle {}: {}: frame {} ({}, {}): tlast {}, expected {}", cycle, stream_.port,
                                frames_done_, x, y, int(beat.last), int(row_end)));
    for (int i = 0; i < stream_.pixels; ++i) {
      const uint32_t pixel = beat.bits(i * stream_.pixel_bits, stream_.pixel_bits);
      if ((pixel & outside_words_) != 0)
        protocol_.add(fmt::format("cycle {}: {}: frame {} ({}, {}): tdata {} has bits set outside its words", cycle,
                                  stream_.port, frames_done_, x + i, y, beat.hex()));
      for (const auto& word : stream_.words)
        frame_[word.plane].at(x + i, y) = uint16_t((pixel >> word.lsb) & mask(word.bits));
    }
    if (in_frame_ == 0) start_cycle_.push_back(cycle);
    received_ += size_t(stream_.pixels);
    in_frame_ += size_t(stream_.pixels);
    if (in_frame_ == size_t(width) * size_t(sizes_[frames_done_].second)) {
      for (const auto& word : stream_.words) frames_[word.plane].push_back(frame_[word.plane]);
      end_cycle_.push_back(cycle);
      ++frames_done_;
      in_frame_ = 0;
      start_frame();
    }
  }

  const rtl::OutputStream& stream_;
  const std::vector<std::pair<int, int>>& sizes_;
  std::map<Plane, std::vector<DisparityImage>>& frames_;
  std::vector<uint64_t>& start_cycle_;
  std::vector<uint64_t>& end_cycle_;
  ProtocolErrors& protocol_;
  uint64_t outside_words_ = ~uint64_t(0);
  std::map<Plane, DisparityImage> frame_;  // the frame being received, per word net's plane
  size_t frames_done_ = 0;
  size_t in_frame_ = 0;  // pixels of the current frame received
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

std::vector<rtl::OutputStream> output_streams(const StereoConfig& cfg) {
  return rtl::output_streams(rtl::plan_geometry(cfg));
}

int held_tdata_bits(const std::string& port) {
#define FPSTEREO_TB_PORT(NAME) \
  if (port == #NAME) return int(8 * sizeof(std::declval<Vdut&>().NAME##_tdata));
#include "output_ports.inc"
#undef FPSTEREO_TB_PORT
  throw InputError("the design has no output port " + port + ", which its output list names");
}

const DesignFiles& design_files() {
#ifdef FPSTEREO_TB_REGS_HEADER
  static const DesignFiles files{FPSTEREO_TB_CONFIG_FILE, FPSTEREO_TB_TOP_FILE, FPSTEREO_TB_REGS_HEADER};
#else  // a design without the AXI4-Lite control interface
  static const DesignFiles files{FPSTEREO_TB_CONFIG_FILE, FPSTEREO_TB_TOP_FILE, ""};
#endif
  return files;
}

bool has_control() { return !design_files().registers.empty(); }

namespace {

// On a terminal, the progress line is redrawn every this many simulated cycles (a fraction of a
// second at the simulator's few hundred thousand cycles per second).
constexpr uint64_t kProgressCycles = 1 << 16;

void show_progress(size_t frames_done, size_t frames, uint64_t cycle,
                   std::chrono::steady_clock::time_point start) {
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << fmt::format("\r\033[Kfpstereo-tb: {}/{} frames, {} cycles, {:.0f} kcycles/s", frames_done,
                           frames, cycle, seconds > 0 ? double(cycle) / seconds / 1e3 : 0.0)
            << std::flush;
}

// AXI4-Lite master: one access at a time, from a queue; address and data of a write are offered
// together, each held until its ready.
class LiteMaster {
 public:
  void queue(const RegisterAccess& access) { pending_.push_back(access); }
  bool idle() const { return pending_.empty() && !active_; }

  void drive(Vdut& dut) {
    if (!active_ && !pending_.empty()) {
      current_ = pending_.front();
      pending_.erase(pending_.begin());
      active_ = true;
      address_sent_ = data_sent_ = false;
    }
#ifdef FPSTEREO_TB_REGS_HEADER
    const bool write = active_ && current_.write, read = active_ && !current_.write;
    dut.s_axi_ctrl_awvalid = write && !address_sent_;
    dut.s_axi_ctrl_awaddr = current_.offset;
    dut.s_axi_ctrl_wvalid = write && !data_sent_;
    dut.s_axi_ctrl_wdata = current_.value;
    dut.s_axi_ctrl_wstrb = 0xF;
    dut.s_axi_ctrl_bready = 1;
    dut.s_axi_ctrl_arvalid = read && !address_sent_;
    dut.s_axi_ctrl_araddr = current_.offset;
    dut.s_axi_ctrl_rready = 1;
#else
    (void)dut;
#endif
  }

  // Before the rising edge: the handshakes that happen at it.
  void sample(const Vdut& dut, std::vector<RegisterAccess>& log) {
#ifdef FPSTEREO_TB_REGS_HEADER
    if (!active_) return;
    if (current_.write) {
      address_sent_ |= dut.s_axi_ctrl_awvalid && dut.s_axi_ctrl_awready;
      data_sent_ |= dut.s_axi_ctrl_wvalid && dut.s_axi_ctrl_wready;
      if (dut.s_axi_ctrl_bvalid) finish(dut.s_axi_ctrl_bresp, current_.value, log);
    } else {
      address_sent_ |= dut.s_axi_ctrl_arvalid && dut.s_axi_ctrl_arready;
      if (dut.s_axi_ctrl_rvalid) finish(dut.s_axi_ctrl_rresp, dut.s_axi_ctrl_rdata, log);
    }
#else
    (void)dut;
    (void)log;
#endif
  }

  void reset() {
    active_ = false;
    pending_.clear();
  }

 private:
  void finish(uint8_t response, uint32_t value, std::vector<RegisterAccess>& log) {
    current_.response = response;
    current_.value = value;
    log.push_back(current_);
    active_ = false;
  }

  std::vector<RegisterAccess> pending_;
  RegisterAccess current_;
  bool active_ = false, address_sent_ = false, data_sent_ = false;
};

}  // namespace

std::vector<Beat> frame_beats(const GrayImage& image, int ppc) {
  std::vector<Beat> beats;
  beats.reserve(image.pixels.size() / size_t(ppc));
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; x += ppc) {
      Beat beat{0, x == 0 && y == 0, x + ppc == image.width};
      for (int i = 0; i < ppc; ++i) beat.data |= uint32_t(image.at(x + i, y)) << (8 * i);
      beats.push_back(beat);
    }
  return beats;
}

StreamRun stream(const StereoConfig& cfg, const StreamPlan& plan, const StreamSettings& settings) {
  auto context = std::make_unique<VerilatedContext>();
  context->randReset(settings.random_init ? 2 : 0);
  context->randSeed(int(settings.seed));
  auto dut = std::make_unique<Vdut>(context.get(), "dut");

  AxisSource left(plan.left), right(plan.right);
  StreamRun run;
  // A monitor and a sink per output stream; the cycles of the streams after the first are not
  // reported.
  const std::vector<rtl::OutputStream> streams = output_streams(cfg);
  std::vector<OutputPort> ports;
  std::vector<OutputMonitor> monitors;
  std::vector<std::vector<uint64_t>> other_cycles(2 * streams.size());
  monitors.reserve(streams.size());
  for (size_t i = 0; i < streams.size(); ++i) {
    ports.push_back(output_port(*dut, streams[i].port));
    monitors.emplace_back(streams[i], plan.output_sizes, run.frames,
                          i == 0 ? run.frame_start_cycle : other_cycles[2 * i],
                          i == 0 ? run.frame_end_cycle : other_cycles[2 * i + 1], run.protocol);
  }
  OutputMonitor& words = monitors.front();
  const auto all_done = [&] {
    return std::all_of(monitors.begin(), monitors.end(), [](const OutputMonitor& m) { return m.done(); });
  };
  LiteMaster lite;

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
  auto reset = [&] {
    dut->aresetn = 0;
    lite.reset();
    lite.drive(*dut);
    for (int i = 0; i < kResetCycles; ++i) {
      half_cycle(false);
      half_cycle(true);
    }
    dut->aresetn = 1;
  };

  dut->s_axis_left_tvalid = dut->s_axis_right_tvalid = 0;
  for (const auto& port : ports) port.set_ready(false);
  reset();
  constexpr size_t kNoHold = std::numeric_limits<size_t>::max();
  size_t hold_from = kNoHold;
  bool releasing = false;
  left.advance(false, withhold(), hold_from);
  right.advance(false, withhold(), hold_from);
  // Each sink has backpressure of its own, drawn in the list's order.
  std::vector<bool> ready(ports.size());
  const auto draw_ready = [&] {
    for (size_t i = 0; i < ready.size(); ++i) ready[i] = sink_ready();
  };
  draw_ready();

  // Once every pixel is out, keep watching long enough for a spurious extra row to show.
  const uint64_t drain_cycles = 2 * uint64_t(cfg.width) * uint64_t(cfg.dmax / cfg.uf) + 100;
  size_t next_action = 0;
  bool reads_queued = false;
  bool seen_input = false;
  uint64_t last_progress = 0;  // cycle of the last output handshake (or reset)
  uint64_t cycle = 0;
  const auto start = std::chrono::steady_clock::now();
  for (;; ++cycle) {
    if (settings.progress && cycle % kProgressCycles == 0 && cycle > 0)
      show_progress(run.frame_end_cycle.size(), plan.output_sizes.size(), cycle, start);
    // Actions due: the left stream has had enough beats taken.
    while (next_action < plan.actions.size() && left.taken() >= plan.actions[next_action].after_taken) {
      const Action& action = plan.actions[next_action++];
      if (action.reset) {
        reset();
        for (auto& monitor : monitors) monitor.reset();
        last_progress = cycle;
      }
      for (const auto& access : action.writes) lite.queue(access);
      if (action.hold_from != kNoHold) hold_from = action.hold_from;
      releasing |= action.release;
    }
    if (releasing && lite.idle()) {
      hold_from = kNoHold;
      releasing = false;
    }
    if (words.done() && !reads_queued) {
      for (uint32_t offset : plan.reads_at_end) lite.queue({offset, 0, false});
      reads_queued = true;
    }

    left.drive(dut->s_axis_left_tdata, dut->s_axis_left_tvalid, dut->s_axis_left_tuser,
               dut->s_axis_left_tlast);
    right.drive(dut->s_axis_right_tdata, dut->s_axis_right_tvalid, dut->s_axis_right_tuser,
                dut->s_axis_right_tlast);
    for (size_t i = 0; i < ports.size(); ++i) ports[i].set_ready(ready[i]);
    lite.drive(*dut);
    half_cycle(false);

    const bool left_taken = left.valid() && dut->s_axis_left_tready;
    const bool right_taken = right.valid() && dut->s_axis_right_tready;
    const bool output_valid = ports.front().valid();
    run.left_idle_while_ready += left.withholding() && dut->s_axis_left_tready;
    run.right_idle_while_ready += right.withholding() && dut->s_axis_right_tready;
    run.output_held += output_valid && !ready.front();
    if ((left_taken || right_taken) && !seen_input) {
      seen_input = true;
      run.first_input_cycle = cycle;
    }
    for (size_t i = 0; i < ports.size(); ++i)
      monitors[i].observe(cycle, ports[i].valid(), ready[i], ports[i].beat());
    lite.sample(*dut, run.accesses);
    half_cycle(true);

    if (output_valid && ready.front()) last_progress = cycle;
    const bool finished = all_done() && lite.idle() && next_action == plan.actions.size();
    if (finished && cycle >= (run.frame_end_cycle.empty() ? 0 : run.frame_end_cycle.back()) + drain_cycles)
      break;
    if (!finished && cycle - last_progress >= settings.timeout) {
      run.timeout = timeout_message(cycle - last_progress, words, words.expected(), left, right);
      break;
    }
    left.advance(left_taken, withhold(), hold_from);
    right.advance(right_taken, withhold(), hold_from);
    draw_ready();
  }
  run.cycles = cycle + 1;
  if (settings.progress) std::cerr << "\r\033[K" << std::flush;  // the results take the line
  dut->final();
  return run;
}

}  // namespace fpstereo::tb
