// textDocument/semanticTokens/full and /range (features/semantic_tokens.h): the buffer's
// tokens, classified; the range form for what an editor shows of a large buffer.
#include "semantic_tokens.h"

#include "methods.h"
#include "positions.h"

namespace gfec::lsp::handlers {

using nlohmann::json;

void advertise_semantic_tokens(json &caps) {
  caps["semanticTokensProvider"] = {{"legend", semantic_tokens_legend()}, {"full", true}, {"range", true}};
}

json semantic_tokens_full(Session &s, const json &params) {
  return lsp::semantic_tokens(s.open_document(document_uri(params)).text);
}

json semantic_tokens_range(Session &s, const json &params) {
  const std::string &text = s.open_document(document_uri(params)).text;
  const json &range = params.at("range");
  const std::size_t begin = offset_of(text, read_position(range.at("start")));
  const std::size_t end = offset_of(text, read_position(range.at("end")));
  return lsp::semantic_tokens(text, static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end));
}

}  // namespace gfec::lsp::handlers
