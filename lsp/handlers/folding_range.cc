// textDocument/foldingRange (features/folding_ranges.h): blocks, comment runs, import groups.
#include "folding_ranges.h"

#include "methods.h"

namespace gfec::lsp::handlers {

using nlohmann::json;

void advertise_folding_range(json &caps) { caps["foldingRangeProvider"] = true; }

json folding_range(Session &s, const json &params) {
  return lsp::folding_ranges(s.open_document(document_uri(params)).text);
}

}  // namespace gfec::lsp::handlers
