// The core builder (gen/rtl/core_builder.*) and the template signatures it reads: a design whose
// nets are wrong is refused when it is generated, with one line naming the net and the stages.
#include <catch2/catch.hpp>

#include "core_builder.hpp"
#include "module_signature.hpp"
#include "rtl_templates.hpp"

using namespace fpstereo;
using rtl::CoreBuilder;

namespace {

// A core with a clock and a reset, and one delay line from `in` to `out` of `bits`.
CoreBuilder delay_core(int64_t in_bits, int64_t out_bits) {
  CoreBuilder core;
  core.input("clk", 1);
  core.input("rst", 1);
  core.input("in", in_bits);
  core.output("out", out_bits);
  core.stage("delay");
  core.wire("en", 1);
  core.logic("  assign en = 1'b1;\n", {"en"});
  core.instance("fpstereo_delay", "line", {{"WIDTH", "8"}, {"DEPTH", "2"}});
  return core;
}

std::string error_of(const CoreBuilder& core) {
  try {
    core.module_text("m");
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a template's signature: parameters, ports, directions and widths", "[builder]") {
  const auto& s = rtl::template_signature("fpstereo_delay");
  REQUIRE(s.parameters.size() == 3);
  CHECK(s.parameters[0] == std::pair<std::string, std::string>{"WIDTH", "8"});
  REQUIRE(s.ports.size() == 5);
  CHECK(s.port("in")->input);
  CHECK(!s.port("out")->input);
  CHECK(s.port("out")->msb == "WIDTH-1");
  const auto widths = rtl::port_widths(s, {{"WIDTH", "13"}});
  CHECK(widths.at("in") == 13);
  CHECK(widths.at("clk") == 1);
  // A defaulted parameter may depend on an earlier one.
  const auto parsed = rtl::parse_module_signature(
      "module m #(\n  parameter A = 3,\n  parameter B = A * 2 // six\n) (\n  input wire [B-1:0] x,\n"
      "  output reg signed [(A > 2 ? A : 1):0] y\n);\nendmodule\n");
  const auto w = rtl::port_widths(parsed, {});
  CHECK(w.at("x") == 6);
  CHECK(w.at("y") == 4);
  CHECK(rtl::port_widths(parsed, {{"A", "1"}}).at("y") == 2);
}

TEST_CASE("every template's signature reads, with every port width known at its defaults", "[builder]") {
  for (const auto& [name, text] : rtl::templates()) {
    INFO(name);
    const auto& s = rtl::template_signature(name);
    CHECK(s.name == name);
    CHECK(!s.ports.empty());
    CHECK(rtl::port_widths(s, {}).size() == s.ports.size());
  }
}

TEST_CASE("constant expressions evaluate as Verilog's", "[builder]") {
  const std::map<std::string, int64_t> v = {{"UF", 32}, {"COST_W", 6}, {"N", 7}};
  CHECK(rtl::evaluate_constant("UF*COST_W+2-1", v) == 193);
  CHECK(rtl::evaluate_constant("(UF+N-1)*2", v) == 76);
  CHECK(rtl::evaluate_constant("$clog2(UF) + 1", v) == 6);
  CHECK(rtl::evaluate_constant("UF > 16 && N == 7 ? 1 : 0", v) == 1);
  CHECK(rtl::evaluate_constant("8'd5 << 2", v) == 20);
  CHECK(rtl::evaluate_constant("2 ** 10 / 3 % 7", v) == 5);
  CHECK(!rtl::evaluate_constant("UNKNOWN + 1", v));
  CHECK(!rtl::evaluate_constant("1 / 0", v));
  CHECK(!rtl::evaluate_constant("{UF, N}", v));
}

TEST_CASE("the builder connects same-named ports and writes the waivers", "[builder]") {
  const std::string text = delay_core(8, 8).module_text("m");
  CHECK(text.find(".clk(clk), .rst(rst), .en(en), .in(in), .out(out)") != std::string::npos);
  CHECK(text.find("  wire en;\n") != std::string::npos);
  // A net no one reads is declared under a waiver.
  CoreBuilder core = delay_core(8, 8);
  core.wire("spare", 3);
  core.logic("  assign spare = 3'd0;\n", {"spare"});
  const std::string waived = core.module_text("m");
  CHECK(waived.find("/* verilator lint_off UNUSEDSIGNAL */  // not read in this configuration\n  wire [2:0] spare;\n"
                    "  /* verilator lint_on UNUSEDSIGNAL */") != std::string::npos);
}

TEST_CASE("the builder refuses a read of a net no stage drives", "[builder]") {
  CoreBuilder core;
  core.input("clk", 1);
  core.input("rst", 1);
  core.input("in", 8);
  core.output("out", 8);
  core.stage("delay");
  core.wire("en", 1);  // declared, never assigned
  core.instance("fpstereo_delay", "line", {{"WIDTH", "8"}});
  CHECK(error_of(core) == "net en: read by stage delay (instance line, port en), but no stage drives it");
}

TEST_CASE("the builder refuses two drivers of one net", "[builder]") {
  CoreBuilder core = delay_core(8, 8);
  core.stage("second");
  core.instance("fpstereo_delay", "again", {{"WIDTH", "8"}});
  CHECK(error_of(core) ==
        "net out: two drivers, stage delay (instance line, port out) and stage second (instance again, port out)");
  CoreBuilder assigned = delay_core(8, 8);
  assigned.stage("logic");
  assigned.logic("  assign en = 1'b0;\n", {"en"});
  CHECK(error_of(assigned) == "net en: two drivers, stage delay and stage logic");
}

TEST_CASE("the builder refuses a connection whose width is not the port's", "[builder]") {
  CHECK(error_of(delay_core(7, 8)) == "net in: 7 bits, but stage delay (instance line, port in) is 8 bits");
  CHECK(error_of(delay_core(8, 9)) == "net out: 9 bits, but stage delay (instance line, port out) is 8 bits");
  // Concatenations and part-selects add up their parts.
  CoreBuilder core = delay_core(8, 8);
  core.stage("select");
  core.instance("fpstereo_delay", "part", {{"WIDTH", "6"}}, {{"in", "{in[3:0], 1'b0}"}});
  CHECK(error_of(core) == "net {in[3:0], 1'b0}: 5 bits, but stage select (instance part, port in) is 6 bits");
  // A part-select must lie inside its net.
  CoreBuilder outside = delay_core(8, 8);
  outside.stage("select");
  outside.instance("fpstereo_delay", "part", {{"WIDTH", "4"}}, {{"in", "in[8:5]"}});
  CHECK(error_of(outside) == "net in: stage select (instance part, port in) reads `in[8:5]`, outside its 8 bits");
  CoreBuilder reversed = delay_core(8, 8);
  reversed.stage("select");
  reversed.instance("fpstereo_delay", "part", {{"WIDTH", "4"}}, {{"in", "{in[0:3]}"}});
  CHECK(error_of(reversed) == "net in: stage select (instance part, port in) reads `in[0:3]`, outside its 8 bits");
}

TEST_CASE("the builder refuses unknown ports, unconnected ports and undeclared nets", "[builder]") {
  CoreBuilder core = delay_core(8, 8);
  core.instance("fpstereo_delay", "bad", {{"WIDTH", "8"}}, {{"input", "in"}});
  CHECK(error_of(core) == "instance bad (stage delay): fpstereo_delay has no port input");
  CoreBuilder open;
  open.input("clk", 1);
  open.stage("delay");
  open.instance("fpstereo_delay", "line", {});
  CHECK(error_of(open) == "instance line (stage delay): port rst is not connected and no net has its name");
  CoreBuilder undeclared = delay_core(8, 8);
  undeclared.instance("fpstereo_delay", "more", {{"WIDTH", "8"}}, {{"out", "nowhere"}});
  CHECK(error_of(undeclared) == "net nowhere: connected but never declared");
  CoreBuilder twice = delay_core(8, 8);
  twice.stage("again");
  twice.wire("en", 1);
  CHECK(error_of(twice) == "net en: declared twice, by stage delay and by stage again");
}
