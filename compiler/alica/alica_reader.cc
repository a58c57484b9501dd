// The ALICA reader's entry points, and the reading of the main plan from start to end: the
// conversion itself is in plans.cc and states.cc, finding files in plan_files.cc
// (reader_context.h says which file holds what).
#include "alica/alica_reader.h"

#include "alica/identifiers.h"
#include "alica/reader_context.h"
#include "escape.h"
#include "input_languages.h"

#include <fmt/format.h>

#include <algorithm>

namespace gfec::alica {

void Reader::read_main(const std::string &path, std::string text) {
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
    s = text::printable(s);
  };
  for (std::size_t i = first_diagnostic; i < diag_.all().size(); ++i) {
    clean(diag_.all()[i].message);
    for (auto &n : diag_.all()[i].notes) clean(n.message);
  }
  for (auto &e : result_.elements) clean(e.description);
}

void Reader::read_plan(const std::string &path, std::string text) {
  Doc *doc = files_.open(normal_path(path), std::move(text));
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

/// A member named twice in one object, in every file read: JSON leaves its meaning open, and
/// ALICA's tools disagree (its engine reads the first, its designer keeps the last). gfec reads
/// the first; when it read that member and the second says otherwise, what gfec makes of the
/// plan would differ from what the designer shows, so that is an error (docs/alica.md).
/// After the plan is read, since only then is it known which members gfec looked up.
void Reader::duplicate_members() {
  for (const Doc *doc : files_.parsed()) duplicate_members(*doc, *doc->root);
}

void Reader::duplicate_members(const Doc &doc, const JsonValue &v) {
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
bool Reader::not_an_id(const Doc &doc, const JsonValue *v, const std::string &what) {
  if (!v || v->is_null() || id_of(v)) return false;
  std::string written = sources_.file(doc.file).text().substr(v->begin, std::min<std::uint32_t>(v->end - v->begin, 40));
  diag_.error(range(doc, *v), ErrorKind::AlicaFormat,
              fmt::format("{} is {}, which is no id: ALICA's ids are 64-bit integers", what, written));
  return true;
}

void read_alica_program(const std::string &main_path, std::string text, const LoadOptions &options,
                        const FileSystem &fs, SourceManager &sources, Diagnostics &diag, LoadResult &result) {
  Reader(options, fs, sources, diag, result).read_main(main_path, std::move(text));
}

}  // namespace gfec::alica

namespace gfec {

void annotate_elements(Diagnostics &diag, const LoadResult &loaded, std::size_t first) {
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
  for (std::size_t i = first; i < diag.all().size(); ++i) {
    Diagnostic &d = diag.all()[i];
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
