#include "files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "text.hpp"

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

namespace {

// Writes all of data to fd; 0 or the errno of the failure.
int write_all(int fd, const char* data, size_t size) {
  for (size_t done = 0; done < size;) {
    const ssize_t n = ::write(fd, data + done, size - done);
    if (n < 0 && errno != EINTR) return errno;
    if (n > 0) done += size_t(n);
  }
  return 0;
}

}  // namespace

void write_file_atomically(const fs::path& path, const std::string& text) {
  write_file_atomically(path, text.data(), text.size());
}

void write_file_atomically(const fs::path& path, const void* data, size_t size) {
  const auto fail = [&](const std::string& reason) {
    return FileError("cannot write " + quoted(path.string()) + ": " + reason);
  };
  const char* bytes = static_cast<const char*>(data);
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    if (S_ISDIR(st.st_mode)) throw fail("is a directory");
    const int fd = ::open(path.c_str(), O_WRONLY);  // a device or pipe: nothing to replace
    if (fd < 0) throw fail(std::strerror(errno));
    int error = write_all(fd, bytes, size);
    if (::close(fd) != 0 && !error) error = errno;
    if (error) throw fail(std::strerror(error));
    return;
  }
  std::string temp = path.string() + ".tmp.XXXXXX";
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) throw fail(std::strerror(errno));
  int error = ::fchmod(fd, 0644) == 0 ? 0 : errno;
  if (!error) error = write_all(fd, bytes, size);
  if (::close(fd) != 0 && !error) error = errno;
  if (!error && std::rename(temp.c_str(), path.c_str()) != 0) error = errno;
  if (!error) return;
  ::unlink(temp.c_str());
  throw fail(std::strerror(error));
}

void check_writable(const fs::path& path) {
  const auto fail = [&](const std::string& reason) {
    return FileError("cannot write " + quoted(path.string()) + ": " + reason);
  };
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw fail("is a directory");
  fs::path dir = path.parent_path();
  if (dir.empty()) dir = ".";
  if (!fs::is_directory(dir, ec)) throw fail("no such directory " + quoted(dir.string()));
  if (::access(path.c_str(), F_OK) == 0 && ::access(path.c_str(), W_OK) != 0) throw fail(std::strerror(errno));
  if (::access(dir.c_str(), W_OK | X_OK) != 0) throw fail(std::strerror(errno));
}

std::string read_regular_file(const fs::path& path, const std::string& what, size_t max_bytes) {
  const auto fail = [&](const std::string& reason) {
    return FileError(what + " " + quoted(path.string()) + ": " + reason);
  };
  // O_NONBLOCK: opening a pipe must not wait for a writer; a regular file ignores it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    if (error == ENOENT) throw fail("cannot be read: no such file");
    throw fail(std::string("cannot be read (") + std::strerror(error) + ")");
  }
  struct stat st;
  std::string reason;
  if (::fstat(fd, &st) != 0)
    reason = std::string("cannot be read (") + std::strerror(errno) + ")";
  else if (S_ISDIR(st.st_mode))
    reason = "not a regular file (a directory)";
  else if (!S_ISREG(st.st_mode))
    reason = "not a regular file";
  else if (size_t(st.st_size) > max_bytes)
    reason = "larger than " + std::to_string(max_bytes >> 20) + " MiB";
  std::string text;
  if (reason.empty()) {
    text.resize(size_t(st.st_size));
    size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = ::read(fd, text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        reason = std::string("cannot be read (") + std::strerror(errno) + ")";
        break;
      }
      if (n == 0) break;  // shrank while reading: what is there
      done += size_t(n);
    }
    text.resize(done);
  }
  ::close(fd);
  if (!reason.empty()) throw fail(reason);
  return text;
}

}  // namespace fpstereo
