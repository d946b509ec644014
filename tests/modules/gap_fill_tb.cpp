// fpstereo_gap_fill: gap interpolation (docs/semantics.md section 7) at P words a slot, against
// fill_row_gaps (the golden model's row pass). Groups of frames of one run-time width (whole slots)
// and height stream as slot events, with idle steps (adv low) and steps without an event: the
// group's later frames follow back to back (wrapped: their row 0 brings the result of the frame
// before), and a dummy row after the group's last frame brings out its last row. Rows mix runs
// inside a slot, across slots, at the row ends and whole invalid rows. Every word of every row
// must leave, in raster order, equal to the model's. LINEAR: the linear fill of runs between close
// ends (fill_row_gaps with words 2^UNIT_LOG a pixel), on rows that also change slowly.
#include <string>
#include <vector>

#include "gap_fill.hpp"
#include "gap_fill_sets.hpp"
#include "pipe_model.hpp"
#include "tb_common.hpp"

namespace {

struct GapParams {
  int W = 16, WORD_W = 8, X_W = 5, Y_W = 6, P = 1, LINEAR = 0, UNIT_LOG = 0;
};

// A row of `width` words of WORD_W bits (the top bit: invalid), in one of a few shapes.
std::vector<uint64_t> random_row(int width, int word_w, int p, modtb::Rng& rng) {
  const uint64_t invalid = uint64_t{1} << (word_w - 1);
  const bool narrow = rng.chance(40);  // few values: ties between the neighbours
  auto value = [&] { return narrow ? rng.below(3) : rng.bits(word_w - 1); };
  std::vector<uint64_t> row(size_t(width), invalid);
  switch (rng.below(7)) {
    case 0: {  // each word invalid with one share
      const unsigned share = unsigned(rng.below(5)) * 25;
      for (auto& w : row) w = rng.chance(share) ? invalid : value();
      break;
    }
    case 1: break;  // a whole invalid row
    case 2: {       // long runs of either
      bool valid = rng.chance(50);
      for (auto& w : row) {
        if (rng.chance(15)) valid = !valid;
        w = valid ? value() : invalid;
      }
      break;
    }
    case 3:  // one valid word
      row[size_t(rng.below(uint64_t(width)))] = value();
      break;
    case 4:  // runs that start or end at slot edges
      for (int x = 0; x < width; x += p) {
        const bool valid = rng.chance(50);
        for (int q = 0; q < p; ++q) row[size_t(x + q)] = valid || rng.chance(20) ? value() : invalid;
      }
      break;
    case 6: {  // a slow walk with invalid runs: ends close enough for the linear fill, and some not
      int64_t v = int64_t(rng.bits(word_w - 1));
      const int64_t top = int64_t(invalid) - 1;
      for (auto& w : row) {
        v += int64_t(rng.below(9)) - 4;
        v = v < 0 ? 0 : v > top ? top : v;
        w = rng.chance(45) ? invalid : uint64_t(v);
      }
      break;
    }
    default:  // valid but for runs at the row's ends
      for (auto& w : row) w = value();
      for (int x = 0, n = int(rng.below(uint64_t(width))); x < n; ++x) row[size_t(x)] = invalid;
      for (int x = width - 1, n = int(rng.below(uint64_t(width))); n > 0; --x, --n) row[size_t(x)] = invalid;
      break;
  }
  return row;
}

template <typename M>
int run_gap_fill(const char* name, const GapParams& p, const modtb::Options& o) {
  VerilatedContext ctx;
  modtb::seed_context(ctx, o.seed);
  M m{&ctx};
  modtb::Rng rng(o.seed);
  modtb::Checker check(name);
  const uint64_t invalid = uint64_t{1} << (p.WORD_W - 1);
  const int max_slots = p.W / p.P;

  // The events: {slot, row, words}, each group's frames and its dummy row; and what must leave.
  struct Event {
    int x, y;
    std::vector<uint64_t> words;
    bool wrapped;
    int height, slots;
  };
  struct Out {
    int x, y;
    std::vector<uint64_t> words;
  };
  std::vector<Event> events;
  std::vector<Out> expected;
  long filled = 0, linear = 0;  // linear: words whose linear fill differs from the smaller end's
  while (long(events.size()) < o.cycles / 2) {
    const int slots = int(rng.range(1, uint64_t(max_slots))), width = slots * p.P;
    const int height = int(rng.range(2, 6)), frames = int(rng.range(1, 3));
    for (int f = 0; f < frames; ++f)
      for (int y = 0; y < height; ++y) {
        std::vector<uint64_t> row = random_row(width, p.WORD_W, p.P, rng), want = row;
        fpstereo::fill_row_gaps(want.data(), width, [&](uint64_t w) { return w < invalid; },
                                p.LINEAR ? int64_t{1} << p.UNIT_LOG : 0);
        std::vector<uint64_t> smaller_end = row;
        fpstereo::fill_row_gaps(smaller_end.data(), width, [&](uint64_t w) { return w < invalid; });
        for (int x = 0; x < width; ++x) {
          filled += want[size_t(x)] != row[size_t(x)];
          linear += want[size_t(x)] != smaller_end[size_t(x)];
        }
        for (int s = 0; s < slots; ++s) {
          const auto first = row.begin() + s * p.P, first_want = want.begin() + s * p.P;
          events.push_back({s, y, {first, first + p.P}, f > 0, height, slots});
          expected.push_back({s, y, {first_want, first_want + p.P}});
        }
      }
    for (int s = 0; s < slots; ++s)  // the dummy row
      events.push_back({s, height, std::vector<uint64_t>(size_t(p.P), invalid), frames > 1, height, slots});
  }

  m.clk = 0;
  m.restart = 1;
  m.adv = 1;
  m.in_event = 0;
  m.eval();
  modtb::tick(m);
  m.restart = 0;
  size_t next = 0, seen = 0;
  long cycle = 0, idle = 0, extra = 0;
  const long limit = long(events.size()) * 10 + 1000;
  // After the last slot has left, 16 more steps without events: nothing more may leave.
  for (long quiet = 0; cycle < limit && quiet < 16; ++cycle) {
    const bool adv = !rng.chance(modtb::idle_percent(cycle));
    const bool send = adv && next < events.size() && !rng.chance(20);
    m.adv = adv;
    m.in_event = send;
    if (next < events.size()) {
      const Event& e = events[next];
      m.in_x = uint32_t(e.x);
      m.in_y = uint32_t(e.y);
      m.frame_height = uint32_t(e.height);
      m.frame_last_x = uint32_t(e.slots - 1);
      m.frame_last_y = uint32_t(e.height - 1);
      m.wrapped = e.wrapped;
      for (int q = 0; q < p.P; ++q) modtb::set_bits(m.in_word, q * p.WORD_W, p.WORD_W, e.words[size_t(q)]);
    }
    idle += !adv;
    m.eval();
    modtb::tick(m);
    next += send;
    quiet += seen == expected.size() && adv;
    if (!adv || !m.out_event) continue;
    if (seen == expected.size()) {
      ++extra;
      continue;
    }
    const Out& want = expected[seen++];
    const std::string at = "(" + std::to_string(want.x) + ", " + std::to_string(want.y) + ")";
    check.expect(cycle, "out_x at slot " + at, uint64_t(want.x), m.out_x);
    check.expect(cycle, "out_y at slot " + at, uint64_t(want.y), m.out_y);
    for (int q = 0; q < p.P; ++q)
      check.expect(cycle, "word " + std::to_string(q) + " of slot " + at, want.words[size_t(q)],
                   modtb::get_bits(m.out_word, q * p.WORD_W, p.WORD_W));
  }
  check.expect(cycle, "events after the last slot", 0, uint64_t(extra));
  check.expect(cycle, "slots out", expected.size(), seen);
  return check.finish("W=" + std::to_string(p.W) + " P=" + std::to_string(p.P) + " LINEAR=" + std::to_string(p.LINEAR) +
                      " UNIT_LOG=" + std::to_string(p.UNIT_LOG) + " WORD_W=" +
                      std::to_string(p.WORD_W) + ": fill_row_gaps word for word, " + std::to_string(expected.size()) +
                      " slots (" + std::to_string(filled) + " words filled, " + std::to_string(linear) + " of them along a line), frames back to back and lone, " +
                      std::to_string(cycle) + " cycles, " + std::to_string(idle) + " idle");
}

#define X(NAME, MODEL, SETTER) MODTB_REGISTER_ONE(NAME, MODEL, SETTER, run_gap_fill, GapParams)
MODTB_SETS(X)
#undef X

}  // namespace
