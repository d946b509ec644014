#include "compare.hpp"

#include <sstream>

namespace fpstereo {

Comparison compare_words(const DisparityImage& expected, const DisparityImage& got, size_t keep) {
  Comparison c;
  if (expected.width != got.width || expected.height != got.height) {
    c.size_matches = false;
    return c;
  }
  for (int y = 0; y < expected.height; ++y)
    for (int x = 0; x < expected.width; ++x)
      if (expected.at(x, y) != got.at(x, y)) {
        if (c.first.size() < keep) c.first.push_back({x, y, expected.at(x, y), got.at(x, y)});
        ++c.mismatches;
      }
  return c;
}

std::string Comparison::report() const {
  if (!size_matches) return "output size differs from the expected size";
  std::ostringstream os;
  os << mismatches << " mismatching pixels";
  for (const auto& m : first)
    os << "\n  (" << m.x << ", " << m.y << "): expected " << m.expected << ", got " << m.got;
  if (mismatches > first.size()) os << "\n  ...";
  return os.str();
}

}  // namespace fpstereo
