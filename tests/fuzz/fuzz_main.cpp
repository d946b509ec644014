// fpstereo-fuzz: a mutation fuzzer over what users hand to fpstereo and fpstereo-rtl: files
// (images, ground-truth disparities, JSON/TOML configurations, pairs.csv) and command lines (the
// args target: one argument per line). Each input is a seed from the corpus with a few random
// mutations. Files are read in-process by the same functions the command line calls, and every
// Nth one also goes through the real command line in a child process; command lines always do.
//
// A finding is a crash (signal, or a sanitizer report in a sanitizer build), a hang (the input
// takes longer than --timeout), an exception other than the tools' own error types, an error
// message that is not one line, or a command-line exit status other than 0 and 2. Findings are
// saved under WORK/findings; the input being read is in WORK/<target>/ (current.* or pairs.csv)
// so a crash can be replayed. Exit status: 0 without findings, 1 with findings, 2 on bad usage.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "config.hpp"
#include "dataset.hpp"
#include "files.hpp"
#include "image_io.hpp"
#include "text.hpp"

namespace fs = std::filesystem;
using Bytes = std::string;

namespace {

// --- The targets -------------------------------------------------------------------------------

// What the command line would do with `path`, read in-process. Throws the tools' own error
// types on rejected input; anything else escaping is a finding.
struct Target {
  std::string name;
  std::vector<std::string> dictionary;  // tokens the mutator inserts
  std::function<void(const std::string& path)> read;
  // The command line run on the input, the tool first ("fpstereo" or "fpstereo-rtl"); it runs in
  // `dir`, which holds the input as named by `input_name(ext)` and the fixed files it needs.
  std::function<std::vector<std::string>(const std::string& dir, const std::string& input)> command;
  bool stderr_progress = false;  // the command reports progress on stderr: only its last line is the error
  bool always_exec = false;      // every input runs through the command line, not every Nth
};

const std::vector<std::string> kSmallDesign = {"--width", "64", "--height", "64",
                                               "--dmax",  "16", "--uf",     "4"};

std::vector<std::string> with_small_design(std::vector<std::string> args) {
  args.insert(args.end(), kSmallDesign.begin(), kSmallDesign.end());
  return args;
}

// An args input: one argument per line, the tool first.
std::vector<std::string> command_line(const std::string& path) {
  std::vector<std::string> args;
  std::istringstream in(fpstereo::read_regular_file(path, "args", 1 << 20));
  for (std::string line; std::getline(in, line);) args.push_back(line);
  return args;
}

// A mutated command line must neither run for long nor write outside its folder: synth and dse
// (Yosys, sweeps) become config, and an argument with a slash (a path) outside /dev loses its
// slashes. Anything but fpstereo-rtl as the tool is fpstereo.
std::vector<std::string> contained(std::vector<std::string> args) {
  if (args.empty() || (args[0] != "fpstereo" && args[0] != "fpstereo-rtl"))
    args.insert(args.begin(), "fpstereo");
  for (std::size_t i = 1; i < args.size(); ++i) {
    std::string& a = args[i];
    if (a == "synth" || a == "dse") a = "config";
    const bool device = a.rfind("/dev/", 0) == 0 && a.find("..") == std::string::npos;
    if (!device) std::replace(a.begin(), a.end(), '/', '_');
  }
  return args;
}

std::vector<Target> make_targets() {
  const std::vector<std::string> image_tokens = {"IHDR",
                                                 "IDAT",
                                                 "IEND",
                                                 "PLTE",
                                                 "tRNS",
                                                 "iCCP",
                                                 "P5\n",
                                                 "P2\n",
                                                 "P6\n",
                                                 "65535",
                                                 "4294967295",
                                                 "99999 99999",
                                                 "0 0",
                                                 "-1",
                                                 "#",
                                                 "\n",
                                                 " ",
                                                 "\xff\xff\xff\xff",
                                                 "\x7f\xff\xff\xff",
                                                 "\0\0\0\0"};
  const std::vector<std::string> pfm_tokens = {"Pf\n",        "PF\n",         "-1.0", "1.0",   "0",
                                               "-0",          "nan",          "inf",  "1e309", "-1e-45",
                                               "99999 99999", "2147483647 2", "\n"};
  const std::vector<std::string> config_tokens = {
      "{",          "}",      "[",          "]",          "\"",    ",",       ":",
      "=",          "\n",     "\\u0000",    "\\",         "'''",   "\"\"\"",  "[[a]]",
      "[t]",        "preset", "\"C2\"",     "\"\"",       "dmax",  "uf",      "p1",
      "p2",         "width",  "height",     "cost",       "paths", "\"all\"", "window",
      "median",     "lr",     "uniqueness", "gap-interp", "1e309", "-1",      "18446744073709551609",
      "2147483648", "0x10",   "+64",        " 64",        "nan",   "inf",     "true",
      "null",       "1.5",    "2026-11-23", "#"};
  const std::vector<std::string> csv_tokens = {
      ",",      "\n",     "\r\n",     "\"",       "\0",         "\t",          "pair",   "left", "right",
      "gt_occ", "gt_noc", "noc_mask", "gt_scale", "gt_invalid", "max_disp_px", "inf",    "nan",  "-1",
      "0",      "none",   "1e309",    "../",      "/",          "left.png",    "gt.pfm", "p"};
  const std::vector<std::string> args_tokens = {"\n--preset\n",
                                                "\n--config\n",
                                                "\n--width\n",
                                                "\n--height\n",
                                                "\n--cost\n",
                                                "\n--window\n",
                                                "\n--shd-window\n",
                                                "\n--dmax\n",
                                                "\n--uf\n",
                                                "\n--paths\n",
                                                "\n--p1\n",
                                                "\n--p2\n",
                                                "\n--lr\n",
                                                "\n--lr-threshold\n",
                                                "\n--uniqueness\n",
                                                "\n--median\n",
                                                "\n--gap-interp\n",
                                                "\n-o\n",
                                                "\n--colour\n",
                                                "\n--pfm\n",
                                                "\n--gray-pgm\n",
                                                "\n--json\n",
                                                "\n--csv\n",
                                                "\n--pairs\n",
                                                "\n--baseline\n",
                                                "\n--sgbm-mode\n",
                                                "\n--sgbm-block\n",
                                                "\n--sgbm-p1\n",
                                                "\n--emit\n",
                                                "\n--part\n",
                                                "\n--clock-mhz\n",
                                                "\n--no-axi-lite\n",
                                                "\n--help\n",
                                                "\n--\n",
                                                "\nrun\n",
                                                "\neval\n",
                                                "\nconfig\n",
                                                "\nmerge\n",
                                                "\n\n",
                                                "0",
                                                "-1",
                                                "99999999999999999999",
                                                "1e9",
                                                "nan",
                                                "0,",
                                                "+64",
                                                " 64",
                                                "C2",
                                                "all",
                                                "hls",
                                                "/dev/null",
                                                "/dev/full",
                                                "/dev/zero",
                                                "left.png",
                                                "gt.pfm",
                                                "pairs.csv",
                                                ".",
                                                "..",
                                                "\t",
                                                "\x01",
                                                "="};
  std::vector<Target> targets;
  targets.push_back({"image", image_tokens,
                     [](const std::string& path) {
                       const fpstereo::GrayImage image = fpstereo::load_gray(path, "left image");
                       fpstereo::StereoConfig cfg;
                       cfg.width = 64, cfg.height = 64, cfg.dmax = 16, cfg.uf = 4;
                       fpstereo::check_pair(image, image, cfg);
                     },
                     [](const std::string& dir, const std::string& input) {
                       return with_small_design({"fpstereo", "run", input, input, "-o", dir + "/out.png",
                                                 "--pfm", dir + "/out.pfm"});
                     }});
  targets.push_back({"disparity", pfm_tokens,
                     [](const std::string& path) {
                       fpstereo::read_disparity(path, 256, "0");
                       fpstereo::read_disparity(path, 1, "inf");
                     },
                     [](const std::string& dir, const std::string& input) {
                       // A one-pair dataset whose ground truth is the input.
                       std::ofstream(dir + "/pairs.csv")
                           << "pair,left,right,gt_occ,gt_noc,noc_mask,gt_scale,gt_invalid,max_disp_px\n"
                           << "p,left.png,right.png," << fs::path(input).filename().string() << ",,,256,0,\n";
                       return with_small_design({"fpstereo", "eval", dir});
                     },
                     true});
  targets.push_back({"config", config_tokens,
                     [](const std::string& path) {
                       const fpstereo::StereoConfig cfg = fpstereo::compose_config(std::nullopt, path, {});
                       fpstereo::validate(cfg);
                       fpstereo::describe(cfg);
                       fpstereo::config_tag(cfg);
                     },
                     [](const std::string&, const std::string& input) {
                       return std::vector<std::string>{"fpstereo", "config", "--config", input};
                     }});
  targets.push_back({"pairs", csv_tokens,
                     [](const std::string& path) { fpstereo::read_pairs_csv(fs::path(path).parent_path()); },
                     [](const std::string& dir, const std::string&) {
                       return with_small_design({"fpstereo", "eval", dir});
                     },
                     true});
  targets.push_back(
      {"args", args_tokens, [](const std::string& path) { command_line(path); },
       [](const std::string&, const std::string& input) { return contained(command_line(input)); }, false,
       true});
  return targets;
}

// The file name an input of `target` is read from: pairs.csv must be called so.
std::string input_name(const std::string& target, const std::string& extension) {
  return target == "pairs" ? "pairs.csv" : "current" + extension;
}

// --- Mutations ---------------------------------------------------------------------------------

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed) : rng_(seed) {}

  std::size_t below(std::size_t n) {
    return n ? std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_) : 0;
  }
  bool one_in(std::size_t n) { return below(n) == 0; }

  // 1 to 8 stacked mutations; `other` is another seed of the same target, for splicing.
  Bytes mutate(Bytes data, const Bytes& other, const std::vector<std::string>& dictionary, bool png) {
    if (png && one_in(3)) mutate_png_pixels(data);
    const std::size_t count = one_in(2) ? 1 : 2 + below(7);  // often one: most inputs stay near valid
    for (std::size_t i = 0; i < count; ++i) mutate_once(data, other, dictionary);
    if (png && !one_in(4)) fix_png_crcs(data);  // else libpng stops at the first CRC
    return data;
  }

 private:
  void mutate_once(Bytes& d, const Bytes& other, const std::vector<std::string>& dictionary) {
    static const unsigned char kInteresting[] = {0, 1, 2, 0x7f, 0x80, 0xff, '0', '9', '-', ' ', '\n', '\r'};
    const std::size_t at = below(d.size() + 1);
    switch (below(10)) {
      case 0:
        if (!d.empty()) d[below(d.size())] ^= static_cast<char>(1u << below(8));
        break;
      case 1:
        if (!d.empty()) d[below(d.size())] = static_cast<char>(kInteresting[below(sizeof kInteresting)]);
        break;
      case 2:
        for (std::size_t n = 1 + below(8); n--;) d.insert(d.begin() + at, static_cast<char>(below(256)));
        break;
      case 3:
        if (!d.empty()) d.erase(at < d.size() ? at : 0, 1 + below(16));
        break;
      case 4: {  // copy a block of the input elsewhere
        if (d.empty()) break;
        const std::size_t from = below(d.size());
        d.insert(at, d.substr(from, 1 + below(32)));
        break;
      }
      case 5:
        d.resize(below(d.size() + 1));
        break;
      case 6:
      case 7:
        d.insert(at, dictionary[below(dictionary.size())]);
        break;
      case 8:  // splice: this input's head, the other's tail
        if (!other.empty()) d = d.substr(0, at) + other.substr(below(other.size()));
        break;
      case 9: {  // deep balanced nesting (recursive readers and writers), or a long run of one byte
        const std::size_t depth = one_in(4) ? 100000 : 1 + below(2000);
        if (one_in(2))
          d.insert(at, std::string(depth, '[') + std::string(depth, ']'));
        else
          d.insert(at, std::string(depth, "[{\"0 \n"[below(6)]));
        break;
      }
    }
  }

  // Rewrites the decompressed scanlines of the PNG's IDAT (filter bytes included): libpng's
  // unfiltering and OpenCV's conversion see damaged pixels rather than a broken zlib stream.
  void mutate_png_pixels(Bytes& d) {
    std::size_t pos = 8;
    while (pos + 12 <= d.size()) {
      const std::size_t len = chunk_length(d, pos);
      if (len > d.size() - pos - 12) return;
      if (d.compare(pos + 4, 4, "IDAT") == 0) {
        Bytes raw(1 << 16, '\0');
        uLongf raw_len = raw.size();
        if (uncompress(reinterpret_cast<Bytef*>(raw.data()), &raw_len,
                       reinterpret_cast<const Bytef*>(d.data() + pos + 8), len) != Z_OK)
          return;
        raw.resize(raw_len);
        for (std::size_t n = 1 + below(4); n-- && !raw.empty();)
          raw[below(raw.size())] = static_cast<char>(below(256));
        if (one_in(4)) raw.resize(below(raw.size() + 1));
        if (one_in(8)) raw.append(below(64), '\0');
        Bytes packed(compressBound(raw.size()), '\0');
        uLongf packed_len = packed.size();
        compress(reinterpret_cast<Bytef*>(packed.data()), &packed_len,
                 reinterpret_cast<const Bytef*>(raw.data()), raw.size());
        packed.resize(packed_len);
        d.replace(pos, len + 12, Bytes(4, '\0') + "IDAT" + packed + Bytes(4, '\0'));
        put_u32(d, pos, packed.size());
        return;
      }
      pos += len + 12;
    }
  }

  static std::size_t chunk_length(const Bytes& d, std::size_t pos) {
    std::size_t n = 0;
    for (int i = 0; i < 4; ++i) n = n << 8 | static_cast<unsigned char>(d[pos + i]);
    return n;
  }
  static void put_u32(Bytes& d, std::size_t pos, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) d[pos + i] = static_cast<char>(v >> (24 - 8 * i));
  }
  static void fix_png_crcs(Bytes& d) {
    std::size_t pos = 8;
    while (pos + 12 <= d.size()) {
      const std::size_t len = chunk_length(d, pos);
      if (len > d.size() - pos - 12) return;
      const uLong crc = crc32(0, reinterpret_cast<const Bytef*>(d.data() + pos + 4), len + 4);
      put_u32(d, pos + 8 + len, static_cast<std::uint32_t>(crc));
      pos += len + 12;
    }
  }

  std::mt19937_64 rng_;
};

