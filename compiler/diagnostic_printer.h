// Renders diagnostics as gcc does: "file:line:col: error: message [check]", the source line,
// a caret under the range, the fix-it, then the notes.
#pragma once

#include "diagnostics.h"

#include <string>

namespace gfec {

/// How the text looks; the default is the plain form the tests compare against, the command
/// line asks for gcc 12's form (docs/cli.md).
struct TextStyle {
  bool color = false;             ///< SGR colours as gcc's defaults (error red, warning magenta, ...)
  bool line_numbers = false;      ///< gcc 12's gutter: "    3 |   A -> B;" and "      |   ^"
  bool fixits = false;            ///< the fix-it's text under the caret, as gcc prints it
  bool parseable_fixits = false;  ///< -fdiagnostics-parseable-fixits: fix-it:"file":{l:c-l:c}:"text"
};

/// One diagnostic with its notes, each line ending in '\n'.
std::string render_text(const Diagnostic &d, const SourceManager &sources, const TextStyle &style = {});

/// "error", "warning" or "note".
const char *severity_name(Severity s);

/// The label in brackets after the message: the check name, or for a warning made an error by
/// -Werror / -Werror=NAME gcc's "-Werror=NAME".
std::string check_label(const Diagnostic &d);

}  // namespace gfec
