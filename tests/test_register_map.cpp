// The AXI4-Lite register map: the C header and the documented table are printed from
// rtl::register_map(), the hardware decodes the A_* constants of fpstereo_control.v; the two must
// agree, register by register. The Verilator benches then drive the registers through the
// generated header. The table in docs/hardware.md is checked against the map here, row by row.
#include <fmt/core.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <set>
#include <sstream>

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

TEST_CASE("the register header places each output stream's fields in tdata (docs/semantics.md section 8)") {
  auto header_of = [](const StereoConfig& cfg, std::string& upper) {
    const rtl::RtlDesign d = rtl::plan(cfg);
    upper.clear();
    for (char ch : d.prefix) upper += char(std::toupper(static_cast<unsigned char>(ch)));
    return rtl::emit_register_header(d);
  };
  std::string upper;
  // C2: dmax 128, 7 disparity bits and the invalid flag above them in an 8-bit tdata.
  const std::string plain = header_of(preset("C2"), upper);
  for (const std::string line : {"M_AXIS_DISP_TDATA_BITS 8u", "M_AXIS_DISP_DISPARITY_LSB 0u",
                                 "M_AXIS_DISP_DISPARITY_BITS 7u", "M_AXIS_DISP_INVALID_LSB 7u",
                                 "M_AXIS_DISP_INVALID_BITS 1u"}) {
    INFO(line);
    CHECK(plain.find("#define " + upper + "_" + line + "\n") != std::string::npos);
  }
  for (const std::string absent : {"FRACTION", "CONFIDENCE", "M_AXIS_DISP_RIGHT"}) {
    INFO(absent);
    CHECK(plain.find(absent) == std::string::npos);
  }
  // With 4 fraction bits under the 7, the flag at bit 11 of a 16-bit lane, the confidence above the
  // lane, and the right view's whole disparities in a stream of their own.
  StereoConfig cfg = preset("C2");
  cfg.subpixel_bits = 4;
  cfg.confidence = true;
  cfg.lr = LrCheck::Lr1;
  cfg.right_view = true;
  const std::string full = header_of(cfg, upper);
  for (const std::string line :
       {"M_AXIS_DISP_TDATA_BITS 24u", "M_AXIS_DISP_FRACTION_LSB 0u", "M_AXIS_DISP_FRACTION_BITS 4u",
        "M_AXIS_DISP_DISPARITY_LSB 4u", "M_AXIS_DISP_DISPARITY_BITS 7u", "M_AXIS_DISP_INVALID_LSB 11u",
        "M_AXIS_DISP_INVALID_BITS 1u", "M_AXIS_DISP_CONFIDENCE_LSB 16u", "M_AXIS_DISP_CONFIDENCE_BITS 8u",
        "M_AXIS_DISP_RIGHT_TDATA_BITS 8u", "M_AXIS_DISP_RIGHT_DISPARITY_LSB 0u",
        "M_AXIS_DISP_RIGHT_DISPARITY_BITS 7u"}) {
    INFO(line);
    CHECK(full.find("#define " + upper + "_" + line + "\n") != std::string::npos);
  }
}

namespace {

// One register as a row of the documented table shows it: "0x18 UNIQUENESS rw if generated with".
struct RegisterRow {
  uint32_t offset;
  std::string name, access;
  std::string text() const { return fmt::format("0x{:02X} {} {}", offset, name, access); }
};

// The table as printed from the map: access for the default C2 design, where "rw if generated
// with" marks a register that only a design with the optional feature lets software write.
std::vector<RegisterRow> map_rows() {
  StereoConfig featured = preset("C2");
  featured.uniqueness = 10;
  featured.lr = LrCheck::Lr1;
  const rtl::RtlDesign plain = rtl::plan(preset("C2")), full = rtl::plan(featured);
  const std::vector<rtl::Register> plain_map = rtl::register_map(plain), full_map = rtl::register_map(full);
  REQUIRE(plain_map.size() == full_map.size());
  std::vector<RegisterRow> rows;
  for (size_t i = 0; i < plain_map.size(); ++i) {
    const rtl::Register& r = plain_map[i];
    rows.push_back({r.offset, r.name,
                    r.writable             ? "rw"
                    : full_map[i].writable ? "rw if generated with"
                                           : "ro"});
  }
  const auto words = rtl::info_words(plain);
  for (size_t i = 0; i < words.size(); ++i) rows.push_back({uint32_t(0x40 + 4 * i), words[i].first, "ro"});
  return rows;
}

std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// Cells of a Markdown table line; "\|" is a bar inside a cell.
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  for (size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '|' && line[i - 1] != '\\') {
      out.push_back(trimmed(cell));
      cell.clear();
    } else {
      cell += line[i];
    }
  }
  return out;
}

