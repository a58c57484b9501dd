#include "occurrences.h"

#include "session.h"

#include <algorithm>
#include <set>

namespace gfec::lsp {

namespace {

/// The extensions of the files a workspace holds for gfec (docs/editors.md).
bool is_chart_file(const std::string &path) {
  static const char *const kExtensions[] = {".sfc", ".fsm", ".plan", ".toolbox", ".iface", ".test", ".pml"};
  for (const char *e : kExtensions) {
    const std::size_t n = std::char_traits<char>::length(e);
    if (path.size() > n && path.compare(path.size() - n, n, e) == 0) return true;
  }
  return false;
}

/// The uses of `key` in one compilation, added to `out` keyed by (path, begin) so that a file
/// several compilations read counts each place once.
void collect(const CompiledDocument &doc, const DeclarationKey &key,
             std::map<std::pair<std::string, std::uint32_t>, Occurrence> &out) {
  const auto &c = doc.compilation();
  for (const NameUse &u : c.name_uses.list) {
    if (!c.sources.knows(u.decl.file) || u.decl.begin != key.begin) continue;
    if (normal_path(c.sources.file(u.decl.file).path()) != key.path) continue;
    const std::string path = normal_path(c.sources.file(u.at.file).path());
    auto k = std::make_pair(path, u.at.begin);
    if (out.count(k)) continue;
    out[k] = {doc.uri_of(u.at.file), doc.range(u.at), u.declaration()};
  }
}

}  // namespace

DeclarationKey key_of(const CompiledDocument &doc, const SourceRange &decl) {
  const auto &sources = doc.compilation().sources;
  return {sources.knows(decl.file) ? normal_path(sources.file(decl.file).path()) : std::string(), decl.begin};
}

std::vector<std::string> workspace_files(Session &session) {
  std::set<std::string> paths;
  for (const std::string &folder : session.workspace_folders)
    for (const std::string &p : session.files().walk(folder))
      if (is_chart_file(p)) paths.insert(normal_path(p));
  return {paths.begin(), paths.end()};
}

std::vector<Occurrence> occurrences(Session &session, const DeclarationKey &key, std::string_view name) {
  std::map<std::pair<std::string, std::uint32_t>, Occurrence> found;
  std::set<std::string> done;
  for (const std::string &uri : session.open_uris()) {
    const CompiledDocument &doc = session.validated(uri);
    collect(doc, key, found);
    done.insert(normal_path(doc.path()));
  }
  pipeline::FrontEndOptions options = session.front_end;
  options.record_name_uses = true;
  for (const std::string &path : workspace_files(session)) {
    if (done.count(path)) continue;
    FileText text = session.files().read(path);
    if (!text || text->find(name) == std::string::npos) continue;
    CompiledDocument doc(session, session.uri_of_path(path), path, options, session.files());
    collect(doc, key, found);
  }
  std::vector<Occurrence> list;
  for (auto &f : found) list.push_back(std::move(f.second));
  std::stable_sort(list.begin(), list.end(), [](const Occurrence &a, const Occurrence &b) { return a.uri < b.uri; });
  return list;
}

}  // namespace gfec::lsp
