#include "synth_command.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "config_cli.hpp"
#include "files.hpp"
#include "fpga_parts.hpp"
#include "hash.hpp"
#include "logic_depth.hpp"
#include "rtl_emitter.hpp"
#include "text.hpp"
#include "yosys_progress.hpp"

#ifndef FPSTEREO_SOURCE_DIR
#error "FPSTEREO_SOURCE_DIR must name the source tree, where scripts/synth-yosys.sh lives (CMakeLists.txt)"
#endif

extern char** environ;

namespace fpstereo {
namespace fs = std::filesystem;
namespace {

constexpr const char* kTool = "fpstereo";
constexpr const char* kScriptPrefix = "synth-yosys: ";
constexpr const char* kScriptWarningPrefix = "synth-yosys: warning: ";
// The delay is the same model for both families; it ranks designs, it does not predict timing.
constexpr const char* kDelayNote =
    "  note: delay = Yosys' abc9 7-series model (LUTs, carry chains, no routing), for comparing designs\n";
// abc9 restarts its count after every carry chain, SRL and LUTRAM; the netlist's depth does not.
constexpr const char* kDepthNote =
    "  note: logic depth = LUTs (INV and LUTRAM reads included) on the deepest register-to-register path\n"
    "        of the mapped netlist, through carry chains, which abc9's levels restart after\n";
// The deepest paths recorded, one per end register.
constexpr size_t kWorstPaths = 10;
// Hashed into the cache key: a change in how the netlist is analysed must not serve old records.
constexpr const char* kLogicDepthModel = "logic-depth-1";

struct SynthOptions {
  ConfigFlags config;
  std::string family, part, cache_dir, log, netlist;
  bool no_cache = false;
  bool kv = false;
  bool uram = false;          // synth_xilinx -uram
  bool hierarchical = false;  // synth-yosys.sh --hierarchical
};

// ---- parsing ---------------------------------------------------------------------------------

using KvMap = std::map<std::string, std::string>;

const std::string& field(const KvMap& kv, const std::string& key) {
  const auto it = kv.find(key);
  if (it == kv.end()) throw SynthError(fmt::format("synthesis report lacks {}", quoted(key)));
  return it->second;
}

template <class T>
T parse_number(const std::string& key, const std::string& value) {
  T result{};
  const char* end = value.data() + value.size();
  const auto [ptr, ec] = std::from_chars(value.data(), end, result);
  if (ec != std::errc() || ptr != end || value.empty())
    throw SynthError(fmt::format("synthesis report: {} = {} is not a number", key, quoted(value)));
  return result;
}

int64_t integer(const KvMap& kv, const std::string& key) {
  return parse_number<int64_t>(key, field(kv, key));
}
double number(const KvMap& kv, const std::string& key) { return parse_number<double>(key, field(kv, key)); }

// The script prints "na" for the abc9 figures when abc9 mapped nothing.
std::optional<int64_t> integer_or_na(const KvMap& kv, const std::string& key) {
  const std::string& value = field(kv, key);
  if (value == "na") return std::nullopt;
  return parse_number<int64_t>(key, value);
}

// "path.N=LEVELS LEVELS_WITH_CARRY START END" (Yosys names hold no spaces).
std::string path_value(const LogicPath& p) {
  return fmt::format("{} {} {} {}", p.levels, p.levels_with_carry, p.start, p.end);
}

LogicPath parse_path(const std::string& key, const std::string& value) {
  std::istringstream in(value);
  std::string levels, with_carry, rest;
  LogicPath p;
  if (!(in >> levels >> with_carry >> p.start >> p.end) || (in >> rest))
    throw SynthError(fmt::format("synthesis report: {} = '{}'", key, value));
  p.levels = int(parse_number<int64_t>(key, levels));
  p.levels_with_carry = int(parse_number<int64_t>(key, with_carry));
  return p;
}

// "mem.NAME=WORDSxBITS:TARGET"; the shape is "?" for a memory Yosys created during mapping.
SynthMemory parse_memory(const std::string& name, const std::string& value) {
  const size_t colon = value.find(':');
  if (colon == std::string::npos)
    throw SynthError(fmt::format("synthesis report: mem.{} = {}", name, quoted(value)));
  SynthMemory mem{name, 0, 0, value.substr(colon + 1)};
  const std::string shape = value.substr(0, colon);
  if (shape == "?") return mem;
  const size_t x = shape.find('x');
  if (x == std::string::npos)
    throw SynthError(fmt::format("synthesis report: mem.{} = {}", name, quoted(value)));
  mem.words = parse_number<int64_t>("mem." + name, shape.substr(0, x));
  mem.bits = parse_number<int64_t>("mem." + name, shape.substr(x + 1));
  return mem;
}

void fill_counts(const KvMap& kv, SynthReport& r) {
  r.lut = integer(kv, "lut");
  r.lut_min = integer(kv, "lut_min");
  r.lutram = integer(kv, "lutram");
  r.lut_total = integer(kv, "lut_total");
  r.ff = integer(kv, "ff");
  r.latches = integer(kv, "latches");
  r.bram18 = integer(kv, "bram18");
  r.bram36 = integer(kv, "bram36");
  r.bram36_equiv = number(kv, "bram36_equiv");
  r.uram = integer(kv, "uram");
  r.dsp = integer(kv, "dsp");
  r.carry4 = integer(kv, "carry4");
  r.carry8 = integer(kv, "carry8");
  r.carry4_equiv = integer(kv, "carry4_equiv");
  r.lut_by_inputs = field(kv, "lut_by_inputs");
  r.lutram_cells = field(kv, "lutram_cells");
}

void fill_percentages(const KvMap& kv, SynthReport& r) {
  r.lut_pct = number(kv, "lut_pct");
  r.lut_min_pct = number(kv, "lut_min_pct");
  r.lutram_pct = number(kv, "lutram_pct");
  r.lut_total_pct = number(kv, "lut_total_pct");
  r.ff_pct = number(kv, "ff_pct");
  r.bram18_pct = number(kv, "bram18_pct");
  r.bram36_pct = number(kv, "bram36_pct");
  r.bram36_equiv_pct = number(kv, "bram36_equiv_pct");
  r.uram_pct = number(kv, "uram_pct");
  r.dsp_pct = number(kv, "dsp_pct");
  r.carry_pct = number(kv, "carry_pct");
}

void fill_part(const KvMap& kv, SynthReport& r) {
  r.top = field(kv, "top");
  r.family = field(kv, "family");
  r.part = field(kv, "part");
  r.part_lut = integer(kv, "part_lut");
  r.part_ff = integer(kv, "part_ff");
  r.part_bram36 = integer(kv, "part_bram36");
  r.part_dsp = integer(kv, "part_dsp");
  r.part_lutram = integer(kv, "part_lutram");
  r.part_uram = integer(kv, "part_uram");
}

// ---- formatting ------------------------------------------------------------------------------

std::string resource_row(const std::string& name, const std::string& used, int64_t available, double pct,
                         const std::string& note) {
  return fmt::format("  {:<13} {:>9} {:>8} {:>5.1f} %{}\n", name, used, available, pct,
                     note.empty() ? "" : "   " + note);
}

std::string abc9_rows(const SynthReport& r) {
  const std::string delay = r.delay_ps
                                ? fmt::format("{:>9} ps   {} LUT levels, {} with carry chains", *r.delay_ps,
                                              r.levels.value_or(0), r.levels_with_carry.value_or(0))
                                : fmt::format("{:>9}      abc9 mapped no logic", "n/a");
  return fmt::format("  {:<13} {}\n", "abc9 delay", delay) + kDelayNote;
}

std::string path_row(const LogicPath& p) {
  return fmt::format("  {:>3} {:>3}  {} -> {}\n", p.levels, p.levels_with_carry, p.start, p.end);
}

std::string depth_rows(const SynthReport& r) {
  if (!r.depth_levels) return "";
  std::string out = fmt::format("  {:<13} {:>9} LUT levels, {} with carry/MUXF cells\n", "logic depth",
                                *r.depth_levels, r.depth_levels_with_carry.value_or(0));
  out += kDepthNote;
  if (r.worst_paths.empty()) return out;
  out += "deepest paths (LUT levels, with carry/MUXF: start -> end), one per end register:\n";
  for (const auto& p : r.worst_paths) out += path_row(p);
  if (r.worst_carry_path) out += "deepest with carry/MUXF:\n" + path_row(*r.worst_carry_path);
  return out;
}

std::string memory_rows(const std::vector<SynthMemory>& memories) {
  if (memories.empty()) return "";
  size_t name_width = 0;
  for (const auto& m : memories) name_width = std::max(name_width, m.name.size());
  std::string out = "memories (words x bits -> mapped to):\n";
  for (const auto& m : memories) {
    const std::string shape = m.words ? fmt::format("{}x{}", m.words, m.bits) : "?";
    out += fmt::format("  {:<{}} {:>10} -> {}\n", m.name, name_width, shape, m.target);
  }
  return out;
}

// ---- files and processes ---------------------------------------------------------------------

std::optional<std::string> read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Into the run's own fresh work directory, which nothing else writes.
void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out) throw SynthError(fmt::format("cannot write {}: {}", quoted(path.string()), std::strerror(errno)));
}

