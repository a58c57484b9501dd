#include "session.h"

#include "uri.h"

#include <algorithm>

namespace gfec::lsp {

Session::Session(const FileSystem &disk, std::function<void(const std::string &, nlohmann::json)> notify)
    : disk_(disk), overlay_(disk), notify_(std::move(notify)) {}

void Session::set_text(const std::string &uri, std::string text, long long version) {
  Document &d = documents_[uri];
  d.uri = uri;
  d.path = path_of_uri(uri);
  d.text = std::move(text);
  d.version = version;
  overlay_.open(d.path, d.text);
  invalidate(uri, d.path);
}

void Session::invalidate(const std::string &uri, const std::string &path) {
  const std::string normal = normal_path(path);
  for (auto &c : compiled_)
    if (c.first == uri || c.second.document->reads(normal)) c.second.stale = true;
}

void Session::close(const std::string &uri) {
  auto it = documents_.find(uri);
  if (it == documents_.end()) return;
  overlay_.close(it->second.path);
  invalidate(uri, it->second.path);
  compiled_.erase(uri);
  deferred_.erase(std::remove(deferred_.begin(), deferred_.end(), uri), deferred_.end());
  documents_.erase(it);
}

Document *Session::document(const std::string &uri) {
  auto it = documents_.find(uri);
  return it == documents_.end() ? nullptr : &it->second;
}

Document &Session::open_document(const std::string &uri) {
  if (Document *d = document(uri)) return *d;
  throw RequestError{error_code::kInvalidParams, "the document '" + uri + "' is not open"};
}

std::vector<std::string> Session::open_uris() const {
  std::vector<std::string> uris;
  for (const auto &d : documents_) uris.push_back(d.first);
  return uris;
}

const CompiledDocument &Session::compiled(const std::string &uri) {
  validated(uri);
  CompiledDocument &doc = *compiled_[uri].document;
  doc.analyze();
  return doc;
}

void Session::set_deferred(const std::string &uri, bool deferred) {
  auto it = std::find(deferred_.begin(), deferred_.end(), uri);
  if (deferred && it == deferred_.end()) deferred_.push_back(uri);
  if (!deferred && it != deferred_.end()) deferred_.erase(it);
}

std::string Session::next_deferred() {
  if (deferred_.empty()) return {};
  std::string uri = std::move(deferred_.front());
  deferred_.erase(deferred_.begin());
  return uri;
}

const CompiledDocument &Session::validated(const std::string &uri) {
  Document &d = open_document(uri);
  Cached &c = compiled_[uri];
  if (!c.document || c.stale) {
    c.document.reset();  // the old model points into its sources: gone before the new one is made
    pipeline::FrontEndOptions options = front_end;
    options.keep_syntax_tree = true;  // outlines, hover
    options.record_name_uses = true;  // definition, references, rename
    c.document = std::make_unique<CompiledDocument>(*this, uri, d.path, options, overlay_);
    c.stale = false;
  }
  return *c.document;
}

std::vector<std::string> Session::dependents(const std::string &uri) const {
  std::vector<std::string> uris;
  auto d = documents_.find(uri);
  if (d == documents_.end()) return uris;
  const std::string path = normal_path(d->second.path);
  for (const auto &c : compiled_)
    if (c.first != uri && c.second.document->reads(path)) uris.push_back(c.first);
  return uris;
}

std::vector<std::string> Session::disk_file_changed(const std::string &path) {
  const std::string normal = normal_path(path);
  std::vector<std::string> uris;
  for (const auto &d : documents_)
    if (normal_path(d.second.path) == normal) return uris;
  for (auto &c : compiled_)
    if (c.second.document->reads(normal)) {
      c.second.stale = true;
      uris.push_back(c.first);
    }
  return uris;
}

std::string Session::uri_of_path(const std::string &path) const {
  const std::string wanted = normal_path(path);
  for (const auto &d : documents_)
    if (normal_path(d.second.path) == wanted) return d.first;
  return lsp::uri_of_path(path);
}

std::string document_uri(const nlohmann::json &params) {
  if (!params.is_object() || !params.contains("textDocument") || !params["textDocument"].is_object() ||
      !params["textDocument"].contains("uri") || !params["textDocument"]["uri"].is_string())
    throw RequestError{error_code::kInvalidParams, "the parameters have no textDocument.uri"};
  return params["textDocument"]["uri"].get<std::string>();
}

}  // namespace gfec::lsp
