// textDocument/codeAction (features/code_actions.h): the compiler's fix-its as quick fixes.
#include "code_actions.h"

#include "methods.h"
#include "positions.h"

namespace gfec::lsp::handlers {

using nlohmann::json;

void advertise_code_action(json &caps) { caps["codeActionProvider"] = {{"codeActionKinds", {"quickfix"}}}; }

json code_action(Session &s, const json &params) {
  const std::string uri = document_uri(params);
  const CompiledDocument &doc = s.compiled(uri);
  if (!doc.has_main()) return json::array();
  // Only quick fixes are offered: a client asking for other kinds alone gets none.
  if (params.contains("context") && params["context"].contains("only")) {
    bool wanted = false;
    for (const json &kind : params["context"]["only"])
      if (kind == "quickfix") wanted = true;
    if (!wanted) return json::array();
  }
  const json &range = params.at("range");
  const std::size_t begin = doc.offset_at(read_position(range.at("start")));
  const std::size_t end = doc.offset_at(read_position(range.at("end")));
  const auto &c = doc.compilation();
  return lsp::code_actions(c.diag, c.sources, doc.main_file(), static_cast<std::uint32_t>(begin),
                           static_cast<std::uint32_t>(end), uri);
}

}  // namespace gfec::lsp::handlers
