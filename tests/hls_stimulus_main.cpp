// Writes the image pair an HLS C-simulation test runs on, as 8-bit PGM files the generated test
// bench and `fpstereo run` both read: generated textures (the Verilator bench's stimulus) or a
// region of an image pair.
//   hls_stimulus --width W --height H [--seed S] [--levels L] [--shifted D] LEFT.pgm RIGHT.pgm
//   hls_stimulus [--width W --height H] --from L.png R.png [--at X Y] LEFT.pgm RIGHT.pgm
//     (without --width/--height: the whole images)
#include <CLI/CLI.hpp>
#include <random>

#include "config_cli.hpp"
#include "image_io.hpp"
#include "stimulus.hpp"

namespace {

using namespace fpstereo;

GrayImage region(const GrayImage& img, int x0, int y0, int width, int height) {
  if (x0 < 0 || y0 < 0 || x0 + width > img.width || y0 + height > img.height)
    throw InputError("the region " + std::to_string(width) + "x" + std::to_string(height) + " at (" +
                     std::to_string(x0) + ", " + std::to_string(y0) + ") is outside the image");
  GrayImage out(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) out.at(x, y) = img.at(x0 + x, y0 + y);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hls_stimulus: image pairs for the HLS C-simulation tests"};
  int width = 0, height = 0, levels = 256, shift = -1;
  unsigned seed = 1;
  std::vector<std::string> from;
  std::vector<int> at{0, 0};
  std::string left_path, right_path;
  app.add_option("--width", width);
  app.add_option("--height", height);
  app.add_option("--seed", seed);
  app.add_option("--levels", levels);
  app.add_option("--shifted", shift);
  app.add_option("--from", from)->expected(2);
  app.add_option("--at", at)->expected(2);
  app.add_option("left", left_path)->required();
  app.add_option("right", right_path)->required();
  try {
    app.parse(argc, argv);
    tb::StereoPair pair;
    if (!from.empty()) {
      const GrayImage left = load_gray(from[0], "left image"), right = load_gray(from[1], "right image");
      if (width == 0 || height == 0) {
        width = left.width;
        height = left.height;
      }
      pair.left = region(left, at[0], at[1], width, height);
      pair.right = region(right, at[0], at[1], width, height);
    } else {
      if (width <= 0 || height <= 0)
        throw InputError("--width and --height are required for generated pairs");
      std::mt19937 rng(seed);
      pair = shift >= 0 ? tb::shifted_pair(width, height, shift, levels, rng)
                        : tb::random_pair(width, height, levels, rng);
    }
    write_pgm(pair.left, left_path);
    write_pgm(pair.right, right_path);
  } catch (const CLI::ParseError& e) {
    return report_parse_error(app, "hls_stimulus", e);
  } catch (const InputError& e) {
    return report_error("hls_stimulus", e.what());
  }
  return 0;
}
