// Text synchronisation: didOpen, didChange (incremental and full), didClose, didSave. Every
// change recompiles the document and re-publishes its diagnostics and those of the open
// documents that import it (publish_diagnostics.h).
#include "methods.h"
#include "positions.h"
#include "publish_diagnostics.h"

namespace gfec::lsp::handlers {

using nlohmann::json;

void advertise_text_sync(json &caps) {
  caps["textDocumentSync"] = {{"openClose", true}, {"change", 2 /* Incremental */}, {"save", {{"includeText", false}}}};
}

void did_open(Session &s, const json &params) {
  const json &doc = params.at("textDocument");
  const std::string uri = doc.at("uri").get<std::string>();
  s.set_text(uri, doc.at("text").get<std::string>(), doc.value("version", 0LL));
  publish_diagnostics(s, uri);
}

void did_change(Session &s, const json &params) {
  const std::string uri = document_uri(params);
  Document &d = s.open_document(uri);
  std::string text = d.text;
  for (const json &change : params.at("contentChanges")) {
    if (!change.contains("range")) {
      text = change.at("text").get<std::string>();
      continue;
    }
    const json &range = change["range"];
    std::size_t begin = offset_of(text, read_position(range.at("start")));
    std::size_t end = offset_of(text, read_position(range.at("end")));
    if (end < begin) std::swap(begin, end);
    text.replace(begin, end - begin, change.at("text").get<std::string>());
  }
  s.set_text(uri, std::move(text), params["textDocument"].value("version", d.version + 1));
  publish_diagnostics(s, uri);
}

void did_close(Session &s, const json &params) {
  const std::string uri = document_uri(params);
  std::vector<std::string> dependents = s.dependents(uri);
  s.close(uri);
  // A closed document's diagnostics are cleared (the client keeps them otherwise); those that
  // imported it read the disk again.
  s.notify("textDocument/publishDiagnostics", {{"uri", uri}, {"diagnostics", json::array()}});
  for (const std::string &d : dependents) publish_diagnostics(s, d);
}

void did_save(Session &, const json &) {
  // The buffer was compiled as it was typed; saving changes nothing the server sees.
}

}  // namespace gfec::lsp::handlers
