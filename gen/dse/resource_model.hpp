// The fast resource model of `fpstereo dse`: block RAM exactly as Yosys 0.23 maps the design's
// memories (memory_libmap's cost rules for UltraScale+), LUT, FF and DSP as closed forms in the
// configuration's derived widths with coefficients fitted against Yosys (bench/resource_fit_data.csv,
// refitted by bench_resource_model --refit), and throughput from rtl::plan's cycles per frame.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "config.hpp"
#include "rtl_emitter.hpp"

namespace fpstereo::dse {

// One memory of the emitted design, as Yosys names and sizes it before mapping
// ("core.cost_reorder.cost_ram.mem", words x bits), and what memory_libmap makes of it.
struct MemoryEstimate {
  std::string name;
  int64_t words = 0, bits = 0;
  bool sync_read = true;  // fpstereo_ram_sdp; fpstereo_ram_async can only become LUTRAM
  std::string target;     // "bram", "lutram" or "ff"
  int bram18 = 0, bram36 = 0;
  // Bits of the read multiplexer over the cells a split depth needs: (cells deep - 1) x bits.
  int64_t read_mux_bits = 0;
};

// The memories of a design: its stages' (gen/pipeline/stage.hpp), in data order.
std::vector<MemoryEstimate> design_memories(const rtl::RtlDesign& design);

// memory_libmap's choice for one words x bits memory with one write and one registered read port:
// fills target, bram18, bram36 and read_mux_bits.
void map_memory(MemoryEstimate& memory);

// The closed-form terms LUT and FF are linear in; names for the fit's report.
const std::vector<std::string>& feature_names();
std::vector<double> features(const rtl::RtlDesign& design);
// How the fit ties the terms together: each term enters one group's feature with a weight (a
// group and weight for LUT, another for FF), and the fit finds one coefficient per group and
// resource; a term's coefficient is its group's times its weight.
struct TermTie {
  int lut_group, ff_group;
  double lut_weight, ff_weight;
};
const std::vector<TermTie>& term_ties();
const std::vector<std::string>& group_names();
const std::vector<std::string>& dsp_feature_names();
std::vector<double> dsp_features(const rtl::RtlDesign& design);

struct Coefficients {
  std::vector<double> lut, ff, dsp;
};
// The committed fit (gen/dse/resource_coefficients.inc).
const Coefficients& fitted_coefficients();

// How far the model is from Yosys over a set of designs: |error| in percent of Yosys' figure.
struct ErrorSummary {
  int designs = 0, bram_exact = 0;  // BRAM exact: the RAMB18 and RAMB36 counts both equal
  double lut_mean = 0, lut_max = 0, ff_mean = 0, ff_max = 0;
};
// A Yosys result behind the committed fit: the configuration (fpstereo flags), whether the fit used
// it ("fit") or only checked it ("heldout"), and the hash of the Verilog Yosys ran on.
struct FitRecord {
  const char* name;
  const char* role;
  const char* flags;
  const char* verilog_hash;
};
// What the committed coefficients came from, written with them by bench_resource_model --refit:
// the records and the held-out designs' errors at that time.
struct FitProvenance {
  std::vector<FitRecord> records;
  ErrorSummary heldout;
};
const FitProvenance& fit_provenance();
// A configuration from fpstereo flags ("--cost census --dmax 64 ..."); throws ConfigError.
StereoConfig config_from_flags(const std::string& flags);
// The records whose Verilog the generator no longer emits (emits every recorded design once).
std::vector<std::string> stale_records(const FitProvenance& provenance = fit_provenance());
// One paragraph for the DSE's reports: which figures are the model's, its held-out errors against
// Yosys, and the stale records if there are any.
std::string model_note(const FitProvenance& provenance = fit_provenance());

struct ResourceEstimate {
  double lut = 0, ff = 0, dsp = 0;
  int bram18 = 0, bram36 = 0;
  double bram36_equiv() const { return bram36 + 0.5 * bram18; }
  std::vector<MemoryEstimate> memories;
};

ResourceEstimate estimate(const rtl::RtlDesign& design, const Coefficients& c = fitted_coefficients());
ResourceEstimate estimate(const StereoConfig& cfg);

// Frames per second at a clock, from rtl::plan's exact cycles per frame.
double frames_per_second(const rtl::RtlDesign& design, double clock_mhz);

// Weighted non-negative least squares: the x >= 0 minimising sum_i w_i (a_i . x - b_i)^2
// (Lawson-Hanson). Non-negative because every term adds hardware.
std::vector<double> fit_nonnegative(const std::vector<std::vector<double>>& a, const std::vector<double>& b,
                                    const std::vector<double>& weights);

}  // namespace fpstereo::dse