// --- Running inputs ----------------------------------------------------------------------------

// The input being read, for the crash and hang handlers (which may only use async-signal-safe calls).
char g_current_input[4096] = "";

void say(const char* text) {
  if (write(STDERR_FILENO, text, std::strlen(text)) < 0) return;
}

void on_crash(int sig) {
  say("fpstereo-fuzz: FINDING: crash (");
  say(strsignal(sig));
  say(") reading ");
  say(g_current_input);
  say("\n");
  signal(sig, SIG_DFL);
  raise(sig);
}

void on_hang(int) {
  say("fpstereo-fuzz: FINDING: hang reading ");
  say(g_current_input);
  say("\n");
  _exit(1);
}

bool is_one_line(const std::string& message) {
  return !message.empty() && message.find_first_of("\n\r") == std::string::npos;
}

struct Outcome {
  bool accepted = false;
  std::string finding;  // empty: accepted, or properly rejected
};

// A rejection by the tools' own error types is proper if its message is one line.
Outcome rejected(const std::exception& e) {
  return {false, is_one_line(e.what()) ? "" : std::string("error message not one line: ") + e.what()};
}

// Reads the input in-process as the command line would.
Outcome read_in_process(const Target& target, const std::string& path) {
  try {
    target.read(path);
    return {true, ""};
  } catch (const fpstereo::InputError& e) {
    return rejected(e);
  } catch (const fpstereo::ConfigError& e) {
    return rejected(e);
  } catch (const fpstereo::FileError& e) {
    return rejected(e);
  } catch (const std::exception& e) {
    return {false, std::string("unexpected exception: ") + e.what()};
  } catch (...) {
    return {false, "unexpected non-standard exception"};
  }
}

