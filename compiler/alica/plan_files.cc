#include "alica/plan_files.h"

#include "alica/identifiers.h"
#include "did_you_mean.h"
#include "alica/alica_reader.h"
#include "input_languages.h"

#include <fmt/format.h>

#include <algorithm>

namespace gfec::alica {

namespace fsys = std::filesystem;

std::string extension_of(const std::string &path) { return fsys::path(path).extension().string(); }

std::optional<Ref> split_ref(std::string text) {
  while (!text.empty() && (text.back() == ' ' || text.back() == ',')) text.pop_back();
  while (!text.empty() && text.front() == ' ') text.erase(0, 1);
  auto hash = text.rfind('#');
  if (hash == std::string::npos) return std::nullopt;
  Ref r{text.substr(0, hash), text.substr(hash + 1)};
  if (r.id.empty()) return std::nullopt;
  return r;
}

std::optional<std::string> id_of(const JsonValue *v) {
  if (!v) return std::nullopt;
  if (v->is_string() && !v->text.empty() && v->text[0] == '#') {
    JsonValue copy = *v;
    copy.text.erase(0, 1);
    return copy.as_id();
  }
  return v->as_id();
}

namespace {

/// Every object with an id, by id: what references name.
void index_ids(const JsonValue &v, std::map<std::string, const JsonValue *> &out) {
  if (v.is_object()) {
    if (auto id = id_of(v.find("id"))) out.emplace(*id, &v);
    for (const auto &m : v.members) index_ids(m.second, out);
  } else if (v.is_array()) {
    for (const auto &i : v.items) index_ids(i, out);
  }
}

}  // namespace

Doc *PlanFiles::open(const std::string &path, std::string text) {
  auto doc = std::make_unique<Doc>();
  doc->path = path;
  doc->file = sources_.add(path, std::move(text), language());
  result_.paths.push_back(path);
  auto file = std::make_unique<ast::File>();
  file->id = doc->file;
  result_.program.files.push_back(std::move(file));
  const std::string &t = sources_.file(doc->file).text();
  std::size_t first = t.find_first_not_of(" \t\r\n\xef\xbb\xbf");
  if (first != std::string::npos && t[first] == '<') {
    diag_
        .error({doc->file, static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(first + 1)},
               ErrorKind::AlicaFormat,
               "this is an XML file of ALICA's older Eclipse designer; gfec reads the JSON files of the "
               "current designer")
        .note("open the plans in the current ALICA plan designer and save them again to convert them");
  } else {
    JsonError error;
    doc->root = parse_json(t, error);
    if (!doc->root)
      diag_.error(
          {doc->file, error.offset, std::min<std::uint32_t>(error.offset + 1, static_cast<std::uint32_t>(t.size()))},
          ErrorKind::Json, "malformed JSON: " + error.message);
    else index_ids(*doc->root, doc->by_id);
  }
  Doc *raw = doc.get();
  docs_[path] = std::move(doc);
  return raw;
}

/// Where a reference from `from` may point: its folder, the plans' root folder (the folder
/// less the plan's "relativeDirectory"), -I folders, then ALICA's usual layout above it.
std::vector<std::string> PlanFiles::candidates(const std::string &file, const Doc &from) const {
  std::vector<std::string> out;
  auto add = [&](const fsys::path &p) {
    std::string n = normal_path(p);
    if (std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
  };
  if (fsys::path(file).is_absolute()) {
    add(file);
    return out;
  }
  fsys::path dir = fsys::path(from.path).parent_path();
  add(dir / file);
  std::string rel = from.root && from.root->is_object() ? from.root->string_of("relativeDirectory") : "";
  if (!rel.empty()) {
    fsys::path root = dir;
    for (const auto &part : fsys::path(rel).lexically_normal())
      if (!part.empty() && part != ".") root /= "..";
    add(root / file);
  }
  for (const auto &inc : options_.include_dirs) add(fsys::path(inc) / file);
  std::string ext = extension_of(file);
  fsys::path up = dir;
  for (int level = 0; level < 3; ++level) {
    up /= "..";
    add(up / file);
    if (ext == ".tsk") add(up / "tasks" / file);
    if (ext == ".cnd") add(up / "conditions" / file);
    if (ext == ".beh") add(up / "behaviours" / file);
    add(up / "plans" / file);
    // The folders of ALICA's layouts over the years (etc/behaviours, etc/plans/Behaviours,
    // etc/Misc for the task repository of the XML era, ...), for any kind of file.
    for (const char *folder : {"behaviours", "Behaviours", "conditions", "tasks", "placeholders", "Misc"})
      add(up / folder / file);
  }
  return out;
}

/// ALICA's engine finds a referenced file anywhere below its configuration folder, and the
/// designer leaves stale paths behind when files move: the last resort is the file of that
/// name (and trailing folders) below the folder above the plans' root, nearest first.
std::optional<std::string> PlanFiles::search_below(const std::string &file, const Doc &from) {
  fsys::path dir = fsys::path(from.path).parent_path();
  std::string rel = from.root && from.root->is_object() ? from.root->string_of("relativeDirectory") : "";
  for (const auto &part : fsys::path(rel).lexically_normal())
    if (!part.empty() && part != ".") dir /= "..";
  std::string root = normal_path(dir / "..");
  auto &files = trees_[root];
  if (!trees_listed_.count(root)) {
    trees_listed_.insert(root);
    // Bounded (WalkLimits: 5 levels, 20,000 entries, no hidden folders), so that a plan next to
    // a huge folder tree stays fast: ALICA's folders are a few levels deep and hold hundreds of
    // files. Through the file system, so an editor's unsaved buffers are found too.
    files = fs_.walk(root.empty() ? "." : root);
    std::sort(files.begin(), files.end(), [](const std::string &a, const std::string &b) {
      auto depth = [](const std::string &p) { return std::count(p.begin(), p.end(), '/'); };
      return depth(a) != depth(b) ? depth(a) < depth(b) : a < b;
    });
  }
  // "../Misc/x.tsk" and "Behaviours/y.beh": match the trailing folders that name something.
  std::string want;
  for (const auto &part : fsys::path(file).lexically_normal())
    if (part != ".." && part != "." && !part.empty()) want += (want.empty() ? "" : "/") + part.generic_string();
  if (want.empty()) return std::nullopt;
  for (const auto &f : files)
    if (f == want || (f.size() > want.size() && f.compare(f.size() - want.size(), want.size(), want) == 0 &&
                      f[f.size() - want.size() - 1] == '/'))
      return f;
  std::string base = fsys::path(want).filename().string();
  if (base == want) return std::nullopt;
  for (const auto &f : files)
    if (fsys::path(f).filename().string() == base) return f;
  return std::nullopt;
}

Doc *PlanFiles::find_doc(const std::string &file, const Doc &from, const SourceRange &at, const std::string &id,
                         Need need = Need::Element) {
  std::vector<std::string> tried = candidates(file, from);
  // A file that cannot be found is reported at its first reference only: ten states that
  // run the same missing behaviour are one problem, not ten.
  if (missing_.count(tried.front())) return nullptr;
  // The search below etc/ only when the usual places fail: it is the slow path.
  bool searched = false;
  std::string refused;  ///< cannot_read's message for the first file there that was not read
  auto search = [&] {
    searched = true;
    if (auto found = search_below(file, from))
      if (std::find(tried.begin(), tried.end(), *found) == tried.end()) tried.push_back(*found);
  };
  for (std::size_t i = 0;; ++i) {
    if (i == tried.size() && !searched) search();
    if (i >= tried.size()) break;
    Doc *doc = nullptr;
    auto seen = docs_.find(tried[i]);
    if (seen != docs_.end()) doc = seen->second.get();
    else if (auto text = fs_.read(tried[i])) doc = open(tried[i], std::move(*text));
    else if (refused.empty() && fs_.identity(tried[i])) refused = cannot_read(tried[i], text.why);  // there, not read
    if (!doc) continue;
    // ALICA resolves by id: when the nearest file of that name lacks the id (a behaviour and
    // its interface share a name, an old repository lies beside the new one), a farther one of
    // the same name that holds it is the one meant.
    if (doc->root && !doc->by_id.count(id)) {
      if (!searched) search();
      for (std::size_t j = i + 1; j < tried.size(); ++j)
        if (Doc *other = holding(tried[j], id)) return other;
    }
    return doc;
  }
  missing_.insert(tried.front());
  // A file that is there but refused (a device, a file of /proc, too large) is no typo.
  if (!refused.empty()) {
    diag_.error(at, ErrorKind::AlicaReference, fmt::format("{}, referenced here", refused));
    return nullptr;
  }
  auto &d = need == Need::LabelOnly
                ? diag_.warning(Warning::AlicaIgnored, at,
                                fmt::format("cannot find '{}', referenced here: the entry point is labelled "
                                            "without its task's name",
                                            file))
                : diag_.error(at, ErrorKind::AlicaReference, fmt::format("cannot find '{}', referenced here", file));
  suggest_file(d, file, tried, from.path);
  // The folders that exist (hold files), not every folder of every layout gfec knows.
  for (const auto &t : tried)
    if (&t == &tried.front() || !fs_.list(normal_path(fsys::path(t).parent_path())).empty())
      d.note(fmt::format("looked for '{}'", t));
  return nullptr;
}

/// The file at `path` if it holds an element with `id`, read without a diagnostic otherwise.
Doc *PlanFiles::holding(const std::string &path, const std::string &id) {
  auto seen = docs_.find(path);
  if (seen != docs_.end()) return seen->second->by_id.count(id) ? seen->second.get() : nullptr;
  auto text = fs_.read(path);
  if (!text) return nullptr;
  JsonError error;
  auto root = parse_json(*text, error);
  if (!root) return nullptr;
  std::map<std::string, const JsonValue *> ids;
  index_ids(*root, ids);
  return ids.count(id) ? open(path, std::move(*text)) : nullptr;
}

/// "did you mean 'Behaviours/GoTo.beh'?" from the files in the folders the reference was
/// looked for in; the first closest name wins, so the note is deterministic. Never the file that
/// holds the reference (a plan named like the missing one is not what it meant to run).
void PlanFiles::suggest_file(Diagnostic &d, const std::string &file, const std::vector<std::string> &tried,
                             const std::string &from) {
  std::string want = fsys::path(file).filename().string();
  std::string best;
  NearestName nearest(want, want.size() / 3);
  for (const auto &path : tried)
    for (const auto &name : fs_.list(normal_path(fsys::path(path).parent_path()))) {
      if (normal_path(fsys::path(path).parent_path() / name) == from) continue;
      if (nearest.offer(name)) best = name;
    }
  if (!best.empty() && best != want)
    d.note(fmt::format("did you mean '{}'?", normal_path(fsys::path(file).parent_path() / best)));
}

/// The element a reference "File.ext#id" names, or nothing (reported at `at`).
Resolved PlanFiles::resolve(const std::string &text, Doc &from, const SourceRange &at, Need need) {
  auto ref = split_ref(text);
  if (!ref) {
    diag_.error(at, ErrorKind::AlicaReference,
                fmt::format("'{}' is no reference: ALICA writes them as \"File.ext#id\"", text));
    return {};
  }
  // A NUL would cut the path short (the file opened would not be the one named), and a file
  // name with a line break would put it into every diagnostic's location.
  if (std::any_of(ref->file.begin(), ref->file.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; })) {
    diag_.error(at, ErrorKind::AlicaReference,
                fmt::format("'{}' names a file with a control character in its name", text));
    return {};
  }
  Doc *doc = ref->file.empty() ? &from : find_doc(ref->file, from, at, ref->id, need);
  if (!doc || !doc->root) return {};
  auto it = doc->by_id.find(ref->id);
  if (it == doc->by_id.end()) {
    std::string message = fmt::format("'{}' has no element with id {}", doc->path, ref->id);
    auto &d = need == Need::LabelOnly ? diag_.warning(Warning::AlicaIgnored, at,
                                                      message + ": the entry point is labelled without its task's name")
                                      : diag_.error(at, ErrorKind::AlicaReference, message);
    // A mistyped id: the element whose id is closest (a digit or two off); else, for a file
    // that holds one element (a behaviour, a plan), that element.
    const JsonValue *best = nullptr;
    NearestName nearest(ref->id, 2);
    for (const auto &[id, object] : doc->by_id) {
      if (!object->find("name")) continue;  // blackboard keys, mappings: not what references name
      if (nearest.offer(id)) best = object;
    }
    const JsonValue &root = *doc->root;
    bool repository = root.find("conditions") || root.find("tasks") || root.find("roles");
    if (!best && !repository && id_of(root.find("id"))) best = &root;
    if (best)
      d.note(range(*doc, *best), fmt::format("did you mean '{}' (id {}), which the file holds?", label_of(*best),
                                             *id_of(best->find("id"))));
    return {};
  }
  return {doc, it->second};
}

std::vector<const Doc *> PlanFiles::parsed() const {
  std::vector<const Doc *> docs;
  for (const auto &[path, doc] : docs_)
    if (doc->root) docs.push_back(doc.get());
  std::sort(docs.begin(), docs.end(), [](const Doc *a, const Doc *b) { return a->file < b->file; });
  return docs;
}

}  // namespace gfec::alica
