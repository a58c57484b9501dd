// Everything the command line says, in one value passed down (no option globals).
#pragma once

#include "period_text.h"
#include "backend_registry.h"
#include "diagnostics.h"

#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class App;
}

namespace gfec {

enum class DiagnosticsFormat { Text, Json, SarifStderr, SarifFile };
/// -fdiagnostics-color=: auto colours only a terminal, and not when NO_COLOR is set.
enum class ColorMode { Auto, Always, Never };

/// A target of the dependency rule, as gcc's -MT (written as given, so `$(OBJDIR)/x.o` stays a
/// make variable) or -MQ (quoted for make: spaces escaped, `$` doubled).
struct DependencyTarget {
  std::string name;
  bool quoted = true;
  bool operator==(const DependencyTarget &o) const { return name == o.name && quoted == o.quoted; }
};

/// gcc's -MD, -MF, -MP, -MT, -MQ: a make rule saying which files the outputs were made from.
struct DependencyOptions {
  bool write = false;                     ///< -MD (or -MMD): write a dependency file beside the outputs
  std::string file;                       ///< -MF FILE; empty: the primary output with ".d"
  bool phony = false;                     ///< -MP: an empty rule per import, so deleting one breaks no build
  std::vector<DependencyTarget> targets;  ///< -MT/-MQ TARGET..., in order; empty: every file written (quoted)
};

struct Options {
  std::vector<std::string> inputs;
  std::string output;                     ///< -o; empty: derived from the input's name
  std::vector<std::string> include_dirs;  ///< -I
  std::string language;         ///< -x alica|gfec|iec-st|plcopen: the input language; empty: from the extension
  bool check_only = false;      ///< --check: validate, write nothing
  bool analyze = false;         ///< --analyze: every static analysis, a report (analyze_command.h)
  std::string emit;             ///< --emit=NAME (backend_registry.h); empty: from what is compiled
  std::string chart;            ///< --chart NAME
  bool line_directives = true;  ///< --no-line-directives turns them off
  std::string engine = "auto";  ///< --engine=auto|readable|scalable: the C engine's form
  std::vector<BackendOptionsGiven> backend_options;  ///< each back end's own (--context...): backend_registry.h
  WarningOptions warnings;  ///< -W<name>, -Wno-<name>, -Wall, -Werror[=NAME], -Wno-error=NAME, -w
  DiagnosticsFormat diagnostics_format = DiagnosticsFormat::Text;
  std::size_t error_limit = 50;       ///< -fmax-errors=N
  ColorMode color = ColorMode::Auto;  ///< -fdiagnostics-color[=WHEN], -fno-diagnostics-color
  bool line_numbers = true;           ///< -fno-diagnostics-show-line-numbers drops gcc 12's gutter
  bool parseable_fixits = false;      ///< -fdiagnostics-parseable-fixits
  DependencyOptions deps;             ///< -MD, -MF, -MP, -MT
  std::optional<double> period_ms;    ///< --period: an IEC program's scan period, over its TASK's
};

/// The result of reading argv: options to run with, or an exit code and text to print now
/// (--help, --version, usage errors).
struct ParsedCommandLine {
  Options options;
  bool exit_now = false;
  int exit_code = 0;
  std::string message;  ///< printed to stdout when exit_code is 0, else to stderr
};

ParsedCommandLine parse_command_line(int argc, const char *const *argv);

/// Applies one -f option without its "-f" ("diagnostics-format=json", "max-errors=5"): every
/// command reads them alike. Returns "" or the usage error.
std::string apply_f_flag(const std::string &flag, Options &o);

/// The -W, -w and -f values of a command line as given, until the parse is over.
struct FrontEndFlags {
  std::vector<std::string> warnings;  ///< -W<value>
  std::vector<std::string> f;         ///< -f<value>
  bool no_warnings = false;           ///< -w
  std::string period;                 ///< --period as written
  /// Applies them to `o` (-w last, as gcc); returns "" or the usage error.
  std::string apply(Options &o) const;
};

/// The options every command takes alike, so that `gfec run` and `gfec test` read a chart as gfec
/// does: -I and -x into `o`, and -W..., -w and -f... (diagnostics, -fmax-errors) into `flags`
/// for FrontEndFlags::apply once the parse is over.
void add_front_end_options(CLI::App &app, Options &o, FrontEndFlags &flags);

/// Parses a subcommand's line (`gfec run`, `gfec test`): nothing when the command goes on, else
/// the exit code after --help (0) or a usage error (2, with a hint to `gfec COMMAND --help`).
std::optional<int> parse_subcommand(CLI::App &app, int argc, const char *const *argv, std::ostream &out,
                                    std::ostream &err, const char *command);

}  // namespace gfec
