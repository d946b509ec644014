#include "config_cli.hpp"

#include <fmt/core.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "text.hpp"

namespace fpstereo {

void ConfigFlags::add_to(CLI::App& app) {
  std::string presets;
  for (const auto& n : preset_names()) presets += (presets.empty() ? "" : ", ") + n;
  app.add_option_function<std::string>(
      "--preset", [this](const std::string& v) { preset_ = v; }, "start from a named configuration: " + presets);
  app.add_option("--config", config_file_, "JSON or TOML file with parameter names as keys");
  for (const auto& spec : param_specs()) {
    const StereoConfig defaults;
    app.add_option_function<std::string>(
           "--" + spec.name, [this, name = spec.name](const std::string& v) { values_[name] = v; },
           spec.help + " [C2: " + spec.get(defaults) + "]")
        ->group("Pipeline parameters");
  }
}

StereoConfig ConfigFlags::resolve() const {
  StereoConfig cfg = compose_config(preset_, config_file_, values_);
  validate(cfg);
  return cfg;
}

void check_clock_mhz(double clock_mhz) {
  if (!(clock_mhz >= 1 && clock_mhz <= 1000))
    throw ConfigError(fmt::format("clock-mhz = {}: expected a positive frequency, 1 .. 1000 MHz", clock_mhz));
}

void ConfigFlags::declare_input(OutputSet& outputs) const {
  if (!config_file_.empty()) outputs.add_input(config_file_, "config file");
}

int report_error(const std::string& tool, const std::string& message) {
  // Any message, from any exception, with any input in it: one line.
  std::cerr << tool << ": " << one_line(message) << "\n";
  return kExitBadInput;
}

int report_parse_error(CLI::App& app, const std::string& tool, const CLI::ParseError& e) {
  if (e.get_exit_code() == 0) return finish_stdout(tool, app.exit(e));
  return report_error(tool, std::string(e.what()) + " (see --help)");
}

}  // namespace fpstereo

namespace fpstereo {

CLI::Validator output_file_name() {
  return CLI::Validator([](std::string& name) { return name.empty() ? std::string("an empty file name") : std::string(); },
                        "");
}

CLI::Validator decimal_number() {
  return CLI::Validator(
      [](std::string& text) { return parse_decimal(text) ? std::string() : quoted(text) + " is not a decimal number"; },
      "");
}

int report_stdout_error(const std::string& tool, int error) {
  return report_error(tool, std::string("cannot write to standard output") +
                                (error ? std::string(": ") + std::strerror(error) : std::string()));
}

int finish_stdout(const std::string& tool, int exit_code) {
  errno = 0;
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (!failed) return exit_code;
  const int error = errno;
  std::clearerr(stdout);
  return report_stdout_error(tool, error);
}

}  // namespace fpstereo
