// Image and disparity files, dataset lists and the OpenCV baseline (gen/io). Every file is
// created at run time in a temporary directory.
#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "dataset.hpp"
#include "image_io.hpp"
#include "sgbm_baseline.hpp"

using namespace fpstereo;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

const float kNaN = NAN;
const float kInf = INFINITY;

// A fresh directory, removed with everything in it when the test ends.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    path_ = fs::temp_directory_path() /
            ("fpstereo_test_io_" + std::to_string(stamp) + "_" + std::to_string(counter++));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

void write_file(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// Minimal PFM writer, independent of write_pfm: `rows_top_to_bottom` are written bottom row first.
std::string pfm_bytes(const std::vector<std::vector<float>>& rows_top_to_bottom, int channels,
                      bool little_endian) {
  const int width = int(rows_top_to_bottom[0].size()) / channels;
  std::string out = std::string(channels == 3 ? "PF" : "Pf") + "\n" + std::to_string(width) + " " +
                    std::to_string(rows_top_to_bottom.size()) + "\n" + (little_endian ? "-1.0" : "1.0") +
                    "\n";
  for (auto row = rows_top_to_bottom.rbegin(); row != rows_top_to_bottom.rend(); ++row)
    for (float v : *row) {
      uint32_t bits;
      std::memcpy(&bits, &v, 4);
      for (int i = 0; i < 4; ++i) out += char(bits >> (8 * (little_endian ? i : 3 - i)));
    }
  return out;
}

bool same_value(float a, float b) { return a == b || (std::isnan(a) && std::isnan(b)); }

bool same_map(const cv::Mat1f& a, const cv::Mat1f& b) {
  if (a.size() != b.size()) return false;
  for (int y = 0; y < a.rows; ++y)
    for (int x = 0; x < a.cols; ++x)
      if (!same_value(a(y, x), b(y, x))) return false;
  return true;
}

cv::Mat1f map_of(int rows, int cols, const std::vector<float>& values) {
  cv::Mat1f m(rows, cols);
  std::copy(values.begin(), values.end(), m.begin());
  return m;
}

// The message of the InputError `f` throws, or "no error".
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

GrayImage gray_of(int width, int height, uint8_t value) { return GrayImage(width, height, value); }

}  // namespace

// ---- read_disparity ----------------------------------------------------------------------------

TEST_CASE("read_disparity: 16-bit PNG, KITTI scale, 0 invalid", "[io]") {
  TempDir dir;
  const cv::Mat_<uint16_t> stored = (cv::Mat_<uint16_t>(2, 2) << 0, 256, 1000, 65535);
  cv::imwrite(dir.file("gt.png"), stored);
  // value / 256: 0 -> NaN, 256 -> 1, 1000 -> 3.90625, 65535 -> 255.99609375
  CHECK(same_map(read_disparity(dir.file("gt.png"), 256, "0"),
                 map_of(2, 2, {kNaN, 1, 3.90625f, 255.99609375f})));
}

TEST_CASE("read_disparity: 8-bit PGM with a scale", "[io]") {
  TempDir dir;
  write_file(dir.file("gt.pgm"), std::string("P5\n3 2\n255\n") + std::string("\x00\x04\x0a\xff\x01\x02", 6));
  // value / 4: 0, 1, 2.5, 63.75, 0.25, 0.5
  CHECK(same_map(read_disparity(dir.file("gt.pgm"), 4, "0"),
                 map_of(2, 3, {kNaN, 1, 2.5f, 63.75f, 0.25f, 0.5f})));
  CHECK(same_map(read_disparity(dir.file("gt.pgm"), 4, "none"),
                 map_of(2, 3, {0, 1, 2.5f, 63.75f, 0.25f, 0.5f})));
}

TEST_CASE("read_disparity: PFM in both byte orders, bottom-to-top rows, inf invalid", "[io]") {
  TempDir dir;
  const std::vector<std::vector<float>> rows = {{1.5f, kInf, 3}, {0, 10.25f, -kInf}};
  const cv::Mat1f expected = map_of(2, 3, {1.5f, kNaN, 3, 0, 10.25f, kNaN});
  for (bool little_endian : {true, false}) {
    INFO("little-endian: " << little_endian);
    write_file(dir.file("gt.pfm"), pfm_bytes(rows, 1, little_endian));
    CHECK(same_map(read_disparity(dir.file("gt.pfm"), 1, "inf"), expected));
  }
}

