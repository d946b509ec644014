#include "files.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <mutex>

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

std::string write_error(const fs::path& path, const std::string& reason) {
  return "cannot write " + quoted(path.string()) + ": " + reason;
}

// ---- what the signal handler sees ----------------------------------------------------------
// Changed only with the three signals blocked in the changing thread, so the handler never reads
// them half-changed. Outputs are staged by one thread while no other runs (the commands' workers
// have joined by then).

std::vector<std::string>& staged_paths() {  // temporaries, files and directories, oldest first
  static std::vector<std::string> paths;
  return paths;
}
std::vector<pid_t>& child_groups() {
  static std::vector<pid_t> groups;
  return groups;
}
volatile sig_atomic_t g_deferred = 0;
volatile sig_atomic_t g_signal = 0;
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

class SignalsBlocked {
 public:
  SignalsBlocked() {
    sigset_t set;
    sigemptyset(&set);
    for (int sig : kSignals) sigaddset(&set, sig);
    pthread_sigmask(SIG_BLOCK, &set, &old_);
  }
  ~SignalsBlocked() { pthread_sigmask(SIG_SETMASK, &old_, nullptr); }

 private:
  sigset_t old_;
};

extern "C" void on_signal(int sig) {
  const int saved_errno = errno;
  for (pid_t group : child_groups()) ::kill(-group, sig);
  if (g_deferred) {
    g_signal = sig;
    errno = saved_errno;
    return;
  }
  // Newest first: a directory's files go before the directory.
  const std::vector<std::string>& paths = staged_paths();
  for (size_t i = paths.size(); i-- > 0;)
    if (::unlink(paths[i].c_str()) != 0) ::rmdir(paths[i].c_str());
  ::signal(sig, SIG_DFL);
  ::raise(sig);  // delivered when the handler returns: the process ends by this signal
}

void install_signal_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : kSignals) {
      struct sigaction old;
      if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler == SIG_IGN) continue;  // nohup
      struct sigaction action {};
      action.sa_handler = on_signal;
      sigemptyset(&action.sa_mask);
      for (int other : kSignals) sigaddset(&action.sa_mask, other);
      action.sa_flags = SA_RESTART;
      ::sigaction(sig, &action, nullptr);
    }
  });
}

void untrack(const fs::path& path) {
  SignalsBlocked blocked;
  auto& paths = staged_paths();
  paths.erase(std::remove(paths.begin(), paths.end(), path.string()), paths.end());
}

// The path made absolute with every symlink in its existing part resolved: two spellings of one
// place compare equal even when the file does not exist yet.
fs::path normalised(const fs::path& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) p = fs::absolute(path, ec).lexically_normal();
  return p;
}

bool is_inside(const fs::path& inner, const fs::path& dir) {
  auto i = inner.begin();
  for (auto d = dir.begin(); d != dir.end(); ++d, ++i)
    if (d->empty()) continue;  // a trailing separator
    else if (i == inner.end() || *i != *d) return false;
  return i != inner.end();
}

// Whether `path` is (or points to) a character device or a pipe: written in place, not replaced.
bool written_in_place(const fs::path& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0 && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode));
}

// Whether `place` (absolute, normalised) lies in /dev itself (not /dev/shm, a place for files):
// there a run writes only into a device or a pipe. Replacing a link such as /dev/stdout (to
// /proc/self/fd/1) where it leads to a regular file would break it for every program.
bool in_device_directory(const fs::path& place) {
  std::error_code ec;
  const fs::path dir = fs::weakly_canonical(place.parent_path(), ec);
  return !ec && dir == "/dev";
}

// A file created exclusively (never through a symlink), filled, flushed to disk; 0 or an errno.
int fill_new_file(int fd, const char* data, size_t size) {
  int error = ::fchmod(fd, 0644) == 0 ? 0 : errno;
  if (!error) error = write_all(fd, data, size);
  if (!error && ::fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && !error) error = errno;
  return error;
}

void sync_directory(const fs::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);  // best effort: the renames are done either way
  ::close(fd);
}

fs::path parent_or_dot(const fs::path& path) {
  const fs::path dir = path.parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

enum Kind { kInput, kFile, kDirectory };

}  // namespace

