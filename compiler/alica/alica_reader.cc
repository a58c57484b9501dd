#include "alica/alica_reader.h"

#include "alica/identifiers.h"
#include "alica/json_tree.h"
#include "file_system.h"
#include "input_languages.h"
#include "validate/suggest.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <numeric>
#include <set>

namespace gfec::alica {

namespace {

namespace fsys = std::filesystem;

std::string normal(const fsys::path &p) {
  std::string s = p.lexically_normal().generic_string();
  if (s.size() > 1 && s.back() == '/') s.pop_back();
  return s.empty() ? "." : s;
}

std::string extension_of(const std::string &path) { return fsys::path(path).extension().string(); }

/// Plans nest at most this deep through the states that run them, as imports do (docs/security.md):
/// reading a plan takes a few stack frames, so a chain of thousands would overflow the stack.
constexpr int kMaxPlanDepth = 200;

/// "Behaviours/GoTo.beh#1544160969061" -> file and id; "#42" names the same file.
struct Ref {
  std::string file;
  std::string id;
};

std::optional<Ref> split_ref(std::string text) {
  while (!text.empty() && (text.back() == ' ' || text.back() == ',')) text.pop_back();
  while (!text.empty() && text.front() == ' ') text.erase(0, 1);
  auto hash = text.rfind('#');
  if (hash == std::string::npos) return std::nullopt;
  Ref r{text.substr(0, hash), text.substr(hash + 1)};
  if (r.id.empty()) return std::nullopt;
  return r;
}

/// An id written as a number, a string of digits or "#digits" (the XML era's spelling).
std::optional<std::string> id_of(const JsonValue *v) {
  if (!v) return std::nullopt;
  if (v->is_string() && !v->text.empty() && v->text[0] == '#') {
    JsonValue copy = *v;
    copy.text.erase(0, 1);
    return copy.as_id();
  }
  return v->as_id();
}

/// One JSON file read.
struct Doc {
  std::string path;
  FileId file = 0;
  std::optional<JsonValue> root;  ///< empty: malformed (already reported)
  std::map<std::string, const JsonValue *> by_id;
};

void index_ids(const JsonValue &v, std::map<std::string, const JsonValue *> &out) {
  if (v.is_object()) {
    if (auto id = id_of(v.find("id"))) out.emplace(*id, &v);
    for (const auto &m : v.members) index_ids(m.second, out);
  } else if (v.is_array()) {
    for (const auto &i : v.items) index_ids(i, out);
  }
}

/// An element's name for messages: "" when the designer wrote none (MISSING_NAME, the id).
std::string label_of(const JsonValue &v) {
  std::string name = v.string_of("name");
  return meaningful(name) ? name : "";
}

bool non_empty(const JsonValue *v) {
  if (!v || v->is_null()) return false;
  if (v->is_array()) return !v->items.empty();
  if (v->is_object()) return !v->members.empty();
  if (v->is_string()) return !v->text.empty();
  return true;
}

class Reader {
public:
  Reader(const LoadOptions &options, const FileSystem &fs, SourceManager &sources, Diagnostics &diag,
         LoadResult &result)
      : options_(options), fs_(fs), sources_(sources), diag_(diag), result_(result) {}

  void read_main(const std::string &path, std::string text) {
    std::size_t first_diagnostic = diag_.all().size();
    read_plan(path, std::move(text));
    duplicate_members();
    // Messages quote names as "state 'X' (id N)"; an element without a name is "state (id N)".
    auto unquote = [](std::string &s) {
      for (auto at = s.find("'' (id "); at != std::string::npos; at = s.find("'' (id ", at)) s.erase(at, 3);
      for (auto at = s.find(" (id )"); at != std::string::npos; at = s.find(" (id )", at)) s.erase(at, 6);
    };
    // Names and references are the file's text: a control character in one must not reach the
    // terminal, where "\n" would start a forged diagnostic and ESC a terminal command.
    auto clean = [&](std::string &s) {
      unquote(s);
      s = printable(s);
    };
    for (std::size_t i = first_diagnostic; i < diag_.all().size(); ++i) {
      clean(diag_.all()[i].message);
      for (auto &n : diag_.all()[i].notes) clean(n.message);
    }
    for (auto &e : result_.elements) clean(e.description);
  }

private:
  void read_plan(const std::string &path, std::string text) {
    Doc *doc = open(normal(path), std::move(text));
    main_ = result_.program.files.front().get();
    if (!doc->root) return;
    const JsonValue &root = *doc->root;
    if (!root.is_object() || (!root.find("states") && !root.find("entryPoints"))) {
      auto &d = diag_.error(range(*doc, root), ErrorKind::AlicaFormat,
                            fmt::format("'{}' is not an ALICA plan: a plan is a JSON object with \"entryPoints\" and "
                                        "\"states\"",
                                        doc->path));
      if (const FileType *type = language().file_type(doc->path); type && !type->main)
        d.note(fmt::format("this is {}; gfec compiles plans (.pml): give it the plans that use this file, which it "
                           "then reads too",
                           type->what));
      return;
    }
    main_->interfaces.emplace_back();
    main_->interfaces.back().name = {keep(identifier(label_of(root), "Plan") + "Functions"), range(*doc, root)};
    main_->interfaces.back().range = range(*doc, root);
    plan_chart(*doc, root, range(*doc, root));
    // An interface with no function would only add an empty block to the converted text.
    if (main_->interfaces.back().functions.empty()) main_->interfaces.clear();
  }

  SourceRange range(const Doc &d, const JsonValue &v) const { return {d.file, v.begin, v.end}; }

