// The fast resource model against Yosys: per configuration of bench/resource_fit_configs.txt, the
// model's LUT, FF, BRAM36 and DSP next to Yosys' (bench/resource_fit_data.csv) and the error, with
// the summary over the held-out configurations (never used for fitting).
//
//   bench_resource_model                       compare, from the committed Yosys results, and
//                                              list the rows whose Verilog has changed since
//                                              (stale: each row records its Verilog's hash)
//   bench_resource_model --collect             run `fpstereo synth --kv` for every configuration
//                                              without a current result (cached; serial) and
//                                              rewrite the data file first
//   bench_resource_model --refit --write FILE  fit LUT/FF/DSP on the "fit" rows, write the
//                                              coefficients (gen/dse/resource_coefficients.inc)
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "resource_model.hpp"
#include "rtl_emitter.hpp"
#include "synth_command.hpp"

using namespace fpstereo;

namespace {

struct Row {
  std::string name, role, flags;
  StereoConfig cfg;
  // Yosys
  double lut = 0, ff = 0, dsp = 0, bram36_equiv = 0, seconds = 0;
  int64_t bram18 = 0, bram36 = 0;
  std::string memories;  // name=words x bits:target;...
  std::string verilog_hash;  // of the Verilog Yosys ran on (empty: not recorded)
  bool have_yosys = false;
  // A result is stale once the generator emits other Verilog for the configuration.
  bool stale() const { return have_yosys && verilog_hash != fpstereo::verilog_hash(cfg); }
};

StereoConfig parse_flags(const std::string& flags) {
  std::istringstream in(flags);
  std::string key, value;
  StereoConfig cfg;
  while (in >> key >> value) set_param(cfg, key.substr(2), value);
  validate(cfg);
  return cfg;
}

std::vector<Row> read_configs(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<Row> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    Row r;
    s >> r.name >> r.role;
    std::getline(s, r.flags);
    r.flags = r.flags.substr(r.flags.find_first_not_of(' '));
    r.cfg = parse_flags(r.flags);
    rows.push_back(r);
  }
  return rows;
}

const char* kHeader = "name,role,lut,ff,bram18,bram36,bram36_equiv,dsp,synth_seconds,memories,verilog_hash";

void read_data(const std::string& path, std::vector<Row>& rows) {
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

void write_data(const std::string& path, const std::vector<Row>& rows) {
  std::ofstream out(path);
  out << kHeader << "\n";
  for (const auto& r : rows)
    if (r.have_yosys)
      out << fmt::format("{},{},{},{},{},{},{},{},{},{},{}\n", r.name, r.role, r.lut, r.ff, r.bram18, r.bram36,
                         r.bram36_equiv, r.dsp, r.seconds, r.memories, r.verilog_hash);
}

// One `fpstereo synth --kv` run (served from synth's cache when it has the design).
void collect(Row& r, const std::string& fpstereo) {
  const std::string cmd = fmt::format("nice -n 10 {} synth {} --kv", fpstereo, r.flags);
  std::cerr << r.name << ": " << cmd << "\n";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) throw std::runtime_error("cannot run " + cmd);
  std::string text;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) text.append(buf, n);
  if (pclose(p) != 0) throw std::runtime_error("failed: " + cmd);
  const SynthReport rep = parse_kv(text);
  r.verilog_hash = verilog_hash(r.cfg);
  r.lut = double(rep.lut);
  r.ff = double(rep.ff);
  r.bram18 = rep.bram18;
  r.bram36 = rep.bram36;
  r.bram36_equiv = rep.bram36_equiv;
  r.dsp = double(rep.dsp);
  r.seconds = rep.synth_seconds.value_or(0);
  r.memories.clear();
  for (const auto& m : rep.memories)
    r.memories +=
        fmt::format("{}{}={}x{}:{}", r.memories.empty() ? "" : ";", m.name, m.words, m.bits, m.target);
  r.have_yosys = true;
}

