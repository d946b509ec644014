// The speckle filter (docs/semantics.md section 5a): hand-made maps whose results are worked out
// by hand below, for the golden model's streaming stage and the naive flood fill alike, and both
// against OpenCV's cv::filterSpeckles where the semantics coincide.
#include <catch2/catch.hpp>

#include <opencv2/calib3d.hpp>
#include <random>
#include <string>
#include <vector>

#include "compare.hpp"
#include "golden_model.hpp"
#include "golden_stages.hpp"
#include "image_io.hpp"
#include "naive_model.hpp"
#include "widths.hpp"

using namespace fpstereo;

namespace {

constexpr uint16_t kInvalid = 255;

// One character a pixel: '.' is invalid, '0' .. '9' and 'a' .. 'z' the words 0 .. 35.
DisparityImage map_of(const std::vector<std::string>& rows) {
  DisparityImage map(int(rows.front().size()), int(rows.size()));
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const char c = rows[size_t(y)][size_t(x)];
      map.at(x, y) = c == '.' ? kInvalid : c <= '9' ? uint16_t(c - '0') : uint16_t(c - 'a' + 10);
    }
  return map;
}

// Both models' filter on `before` must give `after`.
void check_filter(const std::vector<std::string>& before, int size, int range, const std::vector<std::string>& after) {
  const DisparityImage expected = map_of(after);
  DisparityImage golden = map_of(before), naive = map_of(before);
  golden::speckle_filter(golden, size, range, kInvalid);
  remove_speckles(naive, size, range, kInvalid);
  INFO("S = " << size << ", r = " << range);
  const Comparison golden_cmp = compare_words(expected, golden), naive_cmp = compare_words(expected, naive);
  INFO("golden: " << golden_cmp.report());
  CHECK(golden_cmp.equal());
  INFO("naive: " << naive_cmp.report());
  CHECK(naive_cmp.equal());
}

// cv::filterSpeckles on the words as 16-bit signed disparities, the invalid word as newVal.
DisparityImage opencv_filtered(const DisparityImage& words, int size, int range, uint16_t invalid) {
  cv::Mat1s mat(words.height, words.width);
  for (int y = 0; y < words.height; ++y)
    for (int x = 0; x < words.width; ++x) mat(y, x) = short(words.at(x, y));
  cv::filterSpeckles(mat, double(invalid), size, double(range));
  DisparityImage out(words.width, words.height);
  for (int y = 0; y < words.height; ++y)
    for (int x = 0; x < words.width; ++x) out.at(x, y) = uint16_t(mat(y, x));
  return out;
}

void check_against_opencv(const DisparityImage& words, int size, int range, uint16_t invalid) {
  const DisparityImage expected = opencv_filtered(words, size, range, invalid);
  DisparityImage golden = words, naive = words;
  golden::speckle_filter(golden, size, range, invalid);
  remove_speckles(naive, size, range, invalid);
  INFO("S = " << size << ", r = " << range);
  const Comparison golden_cmp = compare_words(expected, golden), naive_cmp = compare_words(expected, naive);
  INFO("golden against OpenCV: " << golden_cmp.report());
  REQUIRE(golden_cmp.equal());
  INFO("naive against OpenCV: " << naive_cmp.report());
  REQUIRE(naive_cmp.equal());
}

}  // namespace

TEST_CASE("speckle filter: a single pixel is a region of one", "[speckle]") {
  check_filter({".....",
                "..5..",
                "....."},
               1, 0,
               {".....",
                ".....",
                "....."});
  // The 5 differs by 4 > r = 2 from its neighbours: a region of its own, removed at S = 1; the
  // ring of eight 1s around it stays.
  check_filter({"111",
                "151",
                "111"},
               1, 2,
               {"111",
                "1.1",
                "111"});
}

TEST_CASE("speckle filter: regions of exactly S pixels go, of S + 1 stay (OpenCV's <=)", "[speckle]") {
  // Three 3s and four 4s on a row, S = 3.
  check_filter({"333.4444",
                "........"},
               3, 0,
               {"....4444",
                "........"});
  // The same down a column: the 4s reach row y + S of their top pixel, the 3s do not.
  check_filter({"3.4",
                "3.4",
                "3.4",
                "..4",
                "..."},
               3, 0,
               {"..4",
                "..4",
                "..4",
                "..4",
                "..."});
  // A frame taller than S, so rows leave the filter before the frame ends: the 1s and the 3s
  // (3 pixels) go, the 2s (5 rows) and the 4s (a 2 x 2 block) stay.
  check_filter({"1.2.3",
                "1.2.3",
                "1.2.3",
                "..2..",
                "..2..",
                ".....",
                "..44.",
                "..44."},
               3, 0,
               {"..2..",
                "..2..",
                "..2..",
                "..2..",
                "..2..",
                ".....",
                "..44.",
                "..44."});
}

TEST_CASE("speckle filter: a U joins its arms on its last row", "[speckle]") {
  // Arms of 4 pixels each, joined by the bottom row: 4 + 4 + 3 = 11 pixels in one region.
  const std::vector<std::string> u = {"1...1",
                                      "1...1",
                                      "1...1",
                                      "11111"};
  check_filter(u, 11, 0, {".....", ".....", ".....", "....."});
  check_filter(u, 10, 0, u);
  // An upside-down U: one region from its first row, split into two arms below it.
  const std::vector<std::string> n = {"11111",
                                      "1...1",
                                      "1...1"};
  check_filter(n, 9, 0, {".....", ".....", "....."});
  check_filter(n, 8, 0, n);
}

