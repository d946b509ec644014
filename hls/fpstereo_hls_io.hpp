// File I/O shared by the generated C-simulation test bench and host program (not synthesised):
// 8-bit binary PGM images in, disparity words as PFM (the format `fpstereo run --pfm` writes:
// little-endian floats, rows bottom to top, +inf where invalid) in and out, and each output frame
// in the encoding of its plane.
#pragma once

#include <pthread.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fpstereo_hls_io {

// Bad input: the programs print "<tool>: <what()>" and exit with status 2.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Gray {
  int width = 0, height = 0;
  std::vector<unsigned char> pixels;
};
struct Words {
  int width = 0, height = 0;
  std::vector<unsigned short> words;  // output words: disparity, or the invalid word
};

inline std::string read_file(const std::string& path, const std::string& role) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(role + " '" + path + "': no such file or not readable");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// Header fields of a Netpbm-style file: whitespace-separated tokens, '#' comments.
class HeaderReader {
 public:
  HeaderReader(const std::string& bytes, const std::string& what) : bytes_(bytes), what_(what) {}
  std::string token() {
    for (;;) {
      while (pos_ < bytes_.size() && std::isspace((unsigned char)bytes_[pos_])) ++pos_;
      if (pos_ < bytes_.size() && bytes_[pos_] == '#')
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
      else
        break;
    }
    const size_t start = pos_;
    while (pos_ < bytes_.size() && !std::isspace((unsigned char)bytes_[pos_])) ++pos_;
    if (start == pos_) throw InputError(what_ + ": truncated header");
    return bytes_.substr(start, pos_ - start);
  }
  int positive(const char* field) {
    const std::string t = token();
    char* end = nullptr;
    const long v = std::strtol(t.c_str(), &end, 10);
    if (*end != '\0' || v <= 0 || v > 65535) throw InputError(what_ + ": bad " + field + " '" + t + "'");
    return int(v);
  }
  // The single whitespace byte after the header, then the raster.
  size_t data_start() const { return pos_ + 1; }

 private:
  const std::string& bytes_;
  std::string what_;
  size_t pos_ = 0;
};

inline Gray load_pgm(const std::string& path, const std::string& role) {
  const std::string bytes = read_file(path, role);
  const std::string what = role + " '" + path + "'";
  HeaderReader header(bytes, what);
  if (bytes.size() < 2 || header.token() != "P5")
    throw InputError(what + ": not a binary PGM (P5) image (`fpstereo run --gray-pgm` converts any format)");
  Gray img;
  img.width = header.positive("width");
  img.height = header.positive("height");
  if (header.positive("maxval") > 255) throw InputError(what + ": only 8-bit PGM images are supported");
  const size_t start = header.data_start(), size = size_t(img.width) * size_t(img.height);
  if (bytes.size() < start + size) throw InputError(what + ": truncated pixel data");
  img.pixels.assign(bytes.begin() + long(start), bytes.begin() + long(start + size));
  return img;
}

// Reads a PFM of disparity words: finite values less min_disp (the words count from it), times
// 2^fraction_bits (sub-pixel bits, exact in a float), must be integers 0 .. invalid_word - 1.
inline Words load_pfm_words(const std::string& path, const std::string& role, unsigned invalid_word,
                            int fraction_bits, int min_disp = 0) {
  const std::string bytes = read_file(path, role);
  const std::string what = role + " '" + path + "'";
  HeaderReader header(bytes, what);
  if (header.token() != "Pf") throw InputError(what + ": not a single-channel PFM");
  Words out;
  out.width = header.positive("width");
  out.height = header.positive("height");
  const double scale = std::atof(header.token().c_str());
  if (scale == 0) throw InputError(what + ": bad scale");
  const bool little_endian = scale < 0;
  const size_t start = header.data_start(), count = size_t(out.width) * size_t(out.height);
  if (bytes.size() < start + 4 * count) throw InputError(what + ": truncated data");
  out.words.resize(count);
  for (int row = 0; row < out.height; ++row)
    for (int x = 0; x < out.width; ++x) {
      unsigned char b[4];
      std::memcpy(b, bytes.data() + start + 4 * (size_t(row) * size_t(out.width) + size_t(x)), 4);
      const uint32_t bits =
          little_endian ? uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24
                        : uint32_t(b[3]) | uint32_t(b[2]) << 8 | uint32_t(b[1]) << 16 | uint32_t(b[0]) << 24;
      float v;
      std::memcpy(&v, &bits, 4);
      const int y = out.height - 1 - row;  // PFM rows run bottom to top
      unsigned short& w = out.words[size_t(y) * size_t(out.width) + size_t(x)];
      const float scaled = (v - float(min_disp)) * float(1 << fraction_bits);
      if (std::isinf(v)) {
        w = (unsigned short)invalid_word;
      } else if (scaled >= 0 && scaled < float(invalid_word) && scaled == std::floor(scaled)) {
        w = (unsigned short)scaled;
      } else {
        throw InputError(what + ": value " + std::to_string(v) + " at (" + std::to_string(x) + ", " +
                         std::to_string(y) + ") is not a disparity of this configuration");
      }
    }
  return out;
}

