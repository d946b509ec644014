// The sweep's outputs: the CSV (written by a sweep or a shard, read back by merge) and the HTML
// report with its SVG plots.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "dse.hpp"
#include "files.hpp"
#include "image_io.hpp"
#include "text.hpp"

namespace fpstereo::dse {
namespace {

// ---- CSV ------------------------------------------------------------------------------------------

std::string number(double v, int digits = 4) {
  return std::isfinite(v) ? fmt::format("{:.{}f}", v, digits) : std::string();
}

std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells(1);
  bool in_quotes = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        cells.back() += c;
      }
    } else if (c == '"') {
      in_quotes = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else if (c != '\r') {
      cells.back() += c;
    }
  }
  return cells;
}

// The largest number a cell may hold: resources, rates and counts all fit far below it, and
// it keeps every conversion to int exact.
constexpr double kMaxCell = 1e9;

// A number cell: empty is "not available" (NaN); anything else must be a whole decimal number,
// finite and in 0 .. kMaxCell. Throws std::invalid_argument naming the value.
double cell_number(const std::string& s) {
  if (s.empty()) return NAN;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (*end != '\0' || !std::isfinite(v) || v < 0 || v > kMaxCell)
    throw std::invalid_argument(fmt::format("{} is not a number from 0 to {:g}", quoted(s), kMaxCell));
  return v;
}

// A count cell: a whole number in 0 .. kMaxCell.
long long cell_integer(const std::string& s) {
  const double v = s.empty() ? -1 : cell_number(s);
  if (v < 0 || v != std::floor(v))
    throw std::invalid_argument(fmt::format("{} is not a whole number from 0 to {:g}", quoted(s), kMaxCell));
  return static_cast<long long>(v);
}

StereoConfig parse_flags(const std::string& flags) {
  std::istringstream in(flags);
  std::string key, value;
  StereoConfig cfg;
  while (in >> key >> value) {
    if (key.rfind("--", 0) != 0) throw ConfigError("malformed flags " + quoted(flags));
    set_param(cfg, key.substr(2), value);
  }
  validate(cfg);
  return cfg;
}

// One column of the CSV: its header, its cell, and how reading it back fills a row. The columns
// the configuration determines are read back through "flags" alone, so they have no reader.
struct CsvColumn {
  const char* name;
  std::function<std::string(const Row&)> write;
  std::function<void(Row&, const std::string&)> read;
};

// A column of a number in the row with `digits` decimals, empty for NaN; `field` points to it in a
// const or a mutable row.
template <class Field>
CsvColumn decimal(const char* name, int digits, Field field) {
  return {name, [=](const Row& r) { return number(*field(r), digits); },
          [=](Row& r, const std::string& s) { *field(r) = cell_number(s); }};
}

