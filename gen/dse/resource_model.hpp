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
};

// The memories of a design: its stages' (gen/pipeline/stage.hpp), in data order.
std::vector<MemoryEstimate> design_memories(const rtl::RtlDesign& design);

// memory_libmap's choice for one words x bits memory with one write and one registered read port:
// fills target, bram18 and bram36.
void map_memory(MemoryEstimate& memory);

// The closed-form terms LUT and FF are linear in; names for the fit's report.
const std::vector<std::string>& feature_names();
std::vector<double> features(const rtl::RtlDesign& design);
const std::vector<std::string>& dsp_feature_names();
std::vector<double> dsp_features(const rtl::RtlDesign& design);

struct Coefficients {
  std::vector<double> lut, ff, dsp;
};
// The committed fit (gen/dse/resource_coefficients.inc).
const Coefficients& fitted_coefficients();

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
