#include "naming/naming.h"

#include <regex>
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

/// Macros and typedefs of the headers a C engine includes (<stdbool.h>, <stdint.h>, <string.h>,
/// <assert.h>, and <stddef.h>, <limits.h>, <float.h> through them on common targets): a name
/// `NULL` or `uint8_t` would be replaced or clash there.
/// intN_t, uintN_t, int_leastN_t, int_fastN_t and their INTn_MAX/_MIN/_C macros; <limits.h>'s
/// INT_MAX, UCHAR_MAX, LLONG_MIN...; <float.h>'s FLT_*, DBL_*, LDBL_*.
bool matches_library_pattern(std::string_view name) {
  // One pattern per leading word, which is read off the pattern (its letters before the first
  // bracket): a name that starts with none of them (every place of a large chart) is settled
  // without a regex, a tenth of a large compile's time otherwise.
  static const char *const patterns[] = {
      "int(_least|_fast)?[0-9]+_t",
      "uint(_least|_fast)?[0-9]+_t",
      "INT((_LEAST|_FAST)?[0-9]+_(MAX|MIN|C)|(PTR|MAX)_(MAX|MIN|C)|_(MAX|MIN))",
      "UINT((_LEAST|_FAST)?[0-9]+_(MAX|MIN|C)|(PTR|MAX)_(MAX|MIN|C)|_(MAX|MIN))",
      "CHAR_(MAX|MIN)",
      "SCHAR_(MAX|MIN)",
      "UCHAR_(MAX|MIN)",
      "SHRT_(MAX|MIN)",
      "USHRT_(MAX|MIN)",
      "LONG_(MAX|MIN)",
      "ULONG_(MAX|MIN)",
      "LLONG_(MAX|MIN)",
      "ULLONG_(MAX|MIN)",
      "FLT_[A-Z0-9_]+",
      "DBL_[A-Z0-9_]+",
      "LDBL_[A-Z0-9_]+",
  };
  struct Family {
    std::string_view start;
    std::regex pattern;
  };
  static const std::vector<Family> families = [] {
    std::vector<Family> out;
    for (const char *p : patterns) {
      std::string_view text(p);
      out.push_back({text.substr(0, text.find_first_of("([")), std::regex(p)});
    }
    return out;
  }();
  for (const Family &f : families)
    if (name.substr(0, f.start.size()) == f.start && std::regex_match(name.begin(), name.end(), f.pattern)) return true;
  return false;
}

bool is_c_library_name(std::string_view name) {
  static const std::unordered_set<std::string_view> names = {"NULL",
                                                             "EOF",
                                                             "offsetof",
                                                             "assert",
                                                             "errno",
                                                             "static_assert",
                                                             "size_t",
                                                             "ptrdiff_t",
                                                             "max_align_t",
                                                             "intptr_t",
                                                             "uintptr_t",
                                                             "intmax_t",
                                                             "uintmax_t",
                                                             "memcpy",
                                                             "memset",
                                                             "memcmp",
                                                             "memmove",
                                                             "strlen",
                                                             "__bool_true_false_are_defined",
                                                             "CHAR_BIT",
                                                             "MB_LEN_MAX",
                                                             "SIZE_MAX",
                                                             "PTRDIFF_MIN",
                                                             "PTRDIFF_MAX",
                                                             "SIG_ATOMIC_MIN",
                                                             "SIG_ATOMIC_MAX",
                                                             "WCHAR_MIN",
                                                             "WCHAR_MAX",
                                                             "WINT_MIN",
                                                             "WINT_MAX",
                                                             "NDEBUG"};
  if (names.count(name)) return true;
  return matches_library_pattern(name);
}

/// Macros of the standard headers the C++ plan runtime pulls in (<cstdio>, <cerrno>).
const std::unordered_set<std::string_view> kCppLibrary = {"stdin", "stdout", "stderr", "EDOM", "ERANGE", "EILSEQ"};

}  // namespace

Reserved reserved(std::string_view word) {
  if (kCKeywords.count(word)) return Reserved::CKeyword;
  if (kCppKeywords.count(word)) return Reserved::CppKeyword;
  if (is_c_library_name(word)) return Reserved::CLibrary;
  if (kCppLibrary.count(word)) return Reserved::CppLibrary;
  return Reserved::None;
}

std::string NameSpace::take(std::string name) {
  while (!(free_outside(name) && record(name))) name += '_';
  return name;
}

bool NameSpace::numbered(const std::string &name) const {
  return !prefix_.empty() && name.size() > prefix_.size() && name.compare(0, prefix_.size(), prefix_) == 0 &&
         name.find_first_not_of("0123456789", prefix_.size()) == std::string::npos;
}

bool NameSpace::has_numbered(const std::string &prefix) const {
  // Once an engine (reserve_numbered_prefix): a pass over the names is linear, as the rest.
  for (const std::string &name : names_)
    if (name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0 &&
        name.find_first_not_of("0123456789", prefix.size()) == std::string::npos)
      return true;
  return outer_ && outer_->has_numbered(prefix);
}

const std::string &NameSpace::reserve_numbered_prefix(std::string base) {
  while (has_numbered(base)) base += '_';
  prefix_ = std::move(base);
  return prefix_;
}

}  // namespace gfec::naming