void make_directory(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw SynthError(fmt::format("cannot create directory {}: {}", quoted(dir.string()), ec.message()));
}

// Names and contents of every emitted file: what the cache key hashes.
std::string verilog_text(const std::vector<rtl::EmittedFile>& files) {
  std::string text;
  for (const auto& f : files) text += f.name + '\0' + f.text + '\0';
  return text;
}

// Cache keys become file names: anything but [A-Za-z0-9_] in a user-given name becomes '_' (the
// hash still tells such names apart).
std::string file_name_safe(const std::string& s) {
  std::string out = s.empty() ? "default" : s;
  for (char& ch : out)
    if (!std::isalnum(uint8_t(ch)) && ch != '_') ch = '_';
  return out;
}

// A fresh directory under the cache for one run's Verilog; removed with everything in it when the
// run ends. mkdtemp keeps concurrent runs of the same configuration apart.
class WorkDir {
 public:
  WorkDir(const fs::path& parent, const std::string& key) {
    make_directory(parent);
    std::string pattern = (parent / (key + ".XXXXXX")).string();
    if (!mkdtemp(pattern.data()))
      throw SynthError(fmt::format("cannot create a work directory in {}: {}", quoted(parent.string()),
                                   std::strerror(errno)));
    path_ = pattern;
  }
  ~WorkDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  WorkDir(const WorkDir&) = delete;
  WorkDir& operator=(const WorkDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// One file per module plus filelist.f, the layout fpstereo-rtl -o writes.
fs::path write_design(const fs::path& dir, const std::vector<rtl::EmittedFile>& files) {
  std::string filelist;
  for (const auto& f : files) {
    write_text(dir / f.name, f.text);
    filelist += f.name + "\n";
  }
  write_text(dir / "filelist.f", filelist);
  return dir / "filelist.f";
}

// Runs args[0] (searched in PATH) with stdin from /dev/null and stdout/stderr into files; returns
// the wait status. Files rather than pipes: nothing to drain while Yosys runs for minutes. The
// child leads its own process group, which gets every signal we get (SignalsDeferred): the script
// and Yosys end with us. `waiting`, when given, is called twice a second while the process runs.
int run_process(const std::vector<std::string>& args, const fs::path& out, const fs::path& err,
                const std::function<void()>& waiting = {}) {
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (rc != 0) throw SynthError(fmt::format("cannot run {}: {}", args[0], std::strerror(rc)));
  const ChildGroup group(pid);
  if (interrupted()) ::kill(-pid, interrupted());  // arrived before the group was known
  int status = 0;
  for (pid_t done; (done = waitpid(pid, &status, waiting ? WNOHANG : 0)) != pid;) {
    if (done < 0 && errno != EINTR)
      throw SynthError(fmt::format("waiting for {}: {}", args[0], std::strerror(errno)));
    if (done == 0 && !interrupted()) {
      waiting();
      usleep(500000);
    }
  }
  if (interrupted()) throw SynthError(fmt::format("interrupted by signal {}", interrupted()));
  return status;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  return lines;
}

// The script ends every failure with one line of its own ("synth-yosys: ..."); pass it on as is.
std::string failure_message(const std::string& stderr_text, int status) {
  const std::vector<std::string> lines = lines_of(stderr_text);
  if (!lines.empty()) return lines.back();
  if (WIFSIGNALED(status)) return fmt::format("synth-yosys.sh was killed by signal {}", WTERMSIG(status));
  return fmt::format("synth-yosys.sh failed with exit status {}", WEXITSTATUS(status));
}

// A failed run's message names Yosys' log in the work directory, which goes with it: the log moves
// to the cache's failed/TAG.log (the last failure of each configuration) and the message says so.
std::string kept_log(std::string message, const fs::path& work, const fs::path& cache_dir,
                     const std::string& tag) {
  const std::string log = (work / "yosys.log").string();
  const size_t at = message.find(log);
  if (at == std::string::npos) return message;
  const fs::path kept = cache_dir / "failed" / (tag + ".log");
  std::error_code error;
  fs::create_directories(kept.parent_path(), error);
  if (!error) fs::rename(log, kept, error);
  return message.replace(at, log.size(), error ? "removed with the work directory" : kept.string());
}

// The script's warnings as "warning=..." record lines, so a cached report repeats them.
std::string warning_lines(const std::string& stderr_text) {
  std::string out;
  const size_t prefix = std::strlen(kScriptWarningPrefix);
  for (const auto& line : lines_of(stderr_text))
    if (line.compare(0, prefix, kScriptWarningPrefix) == 0) out += "warning=" + line.substr(prefix) + "\n";
  return out;
}

// The logic depth of the mapped netlist as record lines. Not analysing costs only these figures,
// so a failure (a combinational loop, say) becomes a warning.
std::string depth_lines(const fs::path& netlist) {
  try {
    const std::optional<std::string> json = read_text(netlist);
    if (!json) throw LogicDepthError(fmt::format("cannot read '{}'", netlist.string()));
    const LogicDepth d = analyse_logic_depth(*json, kWorstPaths);
    std::string out = fmt::format("depth_levels={}\ndepth_levels_with_carry={}\n", d.levels, d.levels_with_carry);
    for (size_t i = 0; i < d.worst.size(); ++i) out += fmt::format("path.{}={}\n", i + 1, path_value(d.worst[i]));
    if (!d.worst.empty()) out += "carry_path=" + path_value(d.worst_with_carry) + "\n";
    return out;
  } catch (const LogicDepthError& e) {
    return fmt::format("depth_levels=na\ndepth_levels_with_carry=na\nwarning=logic depth not analysed: {}\n",
                       e.what());
  }
}

// ---- the cache -------------------------------------------------------------------------------

// A cache record is the script's --kv output plus config=, synth_seconds= and warning= lines.
struct Record {
  std::string text;
  SynthReport report;
};

// A record that does not parse (written by an incompatible version) or is no regular file (a
// pipe would block the read) is a miss, not an error.
std::optional<Record> load_record(const fs::path& path) {
  try {
    const std::string text = read_regular_file(path, "cache record", kMaxTextFileBytes);
    return Record{text, parse_kv(text)};
  } catch (const FileError&) {
    return std::nullopt;
  } catch (const SynthError&) {
    return std::nullopt;
  }
}

// Atomic, as concurrent runs may store the same record. A failure costs only the cache, so it warns.
void store_record(const fs::path& path, const std::string& text) {
  try {
    write_file_atomically(path, text);
  } catch (const FileError& e) {
    std::cerr << fmt::format("{}: warning: cannot store the result: {}\n", kTool, one_line(e.what()));
  }
}

// ---- the command -----------------------------------------------------------------------------

// Yosys writes the netlist and the log into the work directory; run() copies them to --netlist and
// --log only after a success, so a failed or interrupted run leaves the previous files as they were.
std::vector<std::string> script_args(const SynthOptions& o, const fs::path& script, const fs::path& filelist,
                                     const fs::path& work) {
  std::vector<std::string> args = {"bash", script.string(), "--kv", "--netlist", (work / "netlist.json").string()};
  if (!o.family.empty()) args.insert(args.end(), {"--family", o.family});
  if (!o.part.empty()) args.insert(args.end(), {"--part", o.part});
  if (o.uram) args.push_back("--uram");
  if (o.hierarchical) args.push_back("--hierarchical");
  if (!o.log.empty()) args.insert(args.end(), {"--log", (work / "yosys.log").string()});
  args.push_back(filelist.string());
  return args;
}

Record synthesise(const SynthOptions& o, const StereoConfig& cfg, const std::vector<rtl::EmittedFile>& files,
                  const fs::path& script, const fs::path& cache_dir, const std::string& key, OutputSet& outputs) {
  const WorkDir work(cache_dir / "work", key);
  const fs::path filelist = write_design(work.path(), files);
  const std::string tag = config_tag(cfg);
  // Progress only on a terminal: to a script, a failure stays exactly one line on stderr.
  const bool progress = isatty(STDERR_FILENO);
  // There, the pass Yosys is in, from its log, which Yosys writes into the work directory whenever
  // a log is asked for (script_args): on a terminal one always is.
  SynthOptions logged = o;
  if (progress && logged.log.empty()) logged.log = "yosys.log";
  YosysProgress shown((work.path() / "yosys.log").string(), fmt::format("{} synth: {}", kTool, tag));
  const auto start = std::chrono::steady_clock::now();
  const fs::path netlist = work.path() / "netlist.json";
  const int status = run_process(script_args(logged, script, filelist, work.path()), work.path() / "synth.out",
                                 work.path() / "synth.err", progress ? [&] { shown.update(); } : std::function<void()>());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (progress) {
    shown.finish();
    std::cerr << fmt::format("{} synth: {}: Yosys {:.1f} s\n", kTool, tag, seconds);
  }
  const std::string out = read_text(work.path() / "synth.out").value_or("");
  const std::string err = read_text(work.path() / "synth.err").value_or("");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw SynthError(kept_log(failure_message(err, status), work.path(), cache_dir, tag));
  const std::string text = fmt::format("config={}\n{}synth_seconds={:.1f}\n{}{}", tag, out, seconds,
                                       depth_lines(netlist), warning_lines(err));
  if (!o.netlist.empty()) outputs.stage_copy(o.netlist, netlist);
  if (!o.log.empty()) outputs.stage_copy(o.log, work.path() / "yosys.log");
  return Record{text, parse_kv(text)};
}

// --kv prints the record (warnings go to stderr, as the script does) and whether it was cached.
std::string kv_output(const Record& record, bool cached) {
  std::string out;
  for (const auto& line : lines_of(record.text))
    if (line.rfind("warning=", 0) != 0) out += line + "\n";
  return out + fmt::format("cached={}\n", cached ? 1 : 0);
}

void print(const Record& record, bool cached, bool kv) {
  for (const auto& w : record.report.warnings)
    std::cerr << kScriptPrefix << "warning: " << one_line(w) << "\n";
  std::cout << (kv ? kv_output(record, cached) : format_report(record.report, cached)) << std::flush;
}

void run(const SynthOptions& o) {
  const SignalsDeferred deferred;  // a signal ends Yosys, then this run unwinds and removes its files
  const StereoConfig cfg = o.config.resolve();
  OutputSet outputs;
  o.config.declare_input(outputs);
  if (!o.netlist.empty()) outputs.add_file(o.netlist, "--netlist");
  if (!o.log.empty()) outputs.add_file(o.log, "--log");
  const std::vector<rtl::EmittedFile> files = rtl::emit(rtl::plan(cfg));
  const fs::path script = synth_script_path();
  const std::optional<std::string> script_text = read_text(script);
  if (!script_text) throw SynthError(fmt::format("cannot read {}", quoted(script.string())));
  const std::string key =
      cache_key(cfg, o.family, o.part, o.uram, o.hierarchical, verilog_text(files), *script_text);
  const fs::path cache = o.cache_dir.empty() ? cache_dir("synth") : fs::path(o.cache_dir);
  create_cache_directory(cache);
  const fs::path record_path = cache / (key + ".kv");

  // A log or netlist exists only if Yosys runs, so asking for one bypasses the cache too.
  std::optional<Record> record;
  if (!o.no_cache && o.log.empty() && o.netlist.empty()) record = load_record(record_path);
  const bool cached = record.has_value();
  if (!cached) {
    record = synthesise(o, cfg, files, script, cache, key, outputs);
    outputs.commit();
    store_record(record_path, record->text);
  }
  print(*record, cached, o.kv);
}

}  // namespace

std::string verilog_hash(const StereoConfig& cfg) {
  // What Yosys builds from: the Verilog files' code. Comments, the configuration's module prefix
  // and its hash (of every parameter; also the CONFIG_ID register's value) are left out, so that a
  // new parameter, which renames the modules, changes that constant and adds a banner line, leaves
  // recorded results current.
  const rtl::RtlDesign plan = rtl::plan(cfg);
  const std::string id = plan.prefix.substr(plan.prefix.rfind('_') + 1);
  auto replace_all = [](std::string& text, const std::string& from, const std::string& to) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
  };
  auto normalised = [&](std::string text) {
    replace_all(text, plan.prefix, "PREFIX");
    replace_all(text, id, "ID");
    return text;
  };
  std::string code;
  for (const auto& file : rtl::emit(plan)) {
    if (!ends_with(file.name, ".v")) continue;
    code += normalised(file.name) + '\0';
    for (const std::string& line : lines_of(file.text)) {
      const std::string kept = normalised(line.substr(0, line.find("//")));
      if (kept.find_first_not_of(" \t") != std::string::npos) code += kept + '\n';
    }
  }
  return fmt::format("{:016x}", fnv1a64(code));
}

