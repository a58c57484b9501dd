// textDocument/semanticTokens/full: every token of a text classified for an editor's colours,
// from the compiler's lexer and the declarations the text itself makes (docs/editors.md
// "Semantic tokens" has the legend). Works on broken text too: it needs tokens, not a tree.
#pragma once

#include <nlohmann/json.hpp>

#include <string_view>

namespace gfec::lsp {

/// The legend the server advertises: {tokenTypes: [...], tokenModifiers: [...]}.
nlohmann::json semantic_tokens_legend();

/// The result of semanticTokens/full for `text`: {data: [...]} in LSP's relative encoding.
nlohmann::json semantic_tokens(std::string_view text);

}  // namespace gfec::lsp
