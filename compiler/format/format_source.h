// gfec fmt and the language server's formatting: the canonical layout of one file of chart text
// (.sfc .fsm .plan .toolbox .iface .test), as docs/formatting.md describes it.
#pragma once

#include "diagnostics.h"
#include "source.h"

#include <optional>
#include <string>

namespace gfec {

/// The canonical text of `file`, one of `sources`' files. The text must parse: otherwise the
/// parser's errors (and only those: names and types are not checked) are reported to `diag` and
/// nothing is returned, so broken text is never rewritten. A file that is not chart text (an
/// ALICA plan) is an error too. What is formatted keeps every token and every comment, so the
/// compiled model is unchanged, and formatting the result again gives it back unchanged.
std::optional<std::string> format_source(const SourceManager &sources, FileId file, Diagnostics &diag);

}  // namespace gfec
