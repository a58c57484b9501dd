// The lexer: turns one file's text into tokens, reporting malformed ones (docs/language.md §1).
#pragma once

#include "diagnostics.h"
#include "token.h"

#include <vector>

namespace gfec {

/// Whether `word` is a keyword of chart text (`place`, `when`, `in`, ...): such a name is written
/// `` `place` `` (docs/language.md §14).
bool is_chart_keyword(std::string_view word);

class Lexer {
public:
  Lexer(const SourceManager &sources, FileId file, Diagnostics &diag);

  /// The next token; Tok::End forever at the end of the file.
  Token next();

  /// From now on, appends the range of every comment skipped (`//` to the end of the line, or
  /// `/* ... */`) to `out`, in order: what the formatter (compiler/format/) needs to keep them.
  /// Off by default, so the compiler pays one null test per comment.
  void record_comments(std::vector<SourceRange> *out) { comments_ = out; }

private:
  Token make(Tok kind, std::uint32_t begin);
  Token error(std::uint32_t begin, std::uint32_t end, std::string message);
  void skip_space_and_comments();
  Token number(std::uint32_t begin);
  Token string(std::uint32_t begin);
  Token verbatim(std::uint32_t begin);
  Token word(std::uint32_t begin);

  char peek(std::uint32_t ahead = 0) const { return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0'; }

  FileId file_;
  std::string_view text_;
  Diagnostics &diag_;
  std::uint32_t pos_ = 0;
  std::vector<SourceRange> *comments_ = nullptr;
};

}  // namespace gfec
