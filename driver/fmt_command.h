// `gfec fmt FILE...`: rewrites chart text in its canonical layout (docs/formatting.md);
// `gfec fmt -` formats stdin to stdout; `--check` lists the files that would change.
#pragma once

#include <iosfwd>

namespace gfec {

/// argv[0] is "fmt". Returns 0 (done; with --check: every file canonical), 1 (a file does not
/// parse, or --check found files to change) or 2 (usage or I/O error).
int fmt_command(int argc, const char *const *argv, std::ostream &out, std::ostream &err);

}  // namespace gfec
