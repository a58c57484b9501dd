#include "validate/types.h"

#include "input_languages.h"
#include "validate/context.h"
#include "validate/suggest.h"

#include <fmt/format.h>

namespace gfec::validation {

namespace {

struct TypeEntry {
  const char *name;
  model::Type type;
  TypeSet bit;
};

const TypeEntry kTypes[] = {
    {"bool", model::Type::Bool, kBool},       {"int", model::Type::Int, kInt},
    {"float", model::Type::Float, kFloat},    {"double", model::Type::Double, kDouble},
    {"void", model::Type::Void, kVoid},       {"string", model::Type::String, kString},
    {"object", model::Type::Object, kObject},
};

}  // namespace

std::string quoted(model::Type t) { return fmt::format("'{}'", model::type_name(t)); }

std::optional<model::Type> lower_type(const ast::TypeName &t, unsigned allowed, const char *use, Diagnostics &diag) {
  if (t.text.empty()) return std::nullopt;  // the parser already reported it
  for (const TypeEntry &e : kTypes) {
    if (t.text != e.name) continue;
    if (allowed & e.bit) return e.type;
    diag.error(t.range, ErrorKind::BadType, fmt::format("type '{}' is not allowed for {}", t.text, use));
    return std::nullopt;
  }
  // Offer only the types this declaration could have used.
  std::vector<Symbol> names;
  for (const TypeEntry &e : kTypes)
    if (allowed & e.bit) names.push_back({Sym::Param, -1, e.name, {}});
  std::vector<const Symbol *> candidates;
  for (const Symbol &s : names) candidates.push_back(&s);
  auto &d = diag.error(t.range, ErrorKind::UnknownType, fmt::format("unknown type name '{}'", t.text));
  if (const Symbol *s = closest(t.text, candidates))
    d.fix(t.range, s->name()).note(fmt::format("did you mean '{}'?", s->name()));
  return std::nullopt;
}

model::Type promote(model::Type a, model::Type b) {
  using model::Type;
  if (a == Type::Double || b == Type::Double) return Type::Double;
  if (a == Type::Float || b == Type::Float) return Type::Float;
  return Type::Int;
}

std::optional<model::Type> unary_type(UnaryOp op, model::Type t) {
  if (op == UnaryOp::Not) return t == model::Type::Bool ? std::optional(t) : std::nullopt;
  return model::is_numeric(t) ? std::optional(t) : std::nullopt;
}

std::optional<model::Type> binary_type(BinaryOp op, model::Type a, model::Type b) {
  using model::Type;
  bool numbers = model::is_numeric(a) && model::is_numeric(b);
  bool durations = a == Type::Duration && b == Type::Duration;
  switch (op) {
  case BinaryOp::Mul:
  case BinaryOp::Div:
  case BinaryOp::Add:
  case BinaryOp::Sub:
    if (numbers) return promote(a, b);
    return std::nullopt;
  case BinaryOp::Mod:
    if (a == Type::Int && b == Type::Int) return Type::Int;
    return std::nullopt;
  case BinaryOp::Lt:
  case BinaryOp::Le:
  case BinaryOp::Gt:
  case BinaryOp::Ge:
    if (numbers || durations) return Type::Bool;
    return std::nullopt;
  case BinaryOp::Eq:
  case BinaryOp::Ne:
    if (numbers || durations || (a == Type::Bool && b == Type::Bool)) return Type::Bool;
    return std::nullopt;
  case BinaryOp::And:
  case BinaryOp::Or:
    if (a == Type::Bool && b == Type::Bool) return Type::Bool;
    return std::nullopt;
  }
  return std::nullopt;
}

bool assignable(model::Type to, model::Type from) {
  if (model::is_numeric(to)) return model::is_numeric(from);
  if (to == model::Type::Duration || to == model::Type::Void) return false;
  return to == from;
}

std::string written_operator(const ast::Expr &e, const SourceManager &sources) {
  const char *c = e.kind == ast::Expr::Kind::Unary ? spelling(e.unary_op) : spelling(e.binary_op);
  const SourceRange &r = e.op_range();
  if (r.end <= r.begin || !sources.knows(r.file)) return c;
  const SourceFile &file = sources.file(r.file);
  if (file.language().chart_text || r.end > file.text().size()) return c;
  return file.text().substr(r.begin, r.end - r.begin);
}

}  // namespace gfec::validation
