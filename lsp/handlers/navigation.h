// What the name handlers (definition, references, hover, rename) share: the name at the
// request's position, or the JSON-RPC error that says why there is none to act on.
#pragma once

#include "compiled_document.h"
#include "session.h"

namespace gfec::lsp::handlers {

/// The compilation of the request's document and the name at its position (null if none).
struct At {
  const CompiledDocument &doc;
  const NameUse *name;
};
At name_at_request(Session &s, const nlohmann::json &params);

/// Why the token at `offset` cannot be renamed or looked up: a keyword, a built-in function,
/// or no name the validator resolved (the file has errors that stopped it). A RequestError.
RequestError no_name_error(const CompiledDocument &doc, std::size_t offset, const char *action);

/// Whether `name` is one of the built-in functions (elapsed, active, ...).
bool is_builtin(std::string_view name);

}  // namespace gfec::lsp::handlers