std::string run_child_command(const std::vector<std::string>& args) {
  const SignalsDeferred deferred;
  const WorkDir work(fs::temp_directory_path(), "fpstereo-child");
  const int status = run_process(args, work.path() / "out", work.path() / "err");
  const std::string out = read_text(work.path() / "out").value_or("");
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return out;
  const std::vector<std::string> lines = lines_of(read_text(work.path() / "err").value_or("") + out);
  throw SynthError(!lines.empty()              ? lines.back()
                   : WIFSIGNALED(status) ? fmt::format("{} was killed by signal {}", args[0], WTERMSIG(status))
                                         : fmt::format("{} failed with exit status {}", args[0], WEXITSTATUS(status)));
}

SynthReport parse_kv(const std::string& text) {
  KvMap kv;
  SynthReport r;
  for (const auto& line : lines_of(text)) {
    const size_t eq = line.find('=');
    if (eq == std::string::npos || eq == 0)
      throw SynthError(fmt::format("synthesis report: malformed line {}", quoted(line)));
    const std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    if (key.rfind("mem.", 0) == 0)
      r.memories.push_back(parse_memory(key.substr(4), value));
    else if (key.rfind("path.", 0) == 0)
      r.worst_paths.push_back(parse_path(key, value));
    else if (key == "warning")
      r.warnings.push_back(value);
    else
      kv[key] = value;
  }
  fill_part(kv, r);
  fill_counts(kv, r);
  fill_percentages(kv, r);
  r.delay_ps = integer_or_na(kv, "delay_ps");
  r.levels = integer_or_na(kv, "levels");
  r.levels_with_carry = integer_or_na(kv, "levels_with_carry");
  // Added by fpstereo after the script, so absent from the script's own output.
  if (kv.count("depth_levels")) r.depth_levels = integer_or_na(kv, "depth_levels");
  if (kv.count("depth_levels_with_carry")) r.depth_levels_with_carry = integer_or_na(kv, "depth_levels_with_carry");
  if (kv.count("carry_path")) r.worst_carry_path = parse_path("carry_path", kv["carry_path"]);
  if (kv.count("config")) r.config = kv["config"];
  if (kv.count("hierarchical")) r.hierarchical = integer(kv, "hierarchical") != 0;
  if (kv.count("synth_seconds")) r.synth_seconds = parse_number<double>("synth_seconds", kv["synth_seconds"]);
  return r;
}

