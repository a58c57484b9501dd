#include "diagnostic_printer.h"

#include <fmt/format.h>

#include <algorithm>

namespace gfec {

namespace {

// gcc's default GCC_COLORS: error=01;31, warning=01;35, note=01;36, range1=32, locus=01,
// fixit-insert=32. "\33[K" after each start clears to the end of the line, as gcc writes it.
constexpr const char *kBold = "01";
constexpr const char *kGreen = "32";

const char *severity_color(Severity s) {
  switch (s) {
  case Severity::Error: return "01;31";
  case Severity::Warning: return "01;35";
  case Severity::Note: return "01;36";
  }
  return "";
}

std::string paint(const TextStyle &style, const char *sgr, std::string_view text) {
  if (!style.color || text.empty()) return std::string(text);
  return fmt::format("\33[{}m\33[K{}\33[m\33[K", sgr, text);
}

/// The quoted source line and a caret line: '^' at the start of the range, '~' under the rest
/// of it on that line, then the fix-it's text under it when the fix stays on that line. Tabs are
/// copied so the caret lines up in any terminal.
void quote(std::string &out, const SourceRange &range, const std::vector<FixIt> &fixits, const SourceManager &sources,
           const TextStyle &style) {
  const SourceFile &file = sources.file(range.file);
  LineCol begin = file.line_col(range.begin);
  std::string_view line = file.line_text(begin.line);
  if (line.empty() && file.text().empty()) return;
  std::string number = std::to_string(begin.line);
  std::size_t width = std::max<std::size_t>(4, number.size());
  // gcc 12: " NNNN | source" and "      | ^~~" (the gutter is as wide as the line number).
  std::string gutter = style.line_numbers ? fmt::format(" {:>{}} |", number, width) : "";
  std::string blank = style.line_numbers ? fmt::format(" {:>{}} |", "", width) : "";
  out += fmt::format("{} {}\n", gutter, line);
  std::string indent;
  std::uint32_t col0 = begin.col - 1;
  for (std::uint32_t i = 0; i < col0 && i < line.size(); ++i) indent += line[i] == '\t' ? '\t' : ' ';
  std::string caret = "^";
  LineCol end = file.line_col(range.end);
  std::uint32_t last = end.line == begin.line ? end.col - 1 : static_cast<std::uint32_t>(line.size());
  if (last > col0 + 1) caret.append(std::min<std::size_t>(last, line.size() + 1) - col0 - 1, '~');
  out += fmt::format("{} {}{}\n", blank, indent, paint(style, kGreen, caret));
  for (const FixIt &f : fixits) {
    LineCol at = file.line_col(f.range.begin);
    if (f.range.file != range.file || at.line != begin.line || f.replacement.empty()) continue;
    std::string fix_indent;
    for (std::uint32_t i = 0; i + 1 < at.col && i < line.size(); ++i) fix_indent += line[i] == '\t' ? '\t' : ' ';
    out += fmt::format("{} {}{}\n", blank, fix_indent, paint(style, kGreen, f.replacement));
  }
}

std::string location(const SourceRange &range, const SourceManager &sources) {
  const SourceFile &file = sources.file(range.file);
  LineCol lc = file.line_col(range.begin);
  return fmt::format("{}:{}:{}", file.path(), lc.line, lc.col);
}

/// gcc's string escapes for a fix-it line: backslash, quote and control characters in octal.
std::string escape(std::string_view s) {
  std::string out;
  for (unsigned char c : s) {
    if (c == '\\' || c == '"') out += {'\\', static_cast<char>(c)};
    else if (c < 0x20 || c == 0x7F) out += fmt::format("\\{:03o}", c);
    else out += static_cast<char>(c);
  }
  return out;
}

}  // namespace

const char *severity_name(Severity s) {
  switch (s) {
  case Severity::Error: return "error";
  case Severity::Warning: return "warning";
  case Severity::Note: return "note";
  }
  return "?";
}

std::string check_label(const Diagnostic &d) {
  if (d.severity == Severity::Error && d.from_warning()) return "-Werror=" + std::string(d.kind->name);
  return d.check();
}

std::string render_text(const Diagnostic &d, const SourceManager &sources, const TextStyle &style) {
  const char *color = severity_color(d.severity);
  std::string out = fmt::format("{} {} {}", paint(style, kBold, location(d.range, sources) + ":"),
                                paint(style, color, std::string(severity_name(d.severity)) + ":"), d.message);
  if (d.kind) out += fmt::format(" [{}]", paint(style, color, check_label(d)));
  out += '\n';
  quote(out, d.range, style.fixits ? d.fixits : std::vector<FixIt>{}, sources, style);
  if (style.parseable_fixits) {
    for (const FixIt &f : d.fixits) {
      const SourceFile &file = sources.file(f.range.file);
      LineCol b = file.line_col(f.range.begin), e = file.line_col(f.range.end);
      out += fmt::format("fix-it:\"{}\":{{{}:{}-{}:{}}}:\"{}\"\n", escape(file.path()), b.line, b.col, e.line, e.col,
                         escape(f.replacement));
    }
  }
  for (const auto &n : d.notes) {
    const SourceRange &at = n.has_range ? n.range : d.range;
    out += fmt::format("{} {} {}\n", paint(style, kBold, location(at, sources) + ":"),
                       paint(style, severity_color(Severity::Note), "note:"), n.message);
    if (n.has_range) quote(out, n.range, {}, sources, style);
  }
  return out;
}

}  // namespace gfec
