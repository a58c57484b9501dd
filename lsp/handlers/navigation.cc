#include "handlers/navigation.h"

#include "validate/names.h"

namespace gfec::lsp::handlers {

At name_at_request(Session &s, const nlohmann::json &params) {
  const CompiledDocument &doc = s.validated(document_uri(params));
  return {doc, doc.name_at(read_position(params.at("position")))};
}

bool is_builtin(std::string_view name) {
  for (std::string_view b : validation::kBuiltinFunctions)
    if (b == name) return true;
  return false;
}

RequestError no_name_error(const CompiledDocument &doc, std::size_t offset, const char *action) {
  Token t = doc.token_at(offset);
  const std::string text(t.text);
  if (t.kind != Tok::End && t.kind != Tok::Ident && !text.empty() && std::isalpha(static_cast<unsigned char>(text[0])))
    return {error_code::kRequestFailed, "'" + text + "' is a keyword: it cannot be " + action};
  if (t.kind == Tok::Ident && is_builtin(t.text))
    return {error_code::kRequestFailed, "'" + text + "' is a built-in function: it cannot be " + action};
  if (doc.compilation().name_uses.list.empty() && doc.compilation().diag.has_errors())
    return {error_code::kRequestFailed, "the file has errors that stop gfec before it resolves names"};
  return {error_code::kRequestFailed, "no declared name here"};
}

}  // namespace gfec::lsp::handlers