std::string with_command(const std::string& what, const std::vector<std::string>& args) {
  std::string text = what + " [";
  for (const auto& a : args)  // the saved input has it whole
    text +=
        (&a == &args.front() ? "" : " ") + fpstereo::quoted(a.size() > 200 ? a.substr(0, 200) + "..." : a);
  return text + "]";
}

// The child's exit status when the kernel refuses the arguments (an argument over 128 KiB).
constexpr int kArgsTooLong = 125;

// Runs the command line in a child process: accepted is exit 0. With `must_accept` (seeds), a
// proper rejection (exit 2) is a finding too.
Outcome run_command(const fs::path& tools_dir, const std::vector<std::string>& args, const fs::path& cwd,
                    bool progress_on_stderr, const fs::path& err_file, int timeout_s,
                    bool must_accept = false) {
  const std::string program = (tools_dir / args.at(0)).string();
  const pid_t pid = fork();
  if (pid < 0) return {false, std::string("fork failed: ") + std::strerror(errno)};
  if (pid == 0) {
    const int in = open("/dev/null", O_RDONLY);
    const int null = open("/dev/null", O_WRONLY);
    const int err = open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(in, STDIN_FILENO);
    dup2(null, STDOUT_FILENO);
    dup2(err, STDERR_FILENO);
    alarm(0);
    if (chdir(cwd.c_str()) != 0) _exit(126);
    std::vector<char*> argv{const_cast<char*>(program.c_str())};
    for (std::size_t i = 1; i < args.size(); ++i) argv.push_back(const_cast<char*>(args[i].c_str()));
    argv.push_back(nullptr);
    execv(program.c_str(), argv.data());
    _exit(errno == E2BIG ? kArgsTooLong : 127);
  }
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_s);
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      return Outcome{
          false, with_command("hang: command did not finish in " + std::to_string(timeout_s) + " s", args)};
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  std::string err = fpstereo::read_regular_file(err_file.string(), "stderr", 1 << 20);
  while (!err.empty() && err.back() == '\n') err.pop_back();
  if (progress_on_stderr)
    err = err.substr(err.find_last_of('\n') == std::string::npos ? 0 : err.find_last_of('\n') + 1);
  if (WIFSIGNALED(status))
    return Outcome{false,
                   with_command(std::string("killed by ") + strsignal(WTERMSIG(status)) + ": " + err, args)};
  const int code = WEXITSTATUS(status);
  if (code == 0) return {true, ""};
  if (code == kArgsTooLong && !must_accept) return {};  // the kernel's limit, not ours
  if (code != 2)
    return Outcome{false, with_command("exit status " + std::to_string(code) + ": " + err, args)};
  if (must_accept) return Outcome{false, with_command("rejected: " + err, args)};
  return {false, is_one_line(err) ? "" : with_command("rejection is not one line: " + err, args)};
}

