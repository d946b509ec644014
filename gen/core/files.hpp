// Where the tools keep their caches, and how they write a file that readers may see at any moment.
#pragma once

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
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace fpstereo
