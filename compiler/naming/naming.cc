#include "naming/naming.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace gfec::naming {

namespace {

// Hashed, not ordered: every name of a million-place chart is looked up here (docs/performance.md).
// clang-format off
const std::unordered_set<std::string_view> kCKeywords = {
    "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum",
    "extern", "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict", "return",
    "short", "signed", "sizeof", "static", "struct", "switch", "typedef", "union", "unsigned", "void",
    "volatile", "while", "_Alignas", "_Alignof", "_Atomic", "_Bool", "_Complex", "_Generic",
    "_Imaginary", "_Noreturn", "_Static_assert", "_Thread_local",
};
// clang-format on

/// C++20's keywords and alternative tokens beyond C's: a C engine's header is read by C++ code
/// too, and a name good for C++17 should stay good under C++20.
// clang-format off
const std::unordered_set<std::string_view> kCppKeywords = {
    "alignas", "alignof", "and", "and_eq", "asm", "bitand", "bitor", "bool", "catch", "char8_t", "char16_t",
    "char32_t", "class", "compl", "concept", "consteval", "constexpr", "constinit", "const_cast", "co_await",
    "co_return", "co_yield", "decltype", "delete", "dynamic_cast", "explicit", "export", "false", "friend",
    "mutable", "namespace", "new", "noexcept", "not", "not_eq", "nullptr", "operator", "or", "or_eq",
    "private", "protected", "public", "reinterpret_cast", "requires", "static_assert", "static_cast",
    "template", "this", "thread_local", "throw", "true", "try", "typeid", "typename", "using", "virtual",
    "wchar_t", "xor", "xor_eq",
};
// clang-format on

/// `s` begins with `prefix`, which is taken off.
bool eat(std::string_view &s, std::string_view prefix) {
  if (s.substr(0, prefix.size()) != prefix) return false;
  s.remove_prefix(prefix.size());
  return true;
}

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

/// After `int` or `uint`: `(_least|_fast)?N_t` (int8_t, uint_least16_t, int_fast32_t).
bool int_type_rest(std::string_view s) {
  if (!eat(s, "_least")) eat(s, "_fast");
  return s.size() > 2 && s.substr(s.size() - 2) == "_t" && all_digits(s.substr(0, s.size() - 2));
}

/// After `INT` or `UINT`: `_MAX`, `_MIN`, `(PTR|MAX)_(MAX|MIN|C)`, `(_LEAST|_FAST)?N_(MAX|MIN|C)`.
bool int_macro_rest(std::string_view s) {
  auto limit = [](std::string_view x) { return x == "MAX" || x == "MIN" || x == "C"; };
  if (s == "_MAX" || s == "_MIN") return true;
  if (eat(s, "PTR_") || eat(s, "MAX_")) return limit(s);
  if (!eat(s, "_LEAST")) eat(s, "_FAST");
  const auto bar = s.find('_');
  return bar != std::string_view::npos && all_digits(s.substr(0, bar)) && limit(s.substr(bar + 1));
}

/// Macros and typedefs of the headers a C engine includes (<stdbool.h>, <stdint.h>, <string.h>,
/// <assert.h>, and <stddef.h>, <limits.h>, <float.h> through them on common targets): a name
/// `NULL` or `uint8_t` would be replaced or clash there. The families by their first word:
/// intN_t, uintN_t, int_leastN_t, int_fastN_t and their INTn_MAX/_MIN/_C macros; <float.h>'s
/// FLT_*, DBL_*, LDBL_*. Plain code, not <regex>: every name of a large chart passes here.
bool matches_library_pattern(std::string_view name) {
  std::string_view s = name;
  if (eat(s, "uint") || eat(s, "int")) return int_type_rest(s);
  s = name;
  if (eat(s, "UINT") || eat(s, "INT")) return int_macro_rest(s);
  s = name;
  if (eat(s, "FLT_") || eat(s, "DBL_") || eat(s, "LDBL_"))
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
      return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    });
  return false;
}

