// Binds every StereoConfig parameter to command-line flags (same names as config-file keys),
// plus --preset and --config. Shared by every fpstereo command-line tool.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <optional>
#include <string>

#include "config.hpp"
#include "files.hpp"

namespace fpstereo {

class ConfigFlags {
 public:
  // Adds --preset, --config and one --NAME flag per parameter to `app`.
  void add_to(CLI::App& app);
  // Preset first, then the config file, then explicit flags; validates the result.
  // Throws ConfigError.
  StereoConfig resolve() const;
  // Declares the --config file, if any, as an input of `outputs` (an output must not replace it).
  void declare_input(OutputSet& outputs) const;

 private:
  std::optional<std::string> preset_;
  std::string config_file_;
  std::map<std::string, std::string> values_;  // flags given on the command line
};

// The check of an output file option: an empty name (an unset shell variable, say) is refused
// ("--pfm: an empty file name"), not taken as no output at all.
CLI::Validator output_file_name();

// The check of a number option: a plain decimal ("300", "2.5e2"), as the parameter table and
// pairs.csv take them; hexadecimal, "inf" and "nan" are refused, not read by strtod's rules.
CLI::Validator decimal_number();

// The target clock of --clock-mhz: throws ConfigError unless 1 .. 1000 MHz (NaN and infinity
// included), so that periods and frame rates stay numbers every reader takes.
void check_clock_mhz(double clock_mhz);

// Prints "fpstereo: <message>" to stderr as one line (control characters escaped); the exit
// status for bad input.
constexpr int kExitBadInput = 2;
// --jobs (golden-model threads): more than this only contend for the cores (and may not start).
constexpr int kMaxJobs = 256;
int report_error(const std::string& tool, const std::string& message);
// A command-line parse error: --help prints and exits 0; anything else is one line,
// "<tool>: <message> (see --help)", and kExitBadInput.
int report_parse_error(CLI::App& app, const std::string& tool, const CLI::ParseError& e);
// Every tool's last step: flushes standard output and checks it, so output that did not arrive
// (a full disk, /dev/full) is never a success. Returns exit_code, or reports the write error as
// one line and returns kExitBadInput.
int finish_stdout(const std::string& tool, int exit_code);
// "<tool>: cannot write to standard output: <strerror(error)>" (no reason when error is 0); returns 2.
int report_stdout_error(const std::string& tool, int error);

}  // namespace fpstereo