void create_cache_directory(const fs::path& dir) {
  std::error_code ec;
  // The directories to be made: from the first missing ancestor down.
  for (fs::path p = fs::absolute(dir, ec).lexically_normal(); !ec && !p.empty() && !fs::exists(p, ec);
       p = p.parent_path()) {
    if (in_device_directory(p))
      throw FileError("cache " + quoted(dir.string()) + ": in /dev a run writes only into a device or a pipe");
    if (p == p.parent_path()) break;
  }
  fs::create_directories(dir, ec);
  if (ec) throw FileError("cache " + quoted(dir.string()) + ": cannot create the directory: " + ec.message());
}

struct OutputSet::Entry {
  fs::path path;
  std::string what;
  int kind = kInput;
  fs::path normal;
  fs::path place;  // where it is renamed to: absolute, symlinks kept, no trailing separator
  bool exists = false;
  bool sink = false;  // an output on a character device (/dev/null): it can replace nothing
  dev_t device = 0;
  ino_t inode = 0;
  bool staged = false;
  bool in_place = false;
  std::string bytes;               // in place: written at commit
  fs::path temp;                   // the temporary file or directory
  std::vector<std::string> names;  // a directory's files
};

OutputSet::OutputSet() { install_signal_handlers(); }

OutputSet::~OutputSet() {
  for (const auto& e : outputs_) {
    if (e->temp.empty()) continue;
    std::error_code ignored;
    fs::remove_all(e->temp, ignored);
    for (const auto& name : e->names) untrack(e->temp / name);
    untrack(e->temp);
  }
}

void OutputSet::add_input(const fs::path& path, const std::string& what) { add(path, what, kInput); }
void OutputSet::add_file(const fs::path& path, const std::string& what) { add(path, what, kFile); }
void OutputSet::add_directory(const fs::path& path, const std::string& what) { add(path, what, kDirectory); }

void OutputSet::add(const fs::path& path, const std::string& what, int kind) {
  auto e = std::make_unique<Entry>();
  e->path = path;
  e->what = what;
  e->kind = kind;
  e->normal = normalised(path);
  std::error_code ec;
  e->place = fs::absolute(path, ec).lexically_normal();
  if (!e->place.has_filename()) e->place = e->place.parent_path();
  struct stat st;
  if (!path.empty() && ::stat(path.c_str(), &st) == 0) {
    e->exists = true;
    e->device = st.st_dev;
    e->inode = st.st_ino;
    e->sink = kind == kFile && S_ISCHR(st.st_mode);
  }
  const auto name = [](const Entry& x) { return x.what + " " + quoted(x.path.string()); };
  if (kind != kInput && path.empty()) throw FileError(what + ": an empty file name");
  if (kind != kInput && !written_in_place(path) && in_device_directory(e->place))
    throw FileError(write_error(path, "in /dev a run writes only into a device or a pipe, and this is neither "
                                      "(give a file name)"));
  std::vector<const Entry*> others;  // one file read twice is fine: an input against the outputs only
  for (const auto& other : outputs_) others.push_back(other.get());
  if (kind != kInput)
    for (const auto& other : inputs_) others.push_back(other.get());
  for (const Entry* other : others) {
    if (e->sink || other->sink) continue;
    const bool same_inode = e->exists && other->exists && e->device == other->device && e->inode == other->inode;
    if (same_inode || e->normal == other->normal)
      throw FileError(name(*e) + " is the same file as " + name(*other));
    if ((other->kind == kDirectory && is_inside(e->normal, other->normal)) ||
        (kind == kDirectory && is_inside(other->normal, e->normal)))
      throw FileError(name(kind == kDirectory ? *other : *e) + " lies inside " +
                      name(kind == kDirectory ? *e : *other));
  }
  if (kind == kFile) {
    if (e->exists && S_ISDIR(st.st_mode)) throw FileError(write_error(path, "is a directory"));
    const fs::path dir = parent_or_dot(path);
    if (!fs::is_directory(dir, ec)) throw FileError(write_error(path, "no such directory " + quoted(dir.string())));
    if (e->exists && S_ISREG(st.st_mode) && ::access(path.c_str(), W_OK) != 0)
      throw FileError(write_error(path, std::strerror(errno)));
    if (!written_in_place(path) && ::access(dir.c_str(), W_OK | X_OK) != 0)
      throw FileError(write_error(path, std::strerror(errno)));
  } else if (kind == kDirectory) {
    const auto fail = [&](const std::string& reason) {
      return FileError("cannot create directory " + quoted(path.string()) + ": " + reason);
    };
    if (e->exists && !S_ISDIR(st.st_mode)) throw fail("not a directory");
    fs::path ancestor = e->place.parent_path();  // it is created there, with missing parents
    while (!fs::exists(ancestor, ec) && ancestor.has_relative_path()) ancestor = ancestor.parent_path();
    if (!fs::is_directory(ancestor, ec)) throw fail(quoted(ancestor.string()) + " is not a directory");
    if (::access(ancestor.c_str(), W_OK | X_OK) != 0) throw fail(std::strerror(errno));
  }
  (kind == kInput ? inputs_ : outputs_).push_back(std::move(e));
}

