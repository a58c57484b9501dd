// Namespaces of declared names: duplicate detection, lookup, and the names gfec may not use
// because generated C or C++ would not compile.
#pragma once

#include "ast.h"
#include "diagnostics.h"
#include "id.h"
#include "name_index.h"
#include "name_uses.h"

#include <cassert>
#include <cstdint>
#include <deque>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace gfec::validation {

/// "function", "place", "config entry", ... as a message says it.
const char *describe(Sym kind);
/// "a place", "an actor": the kind with its article.
std::string with_article(Sym kind);

/// A symbol's index for element `id` of a model table: -1 for none (a declaration with an error).
template <typename Tag> int symbol_index(Id<Tag> id) { return id ? static_cast<int>(id.index()) : -1; }

class Symbol {
public:
  Symbol(Sym kind, int index, std::string_view name, SourceRange range)
      : name_(name.data()), name_size_(static_cast<std::uint32_t>(name.size())), index(index), range(range),
        kind(kind) {}

  /// Views the text of the declaring ast::Name (or, in a list of did-you-mean candidates, a
  /// string that outlives the list): source text and the tree's strings outlive the validator.
  std::string_view name() const { return {name_, name_size_}; }
  /// The element the symbol names, as the id of its model table (the kind says which).
  template <typename IdT> IdT id() const {
    assert(index >= 0);
    return IdT(static_cast<std::size_t>(index));
  }

private:
  // A pointer and a 32-bit size rather than a std::string_view: 32 bytes a symbol, not 40, in
  // a chart that declares two million (docs/performance.md).
  const char *name_;
  std::uint32_t name_size_;

public:
  int index = -1;  ///< into the model table the kind belongs to
  SourceRange range;
  Sym kind;
};

/// One namespace: names in declaration order, the first declaration winning lookups.
class Namespace {
public:
  /// Declares `name`, which must outlive the namespace and stay in place: the symbol views its
  /// text (a node of the syntax tree, never a temporary). A clash is reported (with a note at
  /// the first declaration) and returns false; so does an empty name, which only a recovered
  /// syntax error produces.
  bool declare(const ast::Name &name, Sym kind, int index, Diagnostics &diag);
  /// The same, for the element `id` of a model table (none: its declaration has an error).
  template <typename Tag> bool declare(const ast::Name &name, Sym kind, Id<Tag> id, Diagnostics &diag) {
    return declare(name, kind, symbol_index(id), diag);
  }
  const Symbol *find(std::string_view name) const;
  /// find(name.text), and the use recorded in `uses` when found: every lookup of a name the
  /// user wrote goes through here, so a language server sees what it refers to.
  const Symbol *resolve(const ast::Name &name) const;
  /// Room for `count` more names (NameIndex::reserve).
  void reserve(std::size_t count) { index_.reserve(symbols_.size() + count); }
  /// The symbols of the given kinds in declaration order: did-you-mean candidates.
  std::vector<const Symbol *> of(std::initializer_list<Sym> kinds) const;

  /// Where declarations and resolved uses are recorded (ValidateOptions::name_uses); null: nowhere.
  NameUses *uses = nullptr;

private:
  /// The name at a symbol number, for the index.
  auto key() const {
    return [this](std::uint32_t k) { return symbols_[k].name(); };
  }

  // A chart may declare a million names (docs/performance.md): a symbol views its name in the
  // syntax tree instead of copying it (a deque keeps the symbols in place), and the index holds
  // symbol numbers (name_index.h).
  std::deque<Symbol> symbols_;
  NameIndex index_;
};

/// Reports (check `reserved-name`) a name that generated C or C++ reserves (compiler/naming/:
/// a keyword of C99/C11 or C++17/C++20, a name of the standard headers the engines include) and
/// returns false; generated code names things after the user's names.
/// The chart language's built-in functions (docs/language.md §1): no declaration may take their
/// names, and a misspelt call is offered the nearest.
inline constexpr std::string_view kBuiltinFunctions[] = {"elapsed", "active", "succeeded", "failed",
                                                         "team",    "agent",  "now"};

bool check_reserved(const ast::Name &name, Sym kind, Diagnostics &diag);

/// Reports a clash with `previous` as `duplicate-name`: the same message `declare` gives.
void report_clash(const ast::Name &name, Sym kind, const Symbol &previous, Diagnostics &diag);

}  // namespace gfec::validation