const std::vector<CsvColumn>& csv_columns() {
  static const std::vector<CsvColumn> columns = {
      {"cost", [](const Row& r) { return to_string(r.cfg.cost); }, nullptr},
      {"window", [](const Row& r) { return std::to_string(r.cfg.window); }, nullptr},
      {"dmax", [](const Row& r) { return std::to_string(r.cfg.dmax); }, nullptr},
      {"uf", [](const Row& r) { return std::to_string(r.cfg.uf); }, nullptr},
      {"width", [](const Row& r) { return std::to_string(r.cfg.width); }, nullptr},
      {"height", [](const Row& r) { return std::to_string(r.cfg.height); }, nullptr},
      {"refine", [](const Row& r) { return to_string(r.cfg.lr); }, nullptr},
      {"median", [](const Row& r) { return std::to_string(r.cfg.median); }, nullptr},
      {"p2_adapt", [](const Row& r) { return std::to_string(r.cfg.p2_adapt); }, nullptr},
      {"subpixel_bits", [](const Row& r) { return std::to_string(r.cfg.subpixel_bits); }, nullptr},
      decimal("d1_all", 4, [](auto& r) { return &r.acc.d1_all; }),
      decimal("d1_noc", 4, [](auto& r) { return &r.acc.d1_noc; }),
      decimal("d1_valid", 4, [](auto& r) { return &r.acc.d1_valid; }),
      decimal("density", 4, [](auto& r) { return &r.acc.density; }),
      {"pairs", [](const Row& r) { return std::to_string(r.acc.pairs); },
       [](Row& r, const std::string& s) { r.acc.pairs = int(cell_integer(s)); }},
      decimal("lut", 0, [](auto& r) { return &r.model.lut; }),
      decimal("ff", 0, [](auto& r) { return &r.model.ff; }),
      // BRAM36 equivalents: the RAMB18/RAMB36 split is not in the CSV, halves go to bram18.
      {"bram36", [](const Row& r) { return number(r.model.bram36_equiv(), 1); },
       [](Row& r, const std::string& s) {
         const double bram = cell_number(s);
         r.model.bram36 = int(std::floor(bram));
         r.model.bram18 = int(std::lround((bram - std::floor(bram)) * 2));
       }},
      decimal("dsp", 0, [](auto& r) { return &r.model.dsp; }),
      decimal("lut_pct", 3, [](auto& r) { return &r.lut_pct; }),
      decimal("ff_pct", 3, [](auto& r) { return &r.ff_pct; }),
      decimal("bram_pct", 3, [](auto& r) { return &r.bram_pct; }),
      decimal("dsp_pct", 3, [](auto& r) { return &r.dsp_pct; }),
      decimal("resource_pct", 3, [](auto& r) { return &r.resource_pct; }),
      {"cycles_per_frame", [](const Row& r) { return std::to_string(r.cycles_per_frame); },
       [](Row& r, const std::string& s) { r.cycles_per_frame = cell_integer(s); }},
      decimal("clock_mhz", 3, [](auto& r) { return &r.clock_mhz; }),
      decimal("fps", 3, [](auto& r) { return &r.fps; }),
      {"part", [](const Row& r) { return r.part; }, [](Row& r, const std::string& s) { r.part = find_part(s).name; }},
      {"pareto", [](const Row& r) { return std::string(r.pareto ? "1" : "0"); },
       [](Row& r, const std::string& s) { r.pareto = s == "1"; }},
      decimal("yosys_lut", 0, [](auto& r) { return &r.yosys_lut; }),
      decimal("yosys_ff", 0, [](auto& r) { return &r.yosys_ff; }),
      decimal("yosys_bram36", 1, [](auto& r) { return &r.yosys_bram36; }),
      decimal("yosys_dsp", 0, [](auto& r) { return &r.yosys_dsp; }),
      {"flags", [](const Row& r) { return config_flags(r.cfg); },
       [](Row& r, const std::string& s) {
         if (s.empty()) throw std::invalid_argument("empty, expected the configuration's flags");
         r.cfg = parse_flags(s);
       }},
      {"command", [](const Row& r) { return rtl_command(r.cfg); }, nullptr}};
  return columns;
}

// ---- SVG ------------------------------------------------------------------------------------------

const char* cost_colour(CostFunction c) {
  switch (c) {
    case CostFunction::Census:
      return "#1f77b4";
    case CostFunction::Rank:
      return "#ff7f0e";
    case CostFunction::Sad:
      return "#2ca02c";
    case CostFunction::Zsad:
      return "#d62728";
    case CostFunction::Shd:
      return "#9467bd";
  }
  return "#000";
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

struct Axis {
  double lo, hi;
  bool log;
  double map(double v, double from, double to) const {
    const double t =
        log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) : (v - lo) / (hi - lo);
    return from + t * (to - from);
  }
  std::vector<double> ticks() const {
    std::vector<double> t;
    if (log) {
      for (double p = std::pow(10, std::floor(std::log10(lo))); p <= hi * 1.0001; p *= 10)
        for (double m : {1.0, 2.0, 5.0})
          if (p * m >= lo * 0.9999 && p * m <= hi * 1.0001) t.push_back(p * m);
      return t;
    }
    const double raw = (hi - lo) / 6, mag = std::pow(10, std::floor(std::log10(raw)));
    const double step = raw / mag < 2 ? 2 * mag : raw / mag < 5 ? 5 * mag : 10 * mag;
    for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9; v += step) t.push_back(v);
    return t;
  }
};

