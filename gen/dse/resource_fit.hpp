// The Yosys results the fast resource model is fitted to and checked on: the configuration list
// (bench/resource_fit_configs.txt: "name role --flag value ..."), the results
// (bench/resource_fit_data.csv, one row per configuration with the hash of the Verilog Yosys ran
// on), the fit, the errors, and the generated gen/dse/resource_coefficients.inc. bench_resource_model
// collects and refits; the tests check that the committed coefficients are this fit of the data.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "resource_model.hpp"

namespace fpstereo::dse {

struct YosysRow {
  std::string name, role, flags;  // role: "fit" or "heldout"
  StereoConfig cfg;
  double lut = 0, ff = 0, dsp = 0, bram36_equiv = 0, seconds = 0;
  int64_t bram18 = 0, bram36 = 0;
  std::string memories;      // name=words x bits:target;...
  std::string verilog_hash;  // of the Verilog Yosys ran on (empty: not recorded)
  bool have_yosys = false;
};

// The configuration list, without results; throws std::runtime_error or ConfigError.
std::vector<YosysRow> read_fit_configs(const std::string& path);
// Fills the rows' results from the CSV (a missing file leaves them empty).
void read_fit_data(const std::string& path, std::vector<YosysRow>& rows);
void write_fit_data(const std::string& path, const std::vector<YosysRow>& rows);

// A result is stale once the generator emits other Verilog for its configuration (or it records
// no hash).
bool is_stale(const YosysRow& row);

// LUT, FF and DSP coefficients fitted on the "fit" rows with results.
Coefficients refit(const std::vector<YosysRow>& rows);
// The model's errors against Yosys on the rows of one role.
ErrorSummary summarise(const std::vector<YosysRow>& rows, const std::string& role, const Coefficients& c);
// gen/dse/resource_coefficients.inc for these rows and coefficients.
std::string coefficients_source(const std::vector<YosysRow>& rows, const Coefficients& c);

}  // namespace fpstereo::dse
