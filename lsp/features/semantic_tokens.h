// textDocument/semanticTokens/full: every token of a text classified for an editor's colours,
// from the compiler's lexer and the declarations the text itself makes (docs/editors.md
// "Semantic tokens" has the legend). Works on broken text too: it needs tokens, not a tree.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string_view>

namespace gfec::lsp {

/// The legend the server advertises: {tokenTypes: [...], tokenModifiers: [...]}.
nlohmann::json semantic_tokens_legend();

/// The result of semanticTokens/full for `text`: {data: [...]} in LSP's relative encoding.
/// With `begin`/`end`, semanticTokens/range: only the tokens that overlap those bytes (an
/// editor asks for what it shows of a large buffer).
nlohmann::json semantic_tokens(std::string_view text, std::uint32_t begin = 0, std::uint32_t end = UINT32_MAX);

}  // namespace gfec::lsp
