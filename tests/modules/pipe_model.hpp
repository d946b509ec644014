// Expected outputs of a pipeline that advances only on enabled clock edges: what an input
// presented at an enabled edge becomes LATENCY enabled edges later (latency 1 = registered
// output). Unknown (power-up) outputs are std::nullopt and are not compared.
#pragma once

#include <deque>
#include <optional>

namespace modtb {

template <typename T>
class EnabledPipe {
 public:
  explicit EnabledPipe(int latency) : in_flight_(static_cast<size_t>(latency - 1)) {}
  // One clock edge: with en high, `in` enters and the output moves on; with en low, all holds.
  void edge(bool en, const T& in) {
    if (!en) return;
    in_flight_.push_back(in);
    out_ = in_flight_.front();
    in_flight_.pop_front();
  }
  const std::optional<T>& out() const { return out_; }

 private:
  std::deque<std::optional<T>> in_flight_;
  std::optional<T> out_;
};

// Probability (percent) of an idle cycle, changing by phase so that runs with no idle cycles,
// a few and many all occur.
inline unsigned idle_percent(long cycle) {
  static const unsigned phases[] = {0, 20, 60, 0, 90, 35};
  return phases[(cycle / 500) % 6];
}

}  // namespace modtb