std::string format_report(const SynthReport& r, bool cached) {
  const char* flow = r.hierarchical ? "per module, then flattened" : "-flatten";
  std::string out = fmt::format("{} on {} ({}), Yosys synth_xilinx -abc9 {}{}\n", r.top, r.part, r.family, flow,
                                cached ? " (cached)" : "");
  out += fmt::format("  {:<13} {:>9} {:>8} {:>7}\n", "resource", "used", "of", "util");
  out += resource_row("LUT", std::to_string(r.lut), r.part_lut, r.lut_pct,
                      "LUT1..LUT6 cells " + r.lut_by_inputs);
  out += resource_row("LUT min", std::to_string(r.lut_min), r.part_lut, r.lut_min_pct,
                      "LUT6 + half of LUT1..5 (ideal pairing)");
  out += resource_row("LUTRAM", std::to_string(r.lutram), r.part_lutram, r.lutram_pct,
                      "LUTs as memory: " + (r.lutram_cells.empty() ? "none" : r.lutram_cells));
  out += resource_row("FF", std::to_string(r.ff), r.part_ff, r.ff_pct, r.latches ? "includes latches" : "");
  out += resource_row("BRAM18", std::to_string(r.bram18), 2 * r.part_bram36, r.bram18_pct, "");
  out += resource_row("BRAM36", std::to_string(r.bram36), r.part_bram36, r.bram36_pct, "");
  out += resource_row("BRAM36 equiv", fmt::format("{}", r.bram36_equiv), r.part_bram36, r.bram36_equiv_pct,
                      "BRAM36 + BRAM18/2");
  out += resource_row("URAM", std::to_string(r.uram), r.part_uram, r.uram_pct, "URAM288");
  out += resource_row("DSP", std::to_string(r.dsp), r.part_dsp, r.dsp_pct, "");
  out += resource_row("CARRY4 equiv", std::to_string(r.carry4_equiv), r.part_lut / 4, r.carry_pct,
                      fmt::format("CARRY4 {} + 2 x CARRY8 {}", r.carry4, r.carry8));
  return out + abc9_rows(r) + depth_rows(r) + memory_rows(r.memories);
}