std::string coefficient_list(const std::vector<double>& c) {
  std::string s;
  for (double v : c) s += fmt::format("{}{:.6g}", s.empty() ? "" : ", ", v);
  return s;
}

dse::Coefficients refit(const std::vector<Row>& rows) {
  std::vector<std::vector<double>> a, ad;
  std::vector<double> lut, ff, dsp, wl, wf, wd;
  for (const auto& r : rows) {
    if (r.role != "fit" || !r.have_yosys) continue;
    const rtl::RtlDesign d = rtl::plan(r.cfg);
    a.push_back(dse::features(d));
    ad.push_back(dse::dsp_features(d));
    lut.push_back(r.lut);
    ff.push_back(r.ff);
    dsp.push_back(r.dsp);
    // Relative errors are what the model is judged by: weight each row by 1 / value^2.
    wl.push_back(1.0 / (r.lut * r.lut));
    wf.push_back(1.0 / (r.ff * r.ff));
    wd.push_back(1.0);
  }
  if (a.empty()) throw std::runtime_error("no fit rows with Yosys results");
  return {dse::fit_nonnegative(a, lut, wl), dse::fit_nonnegative(a, ff, wf),
          dse::fit_nonnegative(ad, dsp, wd)};
}

double pct(double model, double ref) { return ref == 0 ? 0 : 100.0 * (model - ref) / ref; }

