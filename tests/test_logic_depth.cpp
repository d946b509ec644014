// The logic depth of hand-written netlists in Yosys' JSON format, as synth_xilinx leaves them.
#include <catch2/catch.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "logic_depth.hpp"

namespace fpstereo {
namespace {

// Pin name to its bits: net bit ids (2 and up) or constants ("0").
using Pins = std::map<std::string, nlohmann::json>;

// One top module; bits are Yosys' net bit ids (2 and up).
class Netlist {
 public:
  void input(const std::string& name, std::vector<int> bits) { port(name, "input", std::move(bits)); }
  void output(const std::string& name, std::vector<int> bits) { port(name, "output", std::move(bits)); }

  // `src`: the cell's src attribute, "|"-separated locations as flatten leaves them.
  void cell(const std::string& name, const std::string& type, const Pins& inputs, const Pins& outputs,
            const std::string& src = "") {
    nlohmann::json c = {{"hide_name", name[0] == '$' ? 1 : 0}, {"type", type}, {"parameters", {{"INIT", "0110"}}},
                        {"attributes", nlohmann::json::object()}, {"port_directions", nlohmann::json::object()},
                        {"connections", nlohmann::json::object()}};
    if (!src.empty()) c["attributes"]["src"] = src;
    for (const auto& [pin, bits] : inputs) {
      c["port_directions"][pin] = "input";
      c["connections"][pin] = bits;
    }
    for (const auto& [pin, bits] : outputs) {
      c["port_directions"][pin] = "output";
      c["connections"][pin] = bits;
    }
    module_["cells"][name] = c;
  }
  void lut(const std::string& name, std::vector<int> inputs, int output) {
    Pins pins;
    for (size_t i = 0; i < inputs.size(); ++i) pins["I" + std::to_string(i)] = nlohmann::json::array({inputs[i]});
    cell(name, "LUT" + std::to_string(inputs.size()), pins, {{"O", {output}}});
  }
  // An FDRE clocked by bit 2, with its Q net named `q_name`.
  void ff(const std::string& q_name, int d, int q, const std::string& src = "top.v:20.3-22.6") {
    cell("$auto$ff.cc:266:slice$" + std::to_string(q), "FDRE", {{"C", {2}}, {"CE", {3}}, {"D", {d}}, {"R", {4}}},
         {{"Q", {q}}}, src);
    net(q_name, {q});
  }
  void net(const std::string& name, std::vector<int> bits, const std::string& src = "") {
    nlohmann::json n = {{"hide_name", name[0] == '$' ? 1 : 0}, {"bits", bits},
                        {"attributes", nlohmann::json::object()}};
    if (!src.empty()) n["attributes"]["src"] = src;
    module_["netnames"][name] = n;
  }
  std::string json() const {
    return nlohmann::json{{"creator", "hand"}, {"modules", {{"top", module_}}}}.dump();
  }

