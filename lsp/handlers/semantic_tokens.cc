// textDocument/semanticTokens/full (features/semantic_tokens.h): the buffer's tokens, classified.
#include "semantic_tokens.h"

#include "methods.h"

namespace gfec::lsp::handlers {

using nlohmann::json;

void advertise_semantic_tokens(json &caps) {
  caps["semanticTokensProvider"] = {{"legend", semantic_tokens_legend()}, {"full", true}, {"range", false}};
}

json semantic_tokens_full(Session &s, const json &params) {
  return lsp::semantic_tokens(s.open_document(document_uri(params)).text);
}

}  // namespace gfec::lsp::handlers
