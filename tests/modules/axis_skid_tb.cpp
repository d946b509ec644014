// fpstereo_axis_skid: two-entry AXI4-Stream register slice. The bench is a well-behaved source
// (holds data while valid && !ready; random idle) and a sink with random backpressure. Checked:
//   - every accepted beat comes out exactly once, in order (scoreboard);
//   - while m_valid && !m_ready, m_valid stays high and m_data stable at the next cycle;
//   - s_ready does not depend combinationally on m_ready (registered outputs);
//   - with the sink always ready and the source always valid, one beat per cycle in and out;
//   - at the end, with the sink ready, everything accepted drains; after reset m_valid is low.
#include <deque>
#include <string>

#include "axis_skid_sets.hpp"
#include "tb_common.hpp"

namespace {

struct SkidParams {
  int DATA_W = 8;
};

template <typename M>
int run_axis_skid(const char* name, const SkidParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  std::deque<uint64_t> in_flight;
  bool src_valid = false;
  uint64_t src_data = 0;
  long accepted = 0, delivered = 0, full_rate_cycles = 0;
  bool prev_stalled = false;  // m_valid && !m_ready at the last edge
  uint64_t prev_data = 0;
  int full_rate_run = 0;      // consecutive cycles with s_valid and m_ready both forced high

  m.clk = 0;
  m.rst = 1;
  m.s_valid = 0;
  m.m_ready = 0;
  m.eval();
  modtb::tick(m);
  modtb::tick(m);
  m.rst = 0;
  m.eval();
  check.require(0, "m_valid low after reset", !m.m_valid);

  const long drain_from = o.cycles - 50;
  for (long cycle = 0; cycle < o.cycles; ++cycle) {
    // phases: random, sink always ready + source always valid (full rate), heavy backpressure
    const long phase = (cycle / 400) % 4;
    const bool full_rate = phase == 1 && cycle < drain_from;
    const bool drain = cycle >= drain_from;
    // source: a new beat only when the last one was taken (AXI: no withdrawing a valid)
    if (!src_valid) {
      if (drain ? false : full_rate || rng.chance(phase == 3 ? 80 : 60)) {
        src_valid = true;
        src_data = rng.bits(p.DATA_W);
      } else {
        src_data = rng.bits(p.DATA_W);  // garbage while invalid
      }
    }
    const bool sink_ready = drain || full_rate || rng.chance(phase == 3 ? 25 : 60);
    m.s_valid = src_valid;
    modtb::set_bits(m.s_data, 0, p.DATA_W, src_data);
    // s_ready must not follow m_ready within the cycle
    m.m_ready = !sink_ready;
    m.eval();
    const bool s_ready_other = m.s_ready;
    m.m_ready = sink_ready;
    m.eval();
    check.require(cycle, "s_ready changed with m_ready in the same cycle", s_ready_other == m.s_ready);

    const bool m_valid = m.m_valid;
    const uint64_t m_data = modtb::get_bits(m.m_data, 0, p.DATA_W);
    if (prev_stalled) {
      check.require(cycle, "m_valid dropped without m_ready", m_valid);
      check.expect(cycle, "m_data held while stalled", prev_data, m_data);
    }
    if (full_rate) {
      if (++full_rate_run > 3) {
        ++full_rate_cycles;
        check.require(cycle, "s_ready high at full rate (sink always ready)", m.s_ready);
        check.require(cycle, "m_valid high at full rate (source always valid)", m_valid);
      }
    } else {
      full_rate_run = 0;
    }
    if (m_valid && sink_ready) {
      if (in_flight.empty()) {
        check.require(cycle, "beat delivered that was never accepted", false);
      } else {
        check.expect(cycle, "m_data (beat " + std::to_string(delivered) + ")", in_flight.front(), m_data);
        in_flight.pop_front();
      }
      ++delivered;
    }
    if (src_valid && m.s_ready) {
      in_flight.push_back(src_data);
      ++accepted;
      src_valid = false;
    }
    prev_stalled = m_valid && !sink_ready;
    prev_data = m_data;
    modtb::tick(m);
  }
  check.expect(o.cycles, "beats left undelivered after draining", 0, in_flight.size());
  m.rst = 1;
  m.eval();
  modtb::tick(m);
  check.require(o.cycles, "m_valid low after a reset", !m.m_valid);
  return check.finish("DATA_W=" + std::to_string(p.DATA_W) + ": " + std::to_string(accepted) + " beats accepted, " +
                      std::to_string(delivered) +
                      " delivered in order once each; stall holds m_valid/m_data; s_ready independent of m_ready; " +
                      std::to_string(full_rate_cycles) + " cycles checked at full rate; " + std::to_string(o.cycles) +
                      " cycles");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_axis_skid, SkidParams)
MODTB_SETS(X)
#undef X

}  // namespace
