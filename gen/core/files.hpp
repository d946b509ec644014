// Where the tools keep their caches, how they write their outputs (all or nothing, never over an
// input) and how they read their inputs (regular files of bounded size).
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace fpstereo {

class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// $XDG_CACHE_HOME/fpstereo/<what>, or $HOME/.cache/fpstereo/<what> when XDG_CACHE_HOME is unset,
// empty or relative (the XDG base directory rules ignore a relative one). Throws FileError when
// HOME is not set either.
std::filesystem::path cache_dir(const std::string& what);
// The rule for help texts: "$XDG_CACHE_HOME/fpstereo/<what> or ~/.cache/fpstereo/<what>".
std::string cache_dir_rule(const std::string& what);
// Creates a cache directory with its missing parents, never one in /dev itself (where a run
// writes only into devices and pipes). Throws FileError naming the directory and the reason.
void create_cache_directory(const std::filesystem::path& dir);

// ---- all-or-nothing outputs ----------------------------------------------------------------
//
// The files and directories one run writes, committed together. A command declares every output
// and every input it reads before its work (aliasing and unwritable paths fail then, one line),
// stages each output's content when it is ready and commits once at the end:
//  - a file is staged as a temporary beside its target (created exclusively, so never through a
//    symlink, 0644, fsynced) and renamed into place: a symlink standing at the target is replaced,
//    not followed. A character device (/dev/null) or a pipe with a reader, or a symlink to one of
//    them (/dev/stdout), is written in place at commit, as there is nothing to replace;
//  - a directory is built in a fresh sibling directory and swapped in whole (renameat2
//    RENAME_EXCHANGE); the previous directory is removed. It must be empty, a previous output of
//    this kind (marked by the file kDirectoryMarker) or hold only names the new one writes;
//  - commit() checks everything before it renames anything. Until then a failure (the destructor)
//    or SIGINT, SIGTERM or SIGHUP removes every temporary and leaves the previous outputs as they
//    were.
class OutputSet {
 public:
  OutputSet();
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // `what` names the path in messages ("--json file", "left image"). Each throws FileError, one
  // line, if the path is the same file as one declared before (device and inode when both exist,
  // the normalised path always), an input lies inside an output directory, or an output cannot be
  // written (its directory missing or read-only, a directory where a file is expected).
  void add_input(const std::filesystem::path& path, const std::string& what);
  void add_file(const std::filesystem::path& path, const std::string& what);
  void add_directory(const std::filesystem::path& path, const std::string& what);

  // The content of a declared file output, or of the file `name` inside a declared directory.
  void stage(const std::filesystem::path& path, const void* data, size_t size);
  void stage(const std::filesystem::path& path, const std::string& text);
  void stage_in_directory(const std::filesystem::path& dir, const std::string& name, const std::string& text);
  // Stages the file at `source` (a result a child process wrote, say) as the output `path`.
  void stage_copy(const std::filesystem::path& path, const std::filesystem::path& source);

  // Every declared output must have been staged. Throws FileError (and changes nothing) if one
  // cannot be put in place.
  void commit();

 private:
  struct Entry;
  Entry& output(const std::filesystem::path& path, bool directory);
  void add(const std::filesystem::path& path, const std::string& what, int kind);
  std::vector<std::unique_ptr<Entry>> inputs_, outputs_;  // inputs are compared only with outputs
};

// The file every directory output holds: a later run may replace such a directory whole.
constexpr const char* kDirectoryMarker = ".fpstereo-output";

// One file as an OutputSet of one: readers see the old file or the new one, never half of one,
// however many writers race (caches). Throws FileError naming the path and the reason.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

// ---- signals and child processes ------------------------------------------------------------
//
// SIGINT, SIGTERM and SIGHUP (unless ignored when the process started) remove every staged
// temporary and end the process by the same signal. While a SignalsDeferred lives they are
// instead passed on to the registered child process groups and recorded: the waiting code sees
// interrupted() and unwinds (removing its work files), and main ends with die_if_interrupted().
class SignalsDeferred {
 public:
  SignalsDeferred();
  ~SignalsDeferred();
  SignalsDeferred(const SignalsDeferred&) = delete;
  SignalsDeferred& operator=(const SignalsDeferred&) = delete;
};
// A child in its own process group (pgid = its pid) that receives the signals the parent gets.
class ChildGroup {
 public:
  explicit ChildGroup(int pgid);
  ~ChildGroup();
  ChildGroup(const ChildGroup&) = delete;
  ChildGroup& operator=(const ChildGroup&) = delete;

 private:
  int pgid_;
};
// The signal received under a SignalsDeferred, or 0.
int interrupted();
// Ends the process by the recorded signal, if any (called by main after unwinding).
void die_if_interrupted();

// The size limits of read_regular_file for the kinds of input the tools read.
constexpr size_t kMaxImageBytes = size_t(256) << 20;
constexpr size_t kMaxTextFileBytes = size_t(1) << 20;  // configuration files
constexpr size_t kMaxTableBytes = size_t(64) << 20;    // CSVs

// The whole content of a regular file of at most max_bytes. Anything else (missing, a
// directory, a device such as /dev/zero, a pipe, too large) throws FileError, one line:
// "<what> '<path>': <reason>", e.g. "left image 'x.png': not a regular file (a directory)".
std::string read_regular_file(const std::filesystem::path& path, const std::string& what, size_t max_bytes);

}  // namespace fpstereo