TEST_CASE("speckle filter: a spiral is one region of 31 pixels", "[speckle]") {
  // Rows of 7, 1, 6, 3, 5, 2 and 7 pixels; the tail (row 4, columns 2 to 4) hangs from column 4.
  const std::vector<std::string> spiral = {"1111111",
                                           "......1",
                                           "11111.1",
                                           "1...1.1",
                                           "1.111.1",
                                           "1.....1",
                                           "1111111"};
  const std::vector<std::string> empty(7, ".......");
  check_filter(spiral, 31, 0, empty);
  check_filter(spiral, 30, 0, spiral);
}

TEST_CASE("speckle filter: diagonal contact does not connect", "[speckle]") {
  // Two 2 x 2 blocks touching at a corner: two regions of 4, not one of 8.
  const std::vector<std::string> blocks = {"11..",
                                           "11..",
                                           "..11",
                                           "..11"};
  check_filter(blocks, 4, 0, {"....", "....", "....", "...."});
  check_filter(blocks, 3, 0, blocks);
}

TEST_CASE("speckle filter: regions at the borders, the last rows decided at the frame's end", "[speckle]") {
  // The 2s at the top-left corner and the 7s down the right border to the bottom row are regions
  // of 2; the six 5s at the left and bottom borders stay.
  check_filter({"22.....",
                ".......",
                "555...7",
                "555...7"},
               2, 0,
               {".......",
                ".......",
                "555....",
                "555...."});
  // S beyond the frame's height: the whole frame is held, one region of 12 stays, at S = 12 goes.
  const std::vector<std::string> full = {"1111", "1111", "1111"};
  check_filter(full, 11, 0, full);
  check_filter(full, 12, 0, {"....", "....", "...."});
}

TEST_CASE("speckle filter: invalid pixels separate regions, whatever their word", "[speckle]") {
  check_filter({"11.11"}, 2, 0, {"....."});
  check_filter({"11.11"}, 1, 0, {"11.11"});
  // The invalid word (255 here) lies within r = 200 of 97, yet is never part of a region.
  DisparityImage map(3, 1, kInvalid);
  map.at(0, 0) = map.at(2, 0) = 97;
  DisparityImage golden = map, naive = map;
  golden::speckle_filter(golden, 1, 200, kInvalid);
  remove_speckles(naive, 1, 200, kInvalid);
  CHECK(compare_words(DisparityImage(3, 1, kInvalid), golden).equal());
  CHECK(compare_words(DisparityImage(3, 1, kInvalid), naive).equal());
}

TEST_CASE("speckle filter: the range, r = 0 and in sub-pixel units", "[speckle]") {
  // r = 0: the 1s and the 2s are two regions of 4; r = 1: one region of 8.
  const std::vector<std::string> steps = {"1122",
                                          "1122"};
  check_filter(steps, 4, 0, {"....", "...."});
  check_filter(steps, 4, 1, steps);
  // Four fraction bits, r = 1: the range is 16 in words. 'g' = 16 and 'w' = 32 are 16 apart,
  // one region of 2; '0' and 'h' = 17 are 17 apart, two regions of 1.
  check_filter({"0h.gw"}, 1, 16, {"...gw"});
  check_filter({"0h.gw"}, 2, 16, {"....."});
}

TEST_CASE("speckle filter: golden and naive equal OpenCV's filterSpeckles on random maps", "[speckle]") {
  std::mt19937 rng(29);
  for (int i = 0; i < 200; ++i) {
    const int width = std::uniform_int_distribution<int>(1, 40)(rng);
    const int height = std::uniform_int_distribution<int>(1, 30)(rng);
    const int levels = std::uniform_int_distribution<int>(1, 8)(rng);
    const int invalid_percent = std::uniform_int_distribution<int>(0, 60)(rng);
    DisparityImage words(width, height);
    for (auto& w : words.pixels)
      w = int(rng() % 100) < invalid_percent ? kInvalid : uint16_t(rng() % unsigned(levels) * 3);
    const int size = std::uniform_int_distribution<int>(1, 40)(rng);
    const int range = std::uniform_int_distribution<int>(0, 7)(rng);
    INFO("case " << i);
    check_against_opencv(words, size, range, kInvalid);
  }
}

TEST_CASE("speckle filter: the models' words equal OpenCV's filterSpeckles on a real pair", "[speckle]") {
  // The cones pair after A4's left-right check and sub-pixel fit, before any filter: integer
  // words, the invalid word as newVal, the range in sixteenths.
  const GrayImage left = load_gray(FPSTEREO_EXAMPLES_DIR "/cones/left.png", "left");
  const GrayImage right = load_gray(FPSTEREO_EXAMPLES_DIR "/cones/right.png", "right");
  StereoConfig cfg = preset("A4");
  cfg.width = left.width;
  cfg.height = left.height;
  cfg.dmax = 64;
  cfg.uf = 16;
  cfg.median = 0;
  const DisparityImage unfiltered = run_golden(cfg, left, right, 2);
  const uint16_t invalid = derive_widths(cfg).invalid_word;
  for (const auto& [size, range] : {std::pair{50, 1}, {100, 2}, {200, 2}, {4096, 0}}) {
    check_against_opencv(unfiltered, size, range << cfg.subpixel_bits, invalid);
    // Not a vacuous comparison: the filter removes pixels here.
    CHECK(compare_words(unfiltered, opencv_filtered(unfiltered, size, range << cfg.subpixel_bits, invalid)).mismatches > 100);
    // The pipeline places the filter right there, after the check and before the median.
    StereoConfig with_filter = cfg;
    with_filter.speckle_size = size;
    with_filter.speckle_range = range;
    const Comparison cmp = compare_words(opencv_filtered(unfiltered, size, range << cfg.subpixel_bits, invalid),
                                         run_golden(with_filter, left, right, 2));
    INFO("run_golden with speckle-size " << size << ", speckle-range " << range << ": " << cmp.report());
    CHECK(cmp.equal());
  }
}