/// <limits.h>'s limits, <stddef.h>'s and <stdint.h>'s other names, <string.h>'s functions.
// clang-format off
const std::unordered_set<std::string_view> kCLibraryNames = {
    "NULL", "EOF", "offsetof", "assert", "errno", "static_assert", "size_t", "ptrdiff_t", "max_align_t",
    "intptr_t", "uintptr_t", "intmax_t", "uintmax_t", "memcpy", "memset", "memcmp", "memmove", "strlen",
    "__bool_true_false_are_defined", "CHAR_BIT", "MB_LEN_MAX", "SIZE_MAX", "PTRDIFF_MIN", "PTRDIFF_MAX",
    "SIG_ATOMIC_MIN", "SIG_ATOMIC_MAX", "WCHAR_MIN", "WCHAR_MAX", "WINT_MIN", "WINT_MAX", "NDEBUG",
    "CHAR_MAX", "CHAR_MIN", "SCHAR_MAX", "SCHAR_MIN", "UCHAR_MAX", "UCHAR_MIN", "SHRT_MAX", "SHRT_MIN",
    "USHRT_MAX", "USHRT_MIN", "LONG_MAX", "LONG_MIN", "ULONG_MAX", "ULONG_MIN", "LLONG_MAX", "LLONG_MIN",
    "ULLONG_MAX", "ULLONG_MIN",
};
// clang-format on

/// Macros of the standard headers the C++ plan runtime pulls in: ISO C's <stdio.h>, <stdlib.h>,
/// <time.h> and <errno.h> (with the POSIX error numbers C++'s <cerrno> adds), which <string>,
/// <chrono> and <mutex> include with the common standard libraries. An outcome `EOF` would be
/// a number in the class's enumeration.
// clang-format off
const std::unordered_set<std::string_view> kCppLibrary = {
    "stdin", "stdout", "stderr", "EOF", "BUFSIZ", "FILENAME_MAX", "FOPEN_MAX", "L_tmpnam", "SEEK_CUR",
    "SEEK_END", "SEEK_SET", "TMP_MAX", "EXIT_FAILURE", "EXIT_SUCCESS", "MB_CUR_MAX", "RAND_MAX",
    "CLOCKS_PER_SEC", "TIME_UTC", "EDOM", "ERANGE", "EILSEQ", "E2BIG", "EACCES", "EADDRINUSE",
    "EADDRNOTAVAIL", "EAFNOSUPPORT", "EAGAIN", "EALREADY", "EBADF", "EBADMSG", "EBUSY", "ECANCELED",
    "ECHILD", "ECONNABORTED", "ECONNREFUSED", "ECONNRESET", "EDEADLK", "EDESTADDRREQ", "EEXIST", "EFAULT",
    "EFBIG", "EHOSTUNREACH", "EIDRM", "EINPROGRESS", "EINTR", "EINVAL", "EIO", "EISCONN", "EISDIR", "ELOOP",
    "EMFILE", "EMLINK", "EMSGSIZE", "ENAMETOOLONG", "ENETDOWN", "ENETRESET", "ENETUNREACH", "ENFILE",
    "ENOBUFS", "ENODATA", "ENODEV", "ENOENT", "ENOEXEC", "ENOLCK", "ENOLINK", "ENOMEM", "ENOMSG",
    "ENOPROTOOPT", "ENOSPC", "ENOSR", "ENOSTR", "ENOSYS", "ENOTCONN", "ENOTDIR", "ENOTEMPTY",
    "ENOTRECOVERABLE", "ENOTSOCK", "ENOTSUP", "ENOTTY", "ENXIO", "EOPNOTSUPP", "EOVERFLOW", "EOWNERDEAD",
    "EPERM", "EPIPE", "EPROTO", "EPROTONOSUPPORT", "EPROTOTYPE", "EROFS", "ESPIPE", "ESRCH", "ETIME",
    "ETIMEDOUT", "ETXTBSY", "EWOULDBLOCK", "EXDEV",
};
// clang-format on

/// The types of ISO C's headers (C++'s <cstdio>, <ctime>, ...), which a C++ standard library may
/// declare in the global namespace as it does the functions.
// clang-format off
const std::unordered_set<std::string_view> kCLibraryTypes = {
    "FILE", "fpos_t", "div_t", "ldiv_t", "lldiv_t", "clock_t", "time_t", "tm", "timespec", "jmp_buf",
    "va_list", "sig_atomic_t", "fenv_t", "fexcept_t", "imaxdiv_t", "lconv", "mbstate_t", "wint_t",
    "wctrans_t", "wctype_t", "float_t", "double_t",
};
// clang-format on