struct Seed {
  fs::path path;
  Bytes bytes;
};

struct Options {
  std::string corpus, work = "fuzz-work", program;
  std::size_t runs = 10000, exec_every = 0;
  std::vector<std::string> targets;  // empty: all
  std::uint64_t seed = 1;
  double max_seconds = 0;
  int timeout_s = 10;
};

Bytes read_file(const fs::path& path) { return fpstereo::read_regular_file(path.string(), "seed", 1 << 20); }

void write_file(const fs::path& path, const Bytes& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

// Seeds of every target: CORPUS/<target>/*, sorted so that a run is reproducible from --seed.
std::map<std::string, std::vector<Seed>> load_corpus(const std::string& corpus,
                                                     const std::vector<Target>& targets) {
  std::map<std::string, std::vector<Seed>> seeds;
  for (const auto& t : targets) {
    const fs::path dir = fs::path(corpus) / t.name;
    if (!fs::is_directory(dir)) throw std::runtime_error("corpus '" + corpus + "': no folder " + t.name);
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.is_regular_file()) seeds[t.name].push_back({entry.path(), read_file(entry.path())});
    std::sort(seeds[t.name].begin(), seeds[t.name].end(),
              [](const Seed& a, const Seed& b) { return a.path < b.path; });
    if (seeds[t.name].empty()) throw std::runtime_error("corpus '" + corpus + "': no seeds in " + t.name);
  }
  return seeds;
}

