#include "files.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace fpstereo {
namespace fs = std::filesystem;

fs::path cache_dir(const std::string& what) {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && *xdg == '/') return fs::path(xdg) / "fpstereo" / what;
  const char* home = std::getenv("HOME");
  if (home && *home) return fs::path(home) / ".cache" / "fpstereo" / what;
  throw FileError("no cache directory: HOME is not set; pass --cache DIR");
}

std::string cache_dir_rule(const std::string& what) {
  return "$XDG_CACHE_HOME/fpstereo/" + what + " or ~/.cache/fpstereo/" + what;
}

void write_file_atomically(const fs::path& path, const std::string& text) {
  const auto fail = [&](int error) {
    return FileError("cannot write '" + path.string() + "': " + std::strerror(error));
  };
  std::string temp = path.string() + ".tmp.XXXXXX";
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) throw fail(errno);
  int error = ::fchmod(fd, 0644) == 0 ? 0 : errno;
  for (size_t done = 0; !error && done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno != EINTR) error = errno;
    if (n > 0) done += size_t(n);
  }
  if (::close(fd) != 0 && !error) error = errno;
  if (!error && std::rename(temp.c_str(), path.c_str()) != 0) error = errno;
  if (!error) return;
  ::unlink(temp.c_str());
  throw fail(error);
}

}  // namespace fpstereo
