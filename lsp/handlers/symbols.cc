// textDocument/documentSymbol (the outline of the document's syntax tree, nested: a chart's
// places, transitions and vars inside it) and workspace/symbol (every declaration of the open
// documents and of the workspace's chart files whose name holds the query's letters in order,
// ignoring case, as editors' fuzzy pickers expect).
#include "methods.h"
#include "occurrences.h"
#include "outline.h"

#include <cctype>
#include <set>

namespace gfec::lsp::handlers {

using nlohmann::json;

namespace {

json document_symbol_json(const CompiledDocument &doc, const OutlineItem &item) {
  json j = {{"name", item.name},
            {"kind", item.kind},
            {"range", doc.range(item.range)},
            {"selectionRange", doc.range(item.selection)}};
  if (!item.detail.empty()) j["detail"] = item.detail;
  if (!item.children.empty()) {
    j["children"] = json::array();
    for (const OutlineItem &c : item.children) j["children"].push_back(document_symbol_json(doc, c));
  }
  return j;
}

bool fuzzy_match(const std::string &query, const std::string &name) {
  std::size_t at = 0;
  for (char q : query) {
    while (at < name.size() &&
           std::tolower(static_cast<unsigned char>(name[at])) != std::tolower(static_cast<unsigned char>(q)))
      ++at;
    if (at == name.size()) return false;
    ++at;
  }
  return true;
}

constexpr std::size_t kMaxWorkspaceSymbols = 1000;

void add_symbols(const CompiledDocument &doc, const std::vector<OutlineItem> &items, const std::string &container,
                 const std::string &query, json &out) {
  for (const OutlineItem &i : items) {
    if (out.size() >= kMaxWorkspaceSymbols) return;
    if (fuzzy_match(query, i.name)) {
      json j = {{"name", i.name}, {"kind", i.kind}, {"location", doc.location(i.selection)}};
      if (!container.empty()) j["containerName"] = container;
      out.push_back(j);
    }
    add_symbols(doc, i.children, i.name, query, out);
  }
}

}  // namespace

json document_symbol(Session &s, const json &params) {
  const CompiledDocument &doc = s.validated(document_uri(params));
  json list = json::array();
  if (const ast::File *file = doc.syntax_of(doc.main_file()))
    for (const OutlineItem &item : outline(*file)) list.push_back(document_symbol_json(doc, item));
  return list;
}

json workspace_symbol(Session &s, const json &params) {
  const std::string query = params.value("query", "");
  json out = json::array();
  std::set<std::string> done;
  auto add = [&](const CompiledDocument &doc) {
    done.insert(normal_path(doc.path()));
    if (const ast::File *file = doc.syntax_of(doc.main_file())) add_symbols(doc, outline(*file), "", query, out);
  };
  for (const std::string &uri : s.open_uris()) add(s.validated(uri));
  pipeline::FrontEndOptions options = s.front_end;
  options.keep_syntax_tree = true;
  for (const std::string &path : workspace_files(s)) {
    if (done.count(path) || out.size() >= kMaxWorkspaceSymbols) continue;
    CompiledDocument doc(s, s.uri_of_path(path), path, options, s.files());
    add(doc);
  }
  return out;
}

void advertise_document_symbol(json &caps) { caps["documentSymbolProvider"] = true; }
void advertise_workspace_symbol(json &caps) { caps["workspaceSymbolProvider"] = true; }

}  // namespace gfec::lsp::handlers
