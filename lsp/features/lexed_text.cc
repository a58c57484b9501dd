#include "lexed_text.h"

#include "diagnostics.h"
#include "lexer.h"

#include <string>

namespace gfec::lsp {

bool is_keyword(Tok kind) { return kind >= Tok::KwSfc && kind <= Tok::KwTeam; }

LexedText lex_text(std::string_view text) {
  // The lexer reads a SourceFile; the views it hands out point into that copy, so they are
  // re-pointed into `text` (same offsets) before the manager goes.
  SourceManager sources;
  FileId file = sources.add("<lsp>", std::string(text));
  Diagnostics diag(WarningOptions{}, SIZE_MAX);
  Lexer lexer(sources, file, diag);
  LexedText out;
  out.tokens.reserve(text.size() / 5);  // chart text runs about five bytes a token
  std::vector<SourceRange> comments;
  lexer.record_comments(&comments);
  for (;;) {
    Token t = lexer.next();
    if (t.kind == Tok::End) break;
    t.text = text.substr(t.range.begin, t.range.end - t.range.begin);
    out.tokens.push_back(std::move(t));
  }
  for (const SourceRange &c : comments) out.comments.push_back({c.begin, c.end});
  return out;
}

}  // namespace gfec::lsp
