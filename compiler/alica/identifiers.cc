#include "alica/identifiers.h"

#include <fmt/format.h>

namespace gfec::alica {

namespace {

// gfec's keywords and built-ins (docs/language.md), then C's and C++'s, the names the C engine
// defines itself and a few of the C headers it includes: a name from any of them would not
// parse, or the validator would refuse it, or it would not compile once it reaches the
// generated code. ALICA allows them all ("init" is a common state name).
// clang-format off
const char *const kReserved[] = {
    "sfc", "fsm", "plan", "toolbox", "interface", "import", "var", "const", "initial", "place", "state",
    "transition", "when", "success", "failure", "post", "period", "actor", "computation", "supervisor",
    "supervise", "events", "start", "terminate", "ignore", "config", "in", "out", "entry", "exit", "true",
    "false", "runs", "if", "else", "team", "test", "elapsed", "succeeded", "failed", "active", "agent",
    "tick", "set", "expect", "called", "calls", "status", "bool", "int", "float", "double", "void", "string",
    "object", "auto", "break", "case", "char", "continue", "default", "do", "enum", "extern", "for", "goto",
    "inline", "long", "register", "restrict", "return", "short", "signed", "sizeof", "static", "struct",
    "switch", "typedef", "union", "unsigned", "volatile", "while", "main",
    // C++ (the C++ back end) and C11
    "alignas", "alignof", "and", "and_eq", "asm", "bitand", "bitor", "catch", "char16_t", "char32_t", "class",
    "compl", "constexpr", "const_cast", "decltype", "delete", "dynamic_cast", "explicit", "export", "friend",
    "mutable", "namespace", "new", "noexcept", "not", "not_eq", "nullptr", "operator", "or", "or_eq", "private",
    "protected", "public", "reinterpret_cast", "static_assert", "static_cast", "template", "this",
    "thread_local", "throw", "try", "typeid", "typename", "using", "virtual", "wchar_t", "xor", "xor_eq",
    // the engine's own members and constants
    "init", "run", "activation", "PLACE_COUNT", "HOOKS", "CHECKS", "activated", "enabled", "TRANSITION_COUNT",
    "set_agent", "report", "TEAM_SIZE",
    // the C headers' macros and types most likely to be a plan's word
    "NULL", "EOF", "assert", "errno", "offsetof", "size_t", "ptrdiff_t", "memcpy", "memset", "memcmp",
    "memmove", "strlen", "NDEBUG",
};
// clang-format on

bool reserved(const std::string &s) {
  for (const char *r : kReserved)
    if (s == r) return true;
  return false;
}

bool ident_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

}  // namespace

bool meaningful(const std::string &name) {
  // The designers write MISSING_NAME, or the element's id as its name, when the user gave none.
  return !name.empty() && name != "MISSING_NAME" && name.find_first_not_of("0123456789") != std::string::npos;
}

std::string identifier(const std::string &text, const std::string &fallback) {
  std::string out;
  bool replaced = false;
  for (char c : text) {
    if (ident_char(c)) {
      out += c;
      replaced = false;
    } else if (!replaced) {
      out += '_';
      replaced = true;
    }
  }
  if (!meaningful(text) || out.empty() || out == "_") return fallback;
  if (out[0] >= '0' && out[0] <= '9') out = "N" + out;
  // <stdint.h>'s intN_t / uintN_t family is reserved as well.
  bool int_type = out.size() > 5 && out.compare(out.size() - 2, 2, "_t") == 0 &&
                  (out.rfind("int", 0) == 0 || out.rfind("uint", 0) == 0);
  if (reserved(out) || int_type) out += '_';
  return out;
}

std::string NameScope::take(const std::string &name, const std::string &id) {
  std::string chosen = name;
  if (used_.count(chosen)) {
    std::string digits = id.empty() || id[0] != '-' ? id : id.substr(1);
    chosen = digits.empty() ? name : fmt::format("{}_{}", name, digits);
    for (int n = 2; used_.count(chosen); ++n) chosen = fmt::format("{}_{}", name, n);
  }
  used_.insert(chosen);
  return chosen;
}

}  // namespace gfec::alica
