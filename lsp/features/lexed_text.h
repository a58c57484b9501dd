// One text as the compiler's lexer reads it, plus the comments the lexer skips: what the
// handlers that need no syntax tree (semantic tokens, folding, completion's context) work on.
// The lexer is the compiler's own (no second tokenizer), recording the comments it skips.
#pragma once

#include "token.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace gfec::lsp {

struct ByteRange {
  std::uint32_t begin = 0, end = 0;
};

struct LexedText {
  std::vector<Token> tokens;  ///< without the final Tok::End; ranges are byte offsets in the text
  std::vector<ByteRange> comments;
};

/// Lexes `text`; lexical errors are dropped (the diagnostics handler reports them). The tokens'
/// `text` views point into `text`, which must outlive the result.
LexedText lex_text(std::string_view text);

bool is_keyword(Tok kind);

}  // namespace gfec::lsp