TEST_CASE("read_disparity: 3-channel PFM uses the first channel; 0 invalid applies too", "[io]") {
  TempDir dir;
  write_file(dir.file("gt.pfm"), pfm_bytes({{2, 9, 9, 0, 9, 9}, {4, 9, 9, 8, 9, 9}}, 3, true));
  // scale 2: 2 -> 1, stored 0 -> NaN, 4 -> 2, 8 -> 4
  CHECK(same_map(read_disparity(dir.file("gt.pfm"), 2, "0"), map_of(2, 2, {1, kNaN, 2, 4})));
}

TEST_CASE("read_disparity: errors are InputErrors naming the problem", "[io]") {
  TempDir dir;
  write_file(dir.file("short.pfm"), pfm_bytes({{1, 2, 3}}, 1, true).substr(0, 20));
  CHECK_THAT(error_of([&] { read_disparity(dir.file("short.pfm"), 1, "inf"); }), Contains("truncated"));
  CHECK_THAT(error_of([&] { read_disparity(dir.file("none.png"), 1, "0"); }), Contains("no such file"));
  write_file(dir.file("gt.pgm"), std::string("P5\n1 1\n255\n\x05", 12));
  CHECK_THAT(error_of([&] { read_disparity(dir.file("gt.pgm"), 1, "nan"); }),
             Contains("expected 0, inf or none"));
  CHECK_THAT(error_of([&] { read_disparity(dir.file("gt.pgm"), 0, "0"); }), Contains("must be positive"));
}

// ---- writers -----------------------------------------------------------------------------------

TEST_CASE("write_kitti_png round trip, a valid 0 is stored as 1", "[io]") {
  TempDir dir;
  const cv::Mat1f disp = map_of(1, 5, {0, 1.5f, kNaN, 100.25f, 0.001f});
  write_kitti_png(disp, dir.file("d.png"));
  const cv::Mat raw = cv::imread(dir.file("d.png"), cv::IMREAD_UNCHANGED);
  REQUIRE(raw.type() == CV_16UC1);
  // round(d * 256): 0 -> 0 but valid, so 1; 384; invalid 0; 25664; 0.256 -> 0 but valid, so 1
  CHECK(raw.at<uint16_t>(0, 0) == 1);
  CHECK(raw.at<uint16_t>(0, 1) == 384);
  CHECK(raw.at<uint16_t>(0, 2) == 0);
  CHECK(raw.at<uint16_t>(0, 3) == 25664);
  CHECK(raw.at<uint16_t>(0, 4) == 1);
  CHECK(same_map(read_disparity(dir.file("d.png"), 256, "0"),
                 map_of(1, 5, {1.0f / 256, 1.5f, kNaN, 100.25f, 1.0f / 256})));
}