std::vector<std::string> split_list(const std::string& s, const std::string& sep) {
  std::vector<std::string> out;
  for (size_t at = 0;;) {
    const size_t next = s.find(sep, at);
    out.push_back(trimmed(s.substr(at, next - at)));
    if (next == std::string::npos) return out;
    at = next + sep.size();
  }
}

// The register rows of docs/hardware.md's table under the "Settings and status" heading, each with
// the table line it comes from. A row may name several registers: "0x20, 0x24" or "0x30 .. 0x3C"
// (every word in between) with as many names.
std::vector<std::pair<RegisterRow, std::string>> documented_rows(const std::string& doc) {
  const size_t heading = doc.find("\n## Settings and status (AXI4-Lite, `s_axi_ctrl`)\n");
  REQUIRE(heading != std::string::npos);
  std::istringstream in(doc.substr(heading));
  std::vector<std::pair<RegisterRow, std::string>> rows;
  bool in_table = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("|", 0) != 0) {
      if (in_table) break;
      continue;
    }
    in_table = true;
    const std::vector<std::string> c = cells(line);
    if (c.size() < 3 || c[0].rfind("0x", 0) != 0) continue;  // the header and its rule
    std::vector<uint32_t> offsets;
    if (c[0].find("..") != std::string::npos) {
      const auto ends = split_list(c[0], "..");
      for (uint32_t o = std::stoul(ends.at(0), nullptr, 16); o <= std::stoul(ends.at(1), nullptr, 16); o += 4)
        offsets.push_back(o);
    } else {
      for (const auto& o : split_list(c[0], ",")) offsets.push_back(std::stoul(o, nullptr, 16));
    }
    const std::vector<std::string> names = split_list(c[1], ",");
    if (names.size() != offsets.size())
      FAIL("docs/hardware.md register row `" << line << "`: " << offsets.size() << " offsets but " << names.size()
                                      << " names");
    const std::string access =
        c[2].rfind("rw if generated with", 0) == 0 ? std::string("rw if generated with") : c[2];
    for (size_t i = 0; i < names.size(); ++i) rows.push_back({{offsets[i], names[i], access}, line});
  }
  return rows;
}

// The first documented row that differs from the map, or "" when they agree.
std::string first_difference(const std::string& doc) {
  const auto documented = documented_rows(doc);
  const std::vector<RegisterRow> expected = map_rows();
  for (size_t i = 0; i < std::max(documented.size(), expected.size()); ++i) {
    if (i >= documented.size())
      return fmt::format("docs/hardware.md lacks register {} (register_map())", expected[i].text());
    const auto& [row, line] = documented[i];
    if (i >= expected.size())
      return fmt::format("docs/hardware.md register row `{}` has {}, which register_map() lacks", line, row.text());
    if (row.text() != expected[i].text())
      return fmt::format("docs/hardware.md register row `{}` has {}, register_map() has {}", line, row.text(),
                         expected[i].text());
  }
  return "";
}

std::string hardware_doc_text() {
  std::ifstream in(FPSTEREO_SOURCE_DIR "/docs/hardware.md");
  REQUIRE(in);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("the register table of docs/hardware.md is the map's, row by row") {
  CHECK(first_difference(hardware_doc_text()) == "");
}

TEST_CASE("a documented register row that differs from the map is named") {
  std::string doc = hardware_doc_text();
  const std::string row = "| 0x20, 0x24 | WIDTH, HEIGHT | rw |";
  const size_t at = doc.find(row);
  REQUIRE(at != std::string::npos);
  doc.replace(at, row.size(), "| 0x20, 0x24 | WIDTH, HEIGHT | ro |");
  CHECK_THAT(first_difference(doc),
             Catch::StartsWith("docs/hardware.md register row `| 0x20, 0x24 | WIDTH, HEIGHT | ro |") &&
                 Catch::EndsWith("has 0x20 WIDTH ro, register_map() has 0x20 WIDTH rw"));
}