  /// A member named twice in one object, in every file read: JSON leaves its meaning open, and
  /// ALICA's tools disagree (its engine reads the first, its designer keeps the last). gfec reads
  /// the first; when it read that member and the second says otherwise, what gfec makes of the
  /// plan would differ from what the designer shows, so that is an error (docs/alica.md).
  /// After the plan is read, since only then is it known which members gfec looked up.
  void duplicate_members() {
    std::vector<const Doc *> docs;
    for (const auto &[path, doc] : docs_)
      if (doc->root) docs.push_back(doc.get());
    std::sort(docs.begin(), docs.end(), [](const Doc *a, const Doc *b) { return a->file < b->file; });
    for (const Doc *doc : docs) duplicate_members(*doc, *doc->root);
  }
  void duplicate_members(const Doc &doc, const JsonValue &v) {
    for (const auto &d : v.duplicates) {
      const auto &[key, first] = v.members[d.first];
      const JsonValue &second = v.members[d.second].second;
      SourceRange at{doc.file, d.key_begin, d.key_end};
      bool same = same_json(first, second);
      Diagnostic &diagnostic =
          first.looked_up && !same
              ? diag_.error(at, ErrorKind::ConflictingKey,
                            fmt::format("member \"{}\" is given a second time in this object, with another value: "
                                        "gfec reads the first, as ALICA's engine does, but ALICA's plan designer "
                                        "keeps this one",
                                        key))
              : diag_.warning(Warning::DuplicateKey, at,
                              same ? fmt::format("member \"{}\" is given a second time in this object, with the "
                                                 "same value",
                                                 key)
                                   : fmt::format("member \"{}\" is given a second time in this object, with another "
                                                 "value; gfec does not read this member here",
                                                 key));
      diagnostic.note({doc.file, d.first_key_begin, d.first_key_end}, fmt::format("the first \"{}\" is here", key));
    }
    for (const auto &item : v.items) duplicate_members(doc, item);
    for (const auto &m : v.members) duplicate_members(doc, m.second);
  }

  /// An id that is there but is no integer ("1.5", "1e3", "x"): a located error saying so, rather
  /// than the id reading as missing further on (`what` names whose id it is). True if reported.
  bool not_an_id(const Doc &doc, const JsonValue *v, const std::string &what) {
    if (!v || v->is_null() || id_of(v)) return false;
    std::string written =
        sources_.file(doc.file).text().substr(v->begin, std::min<std::uint32_t>(v->end - v->begin, 40));
    diag_.error(range(doc, *v), ErrorKind::AlicaFormat,
                fmt::format("{} is {}, which is no id: ALICA's ids are 64-bit integers", what, written));
    return true;
  }

  void element(const Doc &d, const JsonValue &v, std::string description) {
    result_.elements.push_back({range(d, v), std::move(description)});
  }

  void ignored(const Doc &d, const JsonValue &v, std::string message) { ignored(range(d, v), std::move(message)); }
  void ignored(const SourceRange &at, std::string message) {
    diag_.warning(Warning::AlicaIgnored, at, std::move(message));
  }

  // ------------------------------------------------------------ files and references

