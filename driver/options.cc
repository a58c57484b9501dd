#include "options.h"

#include "backend_registry.h"
#include "commands.h"
#include "did_you_mean.h"
#include "escape.h"
#include "input_languages.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

namespace gfec {

namespace {

/// Why `name` is no warning gfec has: an error (errors cannot be turned off), a near miss, or
/// simply unknown. The names come from the table of kinds (compiler/diagnostic_kinds.def).
std::string unknown_warning(const std::string &flag, const std::string &name) {
  if (const DiagnosticKind *k = find_kind(name); k && !k->warning)
    return fmt::format("'-W{}': '{}' is an error, not a warning; errors cannot be turned off or made warnings", flag,
                       name);
  std::string best;
  NearestName nearest(name, name.size() / 3);
  for (std::size_t i = 0; i < static_cast<std::size_t>(Warning::Count_); ++i) {
    std::string_view candidate = kind_info(static_cast<Warning>(i)).name;
    if (nearest.offer(candidate)) best = std::string(candidate);
  }
  std::string message = fmt::format("unknown warning option '-W{}'", flag);
  if (!best.empty())
    message += fmt::format("; did you mean '-W{}{}'?", flag.substr(0, flag.size() - name.size()), best);
  return message + " ('gfec --help' lists the warnings)";
}

/// For an option the command does not have (`--chek`), the nearest it has: "did you mean
/// '--check'?" on a line of its own, or "".
std::string option_suggestion(const CLI::App &app, int argc, const char *const *argv) {
  std::vector<std::string> names;
  for (const CLI::Option *opt : app.get_options()) {
    for (const std::string &l : opt->get_lnames()) names.push_back("--" + l);
    for (const std::string &sn : opt->get_snames()) names.push_back("-" + sn);
  }
  std::string out;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg.size() < 3 || arg.compare(0, 2, "--") != 0) continue;
    arg = arg.substr(0, arg.find('='));
    if (std::find(names.begin(), names.end(), arg) != names.end()) continue;
    NearestName nearest(arg, typo_limit(arg.size() - 2));
    std::string best;
    for (const std::string &n : names)
      if (n.size() > 2 && nearest.offer(n)) best = n;
    if (!best.empty()) out += fmt::format("{}: note: did you mean '{}'?\n", app.get_name(), best);
  }
  return out;
}

/// Applies one -W value ("error", "all", "no-conflict", "conflict"); returns why it cannot, or "".
std::string apply_warning_flag(const std::string &flag, WarningOptions &w) {
  if (flag == "error") {
    w.as_errors = true;
    return {};
  }
  if (flag == "no-error") {
    w.as_errors = false;
    return {};
  }
  // gcc: -Werror=NAME turns NAME on and makes it an error; -Wno-error=NAME keeps it a warning.
  if (flag.rfind("error=", 0) == 0 || flag.rfind("no-error=", 0) == 0) {
    bool error = flag[0] == 'e';
    std::string name = flag.substr(error ? 6 : 9);
    auto found = find_warning(name);
    if (!found) return unknown_warning(flag, name);
    w.error_override[static_cast<int>(*found)] = error ? 1 : -1;
    if (error) w.set(*found, true);
    return {};
  }
  if (flag == "all" || flag == "extra") {
    for (int i = 0; i < static_cast<int>(Warning::Count_); ++i) w.enabled[i] = true;
    return {};
  }
  bool on = true;
  std::string name = flag;
  if (name.rfind("no-", 0) == 0) {
    on = false;
    name = name.substr(3);
  }
  auto found = find_warning(name);
  if (!found) return unknown_warning(flag, name);
  w.set(*found, on);
  return {};
}

