#include "alica/identifiers.h"

#include "alica/json_tree.h"

#include "naming/naming.h"

#include <fmt/format.h>

namespace gfec::alica {

namespace {

// gfec's keywords and built-ins (docs/language.md): a name from them would not parse, or the
// validator would refuse it. The words C, C++ and the C headers reserve, and the names every C
// engine defines (a state `init` would be the constant `X_init`), are the validator's
// (naming::is_reserved, naming::engine_names), so that a name is renamed here exactly when the
// validator would refuse it. ALICA allows them all ("init" is a common state name).
// clang-format off
const char *const kReserved[] = {
    "sfc", "fsm", "plan", "toolbox", "interface", "import", "var", "const", "initial", "place", "state",
    "transition", "when", "success", "failure", "post", "period", "actor", "computation", "supervisor",
    "supervise", "events", "start", "terminate", "ignore", "config", "in", "out", "entry", "exit", "true",
    "false", "runs", "if", "else", "team", "test", "elapsed", "succeeded", "failed", "active", "agent",
    "tick", "set", "expect", "called", "calls", "status", "bool", "int", "float", "double", "void", "string",
    "object", "main",
};
// clang-format on

bool reserved(const std::string &s) {
  if (naming::is_reserved(s)) return true;
  for (const naming::EngineName &e : naming::engine_names())
    if (e.always && s == e.suffix) return true;
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

std::string label_of(const JsonValue &v) {
  std::string name = v.string_of("name");
  return meaningful(name) ? name : "";
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
  // naming::unreserved moves a name C reserves (`_Bool`, `FLT_MAX`) to one it does not; a name
  // that is only gfec's (an engine API word) takes a '_'.
  if (reserved(out)) out = naming::is_reserved(out) ? naming::unreserved(out) : out + '_';
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