// Binary PGM, as fpstereo writes it (`P5`, the size, 255, the bytes).
inline void write_pgm(const Gray& image, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  out << "P5\n" << image.width << " " << image.height << "\n255\n";
  out.write(reinterpret_cast<const char*>(image.pixels.data()), std::streamsize(image.pixels.size()));
  if (!out) throw InputError("cannot write '" + path + "'");
}

// Writes the words as `fpstereo run --pfm` does: min_disp + w / 2^fraction_bits, +inf where invalid.
inline void write_pfm_words(const Words& words, unsigned invalid_word, int fraction_bits, const std::string& path,
                            int min_disp = 0) {
  std::ofstream out(path, std::ios::binary);
  out << "Pf\n" << words.width << " " << words.height << "\n-1\n";
  for (int y = words.height - 1; y >= 0; --y)
    for (int x = 0; x < words.width; ++x) {
      const unsigned w = words.words[size_t(y) * size_t(words.width) + size_t(x)];
      const float v = w == invalid_word ? INFINITY : float(min_disp) + float(w) / float(1 << fraction_bits);
      uint32_t bits;
      std::memcpy(&bits, &v, 4);
      const char b[4] = {char(bits), char(bits >> 8), char(bits >> 16), char(bits >> 24)};
      out.write(b, 4);
    }
  if (!out) throw InputError("cannot write '" + path + "'");
}

// How an output frame is stored in a file, as `fpstereo run` writes its plane (gen/core/outputs.hpp):
// output words as PFM (their fraction, +inf where invalid), whole disparities as PFM, levels
// 0 .. 255 as binary PGM.
enum class Encoding { Disparities, WholeDisparities, Levels };

// One of the kernel's output frames: its name (the memory-mapped kernel's argument), the
// `fpstereo run` option that writes the same plane (the test bench reads its reference, the host
// program writes it, under that option; the words' file is given by position) and its encoding.
struct OutputFrame {
  const char* frame;
  const char* option;
  Encoding encoding;
};
inline const char* file_suffix(Encoding e) { return e == Encoding::Levels ? ".pgm" : ".pfm"; }

template <class Config>
Words load_frame(const std::string& path, const std::string& role, Encoding e) {
  if (e == Encoding::Disparities)
    return load_pfm_words(path, role, Config::kInvalidWord, Config::kSubpixelBits, Config::kMinDisp);
  if (e == Encoding::WholeDisparities) return load_pfm_words(path, role, Config::kInvalidWord, 0, Config::kMinDisp);
  const Gray levels = load_pgm(path, role);
  return Words{levels.width, levels.height, std::vector<unsigned short>(levels.pixels.begin(), levels.pixels.end())};
}

template <class Config>
void write_frame(const Words& words, Encoding e, const std::string& path) {
  if (e == Encoding::Disparities)
    return write_pfm_words(words, Config::kInvalidWord, Config::kSubpixelBits, path, Config::kMinDisp);
  if (e == Encoding::WholeDisparities) return write_pfm_words(words, Config::kInvalidWord, 0, path, Config::kMinDisp);
  Gray levels{words.width, words.height, std::vector<unsigned char>(words.words.size())};
  for (size_t i = 0; i < words.words.size(); ++i) levels.pixels[i] = (unsigned char)words.words[i];
  write_pgm(levels, path);
}

// The C-simulated kernel keeps its line buffers and path-cost rows on the stack, as many
// megabytes as the configured frame needs: run it on a thread with a large stack.
inline void run_with_large_stack(const std::function<void()>& body) {
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_attr_setstacksize(&attr, size_t(1) << 30);
  pthread_t thread;
  auto trampoline = [](void* arg) -> void* {
    (*static_cast<const std::function<void()>*>(arg))();
    return nullptr;
  };
  if (pthread_create(&thread, &attr, trampoline, const_cast<std::function<void()>*>(&body)) != 0)
    body();
  else
    pthread_join(thread, nullptr);
  pthread_attr_destroy(&attr);
}

}  // namespace fpstereo_hls_io