// The files the commands of a target need besides the input: the pair and ground truth a
// pairs.csv may name.
void write_fixed_files(const fs::path& dir, const std::string& corpus) {
  const Bytes image = read_file(fs::path(corpus) / "image/gray8.png");
  for (const char* name : {"left.png", "right.png", "l.png", "r.png", "mask.png"})
    write_file(dir / name, image);
  write_file(dir / "gt.png", read_file(fs::path(corpus) / "disparity/kitti16.png"));
  write_file(dir / "gt.pfm", read_file(fs::path(corpus) / "disparity/le.pfm"));
  write_file(dir / "pairs.csv", read_file(fs::path(corpus) / "pairs/full.csv"));
  write_file(dir / "cfg.json", read_file(fs::path(corpus) / "config/c2.json"));
}

std::vector<Target> selected_targets(const std::vector<std::string>& names) {
  std::vector<Target> all = make_targets(), chosen;
  for (auto& t : all)
    if (names.empty() || std::find(names.begin(), names.end(), t.name) != names.end())
      chosen.push_back(std::move(t));
  return chosen;
}

class Fuzzer {
 public:
  explicit Fuzzer(Options o) : o_(std::move(o)), targets_(selected_targets(o_.targets)), mutator_(o_.seed) {
    seeds_ = load_corpus(o_.corpus, targets_);
    fs::remove_all(o_.work);
    fs::create_directories(fs::path(o_.work) / "findings");
    for (const auto& t : targets_) {
      fs::create_directories(dir(t));
      if (!o_.program.empty()) write_fixed_files(dir(t), o_.corpus);
    }
  }

