// Pixel-for-pixel comparison of output words, with the first mismatches for the report.
#pragma once

#include <string>
#include <vector>

#include "image.hpp"

namespace fpstereo {

struct Mismatch {
  int x, y;
  int expected, got;
};

struct Comparison {
  bool size_matches = true;
  size_t mismatches = 0;
  std::vector<Mismatch> first;  // in raster order
  bool equal() const { return size_matches && mismatches == 0; }
  // "0 mismatches" or the count and the first ones: "(x, y): expected E, got G".
  std::string report() const;
};

Comparison compare_words(const DisparityImage& expected, const DisparityImage& got, size_t keep = 10);

}  // namespace fpstereo
