#include "safe_output.h"

#include <cerrno>
#include <memory>
#include <ostream>
#include <streambuf>
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
constexpr std::size_t kNameMax = 255;  // NAME_MAX of Linux file systems: the longest name of one file
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
  if (name.empty() || name == "." || name == "..") return "cannot write " + quote(path) + ": not a file name";
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

mode_t creation_mode() {
  mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

/// A stream buffer over a temporary's descriptor: text goes to the file in blocks of 64 KiB, so
/// an output of any size costs a fixed amount of memory. The first failed write is kept (errno)
/// and every later write refused, which the owning stream sees as badbit.
class FdBuf : public std::streambuf {
public:
  explicit FdBuf(int fd) : fd_(fd), buffer_(1 << 16) { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
  FdBuf(const FdBuf &) = delete;
  FdBuf &operator=(const FdBuf &) = delete;

  int fd() const { return fd_; }
  int failure() const { return error_; }

protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }
  std::streamsize xsputn(const char *s, std::streamsize n) override {
    // Large pieces bypass the buffer once it is drained.
    if (n >= static_cast<std::streamsize>(buffer_.size())) {
      if (!drain() || !write_fully(s, static_cast<std::size_t>(n))) return 0;
      return n;
    }
    return std::streambuf::xsputn(s, n);
  }

private:
  bool drain() {
    std::size_t n = static_cast<std::size_t>(pptr() - pbase());
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return write_fully(buffer_.data(), n);
  }
  bool write_fully(const char *p, std::size_t left) {
    if (error_) return false;
    while (left > 0) {
      ssize_t n = ::write(fd_, p, left);
      if (n < 0) {
        if (errno == EINTR) continue;
        error_ = errno;
        return false;
      }
      p += n;
      left -= static_cast<std::size_t>(n);
    }
    return true;
  }

  int fd_;
  std::vector<char> buffer_;
  int error_ = 0;
};

}  // namespace

/// One output being written: its checked name, its temporary and the stream on it.
struct Transaction::Output {
  std::string path;
  std::string temp;
  std::unique_ptr<FdBuf> buf;
  std::unique_ptr<std::ostream> stream;
  bool closed = false;
};

/// The signal handler and the names of the temporaries live as long as the transaction.
struct Transaction::State {
  TempRegistry registry;
  std::vector<File> checked;  ///< the outputs opened so far (names only), for the "twice" check
  std::vector<std::string> names;
  std::vector<std::pair<bool, Identity>> ids;
};

Transaction::Transaction(std::vector<std::string> never_overwrite)
    : never_overwrite_(std::move(never_overwrite)), state_(std::make_unique<State>()) {}

Transaction::~Transaction() {
  if (committed_) return;
  for (auto &o : outputs_)
    if (!o->closed) ::close(o->buf->fd());
  TempRegistry::remove_all();
}

std::string temporary_pattern(const std::string &path) {
  // NAME.gfec-tmp-XXXXXX, beside the output; a name near NAME_MAX (255 bytes) is cut so that
  // the temporary's name still fits, or a valid output name could never be written.
  const std::string suffix = ".gfec-tmp-XXXXXX";
  const std::size_t slash = path.rfind('/');
  const std::size_t base = slash == std::string::npos ? 0 : slash + 1;
  std::string name = path.substr(base);
  if (name.size() + suffix.size() > kNameMax) {
    name.resize(kNameMax - suffix.size());
    // Not inside a UTF-8 character: the name stays text (it is shown in messages).
    while (!name.empty() && (static_cast<unsigned char>(name.back()) & 0xC0) == 0x80) name.pop_back();
    if (!name.empty() && static_cast<unsigned char>(name.back()) >= 0xC0) name.pop_back();
  }
  return path.substr(0, base) + name + suffix;
}

std::ostream *Transaction::open(const std::string &path) {
  if (!error_.empty() || committed_) return nullptr;
  state_->checked.push_back({path, {}});
  std::string why = refusal(state_->checked, state_->checked.size() - 1, never_overwrite_, state_->names, state_->ids);
  if (why.empty() && outputs_.size() >= kMaxTemps) why = "too many outputs";
  if (!why.empty()) {
    fail(why);
    return nullptr;
  }
  auto o = std::make_unique<Output>();
  o->path = path;
  o->temp = temporary_pattern(path);
  int fd = state_->registry.create(o->temp);
  if (fd < 0) {
    fail("cannot write " + quote(path) + ": " + std::strerror(errno));
    return nullptr;
  }
  o->buf = std::make_unique<FdBuf>(fd);
  o->stream = std::make_unique<std::ostream>(o->buf.get());
  outputs_.push_back(std::move(o));
  return outputs_.back()->stream.get();
}

void Transaction::fail(const std::string &why) {
  if (error_.empty()) error_ = why;
}

std::string Transaction::commit() {
  if (committed_) return {};
  if (!error_.empty()) return error_;
  // 1. Every temporary complete and closed: a failed write anywhere commits nothing.
  mode_t mode = creation_mode();
  for (auto &o : outputs_) {
    o->stream->flush();
    int e = o->buf->failure();
    if (!e && o->stream->bad()) e = EIO;
    if (!e && ::fchmod(o->buf->fd(), mode) != 0) e = errno;
    o->closed = true;
    if (::close(o->buf->fd()) != 0 && !e) e = errno;
    if (e) {
      fail("cannot write " + quote(o->path) + ": " + std::strerror(e));
      return error_;
    }
  }
  // 2. The renames, with the signals held back so a set is never half committed by them.
  BlockSignals hold;
  for (auto &o : outputs_) {
    if (::rename(o->temp.c_str(), o->path.c_str()) != 0) {
      fail("cannot write " + quote(o->path) + ": " + std::strerror(errno));
      TempRegistry::remove_all();
      return error_;
    }
    TempRegistry::forget(o->temp);
  }
  committed_ = true;
  return {};
}

std::string write_all(const std::vector<File> &files, const std::vector<std::string> &never_overwrite) {
  // Every check first: a refused set creates no temporary at all.
  {
    std::vector<std::string> names;
    std::vector<std::pair<bool, Identity>> ids;
    for (std::size_t i = 0; i < files.size(); ++i) {
      std::string why = refusal(files, i, never_overwrite, names, ids);
      if (!why.empty()) return why;
    }
    if (files.size() > kMaxTemps) return "too many outputs";
  }
  Transaction t(never_overwrite);
  for (const auto &f : files)
    if (std::ostream *out = t.open(f.path))
      out->write(f.contents.data(), static_cast<std::streamsize>(f.contents.size()));
  return t.commit();
}

}  // namespace gfec::safe_output
