// gfec/chartPicture (features/chart_picture.h, docs/editors.md "The chart picture"): the
// picture of the document's chart and where each node comes from; the editor's preview.
#include "chart_picture.h"

#include "methods.h"

namespace gfec::lsp::handlers {

using nlohmann::json;

void advertise_chart_picture(json &caps) { caps["experimental"]["chartPicture"] = true; }

json chart_picture(Session &s, const json &params) {
  const std::string uri = document_uri(params);
  const long long version = s.open_document(uri).version;
  const CompiledDocument &doc = s.compiled(uri);
  const std::string chart =
      params.contains("chart") && params["chart"].is_string() ? params["chart"].get<std::string>() : "";
  UriOf uri_of = [&](const std::string &path) { return path == doc.path() ? uri : s.uri_of_path(path); };
  return lsp::chart_picture(doc.compilation(), chart, version, uri_of, s.tools);
}

}  // namespace gfec::lsp::handlers
