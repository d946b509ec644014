// Reference of the uniqueness summaries (fpstereo_unique_tree / fpstereo_unique_join,
// docs/semantics.md section 4), computed straight from the definitions over a whole range:
//   best, index   the minimum and its lowest index; first / last: index is the range's first / last
//   all           the minimum; but_first / but_last: without the first / last element
//   second        the minimum over elements two or more indices away from index
// An empty minimum is `none` (all ones).
#pragma once

#include <cstdint>
#include <vector>

namespace modtb {

struct UniqueSummary {
  uint64_t best = 0, index = 0, all = 0, but_first = 0, but_last = 0, second = 0;
  bool first = false, last = false;
  bool operator==(const UniqueSummary& o) const {
    return best == o.best && index == o.index && all == o.all && but_first == o.but_first &&
           but_last == o.but_last && second == o.second && first == o.first && last == o.last;
  }
};

inline UniqueSummary unique_reference(const std::vector<uint64_t>& v, uint64_t none) {
  UniqueSummary s;
  const size_t n = v.size();
  size_t at = 0;
  for (size_t i = 1; i < n; ++i)
    if (v[i] < v[at]) at = i;
  s.best = v[at];
  s.index = at;
  s.first = at == 0;
  s.last = at == n - 1;
  s.all = s.but_first = s.but_last = s.second = none;
  for (size_t i = 0; i < n; ++i) {
    if (v[i] < s.all) s.all = v[i];
    if (i != 0 && v[i] < s.but_first) s.but_first = v[i];
    if (i != n - 1 && v[i] < s.but_last) s.but_last = v[i];
    const size_t distance = i > at ? i - at : at - i;
    if (distance >= 2 && v[i] < s.second) s.second = v[i];
  }
  return s;
}

// Values for a summary test: few distinct values (ties), missing ones (all ones), edges, uniform.
inline void unique_values(Rng& rng, std::vector<uint64_t>& v, int w) {
  const unsigned mode = rng.below(5);
  for (auto& x : v) {
    switch (mode) {
      case 0: x = rng.below(3); break;
      case 1: x = rng.chance(40) ? mask_of(w) : rng.below(4); break;
      case 2: x = edgy(rng, w); break;
      default: x = rng.bits(w); break;
    }
    x &= mask_of(w);
  }
}

}  // namespace modtb
