// Where diagnostics go: gcc-style text, gcc's JSON, or SARIF 2.1.0 (-fdiagnostics-format=).
// The driver hands every input's diagnostics to one report; the structured formats collect
// them all and print one document at the end, so stderr stays valid JSON even with --check
// over several files.
#pragma once

#include "diagnostic_printer.h"
#include "diagnostics.h"
#include "options.h"

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace gfec {

class DiagnosticReport {
public:
  virtual ~DiagnosticReport() = default;
  /// The diagnostics of one input file, with the sources they point into.
  virtual void add(const std::string &input, const Diagnostics &diag, const SourceManager &sources) = 0;
  /// A problem of the run rather than of a place in a chart (cannot read the file, no chart to
  /// compile, cannot write an output), about `input`. The text format starts the line with the
  /// input's name when `text_names_input`, else with "gfec" (as gcc does for I/O errors).
  virtual void tool_error(const std::string &input, const std::string &message, bool text_names_input) = 0;
  /// Called once, last: prints or writes what was collected. Returns "" or why it could not
  /// write (sarif-file), which the driver reports as an I/O error.
  virtual std::string finish(int exit_code) = 0;
};

/// The diagnostics of one input in source order, as every format prints them: by file (in the
/// order the files were loaded, the input first), then by position in the file; diagnostics at
/// one position keep the order the stages found them in.
std::vector<const Diagnostic *> in_source_order(const Diagnostics &diag);

/// The report -fdiagnostics-format= asks for; the text one in the style the -fdiagnostics-*
/// flags, the terminal and NO_COLOR ask for (text_style).
/// "compilation terminated due to -fmax-errors=N.", as gcc says it.
std::string limit_message(const Diagnostics &diag);

std::unique_ptr<DiagnosticReport> make_report(const Options &o, std::ostream &err);

/// gcc's rule for colour: always, never, or (auto) when stderr is a terminal, TERM is not
/// "dumb" and NO_COLOR is unset or empty (https://no-color.org).
TextStyle text_style(const Options &o);

/// The columns a structured format reports for a 0-based byte offset: code points (SARIF's
/// "unicodeCodePoints") and display columns with tabs at every 8th column (gcc's
/// "display-column"). All 1-based.
struct Columns {
  std::uint32_t line = 1;
  std::uint32_t byte = 1;
  std::uint32_t code_point = 1;
  std::uint32_t display = 1;
};
Columns columns_at(const SourceFile &file, std::uint32_t offset);

}  // namespace gfec
