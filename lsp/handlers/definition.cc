// textDocument/definition: where the name at the cursor is declared, in whatever file,
// as the validator resolved it (name_uses.h). No name there: null.
#include "handlers/navigation.h"
#include "methods.h"

namespace gfec::lsp::handlers {

nlohmann::json definition(Session &s, const nlohmann::json &params) {
  At at = name_at_request(s, params);
  if (!at.name) return nullptr;
  return at.doc.location(at.name->decl);
}

void advertise_definition(nlohmann::json &caps) { caps["definitionProvider"] = true; }

}  // namespace gfec::lsp::handlers
