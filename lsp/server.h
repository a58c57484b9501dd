// `gfec lsp`: the language server's loop over stdio. It reads frames (transport.h), answers
// JSON-RPC 2.0 through the method table (methods.h) and keeps going whatever the client sends:
// every broken message gets the error the spec names, or is dropped when it cannot be answered.
#pragma once

#include "backend.h"

#include <functional>
#include <iosfwd>

namespace gfec {
class FileSystem;
}

namespace gfec::lsp {

/// Serves until `exit` or the end of the input. Returns the exit code LSP 3.17 names: 0 after
/// `shutdown` then `exit`, 1 otherwise. `log` gets one line per message that could not be read.
/// `tools` runs the external programs a picture goes through (the driver's run_external_tool).
/// The static analyses of a change run when no message waits (publish_diagnostics.h):
/// `input_waiting()` says whether one does; by default, whether `in` holds unread bytes.
int serve(std::istream &in, std::ostream &out, std::ostream &log, const FileSystem &disk, ToolRunner tools = {},
          std::function<bool()> input_waiting = {});

}  // namespace gfec::lsp
