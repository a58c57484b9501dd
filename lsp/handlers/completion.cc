// textDocument/completion (features/completion.h): the context from the buffer as it is now,
// the names from its last compilation's syntax tree (the imports' interfaces and constants).
#include "completion.h"

#include "methods.h"
#include "positions.h"

#include <filesystem>

namespace gfec::lsp::handlers {

using nlohmann::json;

void advertise_completion(json &caps) {
  // `(` for elapsed(/active(, `,` and `>` for a transition's lists, `"` and `/` for imports.
  caps["completionProvider"] = {{"triggerCharacters", {"(", ",", ">", "\"", "/"}}, {"resolveProvider", false}};
}

json completion(Session &s, const json &params) {
  const std::string uri = document_uri(params);
  const Document &doc = s.open_document(uri);
  const std::size_t offset = offset_of(doc.text, read_position(params.at("position")));
  const CompiledDocument &compiled = s.validated(uri);
  const ast::Program &program = compiled.compilation().loaded.program;
  const std::string dir = std::filesystem::path(doc.path).parent_path().string();
  return lsp::completion(doc.text, static_cast<std::uint32_t>(offset), program.files.empty() ? nullptr : &program, dir);
}

}  // namespace gfec::lsp::handlers
