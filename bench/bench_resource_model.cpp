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
//                                              coefficients, the records and the held-out errors
//                                              (gen/dse/resource_coefficients.inc)
//   bench_resource_model --fail-on-stale       exit 1 unless every configuration has a current
//                                              result (ctest -L resource-data)
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "files.hpp"
#include "resource_fit.hpp"
#include "rtl_emitter.hpp"
#include "synth_command.hpp"

using namespace fpstereo;

namespace {

// One `fpstereo synth --kv` run (served from synth's cache when it has the design).
void collect(dse::YosysRow& r, const std::string& fpstereo) {
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

double pct(double model, double ref) { return ref == 0 ? 0 : 100.0 * (model - ref) / ref; }

// The memories whose mapping the model gets wrong (name, Yosys target, model target).
std::string memory_mismatches(const dse::YosysRow& r, const dse::ResourceEstimate& e) {
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
  bool do_collect = false, do_refit = false, memories = false, leave_one_out = false, fail_on_stale = false;
  app.add_option("--configs", configs, "configuration list (name role flags)");
  app.add_option("--data", data, "Yosys results (CSV)");
  app.add_flag("--collect", do_collect,
               "run fpstereo synth (cached) for configurations without results or with stale ones");
  app.add_option("--fpstereo", fpstereo, "the fpstereo binary for --collect");
  app.add_flag("--refit", do_refit, "fit LUT/FF/DSP coefficients on the fit rows");
  app.add_option("--write", write, "with --refit: write the coefficients to FILE (.inc)");
  app.add_flag("--memories", memories, "list every memory whose mapping the model gets wrong");
  app.add_flag("--leave-one-out", leave_one_out,
               "also each fit row's error when the fit leaves it out (cross-validation within the fit rows)");
  bool show_terms = false;
  app.add_flag("--terms", show_terms, "also print each design's terms (the features LUT and FF are linear in)");
  app.add_flag("--fail-on-stale", fail_on_stale,
               "exit 1 when a configuration has no result or a stale one (the data need --collect)");
  CLI11_PARSE(app, argc, argv);
  try {
    std::vector<dse::YosysRow> rows = dse::read_fit_configs(configs);
    dse::read_fit_data(data, rows);
    if (do_collect) {
      for (auto& r : rows)
        if (!r.have_yosys || dse::is_stale(r)) {
          collect(r, fpstereo);
          dse::write_fit_data(data, rows);  // after each run: an interrupted collection keeps what it has
        }
    }
    // A refit does not read the committed coefficients: they may predate a change of the terms.
    dse::Coefficients coef = do_refit ? dse::refit(rows) : dse::fitted_coefficients();
    if (do_refit) {
      const std::string text = dse::coefficients_source(rows, coef);
      if (!write.empty()) {
        write_file_atomically(write, text);
        std::cerr << "wrote " << write << " (rebuild to use it)\n";
      }
      std::cout << text << "\n";
    }

    fmt::print("{:<5} {:<8} {:>7} {:>7} {:>7} | {:>7} {:>7} {:>7} | {:>7} {:>7} | {:>4} {:>4} | config\n",
               "name", "role", "LUT", "model", "err%", "FF", "model", "err%", "BRAM36", "model", "DSP",
               "mdl");
    std::string mismatches, stale, missing;
    int stale_count = 0, recorded = 0;
    for (const auto& r : rows) {
      if (!r.have_yosys) {
        missing += (missing.empty() ? "" : " ") + r.name;
        continue;
      }
      recorded++;
      if (dse::is_stale(r)) {
        stale += (stale.empty() ? "" : " ") + r.name;
        stale_count++;
      }
      const rtl::RtlDesign d = rtl::plan(r.cfg);
      const dse::ResourceEstimate e = dse::estimate(d, coef);
      fmt::print(
          "{:<5} {:<8} {:>7.0f} {:>7.0f} {:>+7.1f} | {:>7.0f} {:>7.0f} {:>+7.1f} | {:>7} {:>7} | {:>4} "
          "{:>4.0f} | {}\n",
          r.name, r.role, r.lut, e.lut, pct(e.lut, r.lut), r.ff, e.ff, pct(e.ff, r.ff), r.bram36_equiv,
          e.bram36_equiv(), r.dsp, e.dsp, r.flags);
      if (memories) mismatches += memory_mismatches(r, e);
      if (show_terms) {
        const std::vector<double> f = dse::features(d);
        std::string terms;
        for (size_t j = 0; j < f.size(); ++j)
          if (f[j] != 0) terms += fmt::format("{}{} {:g}", terms.empty() ? "" : ", ", dse::feature_names()[j], f[j]);
        fmt::print("      terms: {}\n", terms);
      }
    }
    for (const auto& [label, role] : {std::pair<const char*, const char*>{"fit", "fit"}, {"held-out", "heldout"}}) {
      const dse::ErrorSummary s = dse::summarise(rows, role, coef);
      if (s.designs)
        fmt::print(
            "{:<8} ({:>2} configs): BRAM exact (RAMB18 and RAMB36 counts) {}/{}; |LUT err| mean {:.1f} % max "
            "{:.1f} %; |FF err| mean {:.1f} % max {:.1f} %\n",
            label, s.designs, s.bram_exact, s.designs, s.lut_mean, s.lut_max, s.ff_mean, s.ff_max);
    }
    if (leave_one_out) {
      // Each fit row against a fit of the others: how the model does on designs it has not seen,
      // without looking at the held-out rows.
      dse::ErrorSummary s;
      for (size_t i = 0; i < rows.size(); ++i) {
        if (rows[i].role != "fit" || !rows[i].have_yosys) continue;
        std::vector<dse::YosysRow> others = rows;
        others[i].role = "left-out";
        const dse::ErrorSummary one = dse::summarise(others, "left-out", dse::refit(others));
        fmt::print("left out {:<5}: LUT {:.1f} %, FF {:.1f} %\n", rows[i].name, one.lut_max, one.ff_max);
        s.designs++;
        s.lut_mean += one.lut_max;
        s.ff_mean += one.ff_max;
        s.lut_max = std::max(s.lut_max, one.lut_max);
        s.ff_max = std::max(s.ff_max, one.ff_max);
      }
      if (s.designs)
        fmt::print("leave-one-out ({} fit rows): |LUT err| mean {:.1f} % max {:.1f} %; |FF err| mean {:.1f} % max "
                   "{:.1f} %\n",
                   s.designs, s.lut_mean / s.designs, s.lut_max, s.ff_mean / s.designs, s.ff_max);
    }
    if (memories) std::cout << (mismatches.empty() ? "every memory mapped as Yosys maps it\n" : mismatches);
    fmt::print(
        "stale: {} of {} recorded rows came from other Verilog than the generator emits today (or record no "
        "hash){}{}\n",
        stale_count, recorded, stale.empty() ? "" : ": ", stale);
    if (!missing.empty()) fmt::print("without a Yosys result: {}\n", missing);
    if (fail_on_stale && (stale_count > 0 || !missing.empty())) {
      std::cerr << "bench_resource_model: the resource data are not current (stale:" << (stale.empty() ? " none" : " " + stale)
                << "; missing:" << (missing.empty() ? " none" : " " + missing)
                << "); run build/bench/bench_resource_model --collect, then --refit --write "
                   "gen/dse/resource_coefficients.inc\n";
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_resource_model: " << e.what() << "\n";
    return 2;
  }
}