  // Every seed must be accepted, in-process and by the command line: else the harness itself
  // is broken (a target that rejects everything finds nothing).
  bool check_seeds() {
    bool ok = true;
    for (const auto& t : targets_)
      for (const auto& s : seeds_[t.name]) {
        const fs::path path = dir(t) / input_name(t.name, s.path.extension().string());
        write_file(path, s.bytes);
        std::string problem = accepted_in_process(t, path.string());
        if (problem.empty() && !o_.program.empty()) problem = accepted_by_command(t, path.string());
        if (!problem.empty()) {
          std::cerr << "fpstereo-fuzz: seed " << s.path.string() << " is not accepted: " << problem << "\n";
          ok = false;
        }
      }
    return ok;
  }

  // Returns the number of findings.
  std::size_t run() {
    const auto start = std::chrono::steady_clock::now();
    std::size_t done = 0, executed = 0;
    std::map<std::string, std::size_t> per_target, accepted;
    for (; done < o_.runs; ++done) {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (o_.max_seconds > 0 && seconds > o_.max_seconds) break;
      const Target& t = targets_[done % targets_.size()];
      const auto& seeds = seeds_[t.name];
      const Seed& seed = seeds[mutator_.below(seeds.size())];
      const std::string extension = seed.path.extension().string();
      const Bytes input = mutator_.mutate(seed.bytes, seeds[mutator_.below(seeds.size())].bytes, t.dictionary,
                                          extension == ".png");
      const fs::path path = dir(t) / input_name(t.name, extension);
      write_file(path, input);
      std::snprintf(g_current_input, sizeof g_current_input, "%s (input %zu)", path.c_str(), done);
      ++per_target[t.name];

      alarm(static_cast<unsigned>(o_.timeout_s));
      const Outcome outcome = read_in_process(t, path.string());
      std::string finding = outcome.finding;
      if (!t.always_exec) accepted[t.name] += outcome.accepted;
      alarm(0);
      if (finding.empty() && !o_.program.empty() && (t.always_exec || done % o_.exec_every == 0)) {
        ++executed;
        const auto command = t.command(dir(t).string(), path.string());
        const bool progress = t.stderr_progress || std::count(command.begin(), command.end(), "eval");
        const Outcome run = run_command(tools_dir(), command, dir(t), progress,
                                        fs::path(o_.work) / "stderr.txt", o_.timeout_s * 3);
        finding = run.finding;
        if (t.always_exec) accepted[t.name] += run.accepted;  // in-process reading says nothing
      }
      if (!finding.empty()) record(t, done, extension, input, finding);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::string counts;
    for (const auto& [name, n] : per_target)
      counts += (counts.empty() ? "" : ", ") + name + " " + std::to_string(n) + " (" +
                std::to_string(accepted[name]) + " accepted)";
    std::cout << "fpstereo-fuzz: " << done << " inputs (" << counts << ") in " << static_cast<int>(seconds)
              << " s, " << executed << " of them also through the command line; " << findings_
              << " finding(s)" << (findings_ ? ", saved in " + (fs::path(o_.work) / "findings").string() : "")
              << "\n";
    return findings_;
  }

 private:
  fs::path dir(const Target& t) const { return fs::absolute(fs::path(o_.work) / t.name); }
  fs::path tools_dir() const { return fs::path(o_.program).parent_path(); }

  std::string accepted_in_process(const Target& t, const std::string& path) {
    try {
      t.read(path);
      return "";
    } catch (const std::exception& e) {
      return e.what();
    }
  }

  std::string accepted_by_command(const Target& t, const std::string& path) {
    return run_command(tools_dir(), t.command(dir(t).string(), path), dir(t), t.stderr_progress,
                       fs::path(o_.work) / "stderr.txt", 60, true)
        .finding;
  }

  void record(const Target& t, std::size_t index, const std::string& extension, const Bytes& input,
              const std::string& what) {
    ++findings_;
    const fs::path saved =
        fs::path(o_.work) / "findings" / (t.name + "-" + std::to_string(index) + extension);
    write_file(saved, input);
    std::cerr << "fpstereo-fuzz: FINDING: " << t.name << " input " << index << ": " << what << " (saved as "
              << saved.string() << ")\n";
  }

  Options o_;
  std::vector<Target> targets_;
  std::map<std::string, std::vector<Seed>> seeds_;
  Mutator mutator_;
  std::size_t findings_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"fpstereo-fuzz: mutation fuzzer over the image, disparity, config and pairs.csv readers"};
  app.add_option("--corpus", o.corpus, "seed folder with image/, disparity/, config/ and pairs/")->required();
  app.add_option("--work", o.work, "scratch folder (emptied first); findings are kept in WORK/findings")
      ->capture_default_str();
  app.add_option("--runs", o.runs, "number of inputs")->capture_default_str();
  app.add_option("--seed", o.seed, "random seed: the same seed and corpus give the same inputs")
      ->capture_default_str();
  app.add_option("--max-seconds", o.max_seconds,
                 "stop after this long even if --runs are not done (0: no limit)")
      ->capture_default_str();
  app.add_option("--timeout", o.timeout_s, "seconds one input may take in-process before it counts as a hang")
      ->capture_default_str()
      ->check(CLI::Range(1, 3600));
  app.add_option("--exec", o.program,
                 "the fpstereo program (fpstereo-rtl is taken from its folder): every --exec-every-th input, "
                 "and every "
                 "args input, also runs through the command line")
      ->check(CLI::ExistingFile);
  app.add_option("--exec-every", o.exec_every, "see --exec")->check(CLI::Range(1, 1 << 30));
  app.add_option("--targets", o.targets, "the targets to fuzz, in turn (default: all)")
      ->delimiter(',')
      ->check(CLI::IsMember({"image", "disparity", "config", "pairs", "args"}));
  try {
    app.parse(argc, argv);
    if (!o.program.empty() && o.exec_every == 0) o.exec_every = 100;
    o.program = o.program.empty() ? "" : fs::absolute(o.program).string();
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "fpstereo-fuzz: " << e.what() << " (see --help)\n";
    return 2;
  }

#ifndef __SANITIZE_ADDRESS__  // under ASan, its own handler reports the crash with a stack trace
  for (const int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) signal(sig, on_crash);
#endif
  signal(SIGALRM, on_hang);
  try {
    Fuzzer fuzzer(o);
    if (!fuzzer.check_seeds()) return 1;
    return fuzzer.run() ? 1 : 0;
  } catch (const std::exception& e) {
    std::cerr << "fpstereo-fuzz: " << e.what() << "\n";
    return 2;
  }
}
