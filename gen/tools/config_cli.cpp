#include "config_cli.hpp"

#include <iostream>

namespace fpstereo {

void ConfigFlags::add_to(CLI::App& app) {
  std::string presets;
  for (const auto& n : preset_names()) presets += (presets.empty() ? "" : ", ") + n;
  app.add_option("--preset", preset_, "start from a named configuration: " + presets);
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
  StereoConfig cfg = preset_.empty() ? StereoConfig{} : preset(preset_);
  if (!config_file_.empty()) apply_config_file(cfg, config_file_);
  for (const auto& [name, value] : values_) set_param(cfg, name, value);
  validate(cfg);
  return cfg;
}

int report_error(const std::string& tool, const std::string& message) {
  std::cerr << tool << ": " << message << "\n";
  return kExitBadInput;
}

int report_parse_error(CLI::App& app, const std::string& tool, const CLI::ParseError& e) {
  if (e.get_exit_code() == 0) return app.exit(e);
  return report_error(tool, std::string(e.what()) + " (see --help)");
}

}  // namespace fpstereo
