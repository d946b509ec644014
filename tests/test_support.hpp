// Image and configuration generators and scratch paths shared by the test files.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "config.hpp"
#include "image.hpp"

namespace fpstereo::test {

// A path under the temporary directory that no other process uses (two test runs on one machine,
// from two build trees, never share a scratch file), removed when the test process exits. The
// process id goes before the extension, so a ".csv" stays one.
inline std::filesystem::path scratch_path(const std::string& name) {
  struct Scratch {
    std::vector<std::filesystem::path> paths;
    ~Scratch() {
      std::error_code ec;
      for (const auto& p : paths) std::filesystem::remove_all(p, ec);
    }
  };
  static Scratch scratch;
  const std::filesystem::path n(name);
  const std::string unique = n.stem().string() + "." + std::to_string(::getpid()) + n.extension().string();
  scratch.paths.push_back(std::filesystem::temp_directory_path() / unique);
  return scratch.paths.back();
}

inline GrayImage random_image(int width, int height, std::mt19937& rng, int levels = 256) {
  GrayImage img(width, height);
  std::uniform_int_distribution<int> value(0, levels - 1);
  for (auto& p : img.pixels) p = uint8_t(value(rng) * (255 / std::max(1, levels - 1)));
  return img;
}

// A pair whose true left-view disparity is known: right is a random texture and
// left(x, y) = right(x - d(x, y), y); where x - d falls off the image the left pixel is fresh
// noise. Returns {left, right}.
inline std::pair<GrayImage, GrayImage> shifted_pair(int width, int height, std::mt19937& rng,
                                                    const std::function<int(int, int)>& disparity,
                                                    int levels = 256) {
  GrayImage right = random_image(width, height, rng, levels);
  GrayImage left = random_image(width, height, rng, levels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int xs = x - disparity(x, y);
      if (xs >= 0 && xs < width) left.at(x, y) = right.at(xs, y);
    }
  return {left, right};
}

}  // namespace fpstereo::test
