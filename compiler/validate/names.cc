#include "validate/names.h"

#include "naming/naming.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <set>

namespace gfec::validation {

std::string with_article(Sym kind) {
  std::string what = describe(kind);
  bool vowel = std::string("aeiou").find(what[0]) != std::string::npos;
  return (vowel ? "an " : "a ") + what;
}

const char *describe(Sym kind) {
  switch (kind) {
  case Sym::Interface: return "interface";
  case Sym::Function: return "function";
  case Sym::Param: return "parameter";
  case Sym::Const: return "constant";
  case Sym::Chart: return "chart";
  case Sym::Place: return "place";
  case Sym::State: return "state";
  case Sym::Transition: return "transition";
  case Sym::Var: return "variable";
  case Sym::Toolbox: return "toolbox";
  case Sym::Template: return "template";
  case Sym::TemplateParam: return "parameter";
  case Sym::ResultState: return "result state";
  case Sym::Event: return "event";
  case Sym::Plan: return "plan";
  case Sym::ConfigEntry: return "config entry";
  case Sym::Actor: return "actor";
  case Sym::Supervisor: return "supervisor";
  case Sym::Block: return "block";
  case Sym::Instance: return "block instance";
  }
  return "name";
}

bool check_reserved(const ast::Name &name, Sym kind, Diagnostics &diag) {
  // Every name ends up in generated C or C++ (an enum constant, a struct member, a function, a
  // class), so a word either language reserves would make that code fail to compile.
  // The built-in functions cannot be declared again (docs/language.md §1): a variable `active`
  // would make `active(P)` read as a call of it. A parameter's name is only documentation of a
  // prototype, never read by a chart: `void Report(bool failed)` stays valid.
  const bool parameter = kind == Sym::Param || kind == Sym::TemplateParam;
  for (std::string_view builtin : kBuiltinFunctions)
    if (!parameter && name.text == builtin) {
      diag.error(name.range, ErrorKind::ReservedName,
                 fmt::format("'{}' is built into the chart language and cannot name {}", builtin, with_article(kind)));
      return false;
    }
  const char *what = nullptr;
  switch (naming::reserved(name.text)) {
  case naming::Reserved::None: return true;
  case naming::Reserved::CKeyword: what = "a keyword of C"; break;
  case naming::Reserved::CppKeyword: what = "a keyword of C++"; break;
  case naming::Reserved::Implementation:
    what = name.text[1] == '_' ? "reserved for the C and C++ compilers (it begins with '__')"
                               : "reserved for the C and C++ compilers (it begins with '_' and a capital)";
    break;
  case naming::Reserved::Predefined: what = "a macro gcc and clang predefine (in their default GNU modes)"; break;
  case naming::Reserved::EntryPoint: what = "the entry point of a C or C++ program"; break;
  case naming::Reserved::CLibrary: what = "a macro or type of the C headers the engine includes"; break;
  case naming::Reserved::CppLibrary: what = "a macro of the C++ standard headers a plan includes"; break;
  case naming::Reserved::CppNamespace: what = "a namespace the C++ of a plan refers to"; break;
  }
  diag.error(name.range, ErrorKind::ReservedName,
             fmt::format("'{}' is {} and cannot name {}", name.text, what, with_article(kind)));
  return false;
}

void report_clash(const ast::Name &name, Sym kind, const Symbol &previous, Diagnostics &diag) {
  if (previous.kind == kind) {
    diag.error(name.range, ErrorKind::DuplicateName, fmt::format("redefinition of {} '{}'", describe(kind), name.text))
        .note(previous.range, fmt::format("previous definition of '{}' was here", name.text));
  } else {
    diag.error(name.range, ErrorKind::DuplicateName,
               fmt::format("{} '{}' has the same name as {}", describe(kind), name.text, with_article(previous.kind)))
        .note(previous.range, fmt::format("{} '{}' declared here", describe(previous.kind), name.text));
  }
}

bool Namespace::declare(const ast::Name &name, Sym kind, int index, Diagnostics &diag) {
  if (name.text.empty()) return false;
  if (uses) uses->list.push_back({name.range, name.range, kind, index});
  check_reserved(name, kind, diag);
  const std::uint32_t previous = index_.insert(name.text, static_cast<std::uint32_t>(symbols_.size()), key());
  if (previous != NameIndex::kNone) {
    report_clash(name, kind, symbols_[previous], diag);
    return false;
  }
  symbols_.emplace_back(kind, index, name.text, name.range);
  return true;
}

const Symbol *Namespace::find(std::string_view name) const {
  std::uint32_t k = index_.find(name, key());
  return k == NameIndex::kNone ? nullptr : &symbols_[k];
}

const Symbol *Namespace::resolve(const ast::Name &name) const {
  const Symbol *sym = find(name.text);
  if (sym && uses) uses->list.push_back({name.range, sym->range, sym->kind, sym->index});
  return sym;
}

std::vector<const Symbol *> Namespace::of(std::initializer_list<Sym> kinds) const {
  std::vector<const Symbol *> out;
  for (const Symbol &s : symbols_)
    if (std::find(kinds.begin(), kinds.end(), s.kind) != kinds.end()) out.push_back(&s);
  return out;
}

}  // namespace gfec::validation