Axis axis_over(const std::vector<double>& values, bool log) {
  double lo = *std::min_element(values.begin(), values.end());
  double hi = *std::max_element(values.begin(), values.end());
  if (log) {
    lo = std::max(lo, 1e-3) / 1.2;
    hi = hi * 1.2;
  } else {
    const double pad = std::max((hi - lo) * 0.05, 0.5);
    lo = std::max(0.0, lo - pad);
    hi += pad;
  }
  return {lo, hi, log};
}

// A scatter plot of y against resource use; front points ringed, the front joined as a staircase.
std::string scatter(const std::vector<Row>& rows, const std::string& title, const std::string& y_label,
                    double (*y_of)(const Row&), bool y_log, bool lower_is_better) {
  const double w = 700, h = 420, left = 64, right = 110, top = 34, bottom = 48;  // legend on the right
  std::vector<double> xs, ys;
  for (const auto& r : rows)
    if (std::isfinite(y_of(r))) {
      xs.push_back(r.resource_pct);
      ys.push_back(y_of(r));
    }
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"sans-serif\" font-size=\"11\">\n<text x=\"{2}\" y=\"20\" font-size=\"14\" "
      "font-weight=\"bold\">{3}</text>\n",
      w, h, left, escape(title));
  if (xs.empty()) return svg + "<text x=\"80\" y=\"200\">no data</text></svg>\n";
  const Axis ax = axis_over(xs, false), ay = axis_over(ys, y_log);
  const auto X = [&](double v) { return ax.map(v, left, w - right); };
  const auto Y = [&](double v) { return ay.map(v, h - bottom, top); };
  svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#888\"/>\n",
                     left, top, w - left - right, h - top - bottom);
  for (double t : ax.ticks())
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"#eee\"/><text x=\"{0:.1f}\" "
        "y=\"{3}\" "
        "text-anchor=\"middle\">{4:g}</text>\n",
        X(t), top, h - bottom, h - bottom + 14, t);
  for (double t : ay.ticks())
    svg += fmt::format(
        "<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" stroke=\"#eee\"/><text x=\"{3}\" "
        "y=\"{4:.1f}\" "
        "text-anchor=\"end\">{5:g}</text>\n",
        left, Y(t), w - right, left - 4, Y(t) + 4, t);
  svg += fmt::format(
      "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">resource use, % of the part (largest of LUT, FF, BRAM, "
      "DSP)</text>\n<text transform=\"translate(14 {}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
      (left + w - right) / 2, h - 10, (top + h - bottom) / 2, escape(y_label));
  // Points: non-front first, so the front is drawn on top.
  for (int pass = 0; pass < 2; ++pass)
    for (const auto& r : rows) {
      if (r.pareto != (pass == 1) || !std::isfinite(y_of(r))) continue;
      svg += fmt::format(
          "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{}\" fill=\"{}\" fill-opacity=\"{}\"{}><title>{}: D1 "
          "{:.2f} %, "
          "{:.1f} fps, LUT {:.1f} %, BRAM {:.1f} %{}</title></circle>\n",
          X(r.resource_pct), Y(y_of(r)), r.pareto ? 4.5 : 3, cost_colour(r.cfg.cost), r.pareto ? 0.95 : 0.45,
          r.pareto ? " stroke=\"#000\" stroke-width=\"1.2\"" : "", escape(config_tag(r.cfg)), r.acc.d1_all,
          r.fps, r.lut_pct, r.bram_pct, r.pareto ? ", Pareto front" : "");
    }
  // The 2-D front of this plot: best y so far as resource use grows.
  std::vector<const Row*> sorted;
  for (const auto& r : rows)
    if (std::isfinite(y_of(r))) sorted.push_back(&r);
  std::sort(sorted.begin(), sorted.end(),
            [](const Row* a, const Row* b) { return a->resource_pct < b->resource_pct; });
  std::string path;
  double best = NAN;
  for (const Row* r : sorted) {
    const double y = y_of(*r);
    if (std::isfinite(best) && !(lower_is_better ? y < best : y > best)) continue;
    path += path.empty() ? fmt::format("M{:.1f},{:.1f}", X(r->resource_pct), Y(y))
                         : fmt::format(" H{:.1f} V{:.1f}", X(r->resource_pct), Y(y));
    best = y;
  }
  svg += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#000\" stroke-dasharray=\"4 3\"/>\n", path);
  // Legend.
  double ly = top + 12;
  std::vector<CostFunction> seen;
  for (const auto& r : rows)
    if (std::find(seen.begin(), seen.end(), r.cfg.cost) == seen.end()) seen.push_back(r.cfg.cost);
  for (CostFunction c : seen) {
    svg += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"4\" fill=\"{}\"/><text x=\"{}\" y=\"{}\">{}</text>\n",
                       w - right + 14, ly, cost_colour(c), w - right + 22, ly + 4, to_string(c));
    ly += 15;
  }
  svg += fmt::format(
      "<circle cx=\"{}\" cy=\"{}\" r=\"4.5\" fill=\"#fff\" stroke=\"#000\"/><text x=\"{}\" y=\"{}\">Pareto "
      "front</text>\n</svg>\n",
      w - right + 14, ly, w - right + 22, ly + 4);
  return svg;
}

