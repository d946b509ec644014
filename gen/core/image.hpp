// Plain row-major images used by the models (no OpenCV dependency in the core).
#pragma once

#include <cstdint>
#include <vector>

namespace fpstereo {

template <class T>
struct Image {
  int width = 0;
  int height = 0;
  std::vector<T> pixels;

  Image() = default;
  Image(int w, int h, T fill = T{}) : width(w), height(h), pixels(size_t(w) * size_t(h), fill) {}
  T& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  const T& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  bool operator==(const Image& o) const {
    return width == o.width && height == o.height && pixels == o.pixels;
  }
};

using GrayImage = Image<uint8_t>;
// Output words: a disparity in units of 2^-subpixel_bits, 0 .. (dmax-1) * 2^subpixel_bits, or
// Widths::invalid_word.
using DisparityImage = Image<uint16_t>;

}  // namespace fpstereo
