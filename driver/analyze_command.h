// `gfec --analyze FILE...`: every static analysis on every chart and plan of each file, whatever
// -W says, and a summary per chart and plan on stdout (docs/verification.md).
#pragma once

#include "options.h"

#include <iosfwd>

namespace gfec {

/// The summaries go to `out`, the diagnostics to `err` in the chosen format. Exit code as for
/// --check: 0 (even with warnings, unless -Werror), 1 errors in the input, 2 I/O.
int analyze_command(const Options &options, std::ostream &out, std::ostream &err);

}  // namespace gfec
