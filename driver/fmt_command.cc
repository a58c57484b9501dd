#include "fmt_command.h"

#include "commands.h"
#include "diagnostic_report.h"
#include "driver.h"
#include "escape.h"
#include "file_system.h"
#include "format/format_source.h"
#include "input_languages.h"
#include "options.h"
#include "child_process.h"
#include "safe_output.h"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sys/stat.h>
#include <unistd.h>

namespace gfec {

namespace {

struct FmtOptions {
  std::vector<std::string> files;
  bool check = false;
  bool diff = false;  ///< --diff: as --check, and print what would change
  Options report;     ///< -f...: how diagnostics are printed
};

/// The differences between `before` and `after` as `diff -u` prints them, both sides labelled
/// `name`; "" and `why` set when diff cannot run. (diff is part of every Debian system.)
std::string unified_diff(const std::string &name, const std::string &before, const std::string &after,
                         std::string &why) {
  std::error_code ec;
  std::filesystem::path tmp = std::filesystem::temp_directory_path(ec);  // $TMPDIR, else /tmp
  std::string pattern = ((ec ? std::filesystem::path("/tmp") : tmp) / "gfec-fmt-XXXXXX").string();
  const char *dir = ::mkdtemp(pattern.data());
  if (!dir) {
    why = std::string("cannot make a temporary folder for diff: ") + std::strerror(errno);
    return {};
  }
  const std::string a = std::string(dir) + "/a", b = std::string(dir) + "/b", d = std::string(dir) + "/diff";
  std::string result;
  if (std::ofstream(a, std::ios::binary) << before && std::ofstream(b, std::ios::binary) << after) {
    child_process::Spawn spawn;
    spawn.argv = {"diff", "-u", "--label", name, "--label", name, a, b};
    spawn.stdout_path = d;
    spawn.time_limit = 60;
    child_process::Result r = child_process::run(spawn);
    if (r.how == child_process::Result::How::Exited && r.code <= 1) {
      std::ifstream in(d, std::ios::binary);
      result.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    } else {
      why = "diff " + child_process::describe(r);
    }
  } else {
    why = std::string("cannot write a temporary file for diff in ") + dir;
  }
  for (const std::string &f : {a, b, d}) ::unlink(f.c_str());
  ::rmdir(dir);
  return result;
}

/// What --check and --diff print for a file that would change; false when that failed
/// (reported).
bool show_change(const std::string &name, const std::string &before, const std::string &after, const FmtOptions &o,
                 DiagnosticReport &report, std::ostream &out) {
  if (!o.diff) {
    out << text::printable(name) << "\n";
    return true;
  }
  std::string why;
  std::string diff = unified_diff(text::printable(name), before, after, why);
  if (!why.empty()) {
    report.tool_error(name, why, false);
    return false;
  }
  out << diff;
  return true;
}

/// The files below `dir` whose extension is one of chart text's six.
std::vector<std::string> chart_text_below(const std::string &dir) {
  static const char *const kKinds[] = {".sfc", ".fsm", ".plan", ".toolbox", ".iface", ".test"};
  std::vector<std::string> files;
  for (const std::string &path : RealFileSystem().walk(dir)) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (const char *kind : kKinds)
      if (ext == kind) files.push_back(path);
  }
  return files;
}

/// What became of one file.
enum class Outcome { Unchanged, Changed, Broken, IoError };

/// Formats `text`, read from `path`; the canonical text, or nothing when it does not parse (the
/// errors went to `report`).
std::optional<std::string> formatted(const std::string &path, std::string text, DiagnosticReport &report,
                                     const Options &o) {
  SourceManager sources;
  const InputLanguage &language = input_language_of(path, text);
  FileId id = sources.add(path, std::move(text), language);
  Diagnostics diag(o.warnings, o.error_limit);
  std::optional<std::string> result = format_source(sources, id, diag);
  report.add(path, diag, sources);
  return result;
}

Outcome format_stdin(const FmtOptions &o, DiagnosticReport &report, std::ostream &out) {
  std::string text{std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>()};
  auto result = formatted("<stdin>", text, report, o.report);
  if (!result) return Outcome::Broken;
  if (o.check || o.diff) {
    if (*result == text) return Outcome::Unchanged;
    return show_change("<stdin>", text, *result, o, report, out) ? Outcome::Changed : Outcome::IoError;
  }
  out << *result;
  return *result == text ? Outcome::Unchanged : Outcome::Changed;
}

Outcome format_file(const std::string &path, const FmtOptions &o, DiagnosticReport &report, std::ostream &out) {
  // The link would be replaced by a formatted copy, leaving the file it names as it was.
  struct stat st {};
  const bool stated = ::lstat(path.c_str(), &st) == 0;
  if (stated && S_ISLNK(st.st_mode)) {
    report.tool_error(
        path, "not rewritten: '" + text::printable(path) + "' is a symbolic link; format the file it names", false);
    return Outcome::IoError;
  }
  RealFileSystem fs;
  FileText text = fs.read(path);
  if (!text) {
    report.tool_error(path, cannot_read(path, text.why), false);
    return Outcome::IoError;
  }
  auto result = formatted(path, *text, report, o.report);
  if (!result) return Outcome::Broken;
  if (*result == *text) return Outcome::Unchanged;
  if (o.check || o.diff) return show_change(path, *text, *result, o, report, out) ? Outcome::Changed : Outcome::IoError;
  if (std::string failed = safe_output::write_all({{path, *result}}, {}); !failed.empty()) {
    report.tool_error(path, failed, false);
    return Outcome::IoError;
  }
  // The new file has the mode a new output gets; a formatted file keeps the one it had.
  if (stated && ::chmod(path.c_str(), st.st_mode & 07777) != 0) {
    report.tool_error(path, "formatted, but cannot restore its mode: " + std::string(std::strerror(errno)), false);
    return Outcome::IoError;
  }
  return Outcome::Changed;
}

}  // namespace

