#include "diagnostic_printer.h"

#include <fmt/format.h>

#include <algorithm>

namespace gfec {

namespace {

/// The quoted source line and a caret line: '^' at the start of the range, '~' under the rest
/// of it on that line. Tabs are copied so the caret lines up in any terminal.
void quote(std::string &out, const SourceRange &range, const SourceManager &sources) {
  const SourceFile &file = sources.file(range.file);
  LineCol begin = file.line_col(range.begin);
  std::string_view line = file.line_text(begin.line);
  if (line.empty() && file.text().empty()) return;
  out += fmt::format(" {}\n ", line);
  std::uint32_t col0 = begin.col - 1;
  for (std::uint32_t i = 0; i < col0 && i < line.size(); ++i) out += line[i] == '\t' ? '\t' : ' ';
  out += '^';
  LineCol end = file.line_col(range.end);
  std::uint32_t last = end.line == begin.line ? end.col - 1 : static_cast<std::uint32_t>(line.size());
  if (last > col0 + 1) out.append(std::min<std::size_t>(last, line.size() + 1) - col0 - 1, '~');
  out += '\n';
}

std::string location(const SourceRange &range, const SourceManager &sources) {
  const SourceFile &file = sources.file(range.file);
  LineCol lc = file.line_col(range.begin);
  return fmt::format("{}:{}:{}", file.path(), lc.line, lc.col);
}

} // namespace

const char *severity_name(Severity s) {
  switch (s) {
  case Severity::Error: return "error";
  case Severity::Warning: return "warning";
  case Severity::Note: return "note";
  }
  return "?";
}

std::string render_text(const Diagnostic &d, const SourceManager &sources) {
  std::string out = fmt::format("{}: {}: {}", location(d.range, sources), severity_name(d.severity), d.message);
  if (!d.check.empty()) out += fmt::format(" [{}]", d.check);
  out += '\n';
  quote(out, d.range, sources);
  for (const auto &n : d.notes) {
    const SourceRange &at = n.has_range ? n.range : d.range;
    out += fmt::format("{}: note: {}\n", location(at, sources), n.message);
    if (n.has_range) quote(out, n.range, sources);
  }
  return out;
}

} // namespace gfec
