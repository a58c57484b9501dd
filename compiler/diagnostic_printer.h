// Renders diagnostics as gcc does: "file:line:col: error: message [check]", the source line,
// a caret under the range, then the notes.
#pragma once

#include "diagnostics.h"

#include <string>

namespace gfec {

/// One diagnostic with its notes, each line ending in '\n'.
std::string render_text(const Diagnostic &d, const SourceManager &sources);

/// "error", "warning" or "note".
const char *severity_name(Severity s);

} // namespace gfec