std::filesystem::path synth_script_path() {
  return std::filesystem::path(FPSTEREO_SOURCE_DIR) / "scripts" / "synth-yosys.sh";
}

std::string cache_key(const StereoConfig& cfg, const std::string& family, const std::string& part, bool uram,
                      bool hierarchical, const std::string& verilog_text, const std::string& script_text) {
  // The configuration is hashed in full too: config_tag's own hash is only 24 bits.
  const std::string decisive = describe(cfg) + '\0' + family + '\0' + part + '\0' + (uram ? "uram" : "") + '\0' +
                               (hierarchical ? "hierarchical" : "") + '\0' + verilog_text + '\0' + script_text +
                               '\0' + part_table_text() + '\0' + kLogicDepthModel;
  return fmt::format("{}-{}-{}{}{}-{:016x}", config_tag(cfg), file_name_safe(family), file_name_safe(part),
                     uram ? "-uram" : "", hierarchical ? "-hierarchical" : "", fnv1a64(decisive));
}

void register_synth_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<SynthOptions>();
  CLI::App* sub = app.add_subcommand(
      "synth",
      "Synthesise the configuration's Verilog with Yosys (scripts/synth-yosys.sh) and report LUT, FF, "
      "LUTRAM, BRAM, DSP and carry use on an FPGA part, with abc9's logic delay and the deepest "
      "register-to-register paths of the mapped netlist; results are cached");
  o->config.add_to(*sub);
  sub->add_option("--family", o->family, "xcup (UltraScale+, the default) or xc7 (7 series)")
      ->type_name("NAME");
  sub->add_option("--part", o->part, "part for the percentages: " + part_list())->type_name("NAME");
  sub->add_flag("--uram", o->uram,
                "let Yosys map large memories to UltraRAM (synth_xilinx -uram): UltraScale+ parts that have it, "
                "e.g. --part xczu7ev");
  sub->add_flag("--hierarchical", o->hierarchical,
                "map each module once per parameter set, then flatten the mapped netlist (synth_xilinx without "
                "-flatten): for designs too large to flatten first; no optimisation across modules, so LUTs and "
                "depth are at or above a flat run's, and memories are listed per module");
  sub->add_option("--cache", o->cache_dir, "cache directory [" + cache_dir_rule("synth") + "]")
      ->type_name("DIR");
  sub->add_flag("--no-cache", o->no_cache, "run Yosys even if a cached result exists (and refresh it)");
  sub->add_flag("--kv", o->kv,
                "print key=value lines (synth-yosys.sh --kv, plus config, synth_seconds, the logic depth and its "
                "paths, cached)");
  sub->add_option("--log", o->log, "keep Yosys' log in FILE (runs Yosys even if a result is cached)")
      ->type_name("FILE")
      ->check(output_file_name());
  sub->add_option("--netlist", o->netlist,
                  "keep the mapped netlist (Yosys JSON) in FILE (runs Yosys even if a result is cached)")
      ->type_name("FILE")
      ->check(output_file_name());
  sub->footer(
      "A result is cached under the configuration, family, part and a hash of the emitted Verilog and of the "
      "script, so a changed generator never serves a stale report. Progress goes to stderr when it is "
      "a terminal.");
  sub->callback([o, &exit_code] {
    try {
      run(*o);
      exit_code = 0;
    } catch (const ConfigError& e) {
      exit_code = report_error(kTool, std::string("invalid config: ") + e.what());
    } catch (const SynthError& e) {
      exit_code = report_error(kTool, e.what());
    } catch (const FileError& e) {
      exit_code = report_error(kTool, e.what());
    }
  });
}

}  // namespace fpstereo
