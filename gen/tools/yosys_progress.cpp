#include "yosys_progress.hpp"

#include <fmt/core.h>

#include <fstream>
#include <iostream>
#include <regex>

namespace fpstereo {

namespace {
// The line of a terminal the progress keeps to, so that it redraws in place.
constexpr size_t kLineWidth = 100;
}  // namespace

YosysProgress::YosysProgress(std::filesystem::path log, std::string label)
    : log_(std::move(log)), label_(std::move(label)), start_(std::chrono::steady_clock::now()) {}

void YosysProgress::update() {
  std::ifstream in(log_, std::ios::binary);
  if (in) {
    in.seekg(std::streamoff(read_));
    std::string chunk((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    read_ += chunk.size();
    partial_ += chunk;
    // Yosys numbers its passes, the steps of a script nested under it: "4.12. Executing ABC9 pass."
    // The number stays in the line: how far into the script the run is.
    static const std::regex pass(R"(^([0-9.]+) Executing (.*?)\.?$)");
    std::smatch m;
    for (size_t end; (end = partial_.find('\n')) != std::string::npos; partial_.erase(0, end + 1)) {
      const std::string line = partial_.substr(0, end);
      if (std::regex_match(line, m, pass)) pass_ = m[1].str() + " " + m[2].str();
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string text = fmt::format("{}: Yosys {:.0f} s{}{}", label_, seconds, pass_.empty() ? "" : ": ", pass_);
  if (text.size() > kLineWidth) text.resize(kLineWidth);
  std::cerr << "\r\033[K" << text << std::flush;
}

void YosysProgress::finish() { std::cerr << "\r\033[K" << std::flush; }

}  // namespace fpstereo
