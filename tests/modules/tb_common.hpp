// Shared helpers of the per-module Verilator benches (tests/modules): the random source, bit
// access to Verilator's port types, clocking, the mismatch report and the registry that
// modules_main.cpp dispatches on. Every bench checks its module against a reference model of its
// own, written from the module's header comment and docs/semantics.md.
#pragma once

#include <verilated.h>

#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace modtb {

// splitmix64: small, fast and the same on every platform, so a seed replays a run exactly.
class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(seed) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // uniform in 0 .. n-1 (n >= 1)
  uint64_t below(uint64_t n) { return next() % n; }
  // uniform in lo .. hi (inclusive)
  uint64_t range(uint64_t lo, uint64_t hi) { return lo + below(hi - lo + 1); }
  // true with probability percent / 100
  bool chance(unsigned percent) { return below(100) < percent; }
  // a w-bit value (w <= 64)
  uint64_t bits(int w) { return w >= 64 ? next() : next() & ((uint64_t{1} << w) - 1); }

 private:
  uint64_t state_;
};

inline uint64_t mask_of(int w) { return w >= 64 ? ~uint64_t{0} : (uint64_t{1} << w) - 1; }

// Bit fields of a port, whatever type Verilator gave it (CData .. QData, or VlWide<N>).
template <typename T>
uint64_t get_bits(const T& sig, int lsb, int w) {
  if constexpr (std::is_integral_v<T>) {
    return (static_cast<uint64_t>(sig) >> lsb) & mask_of(w);
  } else {
    uint64_t v = 0;
    for (int b = 0; b < w; ++b) {
      const int at = lsb + b;
      v |= static_cast<uint64_t>((sig[at / 32] >> (at % 32)) & 1U) << b;
    }
    return v;
  }
}

template <typename T>
void set_bits(T& sig, int lsb, int w, uint64_t value) {
  if constexpr (std::is_integral_v<T>) {
    const uint64_t m = mask_of(w) << lsb;
    sig = static_cast<T>((static_cast<uint64_t>(sig) & ~m) | ((value << lsb) & m));
  } else {
    for (int b = 0; b < w; ++b) {
      const int at = lsb + b;
      const uint32_t bit = 1U << (at % 32);
      if ((value >> b) & 1U)
        sig[at / 32] |= bit;
      else
        sig[at / 32] &= ~bit;
    }
  }
}

// A few fixed values chosen often (edges, ties), the rest uniform.
inline uint64_t edgy(Rng& rng, int w) {
  switch (rng.below(8)) {
    case 0: return 0;
    case 1: return mask_of(w);
    case 2: return mask_of(w) - (w > 1 ? 1 : 0);
    case 3: return rng.below(4) & mask_of(w);
    default: return rng.bits(w);
  }
}

struct Options {
  uint64_t seed = 1;
  long cycles = 4000;
  bool verbose = false;
};

// Collects differences; prints the first few as they happen and a summary at the end.
class Checker {
 public:
  explicit Checker(std::string name, int show = 10) : name_(std::move(name)), show_(show) {}
  // One comparison: cycle, what (port / lane), expected, got.
  bool expect(long cycle, const std::string& what, uint64_t expected, uint64_t got) {
    ++checks_;
    if (expected == got) return true;
    if (errors_ < show_)
      std::printf("MISMATCH %s: cycle %ld, %s: expected %llu (0x%llx), got %llu (0x%llx)\n", name_.c_str(), cycle,
                  what.c_str(), static_cast<unsigned long long>(expected), static_cast<unsigned long long>(expected),
                  static_cast<unsigned long long>(got), static_cast<unsigned long long>(got));
    ++errors_;
    return false;
  }
  // A property that must hold (no expected value to show).
  bool require(long cycle, const std::string& what, bool ok) {
    ++checks_;
    if (ok) return true;
    if (errors_ < show_) std::printf("VIOLATION %s: cycle %ld: %s\n", name_.c_str(), cycle, what.c_str());
    ++errors_;
    return false;
  }
  long errors() const { return errors_; }
  long checks() const { return checks_; }
  // Prints the summary; the process exit code.
  int finish(const std::string& what_was_checked) const {
    std::printf("%s: %s\n", name_.c_str(), what_was_checked.c_str());
    std::printf("%s: %ld comparisons, %ld mismatches -> %s\n", name_.c_str(), checks_, errors_,
                errors_ ? "FAIL" : "PASS");
    return errors_ ? 1 : 0;
  }

 private:
  std::string name_;
  int show_;
  long checks_ = 0;
  long errors_ = 0;
};

// A fresh simulation context: registers and memories start at random values drawn from the seed
// (the models are built with --x-initial unique), so nothing may depend on power-up state.
inline void seed_context(VerilatedContext& ctx, uint64_t seed) {
  ctx.randReset(2);
  ctx.randSeed(static_cast<int>(seed & 0x7fffffff));
}

// One clock cycle: inputs are already set; outputs sampled before this call are the values seen
// at the rising edge.
template <typename M>
void tick(M& m) {
  m.clk = 1;
  m.eval();
  m.clk = 0;
  m.eval();
}

// Registry: a test name ("min_tree_n8") to the function that runs it.
using RunFn = std::function<int(const Options&)>;
inline std::map<std::string, RunFn>& registry() {
  static std::map<std::string, RunFn> tests;
  return tests;
}
struct Register {
  Register(const char* name, RunFn fn) { registry()[name] = std::move(fn); }
};

}  // namespace modtb

// For each parameter set of a bench, tests/modules/CMakeLists.txt generates <bench>_sets.hpp with
// the model headers and MODTB_SETS(X), calling X(test name, model class, parameter setter) once a
// set; a bench registers them with MODTB_REGISTER(run function template, parameter struct).
#define MODTB_REGISTER_ONE(NAME, MODEL, SETTER, RUN, PARAMS)                                           \
  static const modtb::Register register_##NAME(#NAME, [](const modtb::Options& o) {                   \
    PARAMS p;                                                                                        \
    SETTER;                                                                                          \
    return RUN<MODEL>(#NAME, p, o);                                                                  \
  });
