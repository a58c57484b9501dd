// The declarations of one file's syntax tree as a tree of symbols: documentSymbol's answer,
// workspace/symbol's list and hover's way from a declaration's name to the whole declaration.
// Read from the parser's tree (kept by the pipeline), so a file with errors still has one.
#pragma once

#include "ast.h"

#include <string>
#include <vector>

namespace gfec::lsp {

struct OutlineItem {
  std::string name;
  std::string detail;     ///< "initial place", "bool ()", "var int", ...
  int kind = 0;           ///< LSP SymbolKind
  SourceRange range;      ///< the whole declaration
  SourceRange selection;  ///< its name
  std::vector<OutlineItem> children;
};

/// The declarations of `file`, in source order, with what they contain.
std::vector<OutlineItem> outline(const ast::File &file);

/// The declaration whose name is at `name` (its selection range), found in `items`, or null;
/// `parent` (when given) is set to the item holding it, null at the top.
const OutlineItem *declaration_named_at(const std::vector<OutlineItem> &items, const SourceRange &name,
                                        const OutlineItem **parent = nullptr);

}  // namespace gfec::lsp
