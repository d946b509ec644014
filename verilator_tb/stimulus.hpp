// Stereo pairs the test bench streams into the design: random textures, shifted textures with a
// known disparity, and crops of image files.
#pragma once

#include <algorithm>
#include <random>
#include <utility>

#include "image.hpp"

namespace fpstereo::tb {

struct StereoPair {
  GrayImage left, right;
};

// Uniform noise over `levels` evenly spaced gray levels (2 .. 256); few levels make many
// equal costs, which exercises every tie rule.
inline GrayImage random_texture(int width, int height, int levels, std::mt19937& rng) {
  GrayImage img(width, height);
  std::uniform_int_distribution<int> level(0, levels - 1);
  const int step = 255 / std::max(1, levels - 1);
  for (auto& p : img.pixels) p = uint8_t(level(rng) * step);
  return img;
}

// Two unrelated textures: no true disparity, so the costs and their ties are arbitrary.
inline StereoPair random_pair(int width, int height, int levels, std::mt19937& rng) {
  GrayImage left = random_texture(width, height, levels, rng);
  return {std::move(left), random_texture(width, height, levels, rng)};
}

// right is a texture and left(x, y) = right(x - shift, y): a constant disparity `shift`.
// Where x - shift falls off the image, left is fresh noise.
inline StereoPair shifted_pair(int width, int height, int shift, int levels, std::mt19937& rng) {
  GrayImage right = random_texture(width, height, levels, rng);
  GrayImage left = random_texture(width, height, levels, rng);
  for (int y = 0; y < height; ++y)
    for (int x = shift; x < width; ++x) left.at(x, y) = right.at(x - shift, y);
  return {std::move(left), std::move(right)};
}

// The top-left width x height region; the image must be at least that large.
inline GrayImage crop_top_left(const GrayImage& img, int width, int height) {
  GrayImage out(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) out.at(x, y) = img.at(x, y);
  return out;
}

}  // namespace fpstereo::tb
