#include "dataset.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "files.hpp"
#include "image_io.hpp"
#include "text.hpp"

namespace fpstereo {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kColumns = {"pair",     "left",     "right",      "gt_occ",     "gt_noc",
                                           "noc_mask", "gt_scale", "gt_invalid", "max_disp_px"};

// Plain comma separation: the format has no quoting (paths and names contain no commas).
std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream ss(line);
  std::string field;
  while (std::getline(ss, field, ',')) fields.push_back(trim(field));
  if (!line.empty() && line.back() == ',') fields.emplace_back();  // getline drops a trailing empty field
  return fields;
}

// One row's fields by column name, with the location for error messages.
class Row {
 public:
  Row(std::map<std::string, std::string> fields, std::string where)
      : fields_(std::move(fields)), where_(std::move(where)) {}

  const std::string& operator[](const std::string& column) const { return fields_.at(column); }

  [[noreturn]] void fail(const std::string& message) const { throw InputError(where_ + ": " + message); }

  double number(const std::string& column) const {
    const std::string& text = (*this)[column];
    const std::optional<double> v = parse_decimal(text);
    if (!v) fail(fmt::format("{} {} is not a decimal number", column, quoted(text)));
    return *v;
  }

 private:
  std::map<std::string, std::string> fields_;
  std::string where_;
};

std::map<std::string, size_t> header_columns(const std::string& line, const std::string& csv) {
  const std::vector<std::string> names = split_fields(line);
  std::map<std::string, size_t> index;
  for (size_t i = 0; i < names.size(); ++i)
    if (!index.emplace(names[i], i).second)
      throw InputError(fmt::format("{} line 1: column {} appears twice", quoted(csv), quoted(names[i])));
  for (const auto& column : kColumns)
    if (!index.count(column))
      throw InputError(fmt::format("{} line 1: no column {} in the header", quoted(csv), quoted(column)));
  return index;
}

std::string dataset_path(const std::string& dir, const std::string& field) {
  return field.empty() ? "" : (fs::path(dir) / field).string();
}

DatasetPair pair_from_row(const Row& row, const std::string& dir) {
  DatasetPair p;
  p.name = row["pair"];
  if (p.name.empty()) row.fail("empty pair name");
  if (row["left"].empty() || row["right"].empty()) row.fail("left and right images are required");
  p.left = dataset_path(dir, row["left"]);
  p.right = dataset_path(dir, row["right"]);
  p.gt_occ = dataset_path(dir, row["gt_occ"]);
  p.gt_noc = dataset_path(dir, row["gt_noc"]);
  p.noc_mask = dataset_path(dir, row["noc_mask"]);
  if (p.has_gt()) {
    p.gt_scale = row.number("gt_scale");
    if (p.gt_scale <= 0) row.fail(fmt::format("gt_scale {} must be positive", p.gt_scale));
    p.gt_invalid = row["gt_invalid"];
    if (p.gt_invalid != "0" && p.gt_invalid != "inf" && p.gt_invalid != "none")
      row.fail(fmt::format("gt_invalid {}: expected 0, inf or none", quoted(p.gt_invalid)));
  }
  if (!row["max_disp_px"].empty()) p.max_disp_px = row.number("max_disp_px");
  return p;
}

}  // namespace

std::vector<DatasetPair> read_pairs_csv(const std::string& dataset_dir) {
  std::error_code ec;
  if (!fs::is_directory(dataset_dir, ec))
    throw InputError(fmt::format("dataset {}: no such directory", quoted(dataset_dir)));
  const std::string csv = (fs::path(dataset_dir) / "pairs.csv").string();
  if (!fs::exists(csv, ec)) throw InputError(fmt::format("dataset {}: no pairs.csv", quoted(dataset_dir)));
  std::istringstream in;
  try {
    in.str(read_regular_file(csv, "pairs file", kMaxTableBytes));
  } catch (const FileError& e) {
    throw InputError(e.what());
  }

  std::string line;
  if (!std::getline(in, line)) throw InputError(fmt::format("{}: empty file", quoted(csv)));
  if (line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a UTF-8 byte order mark (spreadsheets write one)
  const auto index = header_columns(line, csv);

  std::vector<DatasetPair> pairs;
  std::set<std::string> names;
  for (int line_no = 2; std::getline(in, line); ++line_no) {
    if (trim(line).empty()) continue;
    const std::string where = fmt::format("{} line {}", quoted(csv), line_no);
    const std::vector<std::string> fields = split_fields(line);
    if (fields.size() != index.size())
      throw InputError(fmt::format("{}: {} fields, expected {}", where, fields.size(), index.size()));
    std::map<std::string, std::string> by_name;
    for (const auto& [name, i] : index) {
      const std::string& field = fields[i];
      if (std::any_of(field.begin(), field.end(), [](char c) { return (unsigned char)c < 0x20 || c == 0x7f; }))
        throw InputError(fmt::format("{}: column {}: {} holds a control character", where, name, quoted(field)));
      by_name[name] = field;
    }
    DatasetPair pair = pair_from_row(Row(std::move(by_name), where), dataset_dir);
    if (!names.insert(pair.name).second) throw InputError(fmt::format("{}: pair {} appears twice", where, quoted(pair.name)));
    pairs.push_back(std::move(pair));
  }
  if (pairs.empty()) throw InputError(fmt::format("{}: no pairs", quoted(csv)));
  return pairs;
}

}  // namespace fpstereo