std::string table(const std::vector<Row>& rows, bool with_command) {
  std::string out =
      "<table>\n<tr><th>#</th><th>cost</th><th>win</th><th>dmax</th><th>uf</th><th>resolution</"
      "th><th>refine</th>"
      "<th>median</th><th>P2 adapt</th><th>sub-pixel bits</th><th>D1 all %</th><th>D1 valid %</th><th>density %</th><th>LUT %</th><th>FF %</th>"
      "<th>BRAM36 %</th><th>DSP</th><th>fps</th><th>Yosys LUT / BRAM36</th>" +
      std::string(with_command ? "<th>command</th>" : "") + "</tr>\n";
  int i = 0;
  for (const auto& r : rows) {
    const std::string yosys = std::isfinite(r.yosys_lut)
                                  ? fmt::format("{:.0f} / {:g}", r.yosys_lut, r.yosys_bram36)
                                  : std::string("-");
    out += fmt::format(
        "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}x{}</td><td>{}</td><td>{}</td>"
        "<td>{}</td><td>{}</td><td>{:.2f}</td><td>{:.2f}</td><td>{:.1f}</td><td>{:.1f}</td><td>{:.1f}</td><td>{:.1f}</"
        "td><td>{:.0f}</td>"
        "<td>{:.1f}</td><td>{}</td>{}</tr>\n",
        ++i, to_string(r.cfg.cost), r.cfg.window, r.cfg.dmax, r.cfg.uf, r.cfg.width, r.cfg.height,
        to_string(r.cfg.lr), r.cfg.median ? std::to_string(r.cfg.median) : std::string("off"),
        r.cfg.p2_adapt ? std::to_string(r.cfg.p2_adapt) : std::string("off"), r.cfg.subpixel_bits, r.acc.d1_all,
        r.acc.d1_valid, r.acc.density, r.lut_pct, r.ff_pct, r.bram_pct, r.model.dsp, r.fps, yosys,
        with_command ? "<td class=\"command\"><code>" + escape(rtl_command(r.cfg)) + "</code></td>" : "");
  }
  return out + "</table>\n";
}

double d1_of(const Row& r) { return r.acc.d1_all; }
double fps_of(const Row& r) { return r.fps; }

}  // namespace

std::string to_csv(const std::vector<Row>& rows) {
  std::string out;
  for (const auto& c : csv_columns()) out += (out.empty() ? "" : ",") + std::string(c.name);
  out += "\n";
  for (const auto& r : rows) {
    std::string line;
    for (const auto& c : csv_columns()) line += (line.empty() ? "" : ",") + csv_cell(c.write(r));
    out += line + "\n";
  }
  return out;
}

