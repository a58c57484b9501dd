#include "validate/names.h"

#include <fmt/format.h>

#include <algorithm>
#include <regex>
#include <set>

namespace gfec::validation {

namespace {

// Every name ends up in generated C or C++ (an enum constant, a struct member, a function, a
// class), so a keyword of either language would make that code fail to compile.
const std::set<std::string> kCKeywords = {
    "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum",
    "extern", "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict", "return",
    "short", "signed", "sizeof", "static", "struct", "switch", "typedef", "union", "unsigned", "void",
    "volatile", "while", "_Alignas", "_Alignof", "_Atomic", "_Bool", "_Complex", "_Generic",
    "_Imaginary", "_Noreturn", "_Static_assert", "_Thread_local",
};

const std::set<std::string> kCppKeywords = {
    "alignas", "alignof", "and", "and_eq", "asm", "bitand", "bitor", "bool", "catch", "char16_t",
    "char32_t", "class", "compl", "constexpr", "const_cast", "decltype", "delete", "dynamic_cast",
    "explicit", "export", "false", "friend", "mutable", "namespace", "new", "noexcept", "not",
    "not_eq", "nullptr", "operator", "or", "or_eq", "private", "protected", "public",
    "reinterpret_cast", "static_assert", "static_cast", "template", "this", "thread_local", "throw",
    "true", "try", "typeid", "typename", "using", "virtual", "wchar_t", "xor", "xor_eq",
};

/// Macros and typedefs of the headers a C engine includes (<stdbool.h>, <stdint.h>, <string.h>,
/// <assert.h>, and <stddef.h>, <limits.h>, <float.h> through them on common targets): an
/// interface function or a var named `NULL` or `uint8_t` would be replaced or clash there.
bool is_c_library_name(const std::string &name) {
  static const std::set<std::string> names = {
      "NULL", "EOF", "offsetof", "assert", "errno", "static_assert", "size_t", "ptrdiff_t", "max_align_t",
      "intptr_t", "uintptr_t", "intmax_t", "uintmax_t", "memcpy", "memset", "memcmp", "memmove", "strlen",
      "__bool_true_false_are_defined", "CHAR_BIT", "MB_LEN_MAX", "SIZE_MAX", "PTRDIFF_MIN", "PTRDIFF_MAX",
      "SIG_ATOMIC_MIN", "SIG_ATOMIC_MAX", "WCHAR_MIN", "WCHAR_MAX", "WINT_MIN", "WINT_MAX", "NDEBUG"};
  if (names.count(name)) return true;
  // intN_t, uintN_t, int_leastN_t, int_fastN_t and their INTn_MAX/_MIN/_C macros; <limits.h>'s
  // INT_MAX, UCHAR_MAX, LLONG_MIN...; <float.h>'s FLT_*, DBL_*, LDBL_*.
  static const std::regex patterns(
      "u?int(_least|_fast)?[0-9]+_t|U?INT(_LEAST|_FAST)?[0-9]+_(MAX|MIN|C)|U?INT(PTR|MAX)_(MAX|MIN|C)|"
      "(S|U)?CHAR_(MAX|MIN)|U?(SHRT|INT|LONG|LLONG)_(MAX|MIN)|(FLT|DBL|LDBL)_[A-Z0-9_]+");
  return std::regex_match(name, patterns);
}

} // namespace

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
  }
  return "name";
}

bool check_reserved(const ast::Name &name, Sym kind, Diagnostics &diag) {
  const char *language = kCKeywords.count(name.text) ? "C" : kCppKeywords.count(name.text) ? "C++" : nullptr;
  if (!language && is_c_library_name(name.text)) {
    diag.error(name.range, ErrorKind::ReservedName,
               fmt::format("'{}' is a macro or type of the C headers the engine includes and cannot name {}", name.text,
                           with_article(kind)));
    return false;
  }
  if (!language) return true;
  diag.error(name.range, ErrorKind::ReservedName,
             fmt::format("'{}' is a keyword of {} and cannot name {}", name.text, language, with_article(kind)));
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
  check_reserved(name, kind, diag);
  if (const Symbol *previous = find(name.text)) {
    report_clash(name, kind, *previous, diag);
    return false;
  }
  by_name_.emplace(name.text, symbols_.size());
  symbols_.push_back({kind, index, name.text, name.range});
  return true;
}

const Symbol *Namespace::find(const std::string &name) const {
  auto it = by_name_.find(name);
  return it == by_name_.end() ? nullptr : &symbols_[it->second];
}

std::vector<const Symbol *> Namespace::of(std::initializer_list<Sym> kinds) const {
  std::vector<const Symbol *> out;
  for (const Symbol &s : symbols_)
    if (std::find(kinds.begin(), kinds.end(), s.kind) != kinds.end()) out.push_back(&s);
  return out;
}

} // namespace gfec::validation