// The memories whose mapping the model gets wrong (name, Yosys target, model target).
std::string memory_mismatches(const Row& r, const dse::ResourceEstimate& e) {
  std::string out;
  std::stringstream s(r.memories);
  std::string item;
  std::map<std::string, const dse::MemoryEstimate*> model;
  for (const auto& m : e.memories) model[m.name] = &m;
  while (std::getline(s, item, ';')) {
    const auto eq = item.find('='), colon = item.rfind(':');
    const std::string name = item.substr(0, eq), shape = item.substr(eq + 1, colon - eq - 1),
                      target = item.substr(colon + 1);
    if (name.size() > 8 && name.compare(name.size() - 8, 8, ".minimum") == 0) continue;  // registers
    const auto it = model.find(name);
    if (it == model.end()) {
      out += fmt::format("  {} {} {}: not in the model\n", r.name, name, shape);
      continue;
    }
    const std::string mshape = fmt::format("{}x{}", it->second->words, it->second->bits);
    if (mshape != shape || it->second->target != target)
      out += fmt::format("  {} {}: Yosys {} {}, model {} {}\n", r.name, name, shape, target, mshape,
                         it->second->target);
    model.erase(it);
  }
  for (const auto& [name, m] : model)
    out += fmt::format("  {} {}: model only ({}x{} {})\n", r.name, name, m->words, m->bits, m->target);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The fast resource model against Yosys (bench/resource_fit_data.csv)"};
  std::string configs = std::string(FPSTEREO_SOURCE_DIR) + "/bench/resource_fit_configs.txt";
  std::string data = std::string(FPSTEREO_SOURCE_DIR) + "/bench/resource_fit_data.csv";
  std::string fpstereo = FPSTEREO_BINARY, write;
  bool do_collect = false, do_refit = false, memories = false;
  app.add_option("--configs", configs, "configuration list (name role flags)");
  app.add_option("--data", data, "Yosys results (CSV)");
  app.add_flag("--collect", do_collect,
               "run fpstereo synth (cached) for configurations without results or with stale ones");
  app.add_option("--fpstereo", fpstereo, "the fpstereo binary for --collect");
  app.add_flag("--refit", do_refit, "fit LUT/FF/DSP coefficients on the fit rows");
  app.add_option("--write", write, "with --refit: write the coefficients to FILE (.inc)");
  app.add_flag("--memories", memories, "list every memory whose mapping the model gets wrong");
  CLI11_PARSE(app, argc, argv);
  try {
    std::vector<Row> rows = read_configs(configs);
    read_data(data, rows);
    if (do_collect) {
      for (auto& r : rows)
        if (!r.have_yosys || r.stale()) {
          collect(r, fpstereo);
          write_data(data, rows);  // after each run: an interrupted collection keeps what it has
        }
    }
    dse::Coefficients coef = dse::fitted_coefficients();
    if (do_refit) {
      coef = refit(rows);
      const std::string text = fmt::format(
          "// Generated by `build/bench/bench_resource_model --refit --write "
          "gen/dse/resource_coefficients.inc`\n"
          "// from bench/resource_fit_data.csv (the configurations marked \"fit\"). Do not edit by hand.\n"
          "// Terms: {}.\n"
          "constexpr double kLut[] = {{{}}};\nconstexpr double kFf[] = {{{}}};\nconstexpr double kDsp[] = "
          "{{{}}};\n",
          [] {
            std::string s;
            for (const auto& n : dse::feature_names()) s += (s.empty() ? "" : ", ") + n;
            return s;
          }(),
          coefficient_list(coef.lut), coefficient_list(coef.ff), coefficient_list(coef.dsp));
      if (!write.empty()) {
        std::ofstream(write) << text;
        std::cerr << "wrote " << write << " (rebuild to use it)\n";
      }
      std::cout << text << "\n";
    }

    fmt::print("{:<5} {:<8} {:>7} {:>7} {:>7} | {:>7} {:>7} {:>7} | {:>7} {:>7} | {:>4} {:>4} | config\n",
               "name", "role", "LUT", "model", "err%", "FF", "model", "err%", "BRAM36", "model", "DSP",
               "mdl");
    struct Summary {
      double lut_max = 0, ff_max = 0, lut_sum = 0, ff_sum = 0;
      int n = 0, bram_exact = 0;
    } fit, held;
    std::string mismatches, stale;
    int stale_count = 0, recorded = 0;
    for (const auto& r : rows) {
      if (!r.have_yosys) continue;
      recorded++;
      if (r.stale()) {
        stale += (stale.empty() ? "" : " ") + r.name;
        stale_count++;
      }
      const rtl::RtlDesign d = rtl::plan(r.cfg);
      const dse::ResourceEstimate e = dse::estimate(d, coef);
      const double el = pct(e.lut, r.lut), ef = pct(e.ff, r.ff);
      fmt::print(
          "{:<5} {:<8} {:>7.0f} {:>7.0f} {:>+7.1f} | {:>7.0f} {:>7.0f} {:>+7.1f} | {:>7} {:>7} | {:>4} "
          "{:>4.0f} | {}\n",
          r.name, r.role, r.lut, e.lut, el, r.ff, e.ff, ef, r.bram36_equiv, e.bram36_equiv(), r.dsp, e.dsp,
          r.flags);
      Summary& s = r.role == "fit" ? fit : held;
      s.n++;
      s.lut_max = std::max(s.lut_max, std::abs(el));
      s.ff_max = std::max(s.ff_max, std::abs(ef));
      s.lut_sum += std::abs(el);
      s.ff_sum += std::abs(ef);
      s.bram_exact += e.bram18 == r.bram18 && e.bram36 == r.bram36;
      if (memories) mismatches += memory_mismatches(r, e);
    }
    for (const auto& [label, s] : {std::pair<const char*, Summary>{"fit", fit}, {"held-out", held}})
      if (s.n)
        fmt::print(
            "{:<8} ({:>2} configs): BRAM exact (RAMB18 and RAMB36 counts) {}/{}; |LUT err| mean {:.1f} % max "
            "{:.1f} %; |FF err| mean {:.1f} % max {:.1f} %\n",
            label, s.n, s.bram_exact, s.n, s.lut_sum / s.n, s.lut_max, s.ff_sum / s.n, s.ff_max);
    if (memories) std::cout << (mismatches.empty() ? "every memory mapped as Yosys maps it\n" : mismatches);
    fmt::print(
        "stale: {} of {} recorded rows came from other Verilog than the generator emits today (or record no "
        "hash){}{}\n",
        stale_count, recorded, stale.empty() ? "" : ": ", stale);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_resource_model: " << e.what() << "\n";
    return 2;
  }
}
