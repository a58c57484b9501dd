#include "safe_output.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace gfec::safe_output {

namespace {

// ---- Temporaries removed on SIGINT/SIGTERM/SIGHUP ------------------------------------------
// The handler may only call async-signal-safe functions: it reads a fixed array of paths that
// is changed only while the signals are blocked, unlinks them, and re-raises the signal with
// its default action so the exit status says how the process died.

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
constexpr std::size_t kMaxTemps = 64;
char *g_temps[kMaxTemps];
volatile std::sig_atomic_t g_temp_count = 0;

extern "C" void remove_temps_and_die(int sig) {
  for (std::sig_atomic_t i = 0; i < g_temp_count; ++i)
    if (g_temps[i]) ::unlink(g_temps[i]);
  ::signal(sig, SIG_DFL);
  ::raise(sig);  // delivered with the default action when the handler returns
}

/// Holds the signals back for its lifetime: registering a temporary and renaming the set are
/// done under it, so a signal never finds the registry half updated or the set half renamed.
class BlockSignals {
public:
  BlockSignals() {
    sigset_t set;
    sigemptyset(&set);
    for (int s : kSignals) sigaddset(&set, s);
    sigprocmask(SIG_BLOCK, &set, &old_);
  }
  ~BlockSignals() { sigprocmask(SIG_SETMASK, &old_, nullptr); }
  BlockSignals(const BlockSignals &) = delete;
  BlockSignals &operator=(const BlockSignals &) = delete;

private:
  sigset_t old_;
};

/// Installs the handler for the signals whose action is the default (an ignored SIGHUP, as
/// under nohup, stays ignored); restores the previous actions and empties the registry.
class TempRegistry {
public:
  TempRegistry() {
    for (std::size_t i = 0; i < std::size(kSignals); ++i) {
      struct sigaction current {};
      installed_[i] = false;
      if (sigaction(kSignals[i], nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
      struct sigaction action {};
      action.sa_handler = remove_temps_and_die;
      sigemptyset(&action.sa_mask);
      for (int s : kSignals) sigaddset(&action.sa_mask, s);
      installed_[i] = sigaction(kSignals[i], &action, &old_[i]) == 0;
    }
  }
  ~TempRegistry() {
    {
      BlockSignals hold;
      for (std::sig_atomic_t i = 0; i < g_temp_count; ++i) std::free(g_temps[i]), g_temps[i] = nullptr;
      g_temp_count = 0;
    }
    for (std::size_t i = 0; i < std::size(kSignals); ++i)
      if (installed_[i]) sigaction(kSignals[i], &old_[i], nullptr);
  }
  TempRegistry(const TempRegistry &) = delete;
  TempRegistry &operator=(const TempRegistry &) = delete;

  /// Creates a temporary from `pattern` (ending in XXXXXX) and registers it, signals blocked.
  /// Returns the descriptor, or -1 with errno set.
  int create(std::string &pattern) {
    if (g_temp_count >= static_cast<std::sig_atomic_t>(kMaxTemps)) {
      errno = EMFILE;
      return -1;
    }
    BlockSignals hold;
    char *copy = ::strdup(pattern.c_str());
    if (!copy) return -1;
    // mkostemp opens with O_CREAT|O_EXCL (a symlink planted under the name makes it fail, it
    // is never followed) and mode 0600; the name's random part is not predictable.
    int fd = ::mkostemp(copy, O_CLOEXEC);
    if (fd < 0) {
      int e = errno;
      std::free(copy);
      errno = e;
      return -1;
    }
    pattern = copy;
    g_temps[g_temp_count] = copy;
    g_temp_count = g_temp_count + 1;
    return fd;
  }

  /// Forgets a temporary that was renamed into place (call with the signals blocked).
  static void forget(const std::string &path) {
    for (std::sig_atomic_t i = 0; i < g_temp_count; ++i)
      if (g_temps[i] && path == g_temps[i]) {
        std::free(g_temps[i]);
        g_temps[i] = nullptr;
      }
  }

  /// Removes every temporary still registered.
  static void remove_all() {
    BlockSignals hold;
    for (std::sig_atomic_t i = 0; i < g_temp_count; ++i)
      if (g_temps[i]) {
        ::unlink(g_temps[i]);
        std::free(g_temps[i]);
        g_temps[i] = nullptr;
      }
  }

private:
  bool installed_[std::size(kSignals)];
  struct sigaction old_[std::size(kSignals)];
};

// ---- Checks before anything is written -----------------------------------------------------

struct Identity {
  dev_t dev;
  ino_t ino;
  bool operator==(const Identity &o) const { return dev == o.dev && ino == o.ino; }
};

bool identity_of(const std::string &path, Identity &id) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return false;  // follows symlinks: what a write would reach
  id = {st.st_dev, st.st_ino};
  return true;
}

std::string directory_of(const std::string &path) {
  auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

std::string file_name_of(const std::string &path) {
  auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// The folder's real path and the file's name: two spellings of one output compare equal.
bool canonical_name(const std::string &path, std::string &out) {
  char *dir = ::realpath(directory_of(path).c_str(), nullptr);
  if (!dir) return false;
  out = std::string(dir) + "/" + file_name_of(path);
  std::free(dir);
  return true;
}

std::string quote(const std::string &path) { return "'" + path + "'"; }

/// Why `files[i]` may not be written, or "".
std::string refusal(const std::vector<File> &files, std::size_t i, const std::vector<std::string> &never_overwrite,
                    std::vector<std::string> &names, std::vector<std::pair<bool, Identity>> &ids) {
  const std::string &path = files[i].path;
  std::string name = file_name_of(path);
  if (path.empty()) return "cannot write an output with an empty name";
  if (name.empty() || name == "." || name == "..")
    return "cannot write " + quote(path) + ": not a file name";
  struct stat st {};
  bool exists = false;
  if (::lstat(path.c_str(), &st) == 0) {
    exists = true;
    struct stat target {};
    if (S_ISLNK(st.st_mode)) {
      // A symlink is replaced, not written through; but one that points at a special file or
      // an input is refused like that file itself.
      if (::stat(path.c_str(), &target) == 0) st = target;
      else exists = false;  // dangling: nothing behind it to protect
    }
    if (exists && !S_ISREG(st.st_mode))
      return "refusing to write " + quote(path) + ": it exists and is not a regular file";
  } else if (errno != ENOENT) {
    return "cannot write " + quote(path) + ": " + std::strerror(errno);
  }
  std::string canonical;
  if (!canonical_name(path, canonical)) return "cannot write " + quote(path) + ": " + std::strerror(errno);
  Identity id{};
  bool has_id = exists && identity_of(path, id);
  if (has_id)
    for (const auto &input : never_overwrite) {
      Identity in{};
      if (identity_of(input, in) && in == id)
        return "refusing to write " + quote(path) + ": it is the input file " + quote(input);
    }
  for (std::size_t j = 0; j < names.size(); ++j)
    if (names[j] == canonical || (has_id && ids[j].first && ids[j].second == id))
      return "refusing to write " + quote(path) + " twice: it is also the output " + quote(files[j].path);
  names.push_back(canonical);
  ids.push_back({has_id, id});
  return {};
}

bool write_fully(int fd, const std::string &text) {
  const char *p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

mode_t creation_mode() {
  mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

} // namespace

std::string write_all(const std::vector<File> &files, const std::vector<std::string> &never_overwrite) {
  // 1. Every check first: a refused set writes nothing.
  std::vector<std::string> names;
  std::vector<std::pair<bool, Identity>> ids;
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::string why = refusal(files, i, never_overwrite, names, ids);
    if (!why.empty()) return why;
  }
  if (files.size() > kMaxTemps) return "too many outputs";

  // 2. Every temporary, written and closed.
  TempRegistry registry;
  std::vector<std::string> temps;
  mode_t mode = creation_mode();
  for (const auto &f : files) {
    std::string temp = f.path + ".gfec-tmp-XXXXXX";
    int fd = registry.create(temp);
    if (fd < 0) {
      std::string why = std::strerror(errno);
      TempRegistry::remove_all();
      return "cannot write " + quote(f.path) + ": " + why;
    }
    temps.push_back(temp);
    bool ok = write_fully(fd, f.contents) && ::fchmod(fd, mode) == 0;
    int e = errno;
    ok = ::close(fd) == 0 && ok;
    if (!ok) {
      std::string why = std::strerror(e ? e : errno);
      TempRegistry::remove_all();
      return "cannot write " + quote(f.path) + ": " + why;
    }
  }

  // 3. The renames, with the signals held back so a set is never half committed by them.
  BlockSignals hold;
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (::rename(temps[i].c_str(), files[i].path.c_str()) != 0) {
      std::string why = std::strerror(errno);
      TempRegistry::remove_all();
      return "cannot write " + quote(files[i].path) + ": " + why;
    }
    TempRegistry::forget(temps[i]);
  }
  return {};
}

} // namespace gfec::safe_output
