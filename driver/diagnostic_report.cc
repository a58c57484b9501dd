#include "diagnostic_report.h"

#include "diagnostic_printer.h"
#include "diagnostics_json.h"
#include "diagnostics_sarif.h"
#include "escape.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <ostream>
#include <string_view>

#include <unistd.h>

namespace gfec {

namespace {

/// gcc's text: printed as it comes, so a long --check run shows progress.
class TextReport : public DiagnosticReport {
public:
  TextReport(std::ostream &err, TextStyle style, bool all_errors) : err_(err), style_(style), all_errors_(all_errors) {}

  void add(const std::string &, const Diagnostics &diag, const SourceManager &sources) override {
    for (const Diagnostic *d : in_source_order(diag)) {
      err_ << render_text(*d, sources, style_);
      if (d->severity == Severity::Error && d->from_warning()) werror_ = true;
    }
    if (diag.limit_reached()) err_ << limit_message(diag) << "\n";
  }
  void tool_error(const std::string &input, const std::string &message, bool text_names_input) override {
    // Both may quote a file name or a chart's string: one line each, never a forged one.
    err_ << fmt::format("{}: error: {}\n", text_names_input && !input.empty() ? text::printable(input) : "gfec",
                        text::printable(message));
  }
  std::string finish(int) override {
    // gcc's closing line when -Werror (not -Werror=NAME) turned a warning into the failure.
    if (werror_ && all_errors_) err_ << "gfec: some warnings being treated as errors\n";
    return {};
  }

private:
  std::ostream &err_;
  TextStyle style_;
  bool all_errors_;
  bool werror_ = false;
};

}  // namespace

std::vector<const Diagnostic *> in_source_order(const Diagnostics &diag) {
  std::vector<const Diagnostic *> out;
  out.reserve(diag.all().size());
  for (const Diagnostic &d : diag.all()) out.push_back(&d);
  std::stable_sort(out.begin(), out.end(), [](const Diagnostic *a, const Diagnostic *b) {
    return a->range.file != b->range.file ? a->range.file < b->range.file : a->range.begin < b->range.begin;
  });
  return out;
}

std::string limit_message(const Diagnostics &diag) {
  // gcc's wording; the limit is the count reached.
  return fmt::format("compilation terminated due to -fmax-errors={}.", diag.error_count());
}

TextStyle text_style(const Options &o) {
  TextStyle s;
  s.line_numbers = o.line_numbers;
  s.fixits = true;
  s.parseable_fixits = o.parseable_fixits;
  if (o.color == ColorMode::Always) s.color = true;
  else if (o.color == ColorMode::Auto) {
    const char *no_color = std::getenv("NO_COLOR");
    const char *term = std::getenv("TERM");
    s.color = isatty(STDERR_FILENO) && !(no_color && *no_color) && !(term && std::string_view(term) == "dumb");
  }
  return s;
}

std::unique_ptr<DiagnosticReport> make_report(const Options &o, std::ostream &err) {
  switch (o.diagnostics_format) {
  case DiagnosticsFormat::Json: return make_json_report(err);
  case DiagnosticsFormat::SarifStderr: return make_sarif_report(&err);
  case DiagnosticsFormat::SarifFile: return make_sarif_report(nullptr);
  case DiagnosticsFormat::Text: break;
  }
  return std::make_unique<TextReport>(err, text_style(o), o.warnings.as_errors);
}

Columns columns_at(const SourceFile &file, std::uint32_t offset) {
  LineCol lc = file.line_col(offset);
  Columns c;
  c.line = lc.line;
  c.byte = lc.col;
  std::string_view line = file.line_text(lc.line);
  std::uint32_t points = 0, display = 0;
  for (std::uint32_t i = 0; i + 1 < lc.col && i < line.size(); ++i) {
    unsigned char ch = static_cast<unsigned char>(line[i]);
    if ((ch & 0xC0) == 0x80) continue;  // a UTF-8 continuation byte: same code point
    ++points;
    display = ch == '\t' ? (display / 8 + 1) * 8 : display + 1;
  }
  // Past the end of the line (a range ending at the newline): count the missing bytes as columns.
  std::uint32_t beyond = lc.col - 1 > line.size() ? lc.col - 1 - static_cast<std::uint32_t>(line.size()) : 0;
  c.code_point = points + beyond + 1;
  c.display = display + beyond + 1;
  return c;
}

}  // namespace gfec
