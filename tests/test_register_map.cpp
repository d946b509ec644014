// The AXI4-Lite register map: the C header and the README are printed from rtl::register_map(),
// the hardware decodes the A_* constants of fpstereo_control.v; the two must agree, register by
// register. The Verilator benches then drive the registers through the generated header.
#include <fmt/core.h>

#include <catch2/catch.hpp>
#include <set>

#include "rtl_emitter.hpp"
#include "rtl_templates.hpp"

using namespace fpstereo;

TEST_CASE("every register of the map is decoded at its offset by fpstereo_control") {
  const std::string& control = rtl::templates().at("fpstereo_control");
  const rtl::RtlDesign d = rtl::plan(preset("C3"));
  std::set<uint32_t> offsets;
  for (const auto& r : rtl::register_map(d)) {
    INFO(r.name);
    CHECK(control.find(fmt::format("A_{} = 8'h{:02X}", r.name, r.offset)) != std::string::npos);
    CHECK(r.offset % 4 == 0);
    CHECK(r.offset < 0x40);
    CHECK(offsets.insert(r.offset).second);
  }
  CHECK(control.find("A_INFO = 8'h40") != std::string::npos);
  CHECK(rtl::info_words(d).size() <= 16);
}

TEST_CASE("the settings a design lacks are read-only in its map") {
  StereoConfig cfg = preset("C2");  // no uniqueness check, no left-right check
  auto writable = [](const rtl::RtlDesign& d, const std::string& name) {
    for (const auto& r : rtl::register_map(d))
      if (r.name == name) return r.writable;
    FAIL("no register " << name);
    return false;
  };
  const rtl::RtlDesign plain = rtl::plan(cfg);
  CHECK_FALSE(writable(plain, "UNIQUENESS"));
  CHECK_FALSE(writable(plain, "LR_THRESHOLD"));
  CHECK(writable(plain, "P1"));
  CHECK(writable(plain, "WIDTH"));
  cfg.uniqueness = 10;
  cfg.lr = LrCheck::Lr1;
  const rtl::RtlDesign checked = rtl::plan(cfg);
  CHECK(writable(checked, "UNIQUENESS"));
  CHECK(writable(checked, "LR_THRESHOLD"));
}

TEST_CASE("the register header names the design and its expected identity") {
  const rtl::RtlDesign d = rtl::plan(preset("C2"));
  const std::string header = rtl::emit_register_header(d);
  std::string upper;
  for (char ch : d.prefix) upper += char(std::toupper(static_cast<unsigned char>(ch)));
  CHECK(header.find("#define " + upper + "_P2 ") != std::string::npos);
  CHECK(header.find(fmt::format("#define {}_CONFIG_ID_VALUE   0x{:08X}u", upper, rtl::config_id(d))) !=
        std::string::npos);
  CHECK(header.find(fmt::format("#define {}_CYCLES_PER_FRAME_VALUE {}u", upper, d.cycles_per_frame)) !=
        std::string::npos);
  CHECK(d.prefix.find(fmt::format("{:06x}", rtl::config_id(d))) != std::string::npos);
}