std::vector<Row> read_csv(const std::string& path) {
  std::istringstream in;
  try {
    in.str(read_regular_file(path, "dse CSV", kMaxTableBytes));
  } catch (const FileError& e) {
    throw InputError(e.what());
  }
  std::string line;
  if (!std::getline(in, line)) throw InputError(fmt::format("{}: empty, expected a dse CSV", quoted(path)));
  const std::vector<std::string> header = split_csv_line(line);
  std::map<std::string, size_t> col;
  for (size_t i = 0; i < header.size(); ++i) col[header[i]] = i;
  for (const auto& c : csv_columns())
    if (!col.count(c.name))
      throw InputError(fmt::format("{}: not a dse CSV (no column {})", quoted(path), quoted(c.name)));
  std::vector<Row> rows;
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty()) continue;
    const std::vector<std::string> f = split_csv_line(line);
    const std::string where = fmt::format("{} line {}", quoted(path), line_no);
    if (f.size() != header.size())
      throw InputError(fmt::format("{}: malformed row ({} cells, expected {})", where, f.size(), header.size()));
    Row r;
    for (const auto& c : csv_columns()) {
      if (!c.read) continue;
      try {
        c.read(r, f[col.at(c.name)]);
      } catch (const std::exception& e) {
        throw InputError(fmt::format("{}, column {}: {}", where, c.name, e.what()));
      }
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

std::string to_html(const std::vector<Row>& rows, const ReportInfo& info) {
  std::vector<Row> front;
  for (const auto& r : rows)
    if (r.pareto) front.push_back(r);
  std::sort(front.begin(), front.end(),
            [](const Row& a, const Row& b) { return a.resource_pct < b.resource_pct; });
  const std::vector<Row> best = recommend(rows, info.constraints);
  const Constraints& c = info.constraints;
  std::string limits;
  const auto add = [&](const char* name, const std::optional<double>& v, const char* unit) {
    if (v) limits += fmt::format("{}{} {:g}{}", limits.empty() ? "" : ", ", name, *v, unit);
  };
  add("LUT ≤", c.max_lut, " %");
  add("FF ≤", c.max_ff, " %");
  add("BRAM ≤", c.max_bram, " %");
  add("DSP ≤", c.max_dsp, " %");
  add("fps ≥", c.min_fps, "");
  std::string html = fmt::format(
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>fpstereo "
      "dse</title>\n<style>body{{font-family:"
      "sans-serif;margin:24px;max-width:1400px}} table{{border-collapse:collapse;font-size:12px}} "
      "td,th{{border:1px "
      "solid #ccc;padding:2px 6px;text-align:right}} code{{font-size:11px}} td.command{{text-align:left;min-width:36em}} "
      ".plots{{display:flex;flex-wrap:wrap;gap:16px}}</style></head><body>\n<h1>fpstereo design-space "
      "exploration</h1>\n<p>{} configurations on part {} at {:g} MHz; dataset {}.{}</p>\n"
      "<p>Accuracy: the golden model (bit-exact with the hardware) on every pair at its own size; D1 = % of "
      "pixels "
      "with ground truth whose error is &gt; 3 px and &gt; 5 %, after KITTI background filling of invalid "
      "pixels, "
      "pixel counts pooled over the pairs. uf and resolution do not change the output (each "
      "accuracy-distinct "
      "configuration is evaluated once): they drive resources and frame rate only. fps = clock / cycles per "
      "frame of the generated design.</p>\n<p>Resources: {} The column Yosys LUT / BRAM36 is Yosys' "
      "(with --yosys-front).</p>\n<p>Command: <code>{}</code></p>\n<div class=\"plots\">\n{}{}</div>\n",
      rows.size(), escape(info.part), info.clock_mhz, escape(info.dataset),
      info.skipped ? fmt::format(" {} invalid combinations skipped.", info.skipped) : std::string(),
      escape(model_note()), escape(info.command),
      scatter(rows, "D1 against resource use (colour: cost function)", "D1 all, % (filled)", d1_of, false,
              true),
      scatter(rows, "Frame rate against resource use", "frames per second (log)", fps_of, true, false));
  html += fmt::format("<h2>Best configurations{}</h2>\n", limits.empty() ? "" : " with " + escape(limits));
  html += best.empty() ? "<p>No configuration meets the constraints.</p>\n" : table(best, true);
  html += fmt::format(
      "<h2>Pareto front ({} configurations: no other is better in D1, resource use and fps at "
      "once)</h2>\n",
      front.size());
  html += table(front, true);
  return html + "</body></html>\n";
}

}  // namespace fpstereo::dse
