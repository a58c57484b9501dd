#include "cpp_names.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>

namespace gfec::cpp_backend {

const char *cpp_type(model::Type type) {
  switch (type) {
  case model::Type::Bool: return "bool";
  case model::Type::Int: return "int";
  case model::Type::Float: return "float";
  case model::Type::Double: return "double";
  case model::Type::String: return "std::string";
  case model::Type::Object: return "afp::Object";
  case model::Type::Void:
  case model::Type::Duration: break;  // never the type of a parameter or config entry
  }
  return "int";
}

std::string afp_type(model::Type type) {
  switch (type) {
  case model::Type::Bool: return "afp::Type::Bool";
  case model::Type::Int: return "afp::Type::Int";
  case model::Type::Float: return "afp::Type::Float";
  case model::Type::Double: return "afp::Type::Double";
  case model::Type::String: return "afp::Type::String";
  case model::Type::Object: return "afp::Type::Object";
  case model::Type::Void:
  case model::Type::Duration: break;
  }
  return "afp::Type::Int";
}

bool is_reserved(const std::string &word) {
  static const std::set<std::string> words = {
      // C++20's keywords and alternative tokens (a name good for C++17 should stay good later)
      "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case",
      "catch", "char", "char8_t", "char16_t", "char32_t", "class", "compl", "concept", "const", "consteval",
      "constexpr", "constinit", "const_cast", "continue", "co_await", "co_return", "co_yield", "decltype",
      "default", "delete", "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern",
      "false", "float", "for", "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new",
      "noexcept", "not", "not_eq", "nullptr", "operator", "or", "or_eq", "private", "protected", "public",
      "register", "reinterpret_cast", "requires", "return", "short", "signed", "sizeof", "static",
      "static_assert", "static_cast", "struct", "switch", "template", "this", "thread_local", "throw", "true",
      "try", "typedef", "typeid", "typename", "union", "unsigned", "using", "virtual", "void", "volatile",
      "wchar_t", "while", "xor", "xor_eq",
      // macros of the standard library that the runtime's headers pull in
      "NULL", "EOF", "errno", "assert", "stdin", "stdout", "stderr", "offsetof", "EDOM", "ERANGE", "EILSEQ"};
  return words.count(word) > 0;
}

std::string identifier(const std::string &name) {
  std::string id = name;
  while (is_reserved(id)) id += '_';
  return id;
}

std::string class_name(const model::Template &t) { return identifier(t.name); }

std::string outcome_name(const model::Template &t, int outcome) {
  return identifier(t.outcomes.at(static_cast<std::size_t>(outcome)));
}

std::string environment_type(const model::Toolbox &box) { return identifier(box.name); }

std::string toolbox_header(const model::Toolbox &box) {
  std::string stem;
  for (unsigned char c : box.name) stem += static_cast<char>(std::tolower(c));
  return stem + "_toolbox.h";
}

std::string chrono_period(double ms) {
  auto whole = [](double x) { return std::fabs(x - std::round(x)) < 1e-9; };
  if (whole(ms / 1000)) return fmt::format("std::chrono::seconds({})", std::llround(ms / 1000));
  if (whole(ms)) return fmt::format("std::chrono::milliseconds({})", std::llround(ms));
  if (whole(ms * 1000)) return fmt::format("std::chrono::microseconds({})", std::llround(ms * 1000));
  return fmt::format("std::chrono::nanoseconds({})", std::llround(ms * 1e6));
}

std::string NameSpace::take(std::string name) {
  while (taken_.count(name) || is_reserved(name)) name += '_';
  taken_.insert(name);
  return name;
}

MemberNames member_names(const model::Template &t) {
  NameSpace scope;
  for (const char *fixed : {"ctx", "State", "Event"}) scope.claim(fixed);
  scope.claim(class_name(t));
  for (std::size_t k = 0; k < t.outcomes.size(); ++k) scope.claim(outcome_name(t, static_cast<int>(k)));
  MemberNames n;
  for (const auto &p : t.params) n.param.push_back(scope.take(p.name));
  n.env_param = scope.take("ee");
  for (const auto &p : n.param) n.member.push_back(scope.take(p + "_"));
  n.env_member = scope.take(n.env_param + "_");
  return n;
}

std::string template_signature(const model::Template &t) {
  const bool supervisor = t.kind == model::Template::Kind::Supervisor;
  std::string params, outcomes;
  for (const auto &p : t.params)
    params += fmt::format("{}{} {} {}", params.empty() ? "" : ", ", p.dir == model::ParamDir::In ? "in" : "out",
                          model::type_name(p.type), p.name);
  for (const auto &o : t.outcomes) outcomes += (outcomes.empty() ? "" : " | ") + o;
  const char *kind = supervisor ? "supervisor" : t.kind == model::Template::Kind::Computation ? "computation" : "actor";
  std::string s = fmt::format("{} {}({}) {} {}", kind, t.name, params, supervisor ? "events" : "->", outcomes);
  if (t.period_ms > 0) s += fmt::format(" period {}ms", t.period_ms);
  return s + ";";
}

std::string banner(const std::string &source_name, const std::string &what) {
  // A file name cannot be allowed to continue the comment on the next line.
  std::string source = source_name;
  for (char &c : source)
    if (c == '\n' || c == '\r') c = ' ';
  return fmt::format("// Generated by gfec {} from {}: {}.", GFEC_VERSION, source, what);
}

std::string include_guard(const std::string &header_base) {
  std::string g;
  for (unsigned char c : header_base) g += std::isalnum(c) ? static_cast<char>(std::toupper(c)) : '_';
  if (g.empty() || std::isdigit(static_cast<unsigned char>(g[0]))) g = "GFEC_" + g;
  return g;
}

void directive(CodeWriter &w, const std::string &text) { w.raw(text + "\n"); }

} // namespace gfec::cpp_backend