 private:
  void port(const std::string& name, const char* direction, std::vector<int> bits) {
    module_["ports"][name] = {{"direction", direction}, {"bits", bits}};
    net(name, bits);
  }
  nlohmann::json module_ = {{"attributes", {{"top", 1}}},
                            {"ports", nlohmann::json::object()},
                            {"cells", nlohmann::json::object()},
                            {"netnames", nlohmann::json::object()}};
};

// A clock, clock enable and reset from ports; the flip-flops use bits 2, 3 and 4.
Netlist with_control_ports() {
  Netlist n;
  n.input("clk", {5});
  n.cell("$clk_ibuf", "IBUF", {{"I", {5}}}, {{"O", {6}}});
  n.cell("$clk_bufg", "BUFG", {{"I", {6}}}, {{"O", {2}}});
  n.input("ce", {3});
  n.input("rst", {4});
  return n;
}

TEST_CASE("three LUTs between two flip-flops are three levels", "[synth][depth]") {
  Netlist n = with_control_ports();
  n.ff("a_q", 30, 10);
  n.lut("$lut1", {10}, 11);
  n.lut("$lut2", {11, 10}, 12);
  n.lut("$lut3", {12, 10, 11}, 13);
  n.ff("b_q", 13, 14);
  const LogicDepth d = analyse_logic_depth(n.json(), 5);
  CHECK(d.levels == 3);
  CHECK(d.levels_with_carry == 3);
  REQUIRE(d.worst.size() >= 1);
  CHECK(d.worst[0].levels == 3);
  CHECK(d.worst[0].start == "a_q");
  CHECK(d.worst[0].end == "b_q/D");
  CHECK(d.worst_with_carry.end == "b_q/D");
  // The clock path through IBUF and BUFG ends nowhere: clock pins end no path.
  for (const auto& p : d.worst) CHECK_THAT(p.end, !Catch::EndsWith("/C"));
}

TEST_CASE("a combinational loop is reported, not followed", "[synth][depth]") {
  Netlist n = with_control_ports();
  n.ff("a_q", 21, 10);
  n.lut("$left", {10, 20}, 21);
  n.lut("$right", {21}, 22);
  n.lut("$back", {22}, 20);
  n.ff("b_q", 22, 11);
  CHECK_THROWS_AS(analyse_logic_depth(n.json(), 5), LogicDepthError);
  CHECK_THROWS_WITH(analyse_logic_depth(n.json(), 5),
                    Catch::StartsWith("combinational loop through 3 cells: ") && Catch::Contains("$left") &&
                        Catch::Contains("$right") && Catch::Contains("$back"));
}

TEST_CASE("a carry chain continues the path, bit by bit", "[synth][depth]") {
  Netlist n = with_control_ports();
  n.ff("a_q", 30, 10);
  n.ff("late_q", 31, 11);
  n.lut("$sel0", {10}, 12);
  n.lut("$sel3", {11}, 13);
  n.lut("$sel3b", {13}, 14);
  // S[0] from one LUT after a_q; S[3] from two LUTs after late_q; O[0] sees only bit 0.
  n.cell("$carry", "CARRY4", {{"CI", {"0"}}, {"CYINIT", {"0"}}, {"DI", {10, 10, 10, 10}}, {"S", {12, 16, 16, 14}}},
         {{"O", {40, 41, 42, 43}}, {"CO", {44, 45, 46, 47}}});
  n.input("in", {16});
  n.ff("sum0_q", 40, 50);
  n.ff("sum3_q", 43, 51);
  n.lut("$after", {47}, 52);
  n.ff("carry_q", 52, 53);
  // A second CARRY4 in the chain.
  n.cell("$carry_hi", "CARRY4", {{"CI", {47}}, {"CYINIT", {"0"}}, {"DI", {10, 10, 10, 10}}, {"S", {16, 16, 16, 16}}},
         {{"O", {60, 61, 62, 63}}, {"CO", {64, 65, 66, 67}}});
  n.ff("hi_q", 63, 54);
  const LogicDepth d = analyse_logic_depth(n.json(), 10);
  CHECK(d.levels == 3);             // late_q -> $sel3 -> $sel3b -> CARRY4 -> $after -> carry_q
  CHECK(d.levels_with_carry == 4);  // the same path, or late_q -> ... -> two CARRY4 -> hi_q
  std::map<std::string, LogicPath> by_end;
  for (const auto& p : d.worst) by_end[p.end] = p;
  REQUIRE(by_end.count("sum0_q/D"));
  CHECK(by_end["sum0_q/D"].levels == 1);
  CHECK(by_end["sum0_q/D"].levels_with_carry == 2);
  CHECK(by_end["sum0_q/D"].start == "a_q");
  CHECK(by_end["sum3_q/D"].levels == 2);
  CHECK(by_end["sum3_q/D"].start == "late_q");
  CHECK(by_end["carry_q/D"].levels == 3);
  CHECK(by_end["carry_q/D"].levels_with_carry == 4);
  CHECK(by_end["hi_q/D"].levels == 2);
  CHECK(by_end["hi_q/D"].levels_with_carry == 4);
  CHECK(d.worst[0].end == "carry_q/D");
}

TEST_CASE("MUXF7 adds no LUT level, a LUTRAM read adds one and its data starts paths", "[synth][depth]") {
  Netlist n = with_control_ports();
  n.ff("addr_q", 30, 10);
  n.lut("$a0", {10}, 11);
  n.lut("$a1", {10}, 12);
  n.lut("$b0", {10}, 13);
  n.cell("$mux", "MUXF7", {{"I0", {11}}, {"I1", {12}}, {"S", {13}}}, {{"O", {14}}});
  n.cell("core.mem.0.0", "RAM64M8",
         {{"ADDRA", {14, 10, 10, 10, 10, 10}}, {"ADDRH", {10, 10, 10, 10, 10, 10}}, {"DIA", {10}}, {"WE", {10}},
          {"WCLK", {2}}},
         {{"DOA", {20}}, {"DOB", {21}}});
  n.lut("$read", {20}, 22);
  n.ff("data_q", 22, 23);
  n.lut("$raw", {21}, 25);
  n.ff("raw_q", 25, 24);  // DOB: no read address connected, the stored word only
  const LogicDepth d = analyse_logic_depth(n.json(), 10);
  CHECK(d.levels == 3);             // $a0, the RAM read, $read
  CHECK(d.levels_with_carry == 4);  // and the MUXF7
  REQUIRE(!d.worst.empty());
  CHECK(d.worst[0].start == "addr_q");
  CHECK(d.worst[0].end == "data_q/D");
  bool raw_seen = false;
  for (const auto& p : d.worst)
    if (p.end == "raw_q/D") {
      raw_seen = true;
      CHECK(p.levels == 1);
      CHECK(p.start == "core.mem.0.0/DOB");
    }
  CHECK(raw_seen);
}

TEST_CASE("ports start and end paths, a bus counts once, the list stops at the limit", "[synth][depth]") {
  Netlist n = with_control_ports();
  n.input("pixel", {7, 8});
  n.cell("$ibuf0", "IBUF", {{"I", {7}}}, {{"O", {9}}});
  n.lut("$l0", {9}, 11);
  n.lut("$l1", {11, 8}, 12);
  n.lut("$l2", {12}, 13);
  n.cell("$d0", "FDRE", {{"C", {2}}, {"CE", {3}}, {"D", {12}}, {"R", {4}}}, {{"Q", {14}}});
  n.cell("$d1", "FDRE", {{"C", {2}}, {"CE", {13}}, {"D", {11}}, {"R", {4}}}, {{"Q", {15}}});
  n.net("sum_q", {14, 15});
  n.lut("$o", {14}, 16);
  n.cell("$obuf", "OBUF", {{"I", {16}}}, {{"O", {17}}});
  n.output("result", {17});
  const LogicDepth d = analyse_logic_depth(n.json(), 10);
  REQUIRE(d.worst.size() == 2);  // sum_q (two bits, three pins) and result
  CHECK(d.worst[0].levels == 3);
  CHECK(d.worst[0].start == "pixel[0]");
  CHECK(d.worst[0].end == "sum_q[1]/CE");
  CHECK(d.worst[1].levels == 1);
  CHECK(d.worst[1].start == "sum_q[0]");
  CHECK(d.worst[1].end == "result");
  CHECK(analyse_logic_depth(n.json(), 1).worst.size() == 1);
}

TEST_CASE("a register is named where its always block declares it", "[synth][depth]") {
  Netlist n = with_control_ports();
  // The instance chain (top.v:40) is in every src; the always block is at stage.v:30, the reg at
  // stage.v:25, the module's output port at stage.v:3, other wires of the same bit at stage.v:24
  // and (made of the reg, after the block) stage.v:35, and the parent's wire in top.v.
  const std::string ff_src = "top.v:40.3-44.5|stage.v:30.3-33.6|/usr/share/yosys/xilinx/ff_map.v:68.41-68.95";
  n.ff("a_q", 30, 10);
  n.lut("$l", {10}, 11);
  n.cell("$auto$ff.cc:266:slice$99", "FDRE", {{"C", {2}}, {"CE", {3}}, {"D", {11}}, {"R", {4}}}, {{"Q", {12}}},
         ff_src);
  n.net("stage_out", {12}, "top.v:12.8-12.17");
  n.net("u_stage.out", {12}, "top.v:40.3-44.5|stage.v:3.16-3.19");
  n.net("u_stage.sum_q", {12}, "top.v:40.3-44.5|stage.v:25.13-25.18");
  n.net("u_stage.early", {12}, "top.v:40.3-44.5|stage.v:24.8-24.13");
  n.net("u_stage.addr", {12}, "top.v:40.3-44.5|stage.v:35.8-35.12");
  n.net("u_next.in", {12}, "top.v:45.3-47.5|next.v:2.15-2.17");
  n.net("$techmap$hidden", {12});
  const LogicDepth d = analyse_logic_depth(n.json(), 5);
  REQUIRE(!d.worst.empty());
  CHECK(d.worst[0].end == "u_stage.sum_q/D");
}

TEST_CASE("a netlist that cannot be analysed is a one-line LogicDepthError", "[synth][depth]") {
  CHECK_THROWS_WITH(analyse_logic_depth("{\"modules\": ", 5), Catch::StartsWith("netlist: not JSON"));
  CHECK_THROWS_WITH(analyse_logic_depth("{}", 5), Catch::Contains("no \"modules\""));
  CHECK_THROWS_WITH(analyse_logic_depth(R"({"modules": {"a": {"cells": {}}}})", 5), Catch::Contains("no module marked top"));
  CHECK_THROWS_WITH(analyse_logic_depth(R"({"modules": {"t": {"attributes": {"top": 1},
                        "netnames": {"w": {"hide_name": 0}}}}})", 5), Catch::Contains("net w has no bit list"));
  CHECK_THROWS_WITH(analyse_logic_depth(R"({"modules": {"t": {"attributes": {"top": 1},
                        "cells": {"c": {"type": 5}}}}})", 5), Catch::StartsWith("netlist: unexpected structure"));
  Netlist twice = with_control_ports();
  twice.lut("$x", {3}, 10);
  twice.lut("$y", {4}, 10);
  CHECK_THROWS_WITH(analyse_logic_depth(twice.json(), 5), Catch::Contains("two drivers"));
}

}  // namespace
}  // namespace fpstereo
