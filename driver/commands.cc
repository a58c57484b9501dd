#include "commands.h"

#include "driver.h"
#include "monitor_command.h"
#include "run_command.h"
#include "test_command.h"

#include <fmt/format.h>

#include <cstring>
#include <filesystem>
#include <system_error>

namespace gfec {

namespace {

// One row per command; the compiler (no name) first.
const std::vector<Command> kCommands = {
    {"", "gfec CHART [-o OUT] [OPTIONS]", "compile an sfc or fsm to a C engine, a plan to C++", compile_command},
    {"run", "gfec run CHART --inputs TRACE.csv", "run a chart in the reference interpreter, tick by tick", run_command},
    {"test", "gfec test FILE... [OPTIONS]", "run scenario tests on the interpreter and the C engine", test_command},
    {"monitor", "gfec monitor CHART --log", "decode a live trace of an engine built with --trace", monitor_command},
};

/// The compiler's other forms: modes of its options rather than commands of their own.
constexpr const char *kCompilerModes[][2] = {
    {"gfec --check FILE... [OPTIONS]", "validate, report every diagnostic, write nothing"},
    {"gfec --analyze FILE... [OPTIONS]", "every static analysis, a report per chart and plan"},
};

}  // namespace

const std::vector<Command> &commands() { return kCommands; }

int dispatch(int argc, const char *const *argv, std::ostream &out, std::ostream &err) {
  if (argc > 1)
    for (const Command &c : kCommands)
      if (c.name[0] != '\0' && std::strcmp(argv[1], c.name) == 0) return c.main(argc - 1, argv + 1, out, err);
  return kCommands.front().main(argc, argv, out, err);
}

std::string usage_lines() {
  std::string s;
  auto line = [&](const char *synopsis, const char *summary) {
    s += fmt::format("{:<7}{:<35}{}\n", s.empty() ? "Usage:" : "", synopsis, summary);
  };
  for (const Command &c : kCommands) {
    line(c.synopsis, c.summary);
    if (c.name[0] == '\0')
      for (const auto &mode : kCompilerModes) line(mode[0], mode[1]);
  }
  return s;
}

std::string commands_help() {
  std::string names;
  for (const Command &c : kCommands)
    if (c.name[0] != '\0') names += fmt::format("{}'gfec {} --help'", names.empty() ? "" : ", ", c.name);
  return fmt::format("Commands: 'gfec NAME ...' runs a command instead of the compiler (the usage lines above);\n"
                     "{} list their options.\n",
                     names);
}

std::string documentation_line(const char *file) {
  namespace fs = std::filesystem;
  std::error_code ec;
  // /proc/self/exe, not argv[0]: gfec is usually found through PATH.
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    fs::path installed = exe.parent_path().parent_path() / "share" / "doc" / "gfec" / file;
    if (fs::is_regular_file(installed, ec)) return fmt::format("Documentation: man gfec; {}", installed.string());
  }
  return fmt::format("Documentation: man gfec; {} in share/doc/gfec/ of gfec's installation, docs/ of its source",
                     file);
}

}  // namespace gfec