TEST_CASE("write_pfm: little-endian, bottom-to-top, inf for invalid", "[io]") {
  TempDir dir;
  const cv::Mat1f disp = map_of(2, 2, {1, kNaN, 3.5f, 0});
  write_pfm(disp, dir.file("d.pfm"));
  std::ifstream in(dir.file("d.pfm"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string header = "Pf\n2 2\n-1\n";
  REQUIRE(bytes.size() == header.size() + 16);
  CHECK(bytes.substr(0, header.size()) == header);
  float first;  // first stored value: the bottom row's left pixel
  std::memcpy(&first, bytes.data() + header.size(), 4);
  CHECK(first == 3.5f);
  float second_row_right;
  std::memcpy(&second_row_right, bytes.data() + header.size() + 12, 4);
  CHECK(std::isinf(second_row_right));
  CHECK(same_map(read_disparity(dir.file("d.pfm"), 1, "inf"), disp));
}

TEST_CASE("write_pgm: binary P5 header, raster bytes, read back by load_gray", "[io]") {
  TempDir dir;
  GrayImage image(3, 2);
  image.pixels = {0, 1, 2, 128, 254, 255};
  write_pgm(image, dir.file("g.pgm"));
  std::ifstream in(dir.file("g.pgm"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(bytes == std::string("P5\n3 2\n255\n") + std::string("\x00\x01\x02\x80\xfe\xff", 6));
  CHECK(load_gray(dir.file("g.pgm"), "left image") == image);
}

TEST_CASE("encode_gray_png: one 8-bit gray pixel per value, raster order", "[io]") {
  DisparityImage values(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) values.at(x, y) = uint16_t(x * 60 + y);
  const std::vector<uchar> bytes = encode_gray_png(values);
  const cv::Mat back = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  REQUIRE(back.type() == CV_8UC1);
  REQUIRE(back.cols == 5);
  REQUIRE(back.rows == 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) CHECK(back.at<uchar>(y, x) == x * 60 + y);
}

TEST_CASE("write_colour_png: colour map, black invalid pixels, legend on the right", "[io]") {
  TempDir dir;
  cv::Mat1f disp(200, 300, 20.0f);
  disp(10, 10) = kNaN;
  write_colour_png(disp, 0, 64, dir.file("c.png"));
  const cv::Mat3b image = cv::imread(dir.file("c.png"), cv::IMREAD_COLOR);
  REQUIRE(image.rows == 200);
  CHECK(image.cols > 300);  // the legend
  CHECK(image(10, 10) == cv::Vec3b(0, 0, 0));
  CHECK(image(50, 50) != cv::Vec3b(0, 0, 0));
  CHECK(image(50, 50) == image(150, 250));  // one disparity, one colour
}

TEST_CASE("writers report unwritable paths as InputError", "[io]") {
  const cv::Mat1f disp(2, 2, 1.0f);
  const std::string path = "/nonexistent_fpstereo_dir/d";
  CHECK_THAT(error_of([&] { write_kitti_png(disp, path + ".png"); }), Contains("cannot write"));
  CHECK_THAT(error_of([&] { write_pfm(disp, path + ".pfm"); }), Contains("cannot write"));
  CHECK_THAT(error_of([&] { write_colour_png(disp, 0, 10, path + "_c.png"); }), Contains("cannot write"));
  CHECK_THAT(error_of([&] { write_pgm(GrayImage(2, 2), path + ".pgm"); }), Contains("cannot write"));
}

TEST_CASE("to_float_disparity maps the invalid word to NaN", "[io]") {
  StereoConfig cfg;  // dmax 128: 8-bit words, 128 = invalid
  DisparityImage words(4, 1);
  words.pixels = {0, 5, 128, 127};
  CHECK(same_map(to_float_disparity(words, cfg), map_of(1, 4, {0, 5, kNaN, 127})));
}

// ---- load_gray and check_pair ------------------------------------------------------------------

TEST_CASE("load_gray converts colour and keeps gray", "[io]") {
  TempDir dir;
  const cv::Mat3b bgr(2, 3, cv::Vec3b(10, 200, 60));
  cv::imwrite(dir.file("c.png"), bgr);
  cv::Mat1b expected;
  cv::cvtColor(bgr, expected, cv::COLOR_BGR2GRAY);
  const GrayImage colour = load_gray(dir.file("c.png"), "left image");
  REQUIRE(colour.width == 3);
  REQUIRE(colour.height == 2);
  CHECK(colour.at(2, 1) == expected(1, 2));

  cv::imwrite(dir.file("a.png"), cv::Mat4b(2, 3, cv::Vec4b(10, 200, 60, 255)));
  CHECK(load_gray(dir.file("a.png"), "left image").at(0, 0) == expected(0, 0));

  cv::Mat1b gray = (cv::Mat1b(1, 3) << 0, 128, 255);
  cv::imwrite(dir.file("g.png"), gray);
  CHECK(load_gray(dir.file("g.png"), "right image").pixels == std::vector<uint8_t>{0, 128, 255});
}

TEST_CASE("load_gray errors name the role and the file", "[io]") {
  TempDir dir;
  const std::string missing = error_of([&] { load_gray(dir.file("x.png"), "left image"); });
  CHECK_THAT(missing, Contains("left image") && Contains("x.png") && Contains("no such file"));
  write_file(dir.file("bad.png"), "\x89PNG this is not really an image");
  CHECK_THAT(error_of([&] { load_gray(dir.file("bad.png"), "right image"); }),
             Contains("right image") && Contains("not a decodable image"));
  cv::imwrite(dir.file("deep.png"), cv::Mat_<uint16_t>(2, 2, uint16_t(1000)));
  CHECK_THAT(error_of([&] { load_gray(dir.file("deep.png"), "left image"); }), Contains("expected 8-bit"));
  CHECK(missing.find('\n') == std::string::npos);
}

TEST_CASE("check_pair rejects mismatched and oversized pairs", "[io]") {
  StereoConfig cfg;
  cfg.width = 100;
  cfg.height = 50;
  CHECK_NOTHROW(check_pair(gray_of(100, 50, 0), gray_of(100, 50, 0), cfg));
  CHECK_THAT(error_of([&] { check_pair(gray_of(90, 50, 0), gray_of(91, 50, 0), cfg); }),
             Contains("90x50") && Contains("91x50"));
  CHECK_THAT(error_of([&] { check_pair(gray_of(101, 50, 0), gray_of(101, 50, 0), cfg); }),
             Contains("101x50") && Contains("100x50") && Contains("--width/--height"));
}

// ---- read_pairs_csv ----------------------------------------------------------------------------

TEST_CASE("read_pairs_csv: paths joined to the folder, empty fields unavailable", "[io]") {
  TempDir dir;
  write_file(dir.file("pairs.csv"),
             "pair,left,right,gt_occ,gt_noc,noc_mask,gt_scale,gt_invalid,max_disp_px\r\n"
             "a,l/a.png,r/a.png,gt/a.png,,m/a.png,4,0,55.00\r\n"
             "b,l/b.png,r/b.png,gt/b.pfm,,,1,inf,\r\n");
  const auto pairs = read_pairs_csv(dir.file(""));
  REQUIRE(pairs.size() == 2);
  CHECK(pairs[0].name == "a");
  CHECK(pairs[0].left == dir.file("l/a.png"));
  CHECK(pairs[0].gt_noc.empty());
  CHECK(pairs[0].noc_mask == dir.file("m/a.png"));
  CHECK(pairs[0].has_noc());  // gt_occ restricted to the mask
  CHECK(pairs[0].gt_scale == 4);
  CHECK(pairs[0].gt_invalid == "0");
  CHECK(pairs[0].max_disp_px == 55.0);
  CHECK_FALSE(pairs[1].has_noc());
  CHECK(pairs[1].gt_invalid == "inf");
  CHECK_FALSE(pairs[1].max_disp_px.has_value());
}

TEST_CASE("read_pairs_csv: missing or malformed files are InputErrors", "[io]") {
  TempDir dir;
  CHECK_THAT(error_of([&] { read_pairs_csv(dir.file("")); }), Contains("pairs.csv"));
  const std::string header = "pair,left,right,gt_occ,gt_noc,noc_mask,gt_scale,gt_invalid,max_disp_px\n";
  write_file(dir.file("pairs.csv"), header + "a,l.png,r.png,gt.png,,,4,0\n");
  CHECK_THAT(error_of([&] { read_pairs_csv(dir.file("")); }), Contains("line 2") && Contains("8 fields"));
  write_file(dir.file("pairs.csv"), header + "a,l.png,r.png,gt.png,,,four,0,\n");
  CHECK_THAT(error_of([&] { read_pairs_csv(dir.file("")); }), Contains("gt_scale 'four'"));
  write_file(dir.file("pairs.csv"), header);
  CHECK_THAT(error_of([&] { read_pairs_csv(dir.file("")); }), Contains("no pairs"));
  for (const char* scale : {"0x10", "1e-310", "inf", "nan", "4 x"}) {
    write_file(dir.file("pairs.csv"), header + "a,l.png,r.png,gt.png,,," + scale + ",0,\n");
    CHECK_THAT(error_of([&] { read_pairs_csv(dir.file("")); }), Contains("is not a decimal number"));
  }
}

TEST_CASE("read_pairs_csv: a UTF-8 byte order mark before the header is skipped", "[io]") {
  TempDir dir;
  write_file(dir.file("pairs.csv"),
             "\xEF\xBB\xBFpair,left,right,gt_occ,gt_noc,noc_mask,gt_scale,gt_invalid,max_disp_px\na,l.png,r.png,,,,,,\n");
  const auto pairs = read_pairs_csv(dir.file(""));
  REQUIRE(pairs.size() == 1);
  CHECK(pairs[0].name == "a");
}

TEST_CASE("read_pairs_csv: a repeated pair name is found among many rows", "[io]") {
  TempDir dir;
  std::string text = "pair,left,right,gt_occ,gt_noc,noc_mask,gt_scale,gt_invalid,max_disp_px\n";
  for (int i = 0; i < 20000; ++i) text += "p" + std::to_string(i) + ",l.png,r.png,,,,,,\n";
  text += "p7,l.png,r.png,,,,,,\n";
  write_file(dir.file("pairs.csv"), text);
  CHECK_THAT(error_of([&] { read_pairs_csv(dir.file("")); }), Contains("line 20002") && Contains("'p7' appears twice"));
}

TEST_CASE("encode_kitti_png refuses a disparity of 256 or more instead of clamping it", "[io]") {
  cv::Mat1f disp(1, 3, 10.0f);
  disp(0, 1) = 255.99f;
  CHECK_NOTHROW(encode_kitti_png(disp));
  disp(0, 2) = 256.0f;
  CHECK_THAT(error_of([&] { encode_kitti_png(disp); }), Contains("cannot hold the disparity 256 at (2, 0)"));
  CHECK(encode_disparity_file("x.pfm", disp) == encode_pfm(disp));
}

TEST_CASE("the colour map spans min-disp .. max: negatives keep their own colours", "[io]") {
  cv::Mat1f disp(200, 300, -20.0f);
  disp(cv::Rect(150, 0, 150, 200)) = -10.0f;
  const cv::Mat3b image = cv::imdecode(encode_colour_png(disp, -32, 31), cv::IMREAD_COLOR);
  CHECK(image(50, 50) != image(50, 250));
  CHECK(image(50, 50) != cv::Vec3b(0, 0, 0));
}

TEST_CASE("an image whose header states more than 8192 pixels on a side is refused before decoding", "[io]") {
  TempDir dir;
  write_file(dir.file("big.pgm"), std::string("P5\n# a comment\n32000 32000\n255\n") + std::string(100, '\0'));
  CHECK_THAT(error_of([&] { load_gray(dir.file("big.pgm"), "left image"); }),
             Contains("the header states 32000x32000 pixels"));
  std::string png = "\x89PNG\r\n\x1a\n";
  png += std::string("\0\0\0\x0dIHDR", 8) + std::string("\0\0\x7d\0\0\0\x7d\0\x08\0\0\0\0", 13) + "crc!";
  write_file(dir.file("big.png"), png);
  CHECK_THAT(error_of([&] { read_disparity(dir.file("big.png"), 1, "0"); }),
             Contains("the header states 32000x32000 pixels"));
}

// ---- OpenCV baseline ---------------------------------------------------------------------------

TEST_CASE("run_sgbm finds a uniform shift and marks the unmatched border NaN", "[io]") {
  constexpr int kShift = 6;
  cv::Mat1b right(60, 120);
  cv::RNG rng(7);
  rng.fill(right, cv::RNG::UNIFORM, 0, 256);
  cv::Mat1b left(right.size(), uchar(0));
  right(cv::Rect(0, 0, right.cols - kShift, right.rows))
      .copyTo(left(cv::Rect(kShift, 0, right.cols - kShift, right.rows)));
  GrayImage l(left.cols, left.rows), r(right.cols, right.rows);
  std::copy(left.begin(), left.end(), l.pixels.begin());
  std::copy(right.begin(), right.end(), r.pixels.begin());
  SgbmOptions options;
  options.num_disparities = 10;  // rounded up to 16
  const cv::Mat1f disp = run_sgbm(l, r, options);
  REQUIRE(disp.size() == left.size());
  CHECK(std::isnan(disp(30, 2)));  // x < numDisparities: no full search range
  CHECK(disp(30, 60) == Approx(kShift));
  CHECK_THAT(describe(options), Contains("numDisparities=16") && Contains("P1=200") && Contains("P2=800"));
  options.block = 4;
  CHECK_THAT(error_of([&] { run_sgbm(l, r, options); }), Contains("sgbm-block"));
}
