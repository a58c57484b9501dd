#include "diagnostic_printer.h"

#include "escape.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <vector>

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

/// One character of a printed text: its bytes, and what the terminal is given for them.
struct Shown {
  std::uint32_t begin = 0;  ///< its first byte in the text
  std::string text;         ///< itself, or an escape such as <U+001B>
  bool tab = false;
};

/// A text as it is safe to print, character by character (support/escape.h): what a chart holds
/// reaches the terminal as text, never as a control. The tab stays (and, where `keep_newlines`,
/// the newline).
std::vector<Shown> characters(std::string_view s, bool keep_newlines = false) {
  std::vector<Shown> out;
  for (std::size_t at = 0; at < s.size();) {
    text::Shown ch = text::shown_at(s, at, keep_newlines);
    out.push_back({static_cast<std::uint32_t>(at), std::move(ch.text), s[at] == '\t'});
    at += ch.length;
  }
  return out;
}

/// The characters as printed, one after the other.
std::string joined(const std::vector<Shown> &shown) {
  std::string out;
  for (const Shown &ch : shown) out += ch.text;
  return out;
}

/// The columns a printed character takes: one for a character (a tab copied as it is), the
/// width of the escape for an escaped one.
std::size_t width(const Shown &ch) { return ch.text.size() > 1 && ch.text[0] == '<' ? ch.text.size() : 1; }

/// What goes under the printed line before byte `byte`: the line's tabs, and a space a column
/// otherwise, so that the caret lines up with what was printed in any terminal.
std::string indent_to(const std::vector<Shown> &line, std::uint32_t byte) {
  std::string indent;
  for (const Shown &ch : line) {
    if (ch.begin >= byte) break;
    if (ch.tab) indent += '\t';
    else indent.append(width(ch), ' ');
  }
  return indent;
}

/// Lines longer than this many bytes are quoted around the range only (see quote()).
constexpr std::uint32_t kLongLine = 240;
/// How much of a long line is quoted before the range, and after it (or after its first
/// kLongLine / 2 bytes, for a long range).
constexpr std::uint32_t kContext = 60;

/// The quoted source line and a caret line: '^' at the start of the range, '~' under the rest
/// of it on that line, then the fix-it's text under it when the fix stays on that line. The
/// line is printed as characters() shows it, and the caret counts its columns. Of a long line
/// (minified JSON, a generated chart on one line) only the part around the range is quoted,
/// cut at characters and marked "...": a diagnostic then costs the same on a line of megabytes
/// as on a short one, however many diagnostics the line has.
void quote(std::string &out, const SourceRange &range, const std::vector<FixIt> &fixits, const SourceManager &sources,
           const TextStyle &style) {
  const SourceFile &file = sources.file(range.file);
  LineCol begin = file.line_col(range.begin);
  std::string_view whole = file.line_text(begin.line);
  if (whole.empty() && file.text().empty()) return;
  std::uint32_t col0 = begin.col - 1;
  LineCol end = file.line_col(range.end);
  std::uint32_t last = end.line == begin.line ? end.col - 1 : static_cast<std::uint32_t>(whole.size());
  // The part of the line quoted: [from, to), in bytes of the line.
  auto size = static_cast<std::uint32_t>(whole.size());
  std::uint32_t from = 0, to = size;
  if (size > kLongLine) {
    std::uint32_t at = std::min(col0, size);
    from = at > kContext ? at - kContext : 0;
    to = std::min<std::uint32_t>(size, std::max(at, std::min(last, at + kLongLine / 2)) + kContext);
    auto continuation = [&](std::uint32_t i) { return (static_cast<unsigned char>(whole[i]) & 0xC0) == 0x80; };
    while (from > 0 && continuation(from)) --from;
    while (to < size && continuation(to)) ++to;
  }
  std::string_view line = whole.substr(from, to - from);
  std::string cut_before = from > 0 ? "..." : "", cut_after = to < size ? "..." : "";
  const std::vector<Shown> shown = characters(line);
  std::string number = std::to_string(begin.line);
  std::size_t gutter_width = std::max<std::size_t>(4, number.size());
  // gcc 12: " NNNN | source" and "      | ^~~" (the gutter is as wide as the line number).
  std::string gutter = style.line_numbers ? fmt::format(" {:>{}} |", number, gutter_width) : "";
  std::string blank = style.line_numbers ? fmt::format(" {:>{}} |", "", gutter_width) : "";
  out += fmt::format("{} {}{}{}\n", gutter, cut_before, joined(shown), cut_after);
  // Columns and bytes from here on count from the start of the quoted part.
  std::string pad(cut_before.size(), ' ');
  auto local = [&](std::uint32_t byte) { return byte > from ? byte - from : 0; };
  // The columns of the characters the range covers on this line; past its end (a missing ';'),
  // one a byte.
  std::size_t columns = 0;
  for (const Shown &ch : shown)
    if (ch.begin >= local(col0) && ch.begin < local(last)) columns += width(ch);
  if (to == size && last > size && col0 <= size)
    columns += std::min<std::size_t>(last, size + 1) - std::max<std::size_t>(col0, size);
  std::string caret = "^";
  if (columns > 1) caret.append(columns - 1, '~');
  out += fmt::format("{} {}{}{}\n", blank, pad, indent_to(shown, local(col0)), paint(style, kGreen, caret));
  for (const FixIt &f : fixits) {
    LineCol at = file.line_col(f.range.begin);
    if (f.range.file != range.file || at.line != begin.line || f.replacement.empty()) continue;
    if (at.col - 1 < from || at.col - 1 > to) continue;  // outside the quoted part of a long line
    out += fmt::format("{} {}{}{}\n", blank, pad, indent_to(shown, local(at.col - 1)),
                       paint(style, kGreen, text::printable(f.replacement)));
  }
}

std::string location(const SourceRange &range, const SourceManager &sources) {
  const SourceFile &file = sources.file(range.file);
  LineCol lc = file.line_col(range.begin);
  return fmt::format("{}:{}:{}", text::printable(file.path()), lc.line, lc.col);
}

/// gcc's string escapes for a fix-it line: backslash and quote escaped, and what is not
/// printable ASCII (control characters, every byte of UTF-8 too) in octal.
std::string escape(std::string_view s) {
  std::string out;
  for (unsigned char c : s) {
    if (c == '\\' || c == '"') out += {'\\', static_cast<char>(c)};
    else if (c < 0x20 || c >= 0x7F) out += fmt::format("\\{:03o}", c);
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
  std::string out =
      fmt::format("{} {} {}", paint(style, kBold, location(d.range, sources) + ":"),
                  paint(style, color, std::string(severity_name(d.severity)) + ":"), text::printable(d.message));
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
                       paint(style, severity_color(Severity::Note), "note:"), text::printable(n.message));
    if (n.has_range) quote(out, n.range, {}, sources, style);
  }
  return out;
}

}  // namespace gfec
