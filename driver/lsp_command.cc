#include "lsp_command.h"

#include "commands.h"
#include "driver.h"
#include "external_tool.h"
#include "file_system.h"
#include "server.h"

#include <cstring>
#include <iostream>
#include <poll.h>

namespace gfec {

int lsp_command(int argc, const char *const *argv, std::ostream &out, std::ostream &err) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
      out << "gfec lsp - the language server (LSP 3.17) for editors, on stdin and stdout\n"
             "Usage: gfec lsp [--stdio]\n\n"
             "An editor's LSP client starts it; it exits 0 after shutdown then exit, 1 otherwise.\n"
             "Options:\n"
             "  --stdio   the transport (the only one; editors' clients pass it)\n"
          << documentation_line("editors.md") << "\n";
      return kExitOk;
    }
    // Clients add their transport's flag; stdio is the one there is.
    if (std::strcmp(argv[i], "--stdio") == 0) continue;
    err << "gfec lsp: error: unknown option '" << argv[i] << "' (see 'gfec lsp --help')\n";
    return kExitUsageOrIo;
  }
  // The server writes frames to stdout only; the command's `out` is stdout when run by main.
  std::ios::sync_with_stdio(false);
  RealFileSystem disk;
  // A message waits in std::cin's buffer or in the pipe below it (std::cin reads fd 0 through
  // its own buffer once unsynchronised): the server handles it before it runs the analyses of
  // the last change (lsp/server.h).
  const auto stdin_waiting = [] {
    if (std::cin.rdbuf()->in_avail() > 0) return true;
    pollfd p{0, POLLIN, 0};
    return ::poll(&p, 1, 0) > 0;
  };
  return lsp::serve(std::cin, out, err, disk, run_external_tool, stdin_waiting);
}

}  // namespace gfec
