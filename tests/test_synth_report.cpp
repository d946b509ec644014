// `fpstereo synth` without Yosys: parsing the script's key=value report, the table printed from it,
// the cache key and the part table (tests/synth_smoke.cmake runs the command end to end).
#include <catch2/catch.hpp>
#include <cstdio>
#include <string>

#include "fpga_parts.hpp"
#include "synth_command.hpp"

namespace fpstereo {
namespace {

// Verbatim output of `scripts/synth-yosys.sh --kv --part xczu7ev --uram` (Yosys 0.23) on the
// Verilog of `--width 2048 --height 8 --dmax 16 --uf 16 --window 3 --median 0 --paths 0,90`.
const std::string kScriptKv = R"(top=fps_census3_d16u16_0a920b_top
family=xcup
part=xczu7ev
lut=3672
lut_pct=1.6
lut_by_inputs=68/666/925/612/914/487
lut_min=2080
lut_min_pct=0.9
lutram=196
lutram_pct=0.2
lutram_cells=RAM32M16x9 SRL16Ex124
lut_total=3868
lut_total_pct=1.7
ff=2659
ff_pct=0.6
latches=0
bram18=11
bram18_pct=1.8
bram36=1
bram36_pct=0.3
bram36_equiv=6.5
bram36_equiv_pct=2.1
uram=3
uram_pct=3.1
dsp=5
dsp_pct=0.3
carry4=536
carry8=0
carry4_equiv=536
carry_pct=0.9
delay_ps=4146
levels=6
levels_with_carry=9
abc9_runs=1
part_lut=230400
part_ff=460800
part_bram36=312
part_dsp=1728
part_lutram=101760
part_uram=96
mem.core.aggregation.path0.minimum=5x7:lutram
mem.core.aggregation.path0.state.mem=5x112:lutram
mem.core.aggregation.vertical[0].path.row.mem=2049x112:uram
mem.core.aggregation.vertical[0].path.row_min.mem=2049x7:bram
mem.core.cost_reorder.code_ram.mem=10250x16:uram
mem.core.disparity_reorder.disp_ram.mem=12300x5:bram
mem.core.front_end.left_window.line_buffer.mem=2050x16:bram
mem.core.front_end.right_window.line_buffer.mem=2050x16:bram
)";

// Replaces the line "key=..." of a kv text (the key at a line start: "part_lut=" is not "lut=").
std::string with_line(std::string text, const std::string& key, const std::string& value) {
  const size_t found = text.find("\n" + key + "=");
  REQUIRE(found != std::string::npos);
  const size_t start = found + 1;
  return text.replace(start, text.find('\n', start) - start, key + "=" + value);
}

StereoConfig tiny_config() {
  StereoConfig cfg;
  cfg.width = 32;
  cfg.height = 8;
  cfg.dmax = 16;
  cfg.uf = 16;
  cfg.window = 3;
  cfg.median = 0;
  cfg.paths = kPath0;
  return cfg;
}

TEST_CASE("parse_kv reads every figure of a real synth-yosys.sh report", "[synth]") {
  const SynthReport r = parse_kv(kScriptKv);
  CHECK(r.top == "fps_census3_d16u16_0a920b_top");
  CHECK(r.family == "xcup");
  CHECK(r.part == "xczu7ev");
  CHECK(r.config.empty());
  CHECK(r.lut == 3672);
  CHECK(r.lut_min == 2080);
  CHECK(r.lut_by_inputs == "68/666/925/612/914/487");
  CHECK(r.lutram == 196);
  CHECK(r.lutram_cells == "RAM32M16x9 SRL16Ex124");
  CHECK(r.lut_total == 3868);
  CHECK(r.ff == 2659);
  CHECK(r.latches == 0);
  CHECK(r.bram18 == 11);
  CHECK(r.bram36 == 1);
  CHECK(r.bram36_equiv == 6.5);
  CHECK(r.uram == 3);
  CHECK(r.dsp == 5);
  CHECK(r.carry4 == 536);
  CHECK(r.carry8 == 0);
  CHECK(r.carry4_equiv == 536);
  CHECK(r.delay_ps == 4146);
  CHECK(r.levels == 6);
  CHECK(r.levels_with_carry == 9);
  CHECK(r.part_lut == 230400);
  CHECK(r.part_ff == 460800);
  CHECK(r.part_bram36 == 312);
  CHECK(r.part_dsp == 1728);
  CHECK(r.part_lutram == 101760);
  CHECK(r.part_uram == 96);
  CHECK(r.lut_pct == Approx(1.6));
  CHECK(r.lut_min_pct == Approx(0.9));
  CHECK(r.lutram_pct == Approx(0.2));
  CHECK(r.lut_total_pct == Approx(1.7));
  CHECK(r.ff_pct == Approx(0.6));
  CHECK(r.bram36_pct == Approx(0.3));
  CHECK(r.bram36_equiv_pct == Approx(2.1));
  CHECK(r.uram_pct == Approx(3.1));
  CHECK(r.carry_pct == Approx(0.9));
  CHECK_FALSE(r.synth_seconds.has_value());
  CHECK(r.warnings.empty());

  // In the script's order: memories before mapping, with the target each became.
  REQUIRE(r.memories.size() == 8);
  CHECK(r.memories[0].name == "core.aggregation.path0.minimum");
  CHECK(r.memories[0].words == 5);
  CHECK(r.memories[0].bits == 7);
  CHECK(r.memories[0].target == "lutram");
  CHECK(r.memories[2].name == "core.aggregation.vertical[0].path.row.mem");
  CHECK(r.memories[2].words == 2049);
  CHECK(r.memories[2].bits == 112);
  CHECK(r.memories[2].target == "uram");
  CHECK(r.memories[3].target == "bram");
  CHECK(r.memories[7].name == "core.front_end.right_window.line_buffer.mem");
}

TEST_CASE("parse_kv reads a cache record's own lines and the script's special values", "[synth]") {
  std::string record = "config=fps_census3_d16u16_0a920b\n" + kScriptKv +
                       "mem.core.extra=?:removed\n"
                       "synth_seconds=16.8\n"
                       "warning=memory core.big (512 x 16 = 8192 bits) became LUTRAM, not block RAM\n"
                       "some_future_key=ignored\n";
  record = with_line(record, "bram18", "3");
  record = with_line(record, "bram36_equiv", "2.5");
  record = with_line(record, "delay_ps", "na");
  record = with_line(record, "levels", "na");
  record = with_line(record, "levels_with_carry", "na");
  const SynthReport r = parse_kv(record);
  CHECK(r.config == "fps_census3_d16u16_0a920b");
  CHECK(r.bram18 == 3);
  CHECK(r.bram36_equiv == 2.5);
  CHECK_FALSE(r.delay_ps.has_value());
  CHECK_FALSE(r.levels.has_value());
  CHECK_FALSE(r.levels_with_carry.has_value());
  REQUIRE(r.synth_seconds.has_value());
  CHECK(*r.synth_seconds == Approx(16.8));
  REQUIRE(r.memories.size() == 9);
  CHECK(r.memories[8].name == "core.extra");
  CHECK(r.memories[8].words == 0);
  CHECK(r.memories[8].target == "removed");
  REQUIRE(r.warnings.size() == 1);
  CHECK(r.warnings[0] == "memory core.big (512 x 16 = 8192 bits) became LUTRAM, not block RAM");
}

TEST_CASE("parse_kv names what is missing or malformed", "[synth]") {
  CHECK_THROWS_WITH(parse_kv(with_line(kScriptKv, "lut", "many")), Catch::Contains("lut = 'many'"));
  CHECK_THROWS_WITH(parse_kv(with_line(kScriptKv, "ff", "")), Catch::Contains("ff = ''"));
  CHECK_THROWS_WITH(parse_kv(with_line(kScriptKv, "dsp_pct", "1.5%")), Catch::Contains("dsp_pct"));
  CHECK_THROWS_WITH(parse_kv(with_line(kScriptKv, "part_dsp", "na")), Catch::Contains("part_dsp"));
  CHECK_THROWS_WITH(parse_kv(kScriptKv + "mem.core.x=128:bram\n"), Catch::Contains("mem.core.x"));
  CHECK_THROWS_WITH(parse_kv(kScriptKv + "no equals sign\n"), Catch::Contains("malformed line"));
  CHECK_THROWS_WITH(parse_kv("yosys: command not found\n"), Catch::Contains("malformed"));
  std::string without_delay = kScriptKv;
  without_delay.erase(without_delay.find("\ndelay_ps="), std::string("\ndelay_ps=4146").size());
  CHECK_THROWS_AS(parse_kv(without_delay), SynthError);
  CHECK_THROWS_WITH(parse_kv(without_delay), Catch::Contains("lacks 'delay_ps'"));
}

TEST_CASE("format_report shows every figure with its share of the part", "[synth]") {
  const SynthReport r = parse_kv(kScriptKv);
  const std::string table = format_report(r, false);
  INFO(table);
  CHECK_THAT(table, Catch::StartsWith("fps_census3_d16u16_0a920b_top on xczu7ev (xcup)"));
  CHECK_THAT(table, Catch::Contains("LUT                3672   230400   1.6 %"));
  CHECK_THAT(table, Catch::Contains("LUT min            2080   230400   0.9 %"));
  CHECK_THAT(table, Catch::Contains("LUTRAM              196   101760   0.2 %"));
  CHECK_THAT(table, Catch::Contains("RAM32M16x9 SRL16Ex124"));
  CHECK_THAT(table, Catch::Contains("FF                 2659   460800   0.6 %"));
  CHECK_THAT(table, Catch::Contains("BRAM18               11      624   1.8 %"));
  CHECK_THAT(table, Catch::Contains("BRAM36                1      312   0.3 %"));
  CHECK_THAT(table, Catch::Contains("BRAM36 equiv        6.5      312   2.1 %"));
  CHECK_THAT(table, Catch::Contains("URAM                  3       96   3.1 %   URAM288"));
  CHECK_THAT(table, Catch::Contains("DSP                   5     1728   0.3 %"));
  CHECK_THAT(table, Catch::Contains("CARRY4 equiv        536    57600   0.9 %"));
  CHECK_THAT(table, Catch::Contains("4146 ps   6 LUT levels, 9 with carry chains"));
  CHECK_THAT(table, Catch::Contains("abc9 7-series model"));
  CHECK_THAT(table, Catch::Contains("core.cost_reorder.code_ram.mem") && Catch::Contains("10250x16 -> uram"));
  CHECK_THAT(table, !Catch::Contains("(cached)"));
  CHECK_THAT(format_report(r, true), Catch::Contains("-abc9 -flatten (cached)\n"));
  CHECK_FALSE(r.hierarchical);
  const SynthReport per_module = parse_kv(kScriptKv + "hierarchical=1\n");
  CHECK(per_module.hierarchical);
  CHECK_THAT(format_report(per_module, false), Catch::Contains("-abc9 per module, then flattened\n"));

  const SynthReport no_abc9 = parse_kv(with_line(kScriptKv, "delay_ps", "na"));
  CHECK_THAT(format_report(no_abc9, false), Catch::Contains("n/a"));
}

TEST_CASE("parse_kv and format_report carry the netlist's logic depth and deepest paths", "[synth]") {
  // The lines fpstereo synth adds after the script's (logic_depth.hpp).
  const std::string record = kScriptKv +
                             "depth_levels=8\n"
                             "depth_levels_with_carry=13\n"
                             "path.1=8 9 core.framing.width_q[1] core.left_slice.skid_q[0]/CE\n"
                             "path.2=7 13 core.agg.addr_q[0] core.agg.path_q[28]/D\n"
                             "carry_path=7 13 core.agg.addr_q[0] core.agg.path_q[28]/D\n";
  const SynthReport r = parse_kv(record);
  CHECK(r.depth_levels == 8);
  CHECK(r.depth_levels_with_carry == 13);
  REQUIRE(r.worst_paths.size() == 2);
  CHECK(r.worst_paths[0].levels == 8);
  CHECK(r.worst_paths[0].levels_with_carry == 9);
  CHECK(r.worst_paths[0].start == "core.framing.width_q[1]");
  CHECK(r.worst_paths[0].end == "core.left_slice.skid_q[0]/CE");
  REQUIRE(r.worst_carry_path.has_value());
  CHECK(r.worst_carry_path->levels_with_carry == 13);
  const std::string table = format_report(r, false);
  INFO(table);
  CHECK_THAT(table, Catch::Contains("logic depth           8 LUT levels, 13 with carry/MUXF cells"));
  CHECK_THAT(table, Catch::Contains("\n    8   9  core.framing.width_q[1] -> core.left_slice.skid_q[0]/CE\n"));
  CHECK_THAT(table, Catch::Contains("deepest with carry/MUXF:\n    7  13  core.agg.addr_q[0] -> core.agg.path_q[28]/D\n"));

  // The script alone adds no depth; an unanalysed netlist records na.
  CHECK_FALSE(parse_kv(kScriptKv).depth_levels.has_value());
  CHECK_THAT(format_report(parse_kv(kScriptKv), false), !Catch::Contains("logic depth"));
  CHECK_FALSE(parse_kv(kScriptKv + "depth_levels=na\ndepth_levels_with_carry=na\n").depth_levels.has_value());
  CHECK_THROWS_WITH(parse_kv(kScriptKv + "path.1=8 9 only_start\n"), Catch::Contains("path.1 = '8 9 only_start'"));
  CHECK_THROWS_WITH(parse_kv(kScriptKv + "path.1=x 9 a b\n"), Catch::Contains("path.1 = 'x'"));
}

TEST_CASE("cache_key changes with everything that decides the result", "[synth]") {
  const StereoConfig cfg = tiny_config();
  const std::string verilog = "module top; endmodule\n", script = "#!/usr/bin/env bash\n";
  const std::string key = cache_key(cfg, "", "", false, false, verilog, script);
  CHECK(key == cache_key(cfg, "", "", false, false, verilog, script));
  CHECK_THAT(key, Catch::StartsWith(config_tag(cfg) + "-default-default-"));
  CHECK(cache_key(cfg, "xc7", "", false, false, verilog, script) != key);
  CHECK(cache_key(cfg, "", "xck26", false, false, verilog, script) != key);
  CHECK(cache_key(cfg, "", "xczu7ev", true, false, verilog, script) !=
        cache_key(cfg, "", "xczu7ev", false, false, verilog, script));
  CHECK_THAT(cache_key(cfg, "", "xczu7ev", true, false, verilog, script), Catch::Contains("-xczu7ev-uram-"));
  CHECK(cache_key(cfg, "", "", false, true, verilog, script) != key);
  CHECK_THAT(cache_key(cfg, "", "xczu7ev", true, true, verilog, script),
             Catch::Contains("-xczu7ev-uram-hierarchical-"));
  CHECK(cache_key(cfg, "xc7", "xc7z020", false, false, verilog, script) !=
        cache_key(cfg, "xc7", "xc7a100t", false, false, verilog, script));
  StereoConfig other = cfg;
  other.p2 = 87;  // same tag prefix (cost, window, dmax, uf); only the full configuration tells them apart
  CHECK(cache_key(other, "", "", false, false, verilog, script) != key);
  CHECK(cache_key(cfg, "", "", false, false, verilog + " ", script) != key);
  CHECK(cache_key(cfg, "", "", false, false, verilog, script + "# changed\n") != key);
  // Keys are file names: a part name cannot reach outside the cache directory.
  CHECK(cache_key(cfg, "", "../x/y", false, false, verilog, script).find('/') == std::string::npos);
}

TEST_CASE("verilog_hash follows the gates, not the module names or the comments", "[synth]") {
  const StereoConfig cfg = tiny_config();
  // Off, the fused cost's truncation changes no gate, but renames every module (the prefix hashes
  // every parameter) and the banner line that lists it.
  StereoConfig renamed = cfg;
  renamed.fused_trunc = cfg.fused_trunc + 1;
  REQUIRE(config_tag(renamed) != config_tag(cfg));
  CHECK(verilog_hash(renamed) == verilog_hash(cfg));
  StereoConfig other = cfg;
  other.p1 = cfg.p1 + 1;  // the reset value of a register
  CHECK(verilog_hash(other) != verilog_hash(cfg));
  other = cfg;
  other.median = cfg.median == 0 ? 3 : 0;
  CHECK(verilog_hash(other) != verilog_hash(cfg));
}

}  // namespace
TEST_CASE("the parts, their defaults and the --part help come from the embedded part table", "[synth]") {
  const std::vector<Part>& table = parts();
  REQUIRE(table.size() == 6);
  CHECK(table.front().name == "xczu9eg");
  CHECK(table.back().name == "xc7a100t");
  CHECK(find_part("xck26").family == "xcup");
  CHECK(find_part("xc7z020").lutram == 17400);
  CHECK(find_part("xczu7ev").uram == 96);
  CHECK(find_part("xczu9eg").uram == 0);
  CHECK(default_part() == "xczu9eg");
  CHECK(default_part("xc7") == "xc7z020");
  CHECK_THROWS_AS(default_part("xc9"), ConfigError);
  CHECK(part_list() == "xczu9eg (xcup default), xczu7ev, xczu3eg, xck26, xc7z020 (xc7 default), xc7a100t");
  CLI::App app;
  int exit_code = 0;
  register_synth_command(app, exit_code);
  CHECK(app.get_subcommand("synth")->help().find(part_list()) != std::string::npos);
}

