#include "format_source.h"

#include "format/token_spacing.h"
#include "input_languages.h"
#include "lexer.h"
#include "parser.h"

#include <algorithm>
#include <map>
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

/// Lays the items out again: line breaks where the author put them (blank lines collapsed to
/// one), indentation from the braces, the spaces between items of a line from the spacing rules
/// (docs/formatting.md).
class Printer {
public:
  explicit Printer(std::string_view text) : text_(text) {}

  std::string run(const std::vector<Item> &items) {
    index_columns(items);
    for (std::size_t i = 0; i < items.size(); ++i) {
      const Item &item = items[i];
      paragraph_ = paragraphs_[i];
      line_ = lines_[i];
      column_ = columns_of_items_[i];
      std::uint32_t gap_from = i == 0 ? first_offset() : items[i - 1].range.end;
      int newlines = count_newlines(gap_from, item.range.begin);
      // A line comment ends its line, whatever ended it in the original (count_newlines knows
      // the lexer's line ends; this keeps the code after a comment out of it regardless).
      if (i > 0 && newlines == 0 && is_line_comment(items[i - 1])) newlines = 1;
      if (i == 0) {
        start_line(item);
      } else if (newlines > 0) {
        newline();
        // One blank line at most, and none just inside a block.
        if (newlines > 1 && last_token_ != Tok::LBrace && item.kind != Tok::RBrace) newline();
        start_line(item);
      } else {
        space_before(item, gap_from);
      }
      write(item);
    }
    if (!out_.empty()) newline();
    return std::move(out_);
  }

private:
  /// An open brace: where the lines inside it and its closing line begin.
  struct Block {
    std::uint32_t inner = 0;
    std::uint32_t close = 0;
    bool hangs = false;  ///< the brace was followed on its line: inner is not decided yet
  };

  bool is_line_comment(const Item &item) const { return item.comment() && text_.substr(item.range.begin, 2) == "//"; }

  std::uint32_t first_offset() const { return text_.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0; }

  /// Line ends between two offsets: "\n", "\r\n" or a lone "\r" (the lexer's three).
  int count_newlines(std::uint32_t from, std::uint32_t to) const {
    int n = 0;
    for (std::uint32_t i = from; i < to; ++i)
      if (text_[i] == '\n' || (text_[i] == '\r' && (i + 1 >= text_.size() || text_[i + 1] != '\n'))) ++n;
    return n;
  }

  /// The column (0-based, in bytes) where `offset` stands on its line of the original text.
  /// Called in increasing order of offsets (index_columns), so a long line is scanned once.
  std::uint32_t original_column(std::uint32_t offset) {
    for (; scanned_ < offset; ++scanned_)
      if (text_[scanned_] == '\n' || text_[scanned_] == '\r') line_begin_ = scanned_ + 1;
    return offset - line_begin_;
  }

  /// The column of the end of the output.
  std::uint32_t column() const { return static_cast<std::uint32_t>(out_.size() - out_line_begin_); }

  void append(std::string_view text) {
    out_.append(text);
    if (auto nl = text.rfind('\n'); nl != std::string_view::npos)
      out_line_begin_ = out_.size() - (text.size() - nl - 1);
  }

  void newline() {
    out_ += '\n';
    out_line_begin_ = out_.size();
  }

  std::uint32_t block_indent() const { return blocks_.empty() ? 0 : blocks_.back().inner; }

  /// Indents a line that begins with `item`: as its block says, and more when it carries on a
  /// statement (the previous line did not end one and `item` does not close a block).
  void start_line(const Item &item) {
    std::uint32_t width = block_indent();
    if (item.kind == Tok::RBrace && !blocks_.empty()) {
      width = blocks_.back().close;
    } else {
      bool carried = last_token_ != Tok::End && last_token_ != Tok::Semi && last_token_ != Tok::LBrace &&
                     last_token_ != Tok::RBrace && last_token_ != Tok::Verbatim;
      if (carried) width += kContinuation;
    }
    append(std::string(width, ' '));
    line_shift_ = static_cast<std::int64_t>(width) - column_;
    line_multiline_ = false;
    fresh_line_ = true;
  }

  /// The spaces before an item that continues its line. Where the spacing rules want a space
  /// (always before a comment) and the author wrote two or more, they lined something up: the
  /// item keeps its column relative to the start of its line, if the line leaves room for it.
  void space_before(const Item &item, std::uint32_t gap_from) {
    bool want = item.comment() || last_was_comment_ || format::space_between(last_token_, last_unary_, item.kind);
    if (!want) return;
    bool wide = item.range.begin - gap_from >= 2;
    // Statements sharing a line, and a comment after code: one space, or two where the author
    // wrote more.
    bool two = wide && ((last_token_ == Tok::Semi && !last_was_comment_) || item.comment());
    std::uint32_t at = column() + (two ? 2 : 1);
    if (wide && !line_multiline_ && (item.comment() || lined_up(column_))) {
      std::int64_t aligned = column_ + line_shift_;
      if (aligned > at) at = static_cast<std::uint32_t>(aligned);
    }
    append(std::string(at - column(), ' '));
  }

