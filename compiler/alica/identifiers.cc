#include "alica/identifiers.h"

#include <fmt/format.h>

namespace gfec::alica {

namespace {

// gfec's keywords and built-ins (docs/language.md), then C's: a name from either would not
// parse, or would not compile once it reaches the generated C.
const char *const kReserved[] = {
    "sfc", "fsm", "plan", "toolbox", "interface", "import", "var", "const", "initial", "place", "state",
    "transition", "when", "success", "failure", "post", "period", "actor", "computation", "supervisor",
    "supervise", "events", "start", "terminate", "ignore", "config", "in", "out", "entry", "exit", "true",
    "false", "runs", "if", "else", "team", "test", "elapsed", "succeeded", "failed", "active", "agent",
    "tick", "set", "expect", "called", "calls", "status", "bool", "int", "float", "double", "void", "string",
    "object", "auto", "break", "case", "char", "continue", "default", "do", "enum", "extern", "for", "goto",
    "inline", "long", "register", "restrict", "return", "short", "signed", "sizeof", "static", "struct",
    "switch", "typedef", "union", "unsigned", "volatile", "while", "main",
};

bool reserved(const std::string &s) {
  for (const char *r : kReserved)
    if (s == r) return true;
  return false;
}

bool ident_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

} // namespace

bool meaningful(const std::string &name) { return !name.empty() && name != "MISSING_NAME"; }

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
  if (reserved(out)) out += '_';
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

} // namespace gfec::alica
