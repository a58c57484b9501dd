// textDocument/references: every place the name at the cursor's declaration is written, in
// the open documents and in the workspace's files that are not open (occurrences.h);
// context.includeDeclaration says whether the declaration itself is listed.
#include "handlers/navigation.h"
#include "methods.h"
#include "occurrences.h"

namespace gfec::lsp::handlers {

nlohmann::json references(Session &s, const nlohmann::json &params) {
  At at = name_at_request(s, params);
  if (!at.name) return nlohmann::json::array();
  const bool with_declaration = params.contains("context") && params["context"].value("includeDeclaration", false);
  const std::string name(at.doc.text_of(at.name->at));
  const DeclarationKey key = key_of(at.doc, at.name->decl);
  nlohmann::json list = nlohmann::json::array();
  for (const Occurrence &o : occurrences(s, key, name))
    if (with_declaration || !o.declaration) list.push_back({{"uri", o.uri}, {"range", o.range}});
  return list;
}

void advertise_references(nlohmann::json &caps) { caps["referencesProvider"] = true; }

}  // namespace gfec::lsp::handlers
