// textDocument/formatting: the buffer in gfec fmt's canonical layout (compiler/format/, the
// same function as `gfec fmt`), as one edit of the whole text. Text that does not parse is
// never rewritten: the request fails with the parser's first error.
#include "format/format_source.h"
#include "methods.h"
#include "positions.h"

#include <fmt/format.h>

namespace gfec::lsp::handlers {

using nlohmann::json;

void advertise_formatting(json &caps) { caps["documentFormattingProvider"] = true; }

json formatting(Session &s, const json &params) {
  const Document &doc = s.open_document(document_uri(params));
  SourceManager sources;
  const FileId file = sources.add(doc.path, doc.text);
  Diagnostics diag;
  std::optional<std::string> formatted = format_source(sources, file, diag);
  if (!formatted) {
    std::string why = "the text does not parse";
    for (const Diagnostic &d : diag.all())
      if (d.severity == Severity::Error) {
        why = fmt::format("not formatted: line {}: {}", sources.begin_of(d.range).line, d.message);
        break;
      }
    throw RequestError{error_code::kRequestFailed, why};
  }
  if (*formatted == doc.text) return json::array();
  return json::array({{{"range", range_json(doc.text, 0, doc.text.size())}, {"newText", *formatted}}});
}

}  // namespace gfec::lsp::handlers
