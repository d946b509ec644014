#include "image_io.hpp"

#include <fmt/core.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "files.hpp"
#include "text.hpp"
#include "widths.hpp"

namespace fpstereo {
namespace {

std::string size_text(int width, int height) { return fmt::format("{}x{}", width, height); }

// The largest image side any configuration takes (config.cpp's width and height limits).
constexpr uint64_t kMaxImageSide = 8192;

// Reads the whole file ourselves (instead of cv::imread) so that "missing" and "not an image"
// get distinct messages, OpenCV never logs warnings about the path, and a device or a pipe
// (/dev/zero) is refused instead of read forever.
std::vector<uchar> read_bytes(const std::string& path, const std::string& role) {
  try {
    const std::string bytes = read_regular_file(path, role, kMaxImageBytes);
    return {bytes.begin(), bytes.end()};
  } catch (const FileError& e) {
    throw InputError(e.what());
  } catch (const std::bad_alloc&) {  // under a memory limit: name the file, not std::bad_alloc
    throw InputError(fmt::format("{} {}: out of memory reading it", role, quoted(path)));
  }
}

void write_bytes(const std::string& path, const std::vector<uchar>& bytes) {
  try {
    write_file_atomically(path, std::string(bytes.begin(), bytes.end()));
  } catch (const FileError& e) {
    throw InputError(e.what());
  }
}

std::vector<uchar> encode_png(const cv::Mat& image) {
  std::vector<uchar> encoded;
  cv::imencode(".png", image, encoded);
  return encoded;
}

// Runs f with file descriptor 2 pointed at /dev/null: the codecs OpenCV uses (libpng's default
// handlers, libjpeg's) print their own lines about corrupt data on stderr, and ours must be the
// only one. Serialised, since the descriptor is the process's; other threads' stderr output is
// lost for the duration of one decode.
template <class F>
void without_stderr(F&& f) {
  static std::mutex mutex;
  std::lock_guard<std::mutex> lock(mutex);
  std::fflush(stderr);
  const int saved = ::dup(STDERR_FILENO);
  const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (saved >= 0 && null >= 0) ::dup2(null, STDERR_FILENO);
  if (null >= 0) ::close(null);
  const auto restore = [saved] {
    if (saved < 0) return;
    ::dup2(saved, STDERR_FILENO);
    ::close(saved);
  };
  try {
    f();
  } catch (...) {
    restore();
    throw;
  }
  restore();
}

bool is_space(uchar c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

// A PNM side of 13 digits or more, as stated_size reports it.
constexpr uint64_t kHugeSide = 1'000'000'000'000;
std::string side_text(uint64_t side) { return side >= kHugeSide ? "(13 digits or more)" : std::to_string(side); }

// The size a PNG, PNM (P1 .. P6) or JPEG header states, read before decoding so that a small
// file claiming a huge image costs nothing; nullopt for other formats or a header cut short.
std::optional<std::pair<uint64_t, uint64_t>> stated_size(const std::vector<uchar>& b) {
  const auto be = [&](size_t at, int n) {
    uint64_t v = 0;
    for (int i = 0; i < n; ++i) v = v << 8 | b[at + size_t(i)];
    return v;
  };
  static const uchar png[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (b.size() >= 24 && std::equal(png, png + 8, b.begin())) return std::pair{be(16, 4), be(20, 4)};
  if (b.size() >= 2 && b[0] == 'P' && b[1] >= '1' && b[1] <= '6') {
    size_t pos = 2;
    uint64_t side[2] = {0, 0};
    for (uint64_t& v : side) {
      while (pos < b.size() && (is_space(b[pos]) || b[pos] == '#'))  // comments run to the line's end
        if (b[pos] == '#')
          while (pos < b.size() && b[pos] != '\n') ++pos;
        else
          ++pos;
      // Every digit is read, so that the height starts after the whole width; a side of more than
      // 12 digits stays at kHugeSide.
      for (; pos < b.size() && std::isdigit(b[pos]); ++pos)
        v = std::min(kHugeSide, v * 10 + uint64_t(b[pos] - '0'));
    }
    return std::pair{side[0], side[1]};
  }
  if (b.size() >= 4 && b[0] == 0xFF && b[1] == 0xD8) {  // JPEG: walk the segments to a frame header
    for (size_t pos = 2; pos + 9 < b.size() && b[pos] == 0xFF;) {
      const uchar marker = b[pos + 1];
      if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC)
        return std::pair{be(pos + 7, 2), be(pos + 5, 2)};
      pos += 2 + size_t(be(pos + 2, 2));
    }
  }
  return std::nullopt;
}

cv::Mat decode(const std::vector<uchar>& bytes, const std::string& path, const std::string& role) {
  if (const auto size = stated_size(bytes); size && (size->first > kMaxImageSide || size->second > kMaxImageSide))
    throw InputError(fmt::format("{} {}: the header states {}x{} pixels, more than {} on a side", role, quoted(path),
                                 side_text(size->first), side_text(size->second), kMaxImageSide));
  cv::Mat image;
  try {
    if (!bytes.empty()) without_stderr([&] { image = cv::imdecode(bytes, cv::IMREAD_UNCHANGED); });
  } catch (const cv::Exception&) {
    image.release();  // a decoder that throws on corrupt data: same answer as one returning empty
  } catch (const std::bad_alloc&) {
    throw InputError(fmt::format("{} {}: out of memory decoding it", role, quoted(path)));
  }
  if (image.empty()) {
    // A decoder that runs out of memory returns nothing too: with a readable header, say both.
    const auto size = stated_size(bytes);
    throw InputError(size ? fmt::format("{} {}: not a decodable image (its header states {}x{} pixels: corrupt "
                                        "data, or out of memory decoding them)",
                                        role, quoted(path), size->first, size->second)
                          : fmt::format("{} {}: not a decodable image", role, quoted(path)));
  }
  return image;
}

std::string depth_text(int depth) {
  switch (depth) {
    case CV_8U:
    case CV_8S:
      return "8-bit";
    case CV_16U:
    case CV_16S:
      return "16-bit";
    case CV_32S:
      return "32-bit integer";
    case CV_16F:
      return "16-bit float";
    case CV_32F:
      return "32-bit float";
    default:
      return "64-bit float";
  }
}

// `what` names the image in messages: "left image 'a.png'".
cv::Mat1b to_gray(const cv::Mat& image, const std::string& what) {
  if (image.depth() != CV_8U)
    throw InputError(fmt::format("{}: {} image, expected 8-bit", what, depth_text(image.depth())));
  cv::Mat1b gray;
  switch (image.channels()) {
    case 1:
      gray = image;
      break;
    case 3:
      cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
      break;
    case 4:
      cv::cvtColor(image, gray, cv::COLOR_BGRA2GRAY);
      break;
    default:
      throw InputError(
          fmt::format("{}: {} channels, expected gray, colour or colour with alpha", what, image.channels()));
  }
  return gray;
}

// ---- PFM -------------------------------------------------------------------------------------


std::string next_token(const std::vector<uchar>& bytes, size_t& pos) {
  while (pos < bytes.size() && is_space(bytes[pos])) ++pos;
  std::string token;
  while (pos < bytes.size() && !is_space(bytes[pos]) && token.size() < 32) token += char(bytes[pos++]);
  return token;
}

bool has_pfm_magic(const std::vector<uchar>& bytes) {
  return bytes.size() >= 3 && bytes[0] == 'P' && (bytes[1] == 'f' || bytes[1] == 'F') && is_space(bytes[2]);
}

float decode_float(const uchar* p, bool little_endian) {
  const uint32_t bits =
      little_endian ? uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24
                    : uint32_t(p[3]) | uint32_t(p[2]) << 8 | uint32_t(p[1]) << 16 | uint32_t(p[0]) << 24;
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

int parse_dimension(const std::string& token, const std::string& path) {
  char* end = nullptr;
  const long v = std::strtol(token.c_str(), &end, 10);
  if (token.empty() || *end != '\0' || v < 1 || uint64_t(v) > kMaxImageSide)
    throw InputError(fmt::format("PFM {}: bad image size {} in the header", quoted(path), quoted(token)));
  return int(v);
}

// Header "PF" (3 channels) or "Pf" (1), width, height, scale (negative: little-endian), then one
// whitespace byte and the raw floats, rows bottom to top. The scale's magnitude is not applied:
// stereo datasets leave it at 1 and give their own scale.
cv::Mat1f parse_pfm(const std::vector<uchar>& bytes, const std::string& path) {
  size_t pos = 0;
  const int channels = next_token(bytes, pos) == "PF" ? 3 : 1;
  const int width = parse_dimension(next_token(bytes, pos), path);
  const int height = parse_dimension(next_token(bytes, pos), path);
  const std::string scale_token = next_token(bytes, pos);
  char* end = nullptr;
  const double scale = std::strtod(scale_token.c_str(), &end);
  if (scale_token.empty() || *end != '\0' || scale == 0)
    throw InputError(fmt::format("PFM {}: bad scale {} in the header", quoted(path), quoted(scale_token)));
  ++pos;  // the single whitespace byte ending the header
  const size_t row_bytes = size_t(width) * size_t(channels) * 4;
  if (bytes.size() < pos + row_bytes * size_t(height))
    throw InputError(
        fmt::format("PFM {}: truncated, expected {}x{}x{} floats", quoted(path), width, height, channels));
  const bool little_endian = scale < 0;
  cv::Mat1f values(height, width);
  for (int file_row = 0; file_row < height; ++file_row) {
    const uchar* src = bytes.data() + pos + size_t(file_row) * row_bytes;
    float* dst = values[height - 1 - file_row];
    for (int x = 0; x < width; ++x)
      dst[x] = decode_float(src + size_t(x) * size_t(channels) * 4, little_endian);
  }
  return values;
}

void append_le_float(std::vector<uchar>& out, float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  for (int i = 0; i < 4; ++i) out.push_back(uchar(bits >> (8 * i)));
}

// ---- ground truth ----------------------------------------------------------------------------

// Non-finite values are dropped whatever the spec, so only "0" changes anything.
bool zero_means_invalid(const std::string& spec) {
  if (spec == "0") return true;
  if (spec == "inf" || spec == "none") return false;
  throw InputError(fmt::format("ground-truth invalid value {}: expected 0, inf or none", quoted(spec)));
}

cv::Mat1f stored_values(const std::vector<uchar>& bytes, const std::string& path) {
  if (has_pfm_magic(bytes)) return parse_pfm(bytes, path);
  const cv::Mat image = decode(bytes, path, "ground truth");
  if (image.channels() != 1)
    throw InputError(fmt::format("ground truth {}: {} channels, expected a single-channel image",
                                 quoted(path), image.channels()));
  if (image.depth() != CV_8U && image.depth() != CV_16U)
    throw InputError(fmt::format("ground truth {}: {} image, expected 8- or 16-bit", quoted(path),
                                 depth_text(image.depth())));
  cv::Mat1f values;
  image.convertTo(values, CV_32F);
  return values;
}

// ---- colour preview --------------------------------------------------------------------------

const cv::Scalar kLegendBackground(48, 48, 48);
const cv::Scalar kLegendText(255, 255, 255);
constexpr int kLegendWidth = 90;
constexpr int kMinCanvasHeight = 160;  // room for the legend under small images
constexpr int kMargin = 10;
constexpr int kBarLeft = 8, kBarWidth = 16, kLabelLeft = 30;
constexpr int kSwatchHeight = 14;
constexpr double kFontScale = 0.4;

void put_label(cv::Mat3b& panel, const std::string& text, int x, int y_centre) {
  cv::putText(panel, text, {x, y_centre + 4}, cv::FONT_HERSHEY_SIMPLEX, kFontScale, kLegendText, 1,
              cv::LINE_AA);
}

cv::Mat3b turbo(const cv::Mat1b& levels) {
  cv::Mat3b colour;
  cv::applyColorMap(levels, colour, cv::COLORMAP_TURBO);
  return colour;
}

cv::Mat3b colourise(const cv::Mat1f& disp, float min_disp, float max_disp) {
  cv::Mat1b levels(disp.size()), invalid(disp.size());
  for (int y = 0; y < disp.rows; ++y)
    for (int x = 0; x < disp.cols; ++x) {
      const float d = disp(y, x);
      invalid(y, x) = std::isfinite(d) ? 0 : 255;
      levels(y, x) = std::isfinite(d) ? cv::saturate_cast<uchar>((d - min_disp) / (max_disp - min_disp) * 255.0f) : 0;
    }
  cv::Mat3b colour = turbo(levels);
  colour.setTo(cv::Scalar::all(0), invalid);
  return colour;
}

// Vertical colour bar (max at the top), five labelled ticks, and a black "invalid" swatch.
void draw_legend(cv::Mat3b panel, float min_disp, float max_disp) {
  panel.setTo(kLegendBackground);
  const int bar_top = kMargin;
  const int swatch_top = panel.rows - kMargin - kSwatchHeight;
  const int bar_height = swatch_top - kMargin - bar_top;
  cv::Mat1b ramp(bar_height, kBarWidth);
  for (int i = 0; i < bar_height; ++i) ramp.row(i).setTo(255 * (bar_height - 1 - i) / (bar_height - 1));
  turbo(ramp).copyTo(panel(cv::Rect(kBarLeft, bar_top, kBarWidth, bar_height)));
  const char* format = max_disp - min_disp >= 20 ? "{:.0f}" : "{:.1f}";
  for (int i = 0; i <= 4; ++i) {
    const int y = bar_top + (bar_height - 1) * (4 - i) / 4;
    cv::line(panel, {kBarLeft + kBarWidth, y}, {kBarLeft + kBarWidth + 3, y}, kLegendText);
    put_label(panel, fmt::format(fmt::runtime(format), min_disp + (max_disp - min_disp) * float(i) / 4), kLabelLeft, y);
  }
  const cv::Rect swatch(kBarLeft, swatch_top, kBarWidth, kSwatchHeight);
  panel(swatch).setTo(cv::Scalar::all(0));
  cv::rectangle(panel, swatch, cv::Scalar::all(160));  // outline: black on dark gray needs one
  put_label(panel, "invalid", kLabelLeft, swatch_top + kSwatchHeight / 2);
}

}  // namespace

GrayImage upscale(const GrayImage& image, int factor) {
  const cv::Mat1b in(image.height, image.width, const_cast<uint8_t*>(&image.at(0, 0)));
  cv::Mat1b out;
  cv::resize(in, out, cv::Size(), factor, factor, cv::INTER_LINEAR);
  GrayImage result(out.cols, out.rows);
  for (int y = 0; y < out.rows; ++y) std::copy(out[y], out[y] + out.cols, &result.at(0, y));
  return result;
}

void start_image_codecs() {
  try {
    without_stderr([] { (void)cv::haveImageReader(""); });
  } catch (...) {
    // Not built: the first decode builds it and reports what fails there.
  }
}

GrayImage load_gray(const std::string& path, const std::string& role) {
  try {
    return to_gray_image(decode(read_bytes(path, role), path, role), role + " " + quoted(path));
  } catch (const InputError&) {
    throw;
  } catch (const std::bad_alloc&) {  // converting it to gray, after the decoder's own allocations
    throw InputError(fmt::format("{} {}: out of memory loading it", role, quoted(path)));
  } catch (const std::exception& e) {  // e.g. no thread for OpenCV's conversion under a resource limit
    throw InputError(fmt::format("{} {}: {} while loading it", role, quoted(path), e.what()));
  }
}

GrayImage to_gray_image(const cv::Mat& decoded, const std::string& what) {
  const cv::Mat1b gray = to_gray(decoded, what);
  GrayImage image(gray.cols, gray.rows);
  for (int y = 0; y < gray.rows; ++y) std::copy(gray[y], gray[y] + gray.cols, &image.at(0, y));
  return image;
}

void check_pair(const GrayImage& left, const GrayImage& right, const StereoConfig& cfg) {
  if (left.width != right.width || left.height != right.height)
    throw InputError(fmt::format("left image is {} but right image is {}: the two must be the same size",
                                 size_text(left.width, left.height), size_text(right.width, right.height)));
  if (left.width > cfg.width || left.height > cfg.height)
    throw InputError(
        fmt::format("images are {} but the configuration allows at most {} (raise --width/--height)",
                    size_text(left.width, left.height), size_text(cfg.width, cfg.height)));
}

cv::Mat1f to_float_disparity(const DisparityImage& words, const StereoConfig& cfg) {
  const uint16_t invalid = derive_widths(cfg).invalid_word;
  const float unit = 1.0f / float(1 << cfg.subpixel_bits);  // exact: a power of two
  cv::Mat1f disp(words.height, words.width);
  for (int y = 0; y < words.height; ++y)
    for (int x = 0; x < words.width; ++x) {
      const uint16_t w = words.at(x, y);
      disp(y, x) = w == invalid ? NAN : float(cfg.min_disp) + float(w) * unit;
    }
  return disp;
}

std::vector<uchar> encode_kitti_png(const cv::Mat1f& disp) {
  cv::Mat_<uint16_t> stored(disp.size());
  for (int y = 0; y < disp.rows; ++y)
    for (int x = 0; x < disp.cols; ++x) {
      const float d = disp(y, x);
      // 0 is the invalid code, so a valid disparity that would round to 0 is stored as 1.
      if (std::isfinite(d) && d < 0)
        throw InputError(fmt::format("a KITTI PNG cannot hold the negative disparity {} at ({}, {}): write a PFM",
                                     d, x, y));
      const long word = std::isfinite(d) ? std::max(std::lround(d * 256.0f), 1L) : 0;
      if (word > 65535)
        throw InputError(fmt::format(
            "a KITTI PNG cannot hold the disparity {} at ({}, {}) (at most 255.996): write a PFM", d, x, y));
      stored(y, x) = uint16_t(word);
    }
  return encode_png(stored);
}

std::vector<uchar> encode_pgm(const GrayImage& image) {
  const std::string header = fmt::format("P5\n{} {}\n255\n", image.width, image.height);
  std::vector<uchar> bytes(header.begin(), header.end());
  bytes.insert(bytes.end(), image.pixels.begin(), image.pixels.end());
  return bytes;
}

std::vector<uchar> encode_gray_png(const DisparityImage& values) {
  cv::Mat1b stored(values.height, values.width);
  for (int y = 0; y < values.height; ++y)
    for (int x = 0; x < values.width; ++x) stored(y, x) = uchar(std::min<int>(values.at(x, y), 255));
  return encode_png(stored);
}

std::vector<uchar> encode_pfm(const cv::Mat1f& disp) {
  const std::string header = fmt::format("Pf\n{} {}\n-1\n", disp.cols, disp.rows);
  std::vector<uchar> bytes(header.begin(), header.end());
  bytes.reserve(bytes.size() + disp.total() * 4);
  for (int y = disp.rows - 1; y >= 0; --y)
    for (int x = 0; x < disp.cols; ++x) {
      const float d = disp(y, x);
      append_le_float(bytes, std::isfinite(d) ? d : INFINITY);
    }
  return bytes;
}

std::vector<uchar> encode_colour_png(const cv::Mat1f& disp, float min_disp, float max_disp) {
  if (!(max_disp > min_disp)) throw InputError("colour map: the disparity range must not be empty");
  const cv::Mat3b colour = colourise(disp, min_disp, max_disp);
  cv::Mat3b canvas(std::max(disp.rows, kMinCanvasHeight), disp.cols + kLegendWidth);
  canvas.setTo(kLegendBackground);
  colour.copyTo(canvas(cv::Rect(0, 0, disp.cols, disp.rows)));
  draw_legend(canvas(cv::Rect(disp.cols, 0, kLegendWidth, canvas.rows)), min_disp, max_disp);
  return encode_png(canvas);
}

std::vector<uchar> encode_disparity_file(const std::string& path, const cv::Mat1f& disp) {
  return ends_with(path, ".pfm") ? encode_pfm(disp) : encode_kitti_png(disp);
}

void write_kitti_png(const cv::Mat1f& disp, const std::string& path) { write_bytes(path, encode_kitti_png(disp)); }
void write_pgm(const GrayImage& image, const std::string& path) { write_bytes(path, encode_pgm(image)); }
void write_pfm(const cv::Mat1f& disp, const std::string& path) { write_bytes(path, encode_pfm(disp)); }
void write_colour_png(const cv::Mat1f& disp, float min_disp, float max_disp, const std::string& path) {
  write_bytes(path, encode_colour_png(disp, min_disp, max_disp));
}

cv::Mat1f read_disparity(const std::string& path, double scale, const std::string& invalid_spec) {
  const bool zero_invalid = zero_means_invalid(invalid_spec);
  if (!(scale > 0))
    throw InputError(fmt::format("ground truth {}: scale {} must be positive", quoted(path), scale));
  cv::Mat1f disp = stored_values(read_bytes(path, "ground truth"), path);
  for (auto& v : disp) {
    const bool no_value = !std::isfinite(v) || (zero_invalid && v == 0);
    v = no_value ? NAN : float(v / scale);
  }
  return disp;
}

}  // namespace fpstereo