int fmt_command(int argc, const char *const *argv, std::ostream &out, std::ostream &err) {
  FmtOptions o;
  FrontEndFlags flags;
  CLI::App app{"gfec fmt - lays out chart text (.sfc .fsm .plan .toolbox .iface .test) in its canonical form",
               "gfec fmt"};
  app.footer("Rewrites each FILE in place (a file already canonical is left untouched); a folder stands\n"
             "for the .sfc .fsm .plan .toolbox .iface .test files below it; '-' reads stdin\n"
             "and writes the result to stdout. Comments are kept and the compiled chart does not change.\n"
             "A file that does not parse is reported and left as it is.\n"
             "Exit status: 0 done (--check, --diff: nothing to change), 1 a file does not parse or\n"
             "--check or --diff found files to change, 2 usage or I/O error.\n" +
             documentation_line("formatting.md"));
  app.add_option("files", o.files, "Chart text files, folders (the chart text below them) and '-' for stdin")
      ->required();
  app.add_flag("--check", o.check, "Write nothing: list the files that are not canonical, exit 1 if any");
  app.add_flag("--diff", o.diff, "Write nothing: print what would change as a unified diff, exit 1 if anything would");
  app.add_option("-f", flags.f,
                 "-fdiagnostics-format=text|json|sarif-stderr|sarif-file, -fmax-errors=N, -fdiagnostics-color=WHEN")
      ->type_name("OPTION")
      ->allow_extra_args(false);
  if (auto code = parse_subcommand(app, argc, argv, out, err, "fmt")) return *code;
  if (std::string why = flags.apply(o.report); !why.empty()) {
    err << "gfec: error: " << text::printable(why) << "\nRun 'gfec fmt --help' for the options.\n";
    return kExitUsageOrIo;
  }
  auto report = make_report(o.report, err);
  bool broken = false, changed = false, io_error = false;
  auto count = [&](Outcome r) {
    broken |= r == Outcome::Broken;
    changed |= r == Outcome::Changed;
    io_error |= r == Outcome::IoError;
  };
  for (const std::string &path : o.files) {
    std::error_code ec;
    if (path != "-" && std::filesystem::is_directory(path, ec) && !std::filesystem::is_symlink(path, ec)) {
      // A folder: the chart text files below it, in path order, as far as the file system
      // layer's walk goes (hidden folders skipped), as `gfec --check FOLDER` reads them.
      std::vector<std::string> below = chart_text_below(path);
      if (below.empty()) {
        report->tool_error(path, "folder '" + text::printable(path) + "' holds no chart text file", false);
        count(Outcome::IoError);
      }
      for (const std::string &file : below) count(format_file(file, o, *report, out));
      continue;
    }
    count(path == "-" ? format_stdin(o, *report, out) : format_file(path, o, *report, out));
  }
  int code = io_error ? kExitUsageOrIo : broken || ((o.check || o.diff) && changed) ? kExitInputError : kExitOk;
  return finish_report(*report, code, err);
}

}  // namespace gfec
