#include "diagnostic_report.h"

#include "diagnostic_printer.h"
#include "diagnostics_json.h"
#include "diagnostics_sarif.h"

#include <fmt/format.h>

#include <ostream>

namespace gfec {

namespace {

/// gcc's text: printed as it comes, so a long --check run shows progress.
class TextReport : public DiagnosticReport {
public:
  explicit TextReport(std::ostream &err) : err_(err) {}

  void add(const std::string &, const Diagnostics &diag, const SourceManager &sources) override {
    for (const auto &d : diag.all()) err_ << render_text(d, sources);
    if (diag.limit_reached())
      err_ << fmt::format("gfec: compilation stopped after {} errors (-fmax-errors)\n", diag.error_count());
  }
  void tool_error(const std::string &input, const std::string &message, bool text_names_input) override {
    err_ << fmt::format("{}: error: {}\n", text_names_input && !input.empty() ? input : "gfec", message);
  }
  std::string finish(int) override { return {}; }

private:
  std::ostream &err_;
};

} // namespace

std::unique_ptr<DiagnosticReport> make_report(DiagnosticsFormat format, std::ostream &err) {
  switch (format) {
  case DiagnosticsFormat::Json: return make_json_report(err);
  case DiagnosticsFormat::SarifStderr: return make_sarif_report(&err);
  case DiagnosticsFormat::SarifFile: return make_sarif_report(nullptr);
  case DiagnosticsFormat::Text: break;
  }
  return std::make_unique<TextReport>(err);
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

} // namespace gfec