/// Names gcc and clang define as macros in their GNU modes (g++'s default, and gcc's without
/// -std): the header of a C engine included there would not compile.
const std::unordered_set<std::string_view> kPredefined = {"linux", "unix"};

const std::unordered_set<std::string_view> kCppNamespaces = {"std", "afp"};

bool is_implementation_name(std::string_view word) {
  return word.size() >= 2 && word[0] == '_' && (word[1] == '_' || (word[1] >= 'A' && word[1] <= 'Z'));
}

// clang-format off
const std::vector<EngineName> kEngineNames = {
    {"init", true, false}, {"run", true, false}, {"activation", true, false}, {"state", true, false},
    {"status", true, false}, {"place", true, false}, {"transition", true, false}, {"PLACE_COUNT", true, false},
    {"TRANSITION_COUNT", true, false}, {"HOOKS", true, false}, {"CHECKS", true, false}, {"ASSERT", true, false},
    {"ASSERT_OFF", true, false}, {"activated", true, false}, {"enabled", true, false},
    {"set_agent", true, true}, {"report", true, true}, {"TEAM_SIZE", true, true}, {"team", true, true},
    {"instance", false, false}, {"INSTANCE_COUNT", false, false}, {"instance_activation", false, false},
    {"set_context", false, false}, {"context", false, false}, {"place_name", false, false},
    {"transition_name", false, false},
};
// clang-format on

// clang-format off
const CFunction kCFunctions[] = {
#define GFEC_C_FUNCTION(name, builtin, iso, type, prototype) {#name, builtin, iso, type, prototype},
#include "naming/c_library.def"
#undef GFEC_C_FUNCTION
};
// clang-format on

/// The functions afp's base classes of a toolbox's classes declare (runtime/include/afp/actor.h,
/// supervisor.h) and the skeleton's enumerations (docs/toolbox.md); then what else a name
/// inside the class finds first: the base classes' names and their private members.
// clang-format off
const std::unordered_set<std::string_view> kTemplateMembers = {
    "start", "step", "stop", "check", "compute", "period", "nested_plan", "is_computation", "State", "Event",
};
const std::unordered_set<std::string_view> kTemplateInherited = {"Actor", "Computation", "Supervisor", "state_", "period_"};
// clang-format on

}  // namespace

namespace {

/// Every listed word with what it is, the first list that has it winning (`static_assert` is a
/// keyword of C++ before a macro of <assert.h>): one hash per name, as every name of a
/// million-place chart comes here (docs/performance.md).
const std::unordered_map<std::string_view, Reserved> &listed_words() {
  static const std::unordered_map<std::string_view, Reserved> words = [] {
    std::unordered_map<std::string_view, Reserved> w;
    auto add = [&w](const std::unordered_set<std::string_view> &list, Reserved r) {
      for (std::string_view word : list) w.emplace(word, r);
    };
    add(kCKeywords, Reserved::CKeyword);
    add(kCppKeywords, Reserved::CppKeyword);
    add(kPredefined, Reserved::Predefined);
    w.emplace("main", Reserved::EntryPoint);
    add(kCLibraryNames, Reserved::CLibrary);
    add(kCppLibrary, Reserved::CppLibrary);
    add(kCppNamespaces, Reserved::CppNamespace);
    return w;
  }();
  return words;
}

}  // namespace

Reserved reserved(std::string_view word) {
  const auto &words = listed_words();
  const auto listed = words.find(word);
  // Keywords first (`_Bool` is one), then the compilers' own names (`__bool_true_false_are_defined`
  // begins with `__`), then the headers' names.
  if (listed != words.end() && (listed->second == Reserved::CKeyword || listed->second == Reserved::CppKeyword))
    return listed->second;
  if (is_implementation_name(word)) return Reserved::Implementation;
  if (listed != words.end()) return listed->second;
  if (matches_library_pattern(word)) return Reserved::CLibrary;
  return Reserved::None;
}

std::string unreserved(std::string name) {
  if (is_implementation_name(name)) name.insert(0, "g");
  if (!is_reserved(name)) return name;
  name += '_';
  // <float.h> reserves FLT_, DBL_ and LDBL_ followed by any capitals and '_': no '_' frees one.
  while (is_reserved(name)) name += 'x';
  return name;
}

