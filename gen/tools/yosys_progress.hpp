// On a terminal, `fpstereo synth` shows the Yosys pass that runs (half an hour at 4K), read from
// Yosys' log as it grows. In scripts nothing of this is shown.
#pragma once

#include <chrono>
#include <filesystem>
#include <string>

namespace fpstereo {

class YosysProgress {
 public:
  // `label` opens the line, e.g. "fpstereo synth: fps_census7_d128u32_1a2b3c".
  YosysProgress(std::filesystem::path log, std::string label);
  // Reads what the log gained and redraws the line: the label, the seconds so far, the last pass.
  void update();
  // Clears the line.
  void finish();

 private:
  std::filesystem::path log_;
  std::string label_;
  std::chrono::steady_clock::time_point start_;
  size_t read_ = 0;     // bytes of the log already read
  std::string partial_;  // a line not yet complete
  std::string pass_;
};

}  // namespace fpstereo
