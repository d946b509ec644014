// Where the tools keep their caches, and how they write a file that readers may see at any moment.
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>

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

// Writes to a unique temporary file in the same directory and renames it into place: readers see
// the old file or the new one, never half of one, however many writers race. The file is 0644,
// so a shared cache stays readable to other users. Throws FileError naming the path and the reason.
// A target that exists but is not a regular file (/dev/null, a pipe) is written in place; a
// directory is an error.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);
void write_file_atomically(const std::filesystem::path& path, const void* data, size_t size);

// Throws FileError unless `path` can be written later: its directory exists and is writable and
// the path is not a directory. Checked before long work, which then writes with
// write_file_atomically, so a failing run leaves the previous file untouched.
void check_writable(const std::filesystem::path& path);

// The size limits of read_regular_file for the kinds of input the tools read.
constexpr size_t kMaxImageBytes = size_t(256) << 20;
constexpr size_t kMaxTextFileBytes = size_t(1) << 20;  // configuration files
constexpr size_t kMaxTableBytes = size_t(64) << 20;    // CSVs

// The whole content of a regular file of at most max_bytes. Anything else (missing, a
// directory, a device such as /dev/zero, a pipe, too large) throws FileError, one line:
// "<what> '<path>': <reason>", e.g. "left image 'x.png': not a regular file (a directory)".
std::string read_regular_file(const std::filesystem::path& path, const std::string& what, size_t max_bytes);

}  // namespace fpstereo