/// Takes gcc's dependency flags out of argv and returns the rest for CLI11.
///
/// Why by hand: CLI11 knows single-letter short options ("-W", "-f", "-I", "-o") and long ones
/// ("--check"), but not gcc's multi-letter single-dash flags: it would read "-MD" as an option
/// "-M" with the value "D". Makefiles and CMake pass them exactly as they pass them to gcc, so we
/// accept gcc's spelling: -MD, -MMD (the same here: charts have no system files), -MP, and -MF /
/// -MT / -MQ with the value attached ("-MFdeps.d") or as the next argument. "--" ends the scan, as it
/// ends CLI11's options.
std::vector<const char *> take_dependency_flags(int argc, const char *const *argv, DependencyOptions &deps,
                                                std::string &error) {
  std::vector<const char *> rest;
  bool options_ended = false;
  for (int i = 0; i < argc; ++i) {
    std::string a = argv[i];
    if (i == 0 || options_ended || a.rfind("-M", 0) != 0) {
      options_ended = options_ended || (i > 0 && a == "--");
      rest.push_back(argv[i]);
      continue;
    }
    if (a == "-MD" || a == "-MMD") {
      deps.write = true;
    } else if (a == "-MP") {
      deps.phony = true;
    } else if (a.rfind("-MF", 0) == 0 || a.rfind("-MT", 0) == 0 || a.rfind("-MQ", 0) == 0) {
      std::string value = a.substr(3);
      if (value.empty()) {
        if (i + 1 >= argc) {
          error = fmt::format("missing file after '{}'", a);
          return rest;
        }
        value = argv[++i];
      }
      if (a[2] == 'F') deps.file = value;
      else deps.targets.push_back({value, a[2] == 'Q'});
    } else {
      error = fmt::format("unknown option '{}' (dependency files: -MD, -MF FILE, -MP, -MT TARGET, -MQ TARGET)", a);
      return rest;
    }
  }
  return rest;
}

/// -x LANG: the one place its values are checked.
void add_language_option(CLI::App &app, std::string &language) {
  app.add_option("-x", language,
                 "Input language, as gcc's -x: " + input_languages_help() +
                     "; default: from the file's extension (.pml is alica, .st iec-st), other files chart text")
      ->type_name("LANG")
      ->check(CLI::IsMember(input_language_names()));
}

std::string warning_help() {
  std::string s = "Warnings (-W<name> turns one on, -Wno-<name> off; -Wall all; -w none; -Werror makes them errors,\n"
                  "-Werror=<name> one of them, -Wno-error=<name> keeps one a warning):\n";
  for (int i = 0; i < static_cast<int>(Warning::Count_); ++i) {
    const DiagnosticKind &w = kind_info(static_cast<Warning>(i));
    s += fmt::format("  -W{:<20} {}{}\n", w.name, w.summary, w.on_by_default ? " (on by default)" : "");
  }
  return s;
}

}  // namespace

std::string apply_f_flag(const std::string &f, Options &o) {
  if (f.rfind("diagnostics-format=", 0) == 0) {
    std::string v = f.substr(19);
    if (v == "text") o.diagnostics_format = DiagnosticsFormat::Text;
    else if (v == "json") o.diagnostics_format = DiagnosticsFormat::Json;
    else if (v == "sarif-stderr") o.diagnostics_format = DiagnosticsFormat::SarifStderr;
    else if (v == "sarif-file") o.diagnostics_format = DiagnosticsFormat::SarifFile;
    else return fmt::format("unknown diagnostics format '{}' (text, json, sarif-stderr, sarif-file)", v);
  } else if (f == "diagnostics-color" || f == "diagnostics-color=always") {
    o.color = ColorMode::Always;  // gcc: the flag alone means always
  } else if (f == "diagnostics-color=never" || f == "no-diagnostics-color") {
    o.color = ColorMode::Never;
  } else if (f == "diagnostics-color=auto") {
    o.color = ColorMode::Auto;
  } else if (f.rfind("diagnostics-color=", 0) == 0) {
    return fmt::format("unknown colour mode '{}' in '-f{}' (auto, always, never)", f.substr(18), f);
  } else if (f == "diagnostics-show-line-numbers" || f == "no-diagnostics-show-line-numbers") {
    o.line_numbers = f[0] != 'n';
  } else if (f == "diagnostics-parseable-fixits") {
    o.parseable_fixits = true;
  } else if (f.rfind("max-errors=", 0) == 0) {
    try {
      o.error_limit = std::stoul(f.substr(11));
    } catch (const std::exception &) { return fmt::format("'-f{}' needs a number", f); }
    if (o.error_limit == 0) o.error_limit = static_cast<std::size_t>(-1);  // as gcc: 0 = no limit
  } else {
    return fmt::format("unknown option '-f{}'", f);
  }
  return {};
}

