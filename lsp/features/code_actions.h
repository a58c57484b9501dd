// textDocument/codeAction: the compiler's fix-its (Diagnostic::fixits, the edits gcc prints
// under a caret) offered as quick fixes for the diagnostics that touch the requested range.
#pragma once

#include "diagnostics.h"
#include "source_ranges.h"

#include <nlohmann/json.hpp>

namespace gfec::lsp {

/// The CodeAction[] for file `file` of a compilation whose diagnostics are `diags`: one quick
/// fix per diagnostic with fix-its whose range overlaps the byte range [begin, end] of `file`.
nlohmann::json code_actions(const Diagnostics &diags, const SourceManager &sources, FileId file, std::uint32_t begin,
                            std::uint32_t end, const std::string &uri);

}  // namespace gfec::lsp
