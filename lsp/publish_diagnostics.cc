#include "publish_diagnostics.h"

#include "session.h"

namespace gfec::lsp {

using nlohmann::json;

namespace {

int severity_of(Severity s) {
  switch (s) {
  case Severity::Error: return 1;
  case Severity::Warning: return 2;
  case Severity::Note: return 3;
  }
  return 1;
}

json one(const CompiledDocument &doc, const Diagnostic &d) {
  json j = {{"range", doc.range(d.range)}, {"severity", severity_of(d.severity)}, {"source", "gfec"}};
  if (!d.check().empty()) j["code"] = d.check();
  std::string message = d.message;
  json related = json::array();
  for (const DiagnosticNote &n : d.notes) {
    if (n.has_range) related.push_back({{"location", doc.location(n.range)}, {"message", n.message}});
    else message += "\nnote: " + n.message;  // a note of no place reads as part of the message
  }
  j["message"] = message;
  if (!related.empty()) j["relatedInformation"] = related;
  return j;
}

}  // namespace

json diagnostics_of(const CompiledDocument &doc, long long version) {
  const pipeline::Compilation &c = doc.compilation();
  json list = json::array();
  for (const Diagnostic &d : c.diag.all()) {
    if (d.range.file == doc.main_file() && doc.has_main()) {
      list.push_back(one(doc, d));
    } else if (c.sources.knows(d.range.file)) {
      // An error in a file this one imports stops its check: say so at the top, as the
      // error's own file (when open) says it in full.
      if (d.severity != Severity::Error) continue;
      json j = one(doc, d);
      j["message"] = "in '" + c.sources.file(d.range.file).path() + "': " + d.message;
      j["range"] = doc.range({doc.main_file(), 0, 0});
      json related = j.value("relatedInformation", json::array());
      related.insert(related.begin(), {{"location", doc.location(d.range)}, {"message", d.message}});
      j["relatedInformation"] = related;
      list.push_back(j);
    }
  }
  if (c.unreadable())
    list.push_back({{"range", doc.range({doc.main_file(), 0, 0})},
                    {"severity", 1},
                    {"source", "gfec"},
                    {"message", c.cannot_read_main(doc.path())}});
  return {{"uri", doc.uri()}, {"version", version}, {"diagnostics", list}};
}

void publish_document(Session &session, const std::string &uri) {
  const Document *d = session.document(uri);
  if (!d) return;
  const CompiledDocument &doc = session.validated(uri);
  session.notify("textDocument/publishDiagnostics", diagnostics_of(doc, d->version));
  session.set_deferred(uri, doc.analysis_pending());
}

void publish_diagnostics(Session &session, const std::string &uri) {
  std::vector<std::string> uris{uri};
  for (const std::string &d : session.dependents(uri)) uris.push_back(d);
  for (const std::string &u : uris) publish_document(session, u);
}

void publish_analyses(Session &session, const std::function<bool()> &input_waiting) {
  while (session.has_deferred() && !input_waiting()) {
    const std::string uri = session.next_deferred();
    const Document *d = session.document(uri);
    if (!d) continue;
    // Every change to what the compilation read republishes it (publish_diagnostics), so this
    // is the compilation the first publish was of, and the version is still its version.
    const CompiledDocument &doc = session.compiled(uri);
    if (doc.analyses_reported()) session.notify("textDocument/publishDiagnostics", diagnostics_of(doc, d->version));
  }
}

}  // namespace gfec::lsp
