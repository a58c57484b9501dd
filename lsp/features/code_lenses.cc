#include "code_lenses.h"

#include "child_process.h"
#include "lexed_text.h"
#include "text_index.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace gfec::lsp {

nlohmann::json code_lenses(std::string_view text, const std::string &uri) {
  const LexedText lexed = lex_text(text);
  const TextIndex index(text);
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i + 1 < lexed.tokens.size(); ++i) {
    const Token &kw = lexed.tokens[i], &name = lexed.tokens[i + 1];
    if (kw.kind != Tok::KwTest || name.kind != Tok::String) continue;
    nlohmann::json range = {
        {"start",
         {{"line", index.position(kw.range.begin).line}, {"character", index.position(kw.range.begin).character}}},
        {"end",
         {{"line", index.position(name.range.end).line}, {"character", index.position(name.range.end).character}}}};
    out.push_back(
        {{"range", range},
         {"command", {{"title", "Run test"}, {"command", kRunTestCommand}, {"arguments", {uri, name.value}}}}});
  }
  return out;
}

nlohmann::json run_test_command(const std::string &path, const std::string &name, double time_limit) {
  // The gfec that runs the server runs the test: the same compiler the diagnostics came from.
  std::error_code ec;
  std::string self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
  if (ec || self.empty()) self = "gfec";
  char pattern[] = "/tmp/gfec-lsp-test-XXXXXX";
  int fd = ::mkstemp(pattern);
  if (fd < 0) return {{"passed", false}, {"exitCode", nullptr}, {"output", "cannot create a temporary file"}};
  ::close(fd);
  child_process::Spawn spawn;
  spawn.argv = {self, "test", path, "--filter", name};
  spawn.stdin_path = "/dev/null";
  spawn.stdout_path = pattern;
  spawn.stderr_path = "&1";
  spawn.time_limit = time_limit;
  child_process::Result r = child_process::run(spawn);
  std::ifstream in(pattern, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  std::remove(pattern);
  std::string output = text.str();
  if (!r.ok() && r.how != child_process::Result::How::Exited)
    output += "gfec test " + child_process::describe(r) + "\n";
  nlohmann::json code = r.how == child_process::Result::How::Exited ? nlohmann::json(r.code) : nlohmann::json(nullptr);
  return {{"passed", r.ok()}, {"exitCode", code}, {"output", output}};
}

}  // namespace gfec::lsp