  /// The line and paragraph (lines between blank lines) of each item, the columns where items
  /// begin on each line and, in each paragraph, at which columns how many items begin that
  /// follow two spaces or more on their line.
  void index_columns(const std::vector<Item> &items) {
    std::uint32_t line = 0, paragraph = 0;
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (i > 0) {
        line += static_cast<std::uint32_t>(count_newlines(items[i - 1].range.begin, items[i].range.begin));
        if (count_newlines(items[i - 1].range.end, items[i].range.begin) > 1) ++paragraph;
      }
      paragraphs_.push_back(paragraph);
      lines_.push_back(line);
      if (line_columns_.size() <= line) line_columns_.resize(line + 1);
      columns_of_items_.push_back(original_column(items[i].range.begin));
      line_columns_[line].push_back(columns_of_items_.back());
      if (i > 0 && count_newlines(items[i - 1].range.end, items[i].range.begin) == 0 &&
          items[i].range.begin - items[i - 1].range.end >= 2)
        ++columns_[{paragraph, columns_of_items_.back()}];
    }
  }

  /// Whether the author lined the current item up, at column `col` of the original: with an
  /// item of the line above or below, or with another item of its paragraph that follows extra
  /// spaces too. Other extra spaces are noise.
  bool lined_up(std::uint32_t col) const {
    auto on = [&](std::uint32_t line) {  // a line's columns are in increasing order
      return line < line_columns_.size() &&
             std::binary_search(line_columns_[line].begin(), line_columns_[line].end(), col);
    };
    if ((line_ > 0 && on(line_ - 1)) || on(line_ + 1)) return true;
    auto found = columns_.find({paragraph_, col});
    return found != columns_.end() && found->second >= 2;
  }

  void write(const Item &item) {
    std::string_view text = text_.substr(item.range.begin, item.range.end - item.range.begin);
    // A line comment runs to the end of its line, spaces the author left at the end included.
    if (is_line_comment(item)) text = text.substr(0, text.find_last_not_of(" \t\f\v") + 1);
    if (!blocks_.empty() && blocks_.back().hangs) {
      // The first item after a brace on its line: the block's lines line up under it.
      blocks_.back().hangs = false;
      if (!item.comment() && !fresh_line_) blocks_.back().inner = column();
    }
    append(text);
    fresh_line_ = false;
    if (text.find('\n') != std::string_view::npos) line_multiline_ = true;
    last_was_comment_ = item.comment();
    if (item.comment()) return;
    bool sign = item.kind == Tok::Minus || item.kind == Tok::Plus;
    last_unary_ = item.kind == Tok::Not || (sign && format::is_unary_position(last_token_));
    last_token_ = item.kind;
    if (item.kind == Tok::LBrace) blocks_.push_back({block_indent() + kIndent, block_indent(), true});
    if (item.kind == Tok::RBrace && !blocks_.empty()) blocks_.pop_back();
  }

  std::string_view text_;
  std::string out_;
  std::size_t out_line_begin_ = 0;  ///< where the output's last line begins
  std::uint32_t scanned_ = 0;       ///< original_column(): the text is scanned up to here
  std::uint32_t line_begin_ = 0;    ///< and the line there begins here
  std::vector<Block> blocks_;
  std::vector<std::uint32_t> paragraphs_;  ///< per item: its paragraph in the original
  /// Per paragraph and column of the original: how many items that follow extra spaces begin there.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> columns_;
  std::vector<std::uint32_t> lines_;                      ///< per item: its line in the original
  std::vector<std::vector<std::uint32_t>> line_columns_;  ///< per original line: where its items begin
  std::uint32_t paragraph_ = 0;                           ///< the paragraph of the item being laid out
  std::uint32_t line_ = 0;                                ///< its line
  std::uint32_t column_ = 0;                              ///< and its column in the original
  std::vector<std::uint32_t> columns_of_items_;           ///< per item: its column in the original
  Tok last_token_ = Tok::End;
  bool last_unary_ = false;
  bool last_was_comment_ = false;
  std::int64_t line_shift_ = 0;  ///< output column minus original column of the line's first item
  bool fresh_line_ = false;      ///< the next item begins its line
  bool line_multiline_ = false;  ///< a comment or verbatim block spanning lines is on this line
};

/// One pass of the layout over a text that parses.
std::string lay_out(const SourceManager &sources, FileId file) {
  Diagnostics quiet;  // the text parsed: the lexer has nothing to say
  std::vector<SourceRange> comments;
  Lexer lexer(sources, file, quiet);
  lexer.record_comments(&comments);
  std::vector<Item> items;
  std::size_t next_comment = 0;
  for (Token t = lexer.next();; t = lexer.next()) {
    // Comments skipped before this token come first.
    for (; next_comment < comments.size(); ++next_comment) items.push_back({comments[next_comment], Tok::End});
    if (t.kind == Tok::End) break;
    items.push_back({t.range, t.kind});
  }
  return Printer(sources.file(file).text()).run(items);
}

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

  std::string text = lay_out(sources, file);
  // Lining up with a neighbour (Printer::lined_up) looks at the original's columns, which the
  // first pass may move; passing again settles it (the tests check the result is a fixed
  // point). The bound only keeps a pathological text from costing more.
  for (int pass = 0; pass < 3; ++pass) {
    SourceManager again;
    FileId id = again.add(source.path(), text);
    std::string next = lay_out(again, id);
    if (next == text) break;
    text = std::move(next);
  }
  if (source.text().substr(0, 3) == "\xEF\xBB\xBF") text.insert(0, "\xEF\xBB\xBF");
  return text;
}

}  // namespace gfec