std::string FrontEndFlags::apply(Options &o) const {
  for (const auto &w : warnings)
    if (std::string why = apply_warning_flag(w, o.warnings); !why.empty()) return why;
  for (const auto &flag : f)
    if (std::string why = apply_f_flag(flag, o); !why.empty()) return why;
  if (!period.empty()) {
    o.period_ms = parse_period(period);
    if (!o.period_ms)
      return fmt::format("--period '{}' is not a duration above 0: write it as 10ms, 1.5s or T#10ms",
                         text::printable(period));
  }
  // gcc: -w inhibits every warning, whatever -W flags came with it.
  if (no_warnings) o.warnings.enabled.fill(false);
  return {};
}

void add_front_end_options(CLI::App &app, Options &o, FrontEndFlags &flags) {
  // One value per occurrence (-I a -I b, -Wall -Werror): CLI11 would otherwise let a vector
  // option swallow the file names that follow it ("-Wall x.sfc").
  app.add_option("-I", o.include_dirs, "Add DIR to the folders searched for imports")
      ->type_name("DIR")
      ->allow_extra_args(false);
  add_language_option(app, o.language);
  app.add_option("-W", flags.warnings, "Warning control: -W<name>, -Wno-<name>, -Wall, -Werror")
      ->type_name("NAME")
      ->allow_extra_args(false);
  app.add_flag("-w", flags.no_warnings, "Inhibit every warning (as gcc)");
  app.add_option("--period", flags.period,
                 "An IEC program's scan period (10ms, 1.5s, T#10ms), over its TASK's INTERVAL; chart text "
                 "declares its own")
      ->type_name("DURATION");
  app.add_option("-f", flags.f,
                 "-fdiagnostics-format=text|json|sarif-stderr|sarif-file, -fmax-errors=N, -fdiagnostics-color=WHEN, "
                 "-fdiagnostics-parseable-fixits, -fno-diagnostics-show-line-numbers")
      ->type_name("OPTION")
      ->allow_extra_args(false);
}

namespace {

/// CLI11's message for `e` with the error's own text (which quotes the command line: a file name
/// from a glob may hold a newline) escaped as every message gfec prints is (support/escape.h).
std::string printable_error(std::string message, const CLI::ParseError &e) {
  const std::string what = e.what();
  if (auto at = message.find(what); !what.empty() && at != std::string::npos)
    message.replace(at, what.size(), text::printable(what));
  return message;
}

}  // namespace

std::optional<int> parse_subcommand(CLI::App &app, int argc, const char *const *argv, std::ostream &out,
                                    std::ostream &err, const char *command) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError &e) {
    std::ostringstream error;
    int code = app.exit(e, out, error);
    err << printable_error(error.str(), e);
    if (code != 0)
      err << option_suggestion(app, argc, argv) << "Run 'gfec " << command << " --help' for the options.\n";
    return code == 0 ? 0 : 2;
  }
  return std::nullopt;
}

namespace {
class NoUsageFormatter : public CLI::Formatter {
public:
  std::string make_usage(const CLI::App *, std::string) const override { return ""; }
  // The description already ends in a newline (the last usage line).
  std::string make_description(const CLI::App *app) const override { return app->get_description(); }
};
}  // namespace