OutputSet::Entry& OutputSet::output(const fs::path& path, bool directory) {
  Entry* found = nullptr;  // the first not yet staged: a device may be named by several outputs
  for (const auto& e : outputs_)
    if (e->path == path && e->kind == (directory ? kDirectory : kFile) && (!found || (found->staged && !e->staged)))
      found = e.get();
  if (!found) throw std::logic_error("output not declared: " + path.string());
  return *found;
}

void OutputSet::stage(const fs::path& path, const std::string& text) { stage(path, text.data(), text.size()); }

void OutputSet::stage(const fs::path& path, const void* data, size_t size) {
  Entry& e = output(path, false);
  const char* bytes = static_cast<const char*>(data);
  e.staged = true;
  if (written_in_place(path)) {
    e.in_place = true;
    e.bytes.assign(bytes, size);
    return;
  }
  std::string temp = path.string() + ".tmp.XXXXXX";
  SignalsBlocked blocked;  // created and tracked as one step
  const int fd = ::mkostemp(temp.data(), O_CLOEXEC);
  if (fd < 0) throw FileError(write_error(path, std::strerror(errno)));
  e.temp = temp;
  staged_paths().push_back(temp);
  const int error = fill_new_file(fd, bytes, size);
  if (error) throw FileError(write_error(path, std::strerror(error)));  // the destructor removes it
}

void OutputSet::stage_in_directory(const fs::path& dir, const std::string& name, const std::string& text) {
  Entry& e = output(dir, true);
  const auto fail = [&](const std::string& reason) {
    return FileError("cannot create directory " + quoted(dir.string()) + ": " + reason);
  };
  if (name.empty() || name.find('/') != std::string::npos || name == "." || name == "..")
    throw std::logic_error("not a file name: " + name);
  if (e.temp.empty()) {
    std::error_code ec;
    fs::create_directories(e.place.parent_path(), ec);
    if (ec) throw fail(ec.message());
    std::string temp = e.place.string() + ".tmp.XXXXXX";
    {
      SignalsBlocked blocked;
      if (!::mkdtemp(temp.data())) throw fail(std::strerror(errno));
      e.temp = temp;
      staged_paths().push_back(temp);
    }
    if (::chmod(temp.c_str(), 0755) != 0) throw fail(std::strerror(errno));
    e.staged = true;
    stage_in_directory(dir, kDirectoryMarker, "written by fpstereo; the next run to this directory replaces it whole\n");
  }
  const fs::path file = e.temp / name;
  SignalsBlocked blocked;
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) throw FileError(write_error(dir / name, std::strerror(errno)));
  staged_paths().push_back(file.string());
  e.names.push_back(name);
  const int error = fill_new_file(fd, text.data(), text.size());
  if (error) throw FileError(write_error(dir / name, std::strerror(error)));
}

void OutputSet::stage_copy(const fs::path& path, const fs::path& source) {
  stage(path, read_regular_file(source, "result", std::numeric_limits<size_t>::max()));
}