// The script reads the same table (constraints/fpga_parts.txt): its own errors, which come before
// it looks for Yosys, name the same parts in the same order.
TEST_CASE("synth-yosys.sh names the parts and families of the table", "[synth]") {
  const auto script_error = [](const std::string& args) {
    const std::string command = "bash '" + synth_script_path().string() + "' " + args + " x.v 2>&1";
    FILE* out = ::popen(command.c_str(), "r");
    REQUIRE(out);
    std::string text;
    char buf[256];
    for (size_t got; (got = fread(buf, 1, sizeof buf, out)) > 0;) text.append(buf, got);
    CHECK(::pclose(out) != 0);
    return text;
  };
  std::string names;
  for (const Part& p : parts()) names += (names.empty() ? "" : " ") + p.name;
  CHECK(script_error("--part xc9zz") == "synth-yosys: unknown part 'xc9zz' (" + names + ")\n");
  CHECK(script_error("--family xc9") == "synth-yosys: unknown family 'xc9' (xcup xc7)\n");
  CHECK(script_error("--family xc7 --part xczu9eg") == "synth-yosys: part xczu9eg is xcup, not xc7\n");
  CHECK(script_error("--uram") == "synth-yosys: --uram: part xczu9eg has no UltraRAM (parts with it: xczu7ev xck26)\n");
  CHECK(script_error("--uram --family xc7") ==
        "synth-yosys: --uram: part xc7z020 has no UltraRAM (parts with it: xczu7ev xck26)\n");
}

}  // namespace fpstereo
