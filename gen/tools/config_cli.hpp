// Binds every StereoConfig parameter to command-line flags (same names as config-file keys),
// plus --preset and --config. Shared by every fpstereo command-line tool.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>

#include "config.hpp"

namespace fpstereo {

class ConfigFlags {
 public:
  // Adds --preset, --config and one --NAME flag per parameter to `app`.
  void add_to(CLI::App& app);
  // Preset first, then the config file, then explicit flags; validates the result.
  // Throws ConfigError.
  StereoConfig resolve() const;

 private:
  std::string preset_;
  std::string config_file_;
  std::map<std::string, std::string> values_;  // flags given on the command line
};

// Prints "fpstereo: <message>" to stderr; the exit status for bad input.
constexpr int kExitBadInput = 2;
int report_error(const std::string& tool, const std::string& message);
// A command-line parse error: --help prints and exits 0; anything else is one line,
// "<tool>: <message> (see --help)", and kExitBadInput.
int report_parse_error(CLI::App& app, const std::string& tool, const CLI::ParseError& e);

}  // namespace fpstereo
