#include "external_tool.h"

#include "child_process.h"

#include <fmt/format.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace gfec {

namespace {

/// A private temporary file (mkstemp: a fresh name, mode 0600), removed when it goes out of scope.
class TempFile {
public:
  TempFile() {
    std::string pattern = (std::filesystem::temp_directory_path() / "gfec-tool-XXXXXX").string();
    int fd = ::mkstemp(pattern.data());
    if (fd < 0) throw std::runtime_error(fmt::format("cannot create a temporary file: {}", std::strerror(errno)));
    ::close(fd);
    path_ = pattern;
  }
  ~TempFile() { remove(); }
  TempFile(const TempFile &) = delete;
  TempFile &operator=(const TempFile &) = delete;

  const std::string &path() const { return path_; }
  std::string read() const {
    std::ifstream in(path_, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  void remove() {
    if (!path_.empty()) std::remove(path_.c_str());
    path_.clear();
  }

private:
  std::string path_;
};

/// SIGINT, SIGTERM and SIGHUP held back while a tool runs, so that the wait takes them: the
/// tool is stopped and the temporary files removed before the signal acts (docs/security.md).
class HoldSignals {
public:
  HoldSignals() {
    sigset_t set;
    sigemptyset(&set);
    for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, s);
    sigprocmask(SIG_BLOCK, &set, &old_);
  }
  ~HoldSignals() { sigprocmask(SIG_SETMASK, &old_, nullptr); }
  HoldSignals(const HoldSignals &) = delete;
  HoldSignals &operator=(const HoldSignals &) = delete;

private:
  sigset_t old_;
};

}  // namespace

double external_tool_time_limit() {
  const char *text = std::getenv("GFEC_TOOL_TIMEOUT");
  if (!text || !*text) return kDefaultToolTimeLimit;
  char *end = nullptr;
  const double v = std::strtod(text, &end);
  return end && *end == '\0' && v >= 0 && v <= 1e7 ? v : kDefaultToolTimeLimit;
}

// Files, not pipes, for the three standard streams: a large picture cannot deadlock the two
// processes on full pipe buffers, and no poll loop is needed.
std::string run_external_tool(const ExternalTool &tool, const std::string &input) {
  if (tool.command.empty()) throw std::invalid_argument("run_external_tool: no command");
  int taken = 0;  // a signal that arrived while the tool ran: acts once the files are gone
  std::string result, failure;
  bool timed_out = false;
  {
    HoldSignals hold;
    TempFile in, out, err;
    {
      std::ofstream f(in.path(), std::ios::binary);
      f << input;
      if (!f.flush()) throw std::runtime_error(fmt::format("cannot write the temporary file '{}'", in.path()));
    }
    child_process::Spawn spawn;
    spawn.argv = tool.command;
    spawn.stdin_path = in.path();
    spawn.stdout_path = out.path();
    spawn.stderr_path = err.path();
    spawn.time_limit = external_tool_time_limit();
    spawn.take_signals = true;
    const child_process::Result r = child_process::run(spawn);
    std::string command;
    for (const auto &w : tool.command) command += (command.empty() ? "" : " ") + w;
    using How = child_process::Result::How;
    if (r.how == How::NotStarted)
      throw std::runtime_error(
          fmt::format("{}, which could not be started ({}); {}", tool.purpose, r.error, tool.if_missing));
    if (r.how == How::Interrupted) {
      taken = r.signal;
    } else if (r.how == How::TimedOut) {
      timed_out = true;
      failure = fmt::format("'{}' took longer than {:g} s and was stopped (GFEC_TOOL_TIMEOUT sets the limit in "
                            "seconds; a smaller chart, or fewer levels of sub-charts, draws faster)",
                            command, spawn.time_limit);
    } else if (!r.ok()) {
      std::string why = err.read();
      while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
      failure = fmt::format("'{}' failed{}{}", command, why.empty() ? "" : ": ", why);
    } else {
      result = out.read();
    }
  }  // the temporary files are removed, the signal mask restored
  if (taken != 0) {
    std::raise(taken);  // its own action: safe_output's handler, or the default
    _exit(128 + taken);
  }
  if (timed_out) throw ToolTimeLimit(failure);
  if (!failure.empty()) throw std::runtime_error(failure);
  return result;
}

}  // namespace gfec