namespace {

// A directory may be swapped out if it is empty, an earlier output (the marker) or holds only
// names the new one writes; anything else might be the user's.
void check_replaceable(const fs::path& dir, const std::vector<std::string>& names) {
  struct stat st;
  if (::lstat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) return;  // nothing, or a symlink: replaced
  std::error_code ec;
  if (fs::exists(dir / kDirectoryMarker, ec)) return;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw FileError("cannot replace directory " + quoted(dir.string()) + ": it holds " + quoted(name) +
                      ", which this run does not write (give a new or empty directory)");
  }
}

void write_in_place(const fs::path& path, const std::string& bytes) {
  // O_NONBLOCK: a pipe without a reader fails at once (ENXIO) instead of waiting.
  const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw FileError(write_error(path, errno == ENXIO ? "a pipe with no reader" : std::strerror(errno)));
  int error = ::fcntl(fd, F_SETFL, 0) == 0 ? 0 : errno;
  if (!error) error = write_all(fd, bytes.data(), bytes.size());
  if (::close(fd) != 0 && !error) error = errno;
  if (error) throw FileError(write_error(path, std::strerror(error)));
}

}  // namespace

void OutputSet::commit() {
  // Test hook (tests/hostile.py): FPSTEREO_TEST_SIGNAL_AT_COMMIT=N raises signal N here, with
  // every output staged and none in place: the worst moment for an interruption.
  if (const char* sig = std::getenv("FPSTEREO_TEST_SIGNAL_AT_COMMIT")) ::raise(std::atoi(sig));
  for (const auto& e : outputs_) {
    if (!e->staged) throw std::logic_error("output not staged: " + e->path.string());
    if (e->kind == kDirectory) check_replaceable(e->place, e->names);
  }
  for (const auto& e : outputs_)
    if (e->in_place) write_in_place(e->path, e->bytes);
  // A signal waits until every output is in place and every swapped-out directory removed: the
  // handler, run between two renames, would leave one output new and the next old, or a previous
  // directory (its files not this run's) under the temporary's name.
  SignalsBlocked blocked;
  for (const auto& e : outputs_) {
    if (e->temp.empty()) continue;
    struct stat st;
    const bool replace = e->kind == kDirectory && ::lstat(e->place.c_str(), &st) == 0;
    const int rc = replace ? ::renameat2(AT_FDCWD, e->temp.c_str(), AT_FDCWD, e->place.c_str(), RENAME_EXCHANGE)
                           : ::rename(e->temp.c_str(), e->place.c_str());
    if (rc != 0) throw FileError(write_error(e->path, std::strerror(errno)));
    // Test hook (tests/hostile.py): FPSTEREO_TEST_SIGNAL_AT_SWAP=N raises signal N with this output
    // in place and the rest of the commit to do.
    if (const char* sig = std::getenv("FPSTEREO_TEST_SIGNAL_AT_SWAP")) ::raise(std::atoi(sig));
    sync_directory(e->place.parent_path());
    if (replace) {
      std::error_code ignored;
      fs::remove_all(e->temp, ignored);  // the previous directory, swapped out
    }
    for (const auto& name : e->names) untrack(e->temp / name);
    untrack(e->temp);
    e->temp.clear();
  }
}

void write_file_atomically(const fs::path& path, const std::string& text) {
  OutputSet out;
  out.add_file(path, "file");
  out.stage(path, text);
  out.commit();
}

SignalsDeferred::SignalsDeferred() {
  install_signal_handlers();
  ++g_deferred;
}
SignalsDeferred::~SignalsDeferred() { --g_deferred; }

ChildGroup::ChildGroup(int pgid) : pgid_(pgid) {
  SignalsBlocked blocked;
  child_groups().push_back(pgid_);
}
ChildGroup::~ChildGroup() {
  SignalsBlocked blocked;
  auto& groups = child_groups();
  groups.erase(std::remove(groups.begin(), groups.end(), pid_t(pgid_)), groups.end());
}

int interrupted() { return g_signal; }

void die_if_interrupted() {
  const int sig = g_signal;
  if (!sig) return;
  ::signal(sig, SIG_DFL);
  ::raise(sig);
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
