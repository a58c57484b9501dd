#include "format_source.h"

#include "format/token_spacing.h"
#include "input_languages.h"
#include "lexer.h"
#include "parser.h"

#include <algorithm>
#include <vector>

namespace gfec {

namespace {

constexpr int kIndent = 2;        // per open brace
constexpr int kContinuation = 4;  // a statement carried on to the next line

/// A token or a comment, in the order of the text.
struct Item {
  SourceRange range;
  Tok kind = Tok::End;  ///< Tok::End for a comment
  bool comment() const { return kind == Tok::End; }
};

class Printer {
public:
  explicit Printer(std::string_view text) : text_(text) {}

  std::string run(const std::vector<Item> &items) {
    for (std::size_t i = 0; i < items.size(); ++i) {
      const Item &item = items[i];
      std::uint32_t gap_from = i == 0 ? first_offset() : items[i - 1].range.end;
      int newlines = count_newlines(gap_from, item.range.begin);
      // A line comment ends its line even where a lone '\r' ended it in the original.
      if (i > 0 && newlines == 0 && is_line_comment(items[i - 1])) newlines = 1;
      if (i == 0) {
        start_line(item);
      } else if (newlines > 0) {
        out_ += '\n';
        // One blank line at most, and none just inside a block.
        if (newlines > 1 && last_token_ != Tok::LBrace && item.kind != Tok::RBrace) out_ += '\n';
        start_line(item);
      } else {
        space_before(item);
      }
      write(item);
    }
    if (!out_.empty()) out_ += '\n';
    return std::move(out_);
  }

private:
  bool is_line_comment(const Item &item) const { return item.comment() && text_.substr(item.range.begin, 2) == "//"; }

  std::uint32_t first_offset() const { return text_.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0; }

  int count_newlines(std::uint32_t from, std::uint32_t to) const {
    return static_cast<int>(std::count(text_.begin() + from, text_.begin() + to, '\n'));
  }

  /// The column (0-based, in bytes) where `offset` stands on its line of the original text.
  std::uint32_t original_column(std::uint32_t offset) const {
    std::size_t nl = text_.rfind('\n', offset == 0 ? 0 : offset - 1);
    std::uint32_t line_start = nl == std::string_view::npos || offset == 0 ? 0 : static_cast<std::uint32_t>(nl + 1);
    return offset - line_start;
  }

  std::uint32_t column() const {
    std::size_t nl = out_.rfind('\n');
    return static_cast<std::uint32_t>(nl == std::string::npos ? out_.size() : out_.size() - nl - 1);
  }

  /// Indents a line that begins with `item`: by the open braces, and more when it carries on a
  /// statement (the previous line did not end one and `item` does not close a block).
  void start_line(const Item &item) {
    int depth = depth_ - (item.kind == Tok::RBrace ? 1 : 0);
    int width = std::max(depth, 0) * kIndent;
    bool carried = last_token_ != Tok::End && last_token_ != Tok::Semi && last_token_ != Tok::LBrace &&
                   last_token_ != Tok::RBrace && last_token_ != Tok::Verbatim && item.kind != Tok::RBrace;
    if (carried) width += kContinuation;
    out_.append(static_cast<std::size_t>(width), ' ');
  }

  void space_before(const Item &item) {
    if (item.comment()) {
      // A trailing comment keeps its column when the code leaves room for it, so comments
      // aligned in a column stay aligned; else it follows the code after one space.
      std::uint32_t want = std::max(original_column(item.range.begin), column() + 1);
      out_.append(want - column(), ' ');
      return;
    }
    if (last_was_comment_ || format::space_between(last_token_, last_unary_, item.kind)) out_ += ' ';
  }

  void write(const Item &item) {
    out_.append(text_.substr(item.range.begin, item.range.end - item.range.begin));
    last_was_comment_ = item.comment();
    if (item.comment()) return;
    bool sign = item.kind == Tok::Minus || item.kind == Tok::Plus;
    last_unary_ = item.kind == Tok::Not || (sign && format::is_unary_position(last_token_));
    last_token_ = item.kind;
    if (item.kind == Tok::LBrace) ++depth_;
    if (item.kind == Tok::RBrace) --depth_;
  }

  std::string_view text_;
  std::string out_;
  Tok last_token_ = Tok::End;
  bool last_unary_ = false;
  bool last_was_comment_ = false;
  int depth_ = 0;
};

}  // namespace

std::optional<std::string> format_source(const SourceManager &sources, FileId file, Diagnostics &diag) {
  const SourceFile &source = sources.file(file);
  if (!source.language().chart_text) {
    diag.error({file, 0, 0}, ErrorKind::Syntax,
               "gfec fmt formats chart text (.sfc .fsm .plan .toolbox .iface .test), not this file's language");
    return std::nullopt;
  }
  // The parser decides whether the text is well formed; the formatter itself only re-lays the
  // tokens, so it must never see text the parser would have repaired.
  std::size_t errors = diag.error_count();
  parse_file(sources, file, diag);
  if (diag.error_count() != errors) return std::nullopt;

  std::vector<SourceRange> comments;
  Lexer lexer(sources, file, diag);
  lexer.record_comments(&comments);
  std::vector<Item> items;
  std::size_t next_comment = 0;
  for (Token t = lexer.next();; t = lexer.next()) {
    // Comments skipped before this token come first.
    for (; next_comment < comments.size(); ++next_comment) items.push_back({comments[next_comment], Tok::End});
    if (t.kind == Tok::End) break;
    items.push_back({t.range, t.kind});
  }
  std::string text = Printer(source.text()).run(items);
  if (source.text().substr(0, 3) == "\xEF\xBB\xBF") text.insert(0, "\xEF\xBB\xBF");
  return text;
}

}  // namespace gfec
