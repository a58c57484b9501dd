// `gfec lsp`: the language server on stdin and stdout (docs/editors.md). The server is the
// lsp/ library; this is its command-line entry.
#pragma once

#include <iosfwd>

namespace gfec {

/// argv[0] is "lsp". Serves until `exit`; returns 0 after shutdown then exit, 1 otherwise, 2 on
/// a usage error.
int lsp_command(int argc, const char *const *argv, std::ostream &out, std::ostream &err);

}  // namespace gfec
