// textDocument/foldingRange: blocks (every `{ }` over more than one line), runs of comments and
// groups of imports, from the compiler's tokens; works on broken text too.
#pragma once

#include <nlohmann/json.hpp>

#include <string_view>

namespace gfec::lsp {

/// The result: [{startLine, endLine, kind?}], kind "comment" or "imports" (LSP's
/// FoldingRangeKind), none for a block. Sorted by start line.
nlohmann::json folding_ranges(std::string_view text);

}  // namespace gfec::lsp
