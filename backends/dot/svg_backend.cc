// --emit=svg: the DOT picture rendered by Graphviz. We run the `dot` program rather than link
// libgvc: Graphviz stays an optional tool, found on PATH when a user asks for SVG.
#include "dot_backend.h"

#include <ostream>
#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

namespace gfec {

namespace {

/// A temporary file removed when it goes out of scope.
class TempFile {
public:
  TempFile() {
    std::string pattern = (std::filesystem::temp_directory_path() / "gfec-dot-XXXXXX").string();
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

/// Runs `dot -Tsvg` with files for stdin, stdout and stderr (no pipes, so no deadlock on big
/// pictures). Throws with a message for the user when `dot` is missing or fails.
std::string render_svg(const std::string &dot_text) {
  TempFile in, out, err;
  {
    std::ofstream f(in.path(), std::ios::binary);
    f << dot_text;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, in.path().c_str(), O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out.path().c_str(), O_WRONLY | O_TRUNC, 0);
  posix_spawn_file_actions_addopen(&actions, 2, err.path().c_str(), O_WRONLY | O_TRUNC, 0);
  char program[] = "dot", format[] = "-Tsvg";
  char *argv[] = {program, format, nullptr};
  pid_t pid = 0;
  int rc = posix_spawnp(&pid, "dot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0)
    throw std::runtime_error(fmt::format("--emit=svg runs Graphviz's 'dot', which could not be started ({}); "
                                         "install Graphviz (Debian: apt-get install graphviz) or use --emit=dot",
                                         std::strerror(rc)));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::string why = err.read();
    while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
    throw std::runtime_error(fmt::format("'dot -Tsvg' failed{}{}", why.empty() ? "" : ": ", why));
  }
  return out.read();
}

class SvgBackend : public Backend {
public:
  void emit(const model::Model &m, const EmitOptions &o, OutputSink &sink) const override {
    sink.open(o.output_path) << render_svg(dot_picture(m, o));
  }
};

}  // namespace

std::unique_ptr<Backend> make_svg_backend() { return std::make_unique<SvgBackend>(); }

}  // namespace gfec
