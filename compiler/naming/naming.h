// The naming policy of generated code, in one place: the words C and C++ reserve (C99/C11 and
// C++17/C++20 keywords, the names of the headers the engines include, the compilers' own), the
// names a C engine defines for its caller, the C library's functions, how a back end makes a
// name unique, and the prefix of numbered temporaries. The validator refuses a reserved word as
// a user's name (check `reserved-name`); the back ends never hand one out for their own names.
#pragma once

#include "name_index.h"

#include <deque>
#include <string>
#include <string_view>
#include <vector>

namespace gfec::naming {

/// Why a word cannot name anything in generated code.
enum class Reserved {
  None,
  CKeyword,        ///< a keyword of C99 or C11
  CppKeyword,      ///< a keyword or alternative token of C++17 or C++20 (and not of C)
  Implementation,  ///< begins with `__` or `_` and a capital: C and C++ keep these for the compiler
                   ///< and its library (__LINE__, __func__, _Pragma, _Exit)
  Predefined,      ///< a macro gcc and clang predefine in their default GNU modes (linux, unix)
  EntryPoint,      ///< `main`, the program's
  CLibrary,        ///< a macro or type of the C headers an engine includes (NULL, uint8_t, INT_MAX, ...)
  CppLibrary,      ///< a macro the C++ runtime's standard headers define (stdin, ERANGE, EOF, ...)
  CppNamespace,    ///< a namespace generated C++ refers to (std, afp)
};

Reserved reserved(std::string_view word);
inline bool is_reserved(std::string_view word) { return reserved(word) != Reserved::None; }

/// `name` itself or, reserved, with a trailing `_` (`delete_`); a name C keeps for the compiler
/// (`__x`, `_X`) first gets a `g` in front, and one <float.h> still reserves (`FLT_MAX_`) an `x`
/// after the `_`: no number of `_` would free either.
std::string unreserved(std::string name);

/// A name a C engine of chart X defines for its caller as `X_<suffix>` (docs/c-engine.md): the
/// API, the enumerations' types and counts, the hooks and the macros. They are the contract and
/// never move: the validator refuses an interface function with one of these names, and a place
/// or transition whose constant `X_<name>` would be one that every engine has.
struct EngineName {
  std::string_view suffix;
  bool always;  ///< every engine has it (a team machine's: every team machine's); else only some
                ///< (sub-charts, --context, --names), and a constant that clashes moves aside
  bool team;    ///< a team machine's (docs/c-engine.md "Team machines")
};
const std::vector<EngineName> &engine_names();
/// What the header puts between X_init (X_run) and the fingerprint in the names the linker sees
/// (docs/c-engine.md "Header and engine together").
inline constexpr std::string_view kFingerprintInfix = "_regenerate_if_undefined_";
/// The engine name `name` is for chart `chart` (`P_init` for `P`, and `P_init` with a
/// fingerprint), or null.
const EngineName *engine_name(std::string_view chart, std::string_view name);

/// A function of the C library (compiler/naming/c_library.def, which tools/c-library-names.py
/// writes by asking gcc and clang).
struct CFunction {
  std::string_view name;
  bool builtin;                ///< gcc or clang know it: a declaration with another prototype draws a warning
  bool iso;                    ///< ISO C's: C++'s standard headers may declare it in the global namespace
  std::string_view type;       ///< as the compilers know it, `double(double)`; "" if they do not say
  std::string_view prototype;  ///< the one gfec can write that matches it, "" if none; `int()` for
                               ///< one without a prototype (parameters int or double match it)
};
const CFunction *c_library_function(std::string_view name);
/// `double fabs(double)`: the function's C type written as its declaration.
std::string c_declaration(const CFunction &f);
/// The prototype gfec writes (`result` and `params` spelt as docs/language.md spells the types:
/// bool, int, float, double, void) is the library's, so that no compiler warns about it.
bool matches(const CFunction &f, std::string_view result, const std::vector<std::string_view> &params);
/// A name C++'s standard headers may declare in the global namespace, where the classes of a
/// toolbox live: a function or type of ISO C's library (`time`, `abs`, `FILE`, `tm`).
bool is_c_library_global(std::string_view name);

/// What the classes of a toolbox's templates (docs/toolbox.md) declare besides their own names:
/// the functions of afp::Actor, afp::Computation and afp::Supervisor and the skeleton's
/// enumerations (State, Event). A template so named would be its own member; a result state or
/// event so named, a second member of that name.
bool is_template_member(std::string_view name);
/// What a name used inside a template's class finds before a global class: its members, and the
/// names it inherits from afp (the base classes' own names and private members too). The
/// toolbox's environment type is used there, so the toolbox cannot have one of these names.
bool is_template_scope_name(std::string_view name);

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
  /// Room for `count` more names without rehashing (NameIndex::reserve): the C back end takes
  /// one name a place and one a transition, two million for a large chart.
  void reserve(std::size_t count) { index_.reserve(names_.size() + count); }
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

  /// How far has_numbered() has read names_ for one prefix, and whether it found such a name.
  /// Names are only ever added, so a later call for that prefix reads only the names added
  /// since: the C back end asks once per sub-chart instance, in the scope of the whole file,
  /// and a pass over every name each time grew with the square of the instances.
  struct NumberedScan {
    std::string prefix;
    std::size_t read = 0;
    bool found = false;
  };

  const NameSpace *outer_ = nullptr;
  // An engine names two things a place (docs/performance.md): the names in a deque, which never
  // moves them, and an index of their positions rather than a std::set's 80-byte nodes.
  std::deque<std::string> names_;
  NameIndex index_;
  std::string prefix_;  ///< the reserved temporaries' prefix; empty: none yet
  /// By prefix asked for (a few: `gfec_t`, then `gfec_t_` if that one is taken, ...); a cache
  /// that has_numbered() extends, so it changes nothing that the name space says.
  mutable std::vector<NumberedScan> scans_;
};

}  // namespace gfec::naming
