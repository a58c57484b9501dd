// The language server's fuzz checks (docs/verification.md "Fuzzing the language server"): one
// input is a document and a sequence of edits and requests, played against `gfec lsp`'s loop
// in-process (lsp::serve over string streams and an in-memory disk).
#pragma once

#include <cstdint>
#include <string>

namespace gfec::fuzz {

/// Decodes `input` into a session: the text before a line `%%%` is the document (all of it
/// when there is none), each byte after it (or of the whole input) an operation: an incremental
/// or full didChange with ranges and text drawn from the input, a request (completion, semantic
/// tokens, folding, code actions, formatting, code lenses, the chart picture, hover, definition,
/// references, symbols, rename), a framed body of garbage, a close and reopen. Traps unless the
/// server answers every request exactly once and exits 0 after shutdown and exit.
void check_lsp_session(const std::string &input);

/// A pseudo-random input for check_lsp_session: `document` and ops drawn from `seed`.
std::string random_lsp_session(const std::string &document, std::uint32_t seed);

}  // namespace gfec::fuzz
