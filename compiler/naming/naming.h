// The naming policy of generated code, in one place: the words C and C++ reserve (C99/C11 and
// C++17/C++20 keywords, the names of the headers the engines include), how a back end makes a
// name unique, and the prefix of numbered temporaries. The validator refuses a reserved word as
// a user's name (check `reserved-name`); the back ends never hand one out for their own names.
#pragma once

#include "name_index.h"

#include <deque>
#include <string>
#include <string_view>

namespace gfec::naming {

/// Why a word cannot name anything in generated code.
enum class Reserved {
  None,
  CKeyword,    ///< a keyword of C99 or C11
  CppKeyword,  ///< a keyword or alternative token of C++17 or C++20 (and not of C)
  CLibrary,    ///< a macro or type of the C headers an engine includes (NULL, uint8_t, INT_MAX, ...)
  CppLibrary,  ///< a macro the C++ runtime's standard headers define (stdin, ERANGE, ...)
};

Reserved reserved(std::string_view word);
inline bool is_reserved(std::string_view word) { return reserved(word) != Reserved::None; }

/// Hands out names that are unique within one name space of generated code, deterministically:
/// a name that is taken or reserved gets a trailing `_` until it is free.
class NameSpace {
public:
  NameSpace() = default;
  /// A scope inside `outer` (a function's locals inside the file's names): its names avoid the
  /// outer ones too, so that no local hides a global the code refers to. `outer` must outlive it.
  explicit NameSpace(const NameSpace *outer) : outer_(outer) {}

  /// A name that cannot move (a user's function, an API name): later take()s avoid it.
  void claim(const std::string &name) { record(name); }
  bool free(const std::string &name) const { return !contains(name) && free_outside(name); }
  std::string take(std::string name);
  /// Reserves the prefix of numbered temporaries (`gfec_t1`, `gfec_t2`, ...): `base`, with `_`
  /// appended while a name claimed or taken here (or outside) is the prefix followed by digits
  /// only. Names taken here afterwards never have that form either.
  const std::string &reserve_numbered_prefix(std::string base);

private:
  /// The name at a position of names_, for the index.
  auto key() const {
    return [this](std::uint32_t k) -> const std::string & { return names_[k]; };
  }
  bool taken(const std::string &name) const { return contains(name) || (outer_ && outer_->taken(name)); }
  bool contains(std::string_view name) const { return index_.find(name, key()) != NameIndex::kNone; }
  /// free() but for this scope's own names, which record() tests as it records.
  bool free_outside(const std::string &name) const {
    return !(outer_ && outer_->taken(name)) && !is_reserved(name) && !numbered(name);
  }
  /// Adds `name` unless this scope holds it already (one probe of the index); says whether it did.
  bool record(const std::string &name) {
    if (index_.insert(name, static_cast<std::uint32_t>(names_.size()), key()) != NameIndex::kNone) return false;
    names_.push_back(name);
    return true;
  }
  bool numbered(const std::string &name) const;
  /// Some name here or outside is `prefix` followed by digits only.
  bool has_numbered(const std::string &prefix) const;

  const NameSpace *outer_ = nullptr;
  // An engine names two things a place (docs/performance.md): the names in a deque, which never
  // moves them, and an index of their positions rather than a std::set's 80-byte nodes.
  std::deque<std::string> names_;
  NameIndex index_;
  std::string prefix_;  ///< the reserved temporaries' prefix; empty: none yet
};

}  // namespace gfec::naming
