// The commands of the gfec executable, in one table as ninja's tools: `gfec NAME ARGS...` runs
// the row called NAME, anything else (`gfec FILE...`, `gfec --check ...`) the compiler, the row
// without a name. main dispatches through it and `gfec --help` lists it. Adding a command is a
// row here (commands.cc) and a file with its entry point (docs/architecture.md "Adding a command").
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace gfec {

/// A command's entry point. argv[0] is the command's name ("run"; the program's for the
/// compiler); it prints to `out` and `err` and returns the exit code (driver.h ExitCode).
using CommandMain = int (*)(int argc, const char *const *argv, std::ostream &out, std::ostream &err);

struct Command {
  const char *name;      ///< `gfec NAME ...`; "" for the compiler itself
  const char *synopsis;  ///< how it is called, for the usage lines
  const char *summary;   ///< what it does, one line
  CommandMain main;
};

/// Every command, the compiler first, in the order the usage lines list them.
const std::vector<Command> &commands();

/// Runs the command argv[1] names (with argv shifted by one: its argv[0] is the name), else the
/// compiler with the whole argv. What main does.
int dispatch(int argc, const char *const *argv, std::ostream &out, std::ostream &err);

/// "Usage: gfec CHART ...": a line per command (the compiler's with its --check and --analyze
/// forms), for --help and for a command line without files.
std::string usage_lines();
/// The paragraph of `gfec --help` that points to each command's own --help.
std::string commands_help();
/// "Documentation: man gfec; FILE ...": where the installed copy of docs/FILE is (share/doc/gfec
/// beside the running gfec's bin/, as cmake --install and the .deb put it), else where to look.
/// --help must cite a page the user has, not a path in a source tree they may never have seen.
std::string documentation_line(const char *file);

}  // namespace gfec
