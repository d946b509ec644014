#include "resource_fit.hpp"

#include <fmt/core.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "files.hpp"
#include "rtl_emitter.hpp"
#include "synth_command.hpp"

namespace fpstereo::dse {

std::vector<YosysRow> read_fit_configs(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<YosysRow> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    YosysRow r;
    s >> r.name >> r.role;
    std::getline(s, r.flags);
    const size_t first = r.flags.find_first_not_of(' ');
    if (r.name.empty() || (r.role != "fit" && r.role != "heldout") || first == std::string::npos)
      throw std::runtime_error(path + ": expected \"name fit|heldout --flag value ...\", got \"" + line + "\"");
    r.flags = r.flags.substr(first);
    r.cfg = config_from_flags(r.flags);
    rows.push_back(r);
  }
  return rows;
}

namespace {
const char* kHeader = "name,role,lut,ff,bram18,bram36,bram36_equiv,dsp,synth_seconds,memories,verilog_hash";
}

void read_fit_data(const std::string& path, std::vector<YosysRow>& rows) {
  std::ifstream in(path);
  if (!in) return;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) f.push_back(cell);
    if (f.size() < 10) continue;
    for (auto& r : rows)
      if (r.name == f[0]) {
        r.lut = std::stod(f[2]);
        r.ff = std::stod(f[3]);
        r.bram18 = std::stoll(f[4]);
        r.bram36 = std::stoll(f[5]);
        r.bram36_equiv = std::stod(f[6]);
        r.dsp = std::stod(f[7]);
        r.seconds = std::stod(f[8]);
        r.memories = f[9];
        r.verilog_hash = f.size() > 10 ? f[10] : "";
        r.have_yosys = true;
      }
  }
}

void write_fit_data(const std::string& path, const std::vector<YosysRow>& rows) {
  std::string text = std::string(kHeader) + "\n";
  for (const auto& r : rows)
    if (r.have_yosys)
      text += fmt::format("{},{},{},{},{},{},{},{},{},{},{}\n", r.name, r.role, r.lut, r.ff, r.bram18, r.bram36,
                          r.bram36_equiv, r.dsp, r.seconds, r.memories, r.verilog_hash);
  write_file_atomically(path, text);
}

bool is_stale(const YosysRow& r) { return r.have_yosys && r.verilog_hash != verilog_hash(r.cfg); }

Coefficients refit(const std::vector<YosysRow>& rows) {
  std::vector<std::vector<double>> a, ad;
  std::vector<double> lut, ff, dsp, wl, wf, wd;
  for (const auto& r : rows) {
    if (r.role != "fit" || !r.have_yosys) continue;
    const rtl::RtlDesign d = rtl::plan(r.cfg);
    a.push_back(features(d));
    ad.push_back(dsp_features(d));
    lut.push_back(r.lut);
    ff.push_back(r.ff);
    dsp.push_back(r.dsp);
    // Relative errors are what the model is judged by: weight each row by 1 / value^2.
    wl.push_back(1.0 / (r.lut * r.lut));
    wf.push_back(1.0 / (r.ff * r.ff));
    wd.push_back(1.0);
  }
  if (a.empty()) throw std::runtime_error("no fit rows with Yosys results");
  // One coefficient per group of tied terms (term_ties), then each term's.
  const std::vector<TermTie>& ties = term_ties();
  const auto tied_fit = [&](const std::vector<double>& b, const std::vector<double>& w, int TermTie::*group,
                            double TermTie::*weight) {
    std::vector<std::vector<double>> g(a.size(), std::vector<double>(group_names().size(), 0.0));
    for (size_t r = 0; r < a.size(); ++r)
      for (size_t j = 0; j < ties.size(); ++j) g[r][ties[j].*group] += ties[j].*weight * a[r][j];
    const std::vector<double> x = fit_nonnegative(g, b, w);
    std::vector<double> c(ties.size());
    for (size_t j = 0; j < ties.size(); ++j) c[j] = x[ties[j].*group] * ties[j].*weight;
    return c;
  };
  return {tied_fit(lut, wl, &TermTie::lut_group, &TermTie::lut_weight),
          tied_fit(ff, wf, &TermTie::ff_group, &TermTie::ff_weight), fit_nonnegative(ad, dsp, wd)};
}

namespace {
double pct(double model, double ref) { return ref == 0 ? 0 : 100.0 * (model - ref) / ref; }
}  // namespace

ErrorSummary summarise(const std::vector<YosysRow>& rows, const std::string& role, const Coefficients& c) {
  ErrorSummary s;
  for (const auto& r : rows) {
    if (r.role != role || !r.have_yosys) continue;
    const ResourceEstimate e = estimate(rtl::plan(r.cfg), c);
    const double el = std::abs(pct(e.lut, r.lut)), ef = std::abs(pct(e.ff, r.ff));
    s.designs++;
    s.lut_mean += el;
    s.ff_mean += ef;
    s.lut_max = std::max(s.lut_max, el);
    s.ff_max = std::max(s.ff_max, ef);
    s.bram_exact += e.bram18 == r.bram18 && e.bram36 == r.bram36;
  }
  if (s.designs) {
    s.lut_mean /= s.designs;
    s.ff_mean /= s.designs;
  }
  return s;
}

namespace {
std::string number_list(const std::vector<double>& c) {
  std::string s;
  for (double v : c) s += fmt::format("{}{:.6g}", s.empty() ? "" : ", ", v);
  return s;
}
}  // namespace

std::string coefficients_source(const std::vector<YosysRow>& rows, const Coefficients& c) {
  std::string terms, records;
  for (const auto& n : feature_names()) terms += (terms.empty() ? "" : ", ") + n;
  for (const auto& r : rows)
    if (r.have_yosys)
      records += fmt::format("    {{\"{}\", \"{}\", \"{}\", \"{}\"}},\n", r.name, r.role, r.flags, r.verilog_hash);
  const ErrorSummary h = summarise(rows, "heldout", c);
  return fmt::format(
      "// Generated by `build/bench/bench_resource_model --refit --write gen/dse/resource_coefficients.inc`\n"
      "// from bench/resource_fit_data.csv (the configurations marked \"fit\"). Do not edit by hand.\n"
      "// Terms: {}.\n"
      "constexpr double kLut[] = {{{}}};\n"
      "constexpr double kFf[] = {{{}}};\n"
      "constexpr double kDsp[] = {{{}}};\n"
      "// The Yosys results: name, role, configuration, hash of the Verilog Yosys ran on.\n"
      "constexpr FitRecord kRecords[] = {{\n{}}};\n"
      "// The held-out designs: count, BRAM exact, |LUT error| mean and max, |FF error| mean and max (%).\n"
      "constexpr ErrorSummary kHeldOut = {{{}, {}, {:.2f}, {:.2f}, {:.2f}, {:.2f}}};\n",
      terms, number_list(c.lut), number_list(c.ff), number_list(c.dsp), records, h.designs, h.bram_exact,
      h.lut_mean, h.lut_max, h.ff_mean, h.ff_max);
}

}  // namespace fpstereo::dse
