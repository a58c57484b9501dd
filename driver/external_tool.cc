#include "external_tool.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <spawn.h>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char **environ;

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
  ~TempFile() { std::remove(path_.c_str()); }
  TempFile(const TempFile &) = delete;
  TempFile &operator=(const TempFile &) = delete;

  const std::string &path() const { return path_; }
  std::string read() const {
    std::ifstream in(path_, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

private:
  std::string path_;
};

}  // namespace

// Files, not pipes, for the three standard streams: a large picture cannot deadlock the two
// processes on full pipe buffers, and no poll loop is needed.
std::string run_external_tool(const ExternalTool &tool, const std::string &input) {
  if (tool.command.empty()) throw std::invalid_argument("run_external_tool: no command");
  TempFile in, out, err;
  {
    std::ofstream f(in.path(), std::ios::binary);
    f << input;
    if (!f.flush()) throw std::runtime_error(fmt::format("cannot write the temporary file '{}'", in.path()));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, in.path().c_str(), O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out.path().c_str(), O_WRONLY | O_TRUNC, 0);
  posix_spawn_file_actions_addopen(&actions, 2, err.path().c_str(), O_WRONLY | O_TRUNC, 0);
  std::vector<std::string> words = tool.command;  // posix_spawnp takes char *const[]
  std::vector<char *> argv;
  for (auto &w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  int rc = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0)
    throw std::runtime_error(
        fmt::format("{}, which could not be started ({}); {}", tool.purpose, std::strerror(rc), tool.if_missing));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::string why = err.read();
    while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
    std::string command;
    for (const auto &w : tool.command) command += (command.empty() ? "" : " ") + w;
    throw std::runtime_error(fmt::format("'{}' failed{}{}", command, why.empty() ? "" : ": ", why));
  }
  return out.read();
}

}  // namespace gfec
