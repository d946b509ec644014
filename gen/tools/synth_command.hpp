// `fpstereo synth`: synthesises a configuration's Verilog with Yosys (scripts/synth-yosys.sh) and
// reports its resources on one part, caching the result so design-space sweeps pay for each
// design once.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "config.hpp"
#include "logic_depth.hpp"

namespace fpstereo {

// A failed synthesis step (script missing or failing, unwritable cache); what() is one line.
class SynthError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One memory of the design as Yosys saw it before mapping, and what it became.
struct SynthMemory {
  std::string name;    // hierarchical, e.g. "core.cost_ram.mem"
  int64_t words = 0;   // 0 when Yosys did not list its shape
  int64_t bits = 0;    // word width
  std::string target;  // "bram", "lutram", "uram", "ff" or "removed"
};

// The figures of one synth-yosys.sh --kv run (key names in the comments where they differ).
struct SynthReport {
  std::string config;  // configuration tag; empty when the text came straight from the script
  std::string top, family, part;
  bool hierarchical = false;  // mapped module by module, then flattened (--hierarchical)
  int64_t lut = 0, lut_min = 0, lutram = 0, lut_total = 0, ff = 0, latches = 0;
  int64_t bram18 = 0, bram36 = 0, uram = 0, dsp = 0, carry4 = 0, carry8 = 0, carry4_equiv = 0;
  double bram36_equiv = 0;    // BRAM36 + BRAM18 / 2
  std::string lut_by_inputs;  // LUT1/.../LUT6 cell counts
  std::string lutram_cells;   // e.g. "RAM64M8x3 SRL16Ex2"
  // Percent of the part, as the script rounds them (one decimal).
  double lut_pct = 0, lut_min_pct = 0, lutram_pct = 0, lut_total_pct = 0, ff_pct = 0;
  double bram18_pct = 0, bram36_pct = 0, bram36_equiv_pct = 0, uram_pct = 0, dsp_pct = 0, carry_pct = 0;
  // abc9's logic delay and depth of the worst path; empty when abc9 did not run ("na").
  std::optional<int64_t> delay_ps, levels, levels_with_carry;
  // Register-to-register depth of the mapped netlist (logic_depth.hpp; depth_levels,
  // depth_levels_with_carry, path.N, carry_path); empty when not analysed.
  std::optional<int64_t> depth_levels, depth_levels_with_carry;
  std::vector<LogicPath> worst_paths;  // deepest first, one per end register
  std::optional<LogicPath> worst_carry_path;
  int64_t part_lut = 0, part_ff = 0, part_bram36 = 0, part_dsp = 0, part_lutram = 0, part_uram = 0;
  std::vector<SynthMemory> memories;
  std::vector<std::string> warnings;    // the script's warnings, without its "synth-yosys: " prefix
  std::optional<double> synth_seconds;  // wall time of the Yosys run, when recorded
};

// Parses key=value lines (synth-yosys.sh --kv output or a cache record). Unknown keys are
// ignored so a newer script still parses. Throws SynthError naming a missing or malformed key.
SynthReport parse_kv(const std::string& text);

// The hash (16 hex digits) of the Verilog the generator emits for cfg, the files synth
// synthesises, without their comments and module prefix: a recorded Yosys result is current only
// while its hash matches.
std::string verilog_hash(const StereoConfig& cfg);

// The human-readable table: every resource with its share of the part, the abc9 delay and
// levels, the netlist's logic depth and deepest paths, and the memories with what they were
// mapped to.
std::string format_report(const SynthReport& report, bool cached);

// The cache file's stem: readable (tag, family, part, "-uram" with UltraRAM, "-hierarchical") plus
// a hash of everything that decides the result, so a changed generator, script or part table never
// serves a stale report. Empty family or part means the script's default.
std::string cache_key(const StereoConfig& cfg, const std::string& family, const std::string& part, bool uram,
                      bool hierarchical, const std::string& verilog_text, const std::string& script_text);

// scripts/synth-yosys.sh in the source tree, which synth runs.
std::filesystem::path synth_script_path();

// Runs a command (e.g. another `fpstereo synth`, args[0] searched in PATH) in its own process
// group, which gets every signal this process gets: a run interrupted ends the child too. Returns
// its standard output; throws SynthError with the last line of its stderr when it fails.
std::string run_child_command(const std::vector<std::string>& args);

// Adds the `synth` subcommand to `app`. Its callback runs during app.parse() and sets exit_code:
// 0 on success, kExitBadInput (2) after one line "fpstereo: <message>" on stderr.
void register_synth_command(CLI::App& app, int& exit_code);

}  // namespace fpstereo
