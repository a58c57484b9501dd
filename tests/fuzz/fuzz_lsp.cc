// libFuzzer target over the language server (lsp_session.h): a document, then random edits and
// requests, played through `gfec lsp`'s loop in-process. docs/verification.md says how to run it.
#include "lsp_session.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  gfec::fuzz::check_lsp_session(std::string(reinterpret_cast<const char *>(data), size));
  return 0;
}