  Doc *open(const std::string &path, std::string text) {
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
  std::vector<std::string> candidates(const std::string &file, const Doc &from) const {
    std::vector<std::string> out;
    auto add = [&](const fsys::path &p) {
      std::string n = normal(p);
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
  std::optional<std::string> search_below(const std::string &file, const Doc &from) {
    // Only on disk: an in-memory file system (the loader's tests) has no folders to walk.
    if (!dynamic_cast<const RealFileSystem *>(&fs_)) return std::nullopt;
    fsys::path dir = fsys::path(from.path).parent_path();
    std::string rel = from.root && from.root->is_object() ? from.root->string_of("relativeDirectory") : "";
    for (const auto &part : fsys::path(rel).lexically_normal())
      if (!part.empty() && part != ".") dir /= "..";
    std::string root = normal(dir / "..");
    auto &files = trees_[root];
    if (!trees_listed_.count(root)) {
      trees_listed_.insert(root);
      // Bounded, so that a plan next to a huge folder tree stays fast: ALICA's folders are a few
      // levels deep and hold hundreds of files.
      std::error_code ec;
      constexpr int kMaxDepth = 5;
      constexpr std::size_t kMaxEntries = 20000;
      std::size_t seen = 0;
      fsys::recursive_directory_iterator it(root.empty() ? "." : root, fsys::directory_options::skip_permission_denied,
                                            ec);
      for (fsys::recursive_directory_iterator end; !ec && it != end && seen < kMaxEntries; it.increment(ec), ++seen) {
        std::string name = it->path().filename().string();
        if (it->is_directory(ec)) {
          if (it.depth() >= kMaxDepth || (!name.empty() && name[0] == '.')) it.disable_recursion_pending();
          continue;
        }
        if (it->is_regular_file(ec)) files.push_back(normal(it->path()));
      }
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

  /// How much a reference matters: a task names only an entry point's label, so a task file
  /// that cannot be found is a warning, not an error.
  enum class Need { Element, LabelOnly };

  Doc *find_doc(const std::string &file, const Doc &from, const SourceRange &at, const std::string &id,
                Need need = Need::Element) {
    std::vector<std::string> tried = candidates(file, from);
    // A file that cannot be found is reported at its first reference only: ten states that
    // run the same missing behaviour are one problem, not ten.
    if (missing_.count(tried.front())) return nullptr;
    // The search below etc/ only when the usual places fail: it is the slow path.
    bool searched = false;
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
    auto &d = need == Need::LabelOnly
                  ? diag_.warning(Warning::AlicaIgnored, at,
                                  fmt::format("cannot find '{}', referenced here: the entry point is labelled "
                                              "without its task's name",
                                              file))
                  : diag_.error(at, ErrorKind::AlicaReference, fmt::format("cannot find '{}', referenced here", file));
    suggest_file(d, file, tried, from.path);
    // The folders that exist (hold files), not every folder of every layout gfec knows.
    for (const auto &t : tried)
      if (&t == &tried.front() || !fs_.list(normal(fsys::path(t).parent_path())).empty())
        d.note(fmt::format("looked for '{}'", t));
    return nullptr;
  }

  /// The file at `path` if it holds an element with `id`, read without a diagnostic otherwise.
  Doc *holding(const std::string &path, const std::string &id) {
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
  void suggest_file(Diagnostic &d, const std::string &file, const std::vector<std::string> &tried,
                    const std::string &from) {
    std::string want = fsys::path(file).filename().string();
    std::string best;
    std::size_t best_distance = want.size() / 3 + 1;
    for (const auto &path : tried)
      for (const auto &name : fs_.list(normal(fsys::path(path).parent_path()))) {
        if (normal(fsys::path(path).parent_path() / name) == from) continue;
        std::size_t dist = validation::edit_distance(want, name);
        if (dist < best_distance) {
          best = name;
          best_distance = dist;
        }
      }
    if (!best.empty() && best != want)
      d.note(fmt::format("did you mean '{}'?", normal(fsys::path(file).parent_path() / best)));
  }

  struct Target {
    Doc *doc = nullptr;
    const JsonValue *object = nullptr;
  };

  /// The element a reference "File.ext#id" names, or nothing (reported at `at`).
  Target resolve(const std::string &text, Doc &from, const SourceRange &at, Need need = Need::Element) {
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
      auto &d = need == Need::LabelOnly
                    ? diag_.warning(Warning::AlicaIgnored, at,
                                    message + ": the entry point is labelled without its task's name")
                    : diag_.error(at, ErrorKind::AlicaReference, message);
      // A mistyped id: the element whose id is closest (a digit or two off); else, for a file
      // that holds one element (a behaviour, a plan), that element.
      const JsonValue *best = nullptr;
      std::size_t best_distance = 3;
      for (const auto &[id, object] : doc->by_id) {
        if (!object->find("name")) continue;  // blackboard keys, mappings: not what references name
        std::size_t dist = validation::edit_distance(ref->id, id);
        if (dist < best_distance) {
          best = object;
          best_distance = dist;
        }
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

  // ------------------------------------------------------------ functions

  std::string global_name(const std::string &text, const std::string &id, const std::string &fallback) {
    return globals_.take(identifier(text, fallback + id), id);
  }

  void declare(const std::string &name, const char *result, const SourceRange &at) {
    ast::FunctionDecl f;
    f.result = {result, at};
    f.name = {keep(name), at};
    f.range = at;
    main_->interfaces.back().functions.push_back(std::move(f));
  }

  /// The action function of the behaviour `t`: declared on first use.
  std::string behaviour(const Target &t) {
    std::string id = id_of(t.object->find("id")).value_or("");
    std::string key = t.doc->path + "#" + id;
    auto it = functions_.find(key);
    if (it != functions_.end()) return it->second;
    std::string label = label_of(*t.object);
    std::string name = global_name(label, id, "Behaviour");
    functions_[key] = name;
    declare(name, "void", range(*t.doc, *t.object));
    element(*t.doc, *t.object, fmt::format("ALICA behaviour '{}' (id {})", label, id));
    for (const char *c : {"preCondition", "runtimeCondition", "postCondition"})
      if (const JsonValue *v = t.object->find(c); non_empty(v))
        ignored(*t.doc, *v,
                fmt::format("the {} of behaviour '{}' (id {}) is ignored: gfec calls '{}' on every tick "
                            "of the states that hold it",
                            c, label, id, name));
    if (const JsonValue *v = t.object->find("variables"); non_empty(v))
      ignored(*t.doc, *v,
              fmt::format("the variables of behaviour '{}' (id {}) are ignored: a gfec action function "
                          "takes no arguments",
                          label, id));
    if (const JsonValue *v = t.object->find("blackboard"); non_empty(v))
      ignored(*t.doc, *v,
              fmt::format("the blackboard of behaviour '{}' (id {}) is ignored: gfec has no blackboard, "
                          "'{}()' takes no arguments",
                          label, id, name));
    return name;
  }

  /// The sensing function of a condition object: its name, else `fallback`, else "Condition<id>".
  std::string condition(Doc &doc, const JsonValue &cond, const std::string &fallback) {
    std::string id = id_of(cond.find("id")).value_or("");
    std::string key = doc.path + "#" + id;
    auto it = functions_.find(key);
    if (it != functions_.end()) return it->second;
    std::string label = label_of(cond);
    std::string name = globals_.take(identifier(meaningful(label) ? label : fallback, "Condition" + id), id);
    functions_[key] = name;
    declare(name, "bool", range(doc, cond));
    element(doc, cond, fmt::format("ALICA condition '{}' (id {})", label, id));
    condition_warnings(doc, cond, fmt::format("gfec's '{}()' takes no arguments", name));
    return name;
  }

  /// What a condition holds that gfec's sensing functions cannot take; `why` ends each warning.
  void condition_warnings(const Doc &doc, const JsonValue &cond, const std::string &why) {
    std::string id = id_of(cond.find("id")).value_or("");
    std::string label = label_of(cond);
    if (const JsonValue *q = cond.find("quantifiers"); non_empty(q))
      ignored(doc, *q, fmt::format("the quantifiers of condition '{}' (id {}) are ignored: {}", label, id, why));
    if (const JsonValue *v = cond.find("variables"); non_empty(v))
      ignored(doc, *v, fmt::format("the variables of condition '{}' (id {}) are ignored: {}", label, id, why));
    if (const JsonValue *v = cond.find("blackboard"); non_empty(v))
      ignored(doc, *v,
              fmt::format("the blackboard inputs of condition '{}' (id {}) are ignored: gfec has no blackboard, {}",
                          label, id, why));
  }

  ast::ExprPtr call(const std::string &name, const SourceRange &at) {
    auto e = std::make_unique<ast::Expr>();
    e->kind = ast::Expr::Kind::Call;
    e->range = at;
    e->name = {keep(name), at};
    return e;
  }

  // ------------------------------------------------------------ plans

  /// The chart a plan becomes (its fsm, or its sfc with several entry points); converted once.
  /// `at` is the reference that runs it: a plan nested too deep is an error there, and "".
  std::string plan_chart(Doc &doc, const JsonValue &plan, const SourceRange &at) {
    std::string id = id_of(plan.find("id")).value_or("");
    std::string key = doc.path + "#" + id;
    auto it = plan_charts_.find(key);
    if (it != plan_charts_.end()) return it->second;
    if (plan_depth_ > kMaxPlanDepth) {
      diag_.error(at, ErrorKind::AlicaReference,
                  fmt::format("plans nested more than {} deep: plan '{}' (id {}) would run {} levels below the "
                              "compiled plan",
                              kMaxPlanDepth, label_of(plan), id, plan_depth_));
      plan_charts_[key] = "";  // reported once, however many states run it
      return "";
    }
    std::string name = global_name(label_of(plan), id, "Plan");
    plan_charts_[key] = name;  // before the states: a plan that runs itself stops here
    const JsonValue *entries = plan.find("entryPoints");
    fsm_charts_[name] = !entries || !entries->is_array() || entries->items.size() <= 1;
    ++plan_depth_;
    convert_plan(doc, plan, name);
    --plan_depth_;
    return name;
  }

  /// The chart a plan type runs: its first activated plan.
  std::string plan_type_chart(const Target &t, const SourceRange &at) {
    std::string label = label_of(*t.object);
    std::string id = id_of(t.object->find("id")).value_or("");
    const JsonValue *list = t.object->find("annotatedPlans");
    if (!list) list = t.object->find("plans");
    std::vector<std::pair<std::string, const JsonValue *>> activated;
    if (list && list->is_array())
      for (const auto &item : list->items) {
        if (!item.is_object()) continue;
        const JsonValue *on = item.find("activated");
        if (on && on->kind == JsonValue::Kind::Bool && !on->boolean) continue;
        const JsonValue *plan = item.find("plan");
        if (plan && plan->is_string()) activated.emplace_back(plan->text, plan);
      }
    bool first_use = plan_type_warned_.insert(t.object).second;
    for (const char *key : {"variables", "variableBindings"})
      if (const JsonValue *v = t.object->find(key); non_empty(v) && first_use)
        ignored(*t.doc, *v,
                fmt::format("the {} of plan type '{}' (id {}) are ignored: gfec sub-charts share no "
                            "variables",
                            key, label, id));
    if (activated.empty()) {
      diag_
          .error(at, ErrorKind::AlicaReference,
                 fmt::format("plan type '{}' (id {}) has no activated plan to run", label, id))
          .note(range(*t.doc, *t.object), "the plan type is here");
      return "";
    }
    Target first = resolve(activated.front().first, *t.doc, range(*t.doc, *activated.front().second));
    if (!first.object) return "";
    std::string chart = plan_chart(*first.doc, *first.object, at);
    if (activated.size() > 1 && first_use) {
      std::string others;
      for (std::size_t i = 1; i < activated.size(); ++i)
        others += fmt::format("{}'{}'", i > 1 ? ", " : "", activated[i].first);
      ignored(*t.doc, *t.object,
              fmt::format("plan type '{}' (id {}) runs its first activated plan, '{}'; ignored: {} "
                          "(ALICA chooses by utility at run time)",
                          label, id, chart, others));
    }
    return chart;
  }

  struct Machine {
    ast::Chart chart;
    NameScope states, transitions;
    std::string entry_state;  ///< id of its initial state
  };

  void plan_warnings(Doc &doc, const JsonValue &plan, const std::string &what) {
    for (const char *c : {"preCondition", "runtimeCondition"})
      if (const JsonValue *v = plan.find(c); non_empty(v))
        ignored(doc, *v,
                fmt::format("the {} of {} is ignored: gfec starts a sub-chart whenever its state is "
                            "entered and never aborts it",
                            c, what));
    if (const JsonValue *v = plan.find("variables"); non_empty(v))
      ignored(doc, *v, fmt::format("the variables of {} are ignored: gfec has no plan variables", what));
    if (const JsonValue *v = plan.find("blackboard"); non_empty(v))
      ignored(doc, *v, fmt::format("the blackboard of {} is ignored: gfec has no blackboard", what));
    if (const JsonValue *syncs = plan.find("synchronisations"); syncs && syncs->is_array())
      for (const auto &s : syncs->items)
        if (s.is_object())
          ignored(doc, s,
                  fmt::format("synchronisation '{}' (id {}) of {} is ignored: gfec fires each transition "
                              "on its own condition",
                              label_of(s), id_of(s.find("id")).value_or("?"), what));
  }

  /// The entry point's label: its name, else its task's name, else "EntryPoint<id>".
  std::string entry_label(Doc &doc, const JsonValue &ep) {
    std::string name = label_of(ep);
    const JsonValue *task = ep.find("task");
    if (task && task->is_string() && !task->text.empty()) {
      Target t = resolve(task->text, doc, range(doc, *task), Need::LabelOnly);
      if (t.object && !meaningful(name)) name = label_of(*t.object);
    }
    return name;
  }

  void convert_plan(Doc &doc, const JsonValue &plan, const std::string &name) {
    std::string plan_id = id_of(plan.find("id")).value_or("");
    std::string what = fmt::format("plan '{}' (id {})", label_of(plan), plan_id);
    element(doc, plan, "ALICA " + what);
    plan_warnings(doc, plan, what);

    // The plan's states and transitions, by id.
    std::vector<const JsonValue *> states, transitions, entries;
    auto objects = [](const JsonValue *list, std::vector<const JsonValue *> &out) {
      if (list && list->is_array())
        for (const auto &i : list->items)
          if (i.is_object()) out.push_back(&i);
    };
    objects(plan.find("states"), states);
    objects(plan.find("transitions"), transitions);
    objects(plan.find("entryPoints"), entries);
    // Ids only messages quote: one that is no id is still reported where it is written.
    not_an_id(doc, plan.find("id"), fmt::format("the id of plan '{}'", label_of(plan)));
    for (const JsonValue *e : entries)
      not_an_id(doc, e->find("id"), fmt::format("the id of entry point '{}' of {}", label_of(*e), what));
    for (const JsonValue *t : transitions)
      not_an_id(doc, t->find("id"), fmt::format("the id of transition '{}' of {}", label_of(*t), what));
    std::map<std::string, std::size_t> state_index;
    for (std::size_t i = 0; i < states.size(); ++i) {
      auto id = id_of(states[i]->find("id"));
      if (!id) {
        if (!not_an_id(doc, states[i]->find("id"),
                       fmt::format("the id of state '{}' of {}", label_of(*states[i]), what)))
          diag_.error(range(doc, *states[i]), ErrorKind::AlicaFormat, fmt::format("a state of {} has no id", what));
        continue;
      }
      if (!state_index.emplace(*id, i).second)
        diag_
            .error(range(doc, *states[i]), ErrorKind::AlicaFormat,
                   fmt::format("second state with id {} in {}", *id, what))
            .note(range(doc, *states[state_index[*id]]), "the first one is here");
    }
    if (entries.empty()) {
      diag_.error(range(doc, plan), ErrorKind::AlicaFormat,
                  fmt::format("{} has no entry point: gfec needs one to know where its machine starts", what));
      return;
    }

    // States weakly connected by transitions belong to the same entry point's machine.
    std::vector<std::size_t> parent(states.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](std::size_t x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    auto state_of = [&](const JsonValue *v) -> std::optional<std::size_t> {
      auto id = id_of(v);
      if (!id) return std::nullopt;
      auto it = state_index.find(*id);
      if (it == state_index.end()) return std::nullopt;
      return it->second;
    };
    for (const JsonValue *t : transitions) {
      auto a = state_of(t->find("inState")), b = state_of(t->find("outState"));
      if (a && b) parent[root(*a)] = root(*b);
    }

    std::vector<Machine> machines(entries.size());
    std::vector<int> owner(states.size(), -1);
    std::vector<std::string> entry_names(entries.size());  ///< "'label' (id N)", for messages
    bool several = entries.size() > 1;
    for (std::size_t e = 0; e < entries.size(); ++e) {
      const JsonValue &ep = *entries[e];
      std::string ep_id = id_of(ep.find("id")).value_or("");
      std::string label = entry_label(doc, ep);
      entry_names[e] = fmt::format("'{}' (id {})", label, ep_id);
      element(doc, ep, fmt::format("ALICA entry point '{}' (id {}) of {}", label, ep_id, what));
      entry_warnings(doc, ep, label, ep_id, several);
      Machine &m = machines[e];
      m.chart.kind = ast::Chart::Kind::Fsm;
      m.chart.range = several ? range(doc, ep) : range(doc, plan);
      std::string chart_name = several ? global_name(name + identifier(label, "EntryPoint" + ep_id), ep_id, "") : name;
      m.chart.name = {keep(chart_name), m.chart.range};
      auto start = state_of(ep.find("state"));
      if (!start) {
        if (not_an_id(doc, ep.find("state"),
                      fmt::format("the state of entry point '{}' (id {}) of {}", label, ep_id, what)))
          continue;
        diag_.error(range(doc, ep), ErrorKind::AlicaReference,
                    fmt::format("entry point '{}' (id {}) starts in state {}, which {} does not have", label, ep_id,
                                id_of(ep.find("state")).value_or("(none)"), what));
        continue;
      }
      if (owner[*start] >= 0) {
        diag_
            .error(range(doc, ep), ErrorKind::AlicaFormat,
                   fmt::format("entry point {} starts in state '{}', which entry point {} already reaches: gfec "
                               "gives each entry point a machine of its own states",
                               entry_names[e], label_of(*states[*start]), entry_names[owner[*start]]))
            .note(range(doc, *states[*start]), "the state is here");
        continue;
      }
      m.entry_state = *id_of(ep.find("state"));
      for (std::size_t s = 0; s < states.size(); ++s)
        if (owner[s] < 0 && root(s) == root(*start)) owner[s] = static_cast<int>(e);
    }
    // States no entry point reaches go to the first machine, whose checks call them disconnected.
    int first = -1;
    for (std::size_t e = 0; e < machines.size() && first < 0; ++e)
      if (!machines[e].entry_state.empty()) first = static_cast<int>(e);
    if (first < 0) return;  // reported above
    for (auto &o : owner)
      if (o < 0) o = first;

    std::vector<std::string> state_names(states.size());
    for (std::size_t s = 0; s < states.size(); ++s) {
      Machine &m = machines[owner[s]];
      m.chart.places.push_back(convert_state(doc, *states[s], m, what, state_names[s]));
    }
    for (const JsonValue *t : transitions) convert_transition(doc, *t, machines, owner, state_names, state_of, what);

    ast::File &file = *result_.program.files[file_index(doc)];
    if (several) {
      ast::Chart sfc;
      sfc.kind = ast::Chart::Kind::Sfc;
      sfc.range = range(doc, plan);
      sfc.name = {keep(name), sfc.range};
      NameScope places;
      for (std::size_t e = 0; e < entries.size(); ++e) {
        if (machines[e].entry_state.empty()) continue;
        ast::Place p;
        p.initial = true;
        p.range = range(doc, *entries[e]);
        std::string label = entry_label(doc, *entries[e]);
        p.name = {keep(places.take(identifier(label, "EntryPoint" + id_of(entries[e]->find("id")).value_or("")),
                                   id_of(entries[e]->find("id")).value_or(""))),
                  p.range};
        p.extra().runs = ast::Name{machines[e].chart.name.text, p.range};
        sfc.places.push_back(std::move(p));
      }
      file.charts.push_back(std::move(sfc));
    }
    for (auto &m : machines)
      if (!m.entry_state.empty()) file.charts.push_back(std::move(m.chart));
  }

  void entry_warnings(Doc &doc, const JsonValue &ep, const std::string &label, const std::string &id, bool several) {
    const JsonValue *min = ep.find("minCardinality"), *max = ep.find("maxCardinality");
    bool free = (!min || min->text == "0") && (!max || max->text == "2147483647");
    if (!free)
      ignored(doc, ep,
              fmt::format("the cardinalities [{}..{}] of entry point '{}' (id {}) are ignored: one agent "
                          "runs a gfec engine",
                          min ? min->text : "0", max ? max->text : "*", label, id));
    const JsonValue *required = ep.find("successRequired");
    if (several && required && required->kind == JsonValue::Kind::Bool && required->boolean)
      ignored(doc, ep,
              fmt::format("'successRequired' of entry point '{}' (id {}) is ignored: the sfc of a plan with "
                          "several entry points never ends by itself",
                          label, id));
  }

  std::size_t file_index(const Doc &doc) const {
    for (std::size_t i = 0; i < result_.program.files.size(); ++i)
      if (result_.program.files[i]->id == doc.file) return i;
    return 0;
  }

  // ------------------------------------------------------------ states and transitions

  /// The references a state holds, in every spelling ALICA's designers have used.
  std::vector<std::pair<std::string, SourceRange>> references(const Doc &doc, const JsonValue &state,
                                                              const std::string &what) {
    std::vector<std::pair<std::string, SourceRange>> refs;
    auto add_string = [&](const JsonValue &v) {
      // Old files join several references with commas in one string.
      std::string text = v.text;
      std::size_t start = 0;
      while (start < text.size()) {
        std::size_t comma = text.find(',', start);
        std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (part.find_first_not_of(' ') != std::string::npos) refs.emplace_back(part, range(doc, v));
        if (comma == std::string::npos) break;
        start = comma + 1;
      }
    };
    if (const JsonValue *wrappers = state.find("confAbstractPlanWrappers"); wrappers && wrappers->is_array())
      for (const auto &w : wrappers->items) {
        if (!w.is_object()) continue;
        if (const JsonValue *ap = w.find("abstractPlan"); ap && ap->is_string()) {
          // A wrapper exists to run one plan or behaviour: empty, it names nothing ALICA could load.
          if (ap->text.find_first_not_of(' ') == std::string::npos)
            diag_.error(range(doc, *ap), ErrorKind::AlicaReference,
                        fmt::format("{} wraps an empty \"abstractPlan\": ALICA writes a reference as "
                                    "\"File.ext#id\"",
                                    what));
          add_string(*ap);
        }
        if (const JsonValue *km = w.find("keyMapping");
            km && km->is_object() && (non_empty(km->find("input")) || non_empty(km->find("output"))))
          ignored(doc, *km,
                  fmt::format("the blackboard key mapping of '{}' in {} is ignored: gfec has no blackboard",
                              w.string_of("abstractPlan"), what));
        if (const JsonValue *c = w.find("configuration"); non_empty(c))
          ignored(doc, *c,
                  fmt::format("the configuration {}of '{}' in {} is ignored: gfec sub-charts and action "
                              "functions take no parameters",
                              c->is_string() ? "'" + c->text + "' " : "", w.string_of("abstractPlan"), what));
      }
    for (const char *key : {"abstractPlans", "plans"}) {
      const JsonValue *list = state.find(key);
      if (!list) continue;
      if (list->is_string()) add_string(*list);
      if (list->is_array())
        for (const auto &i : list->items)
          if (i.is_string()) add_string(i);
    }
    return refs;
  }

  ast::Place convert_state(Doc &doc, const JsonValue &state, Machine &m, const std::string &plan_what,
                           std::string &gfec_name) {
    ast::Place p;
    p.is_state = true;
    p.range = range(doc, state);
    std::string id = id_of(state.find("id")).value_or("");
    std::string label = label_of(state);
    gfec_name = m.states.take(identifier(label, "State" + id), id);
    p.name = {keep(gfec_name), p.range};
    p.initial = id == m.entry_state;
    std::string what = fmt::format("state '{}' (id {}) of {}", label, id, plan_what);
    element(doc, state, "ALICA " + what);
    std::string type = state.string_of("type");
    const JsonValue *success = state.find("success");
    if (type == "SuccessState" || (type == "TerminalState" && success && success->boolean))
      p.terminal = ast::StateKind::Success;
    else if (type == "FailureState" || type == "TerminalState") p.terminal = ast::StateKind::Failure;
    else if (!type.empty() && type != "State")
      diag_.error(
          range(doc, *state.find("type")), ErrorKind::AlicaFormat,
          fmt::format("unknown state type '{}' of {}: ALICA writes \"State\" or \"TerminalState\"", type, what));

    for (const char *key : {"variableBindings", "parametrisations"})
      if (const JsonValue *v = state.find(key); non_empty(v))
        ignored(doc, *v, fmt::format("the {} of {} are ignored: gfec sub-charts share no variables", key, what));

    std::vector<std::string> extra_plans;
    for (const auto &[text, at] : references(doc, state, what)) {
      auto ref = split_ref(text);
      if (!ref) {
        diag_.error(
            at, ErrorKind::AlicaReference,
            fmt::format("{} holds '{}', which is no reference: ALICA writes them as \"File.ext#id\"", what, text));
        continue;
      }
      std::string ext = extension_of(ref->file.empty() ? doc.path : ref->file);
      if (ext == ".plc") {
        ignored(at, fmt::format("{} holds the placeholder '{}', which is ignored: ALICA picks the "
                                "plan or behaviour behind a placeholder at run time, gfec has nothing to run "
                                "for it",
                                what, text));
        continue;
      }
      if (ext != ".beh" && ext != ".pml" && ext != ".pty") {
        diag_.error(
            at, ErrorKind::AlicaReference,
            fmt::format("{} holds '{}': gfec knows behaviours (.beh), plans (.pml) and plan types (.pty)", what, text));
        continue;
      }
      Target t = resolve(text, doc, at);
      if (!t.object) continue;
      p.has_body = true;
      if (ext == ".beh") {
        ast::Stmt s;
        s.kind = ast::Stmt::Kind::Call;
        s.range = at;
        s.call = call(behaviour(t), at);
        p.action.push_back(std::move(s));
        continue;
      }
      std::string chart = ext == ".pml" ? plan_chart(*t.doc, *t.object, at) : plan_type_chart(t, at);
      if (chart.empty()) continue;
      if (!p.runs()) p.extra().runs = ast::Name{keep(chart), at};
      else extra_plans.push_back(chart);
    }
    if (!extra_plans.empty()) {
      std::string others;
      for (const auto &c : extra_plans) others += (others.empty() ? "'" : ", '") + c + "'";
      ignored(doc, state,
              fmt::format("{} holds several plans; gfec runs only the first, '{}'; ignored: {}", what, p.runs()->text,
                          others));
    }
    if (const JsonValue *post = state.find("postCondition");
        post && post->is_object() && p.terminal != ast::StateKind::Normal)
      p.extra().post = call(condition(doc, *post, label + "_post"), range(doc, *post));
    return p;
  }

  /// ALICA's standard conditions: `true` / `false` for AlwaysTrueCondition / AlwaysFalseCondition;
  /// on the plan a state runs, `succeeded(S)` / `failed(S)` when state S runs an fsm (a state runs
  /// one plan in gfec, so "any" and "all" children agree).
  ast::ExprPtr child_outcome(const JsonValue &cond, const ast::Place *source, const SourceRange &at) {
    std::string name = label_of(cond);
    std::string library = cond.string_of("libraryName");
    if ((name == "AlwaysTrueCondition" || name == "AlwaysFalseCondition") &&
        (library.empty() || library == "alica_standard_library")) {
      // The standard library's constants need no function of the robot library.
      auto e = std::make_unique<ast::Expr>();
      e->kind = ast::Expr::Kind::Bool;
      e->range = at;
      e->bool_value = name == "AlwaysTrueCondition";
      return e;
    }
    bool success = name == "AnyChildSuccess" || name == "AllChildSuccess";
    bool failure = name == "AnyChildFailure" || name == "AllChildFailure";
    if ((!success && !failure) || !source || !source->runs() || !fsm_charts_[std::string(source->runs()->text)])
      return nullptr;
    auto e = call(success ? "succeeded" : "failed", at);
    auto arg = std::make_unique<ast::Expr>();
    arg->kind = ast::Expr::Kind::Name;
    arg->range = at;
    arg->name = {source->name.text, at};
    e->args.push_back(std::move(arg));
    return e;
  }

  /// A standard child condition gfec cannot read from a sub-chart (the state runs behaviours,
  /// whose outcome gfec does not model, or a plan with several entry points, whose sfc never
  /// ends): it stays a sensing function, and the user is told so where it is used.
  void child_outcome_unobserved(const JsonValue &cond, const ast::Place *source, const SourceRange &at,
                                const std::string &what) {
    std::string name = label_of(cond);
    if (name != "AnyChildSuccess" && name != "AllChildSuccess" && name != "AnyChildFailure" &&
        name != "AllChildFailure")
      return;
    std::string state(source ? source->name.text : "?");
    std::string why = source && source->runs()
                          ? fmt::format("the plan it runs, '{}', has several entry points and its sfc never ends",
                                        source->runs()->text)
                      : source && !source->action.empty()
                          ? "it runs no plan, and gfec does not model the success or failure of behaviours"
                          : "it runs neither a plan nor a behaviour";
    ignored(at, fmt::format("{} tests {} of state '{}', but {}: the condition becomes the sensing function '{}()' "
                            "of the robot library",
                            what, name, state, why, name));
  }

  template <typename StateOf>
  void convert_transition(Doc &doc, const JsonValue &t, std::vector<Machine> &machines, const std::vector<int> &owner,
                          const std::vector<std::string> &state_names, StateOf state_of, const std::string &plan_what) {
    std::string id = id_of(t.find("id")).value_or("");
    std::string label = label_of(t);
    std::string what = fmt::format("transition '{}' (id {}) of {}", label, id, plan_what);
    element(doc, t, "ALICA " + what);
    auto from = state_of(t.find("inState")), to = state_of(t.find("outState"));
    for (auto [end, key] : {std::pair{from, "inState"}, std::pair{to, "outState"}})
      if (!end && !not_an_id(doc, t.find(key), fmt::format("the {} of {}", key, what))) {
        diag_.error(range(doc, t), ErrorKind::AlicaReference,
                    fmt::format("{} names {} {}, which the plan has no state for", what, key,
                                id_of(t.find(key)).value_or("(none)")));
      }
    if (!from || !to) return;
    Machine &m = machines[owner[*from]];
    if (owner[*from] != owner[*to]) {
      diag_.error(range(doc, t), ErrorKind::AlicaFormat,
                  fmt::format("{} leads from entry point machine '{}' to machine '{}': gfec machines do not share "
                              "states",
                              what, m.chart.name.text, machines[owner[*to]].chart.name.text));
      return;
    }
    ast::Transition out;
    out.range = range(doc, t);
    if (meaningful(label)) {
      out.named = true;
      out.name = ast::Name{keep(m.transitions.take(identifier(label, "T" + id), id)), out.range};
    }
    out.set_places({ast::Name{keep(state_names[*from]), out.range}}, {ast::Name{keep(state_names[*to]), out.range}});
    const JsonValue *cond = t.find("condition");
    const JsonValue *pre = t.find("preCondition");
    const ast::Place *source = nullptr;
    for (const auto &p : m.chart.places)
      if (p.name.text == state_names[*from]) source = &p;
    if (cond && cond->is_string() && !cond->text.empty()) {
      Target c = resolve(cond->text, doc, range(doc, *cond));
      if (c.object) out.condition = child_outcome(*c.object, source, range(doc, *cond));
      if (c.object && !out.condition) {
        out.condition = call(condition(*c.doc, *c.object, label), range(doc, *cond));
        child_outcome_unobserved(*c.object, source, range(doc, *cond), what);
      }
      // The designer keeps writing a preCondition object beside the reference; it decides nothing,
      // so it gets no function (which would also take a name from the conditions that are used).
      if (pre && pre->is_object())
        condition_warnings(doc, *pre,
                           fmt::format("the transition's \"condition\", '{}', decides when it fires", cond->text));
    } else if (pre && pre->is_object()) {
      out.condition = child_outcome(*pre, source, range(doc, *pre));
      if (!out.condition) {
        out.condition = call(condition(doc, *pre, label), range(doc, *pre));
        child_outcome_unobserved(*pre, source, range(doc, *pre), what);
      }
    }
    if (const JsonValue *sync = t.find("synchronisation"); non_empty(sync))
      ignored(doc, *sync, fmt::format("{} is synchronised with others; the synchronisation is ignored", what));
    if (const JsonValue *km = t.find("keyMapping");
        km && km->is_object() && (non_empty(km->find("input")) || non_empty(km->find("output"))))
      ignored(doc, *km, fmt::format("the blackboard key mapping of {} is ignored: gfec has no blackboard", what));
    m.chart.transitions.push_back(std::move(out));
  }

  const LoadOptions &options_;
  const FileSystem &fs_;
  SourceManager &sources_;
  Diagnostics &diag_;
  LoadResult &result_;
  ast::File *main_ = nullptr;
  /// A made-up name kept for the tree's names to view (ast.h: names own no text).
  std::string_view keep(std::string text) { return main_->strings.emplace_back(std::move(text)); }
  std::map<std::string, std::unique_ptr<Doc>> docs_;
  std::set<std::string> missing_;                          ///< files reported as not found (by the first path tried)
  std::map<std::string, std::vector<std::string>> trees_;  ///< search_below: root -> files below it
  std::set<std::string> trees_listed_;
  std::set<const JsonValue *> plan_type_warned_;    ///< a plan type used by several states warns once
  std::map<std::string, std::string> plan_charts_;  ///< "path#id" -> chart name ("": not converted)
  int plan_depth_ = 0;                              ///< plans being converted, the compiled one first
  std::map<std::string, bool> fsm_charts_;          ///< chart name -> it is an fsm (one entry point)
  std::map<std::string, std::string> functions_;    ///< "path#id" of a behaviour or condition -> function
  NameScope globals_;                               ///< charts and functions share C's namespace
};

}  // namespace

void read_alica_program(const std::string &main_path, std::string text, const LoadOptions &options,
                        const FileSystem &fs, SourceManager &sources, Diagnostics &diag, LoadResult &result) {
  Reader(options, fs, sources, diag, result).read_main(main_path, std::move(text));
}

}  // namespace gfec::alica

namespace gfec {

void annotate_elements(Diagnostics &diag, const LoadResult &loaded) {
  if (loaded.elements.empty()) return;
  // The innermost element holding `r`: elements nest (a plan holds its states).
  auto describe = [&](const SourceRange &r) -> const SourceElement * {
    const SourceElement *best = nullptr;
    for (const auto &e : loaded.elements)
      if (e.range.file == r.file && e.range.begin <= r.begin && r.begin < e.range.end &&
          (!best || e.range.end - e.range.begin < best->range.end - best->range.begin))
        best = &e;
    return best;
  };
  for (Diagnostic &d : diag.all()) {
    // The ALICA reader's own messages name their element already.
    if (d.kind == &kind_info(ErrorKind::Json) || d.kind == &kind_info(ErrorKind::AlicaFormat) ||
        d.kind == &kind_info(ErrorKind::AlicaReference) || d.kind == &kind_info(Warning::AlicaIgnored))
      continue;
    for (auto &n : d.notes)
      if (n.has_range)
        if (const SourceElement *e = describe(n.range)) n.message += fmt::format(" ({})", e->description);
    if (const SourceElement *e = describe(d.range)) d.note(fmt::format("this is {}", e->description));
  }
}

}  // namespace gfec