const std::vector<EngineName> &engine_names() { return kEngineNames; }

const EngineName *engine_name(std::string_view chart, std::string_view name) {
  if (name.size() <= chart.size() + 1 || name.substr(0, chart.size()) != chart || name[chart.size()] != '_')
    return nullptr;
  std::string_view suffix = name.substr(chart.size() + 1);
  // X_init and X_run as the linker sees them (docs/c-engine.md "Header and engine together").
  const std::size_t stamp = suffix.find(kFingerprintInfix);
  if (stamp != std::string_view::npos && suffix.size() == stamp + kFingerprintInfix.size() + 8 &&
      (suffix.substr(0, stamp) == "init" || suffix.substr(0, stamp) == "run"))
    suffix = suffix.substr(0, stamp);
  for (const EngineName &e : kEngineNames)
    if (e.suffix == suffix) return &e;
  return nullptr;
}

const CFunction *c_library_function(std::string_view name) {
  // The table is sorted by name (the script writes it so).
  const auto *end = std::end(kCFunctions);
  const auto *at = std::lower_bound(std::begin(kCFunctions), end, name,
                                    [](const CFunction &f, std::string_view n) { return f.name < n; });
  return at != end && at->name == name ? at : nullptr;
}

std::string c_declaration(const CFunction &f) {
  const std::size_t paren = f.type.find('(');
  if (paren == std::string_view::npos) return std::string(f.name);
  std::string result(f.type.substr(0, paren));
  // `void *(...)` is `void *malloc(...)`: the name follows the star.
  return result + (result.empty() || result.back() == '*' ? "" : " ") + std::string(f.name) +
         std::string(f.type.substr(paren));
}

bool matches(const CFunction &f, std::string_view result, const std::vector<std::string_view> &params) {
  if (f.prototype.empty()) return false;
  const std::string_view expected_result = f.prototype.substr(0, f.prototype.find('('));
  if (f.prototype.substr(expected_result.size()) == "()") {
    // No prototype: C's default argument promotions leave int and double as they are.
    return result == expected_result &&
           std::all_of(params.begin(), params.end(), [](std::string_view p) { return p == "int" || p == "double"; });
  }
  std::string written(result);
  written += '(';
  for (std::size_t i = 0; i < params.size(); ++i) written += std::string(i ? ", " : "") + std::string(params[i]);
  written += params.empty() ? "void)" : ")";
  return written == f.prototype;
}

bool is_c_library_global(std::string_view name) {
  const CFunction *f = c_library_function(name);
  return (f && f->iso) || kCLibraryTypes.count(name);
}

bool is_template_member(std::string_view name) { return kTemplateMembers.count(name) != 0; }

bool is_template_scope_name(std::string_view name) {
  return kTemplateMembers.count(name) != 0 || kTemplateInherited.count(name) != 0;
}

std::string NameSpace::take(std::string name) {
  // Free of reserved words first (a chart FLT's place MAX would be FLT_MAX, which no trailing `_`
  // frees), then of the names taken.
  name = unreserved(std::move(name));
  while (!(free_outside(name) && record(name))) name += '_';
  return name;
}

namespace {

/// `name` is `prefix` followed by one digit or more, and nothing else.
bool numbered_under(const std::string &prefix, const std::string &name) {
  return name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0 &&
         name.find_first_not_of("0123456789", prefix.size()) == std::string::npos;
}

}  // namespace

bool NameSpace::numbered(const std::string &name) const { return !prefix_.empty() && numbered_under(prefix_, name); }

bool NameSpace::has_numbered(const std::string &prefix) const {
  auto scan = std::find_if(scans_.begin(), scans_.end(), [&](const NumberedScan &s) { return s.prefix == prefix; });
  if (scan == scans_.end()) scan = scans_.insert(scans_.end(), NumberedScan{prefix});
  // Only the names added since the last call for this prefix; once found, always found.
  for (; !scan->found && scan->read < names_.size(); ++scan->read)
    scan->found = numbered_under(prefix, names_[scan->read]);
  return scan->found || (outer_ && outer_->has_numbered(prefix));
}

const std::string &NameSpace::reserve_numbered_prefix(std::string base) {
  while (has_numbered(base)) base += '_';
  prefix_ = std::move(base);
  return prefix_;
}

}  // namespace gfec::naming