ParsedCommandLine parse_command_line(int argc, const char *const *argv) {
  ParsedCommandLine result;
  Options &o = result.options;
  CLI::App app{"gfec - compiles chart files (sfc, fsm, plan) into C and C++ engines for robots\n\n" + usage_lines(),
               "gfec"};
  app.footer(backends_help() + "\n" + warning_help() +
             "\nDependency files, as gcc writes them: -MD writes OUTPUT.d (or -MF FILE) for make, naming\n"
             "every file imported; -MP adds an empty rule per import; -MT TARGET names the target (-MQ TARGET\n"
             "quoted for make).\n"
             "\nDiagnostics, as gcc 12 prints them: -fdiagnostics-color=auto|always|never (auto: colour on a\n"
             "terminal unless NO_COLOR is set; -fno-diagnostics-color = never), -fno-diagnostics-show-line-numbers,\n"
             "-fdiagnostics-parseable-fixits (fix-it:\"FILE\":{L:C-L:C}:\"TEXT\" lines for editors).\n"
             "\n" +
             commands_help() + "\nExit status: 0 success, 1 errors in the input, 2 usage or I/O error.\n" +
             documentation_line("cli.md"));
  // The description's usage lines are the usage: CLI11's own "Usage: gfec [OPTIONS] [files...]"
  // would be a second, less precise block.
  app.formatter(std::make_shared<NoUsageFormatter>());
  bool no_line = false;
  app.add_option("files", o.inputs, "Chart files to compile (several only with --check or --analyze)");
  app.add_option("-o,--output", o.output,
                 "Output file; a C engine's header is written beside it; '-' for stdout (one-file back ends)");
  FrontEndFlags front_end;
  add_front_end_options(app, o, front_end);
  app.add_flag("--check", o.check_only, "Validate only: report every diagnostic and write nothing");
  app.add_flag("--analyze", o.analyze,
               "Run every static analysis and print a report per chart and plan; write nothing");
  app.add_option("--emit", o.emit,
                 fmt::format("Back end: {} (default: from the file; the list below)", backend_names_list()))
      ->type_name("NAME");
  app.add_option("--chart", o.chart, "The chart or plan to compile when a file declares several")->type_name("NAME");
  app.add_flag("--no-line-directives", no_line, "Do not write #line directives pointing back to the chart");
  app.add_option("--engine", o.engine,
                 "C engine form: auto (readable up to 64 places or states, or when a quarter of an sfc's places can "
                 "be active at once), readable or scalable")
      ->check(CLI::IsMember({"auto", "readable", "scalable"}));
  // Each back end's own options (the C engine's --context, --names): its registry row declares them.
  o.backend_options = add_backend_options(app);
  app.set_version_flag("--version", fmt::format("gfec {}", GFEC_VERSION));

  std::string dep_error;
  std::vector<const char *> args = take_dependency_flags(argc, argv, o.deps, dep_error);
  if (!dep_error.empty()) {
    result.exit_now = true;
    result.exit_code = 2;
    result.message = "gfec: error: " + text::printable(dep_error) + "\nRun 'gfec --help' for the options.\n";
    return result;
  }

  try {
    app.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError &e) {
    result.exit_now = true;
    std::ostringstream out, err;
    result.exit_code = app.exit(e, out, err) == 0 ? 0 : 2;
    result.message = result.exit_code == 0 ? out.str() : printable_error(err.str(), e);
    if (result.exit_code != 0)
      result.message +=
          option_suggestion(app, static_cast<int>(args.size()), args.data()) + "Run 'gfec --help' for the options.\n";
    return result;
  }

  auto usage_error = [&](std::string message) {
    result.exit_now = true;
    result.exit_code = 2;
    result.message = "gfec: error: " + text::printable(message) + "\n";
    return result;
  };
  if (o.inputs.empty()) {
    // gcc's words, then what a first-time user can type next.
    result.exit_now = true;
    result.exit_code = 2;
    result.message = "gfec: fatal error: no input files\n" + usage_lines() +
                     "Run 'gfec --help' for the options, 'gfec run --help' for the interpreter's.\n";
    return result;
  }
  if (std::string why = front_end.apply(o); !why.empty()) return usage_error(why);
  o.line_directives = !no_line;
  for (auto &given : o.backend_options)
    if (std::string why = given.group->check(); !why.empty()) return usage_error(why);
  if (o.analyze && (!o.output.empty() || o.deps.write)) return usage_error("--analyze writes nothing; drop -o and -MD");
  if (o.analyze) return result;  // several files are fine, as with --check
  if (!o.check_only && o.inputs.size() > 1) return usage_error("several input files are only allowed with --check");
  if (o.check_only && !o.output.empty()) return usage_error("--check writes nothing; drop -o");
  if (o.check_only && o.deps.write) return usage_error("--check writes nothing; drop -MD");
  if (o.output == "-" && o.deps.write) return usage_error("-MD needs an output file, not '-o -'");
  return result;
}

}  // namespace gfec
