#include "validate/types.h"

#include "constant.h"
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
    {"object", model::Type::Object, kObject}, {"time", model::Type::Time, kTime},
    {"int8", model::Type::Int8, kSized},      {"int16", model::Type::Int16, kSized},
    {"int64", model::Type::Int64, kSized},    {"uint8", model::Type::UInt8, kSized},
    {"uint16", model::Type::UInt16, kSized},  {"uint32", model::Type::UInt32, kSized},
    {"uint64", model::Type::UInt64, kSized},
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

model::Type promote(model::Type a, model::Type b) { return constant::common_type(a, b); }

std::optional<model::Type> unary_type(UnaryOp op, model::Type t) {
  if (op == UnaryOp::Not) return t == model::Type::Bool ? std::optional(t) : std::nullopt;
  if (t == model::Type::Time || t == model::Type::Duration) return model::Type::Time;
  return model::is_numeric(t) ? std::optional(t) : std::nullopt;
}

namespace {

bool is_time(model::Type t) { return t == model::Type::Time || t == model::Type::Duration; }

bool comparison_op(BinaryOp op) {
  return op == BinaryOp::Lt || op == BinaryOp::Le || op == BinaryOp::Gt || op == BinaryOp::Ge || op == BinaryOp::Eq ||
         op == BinaryOp::Ne;
}

/// `time OP x` (§4): time ± time, time * integer, integer * time, time / integer and the
/// comparisons of two times. Two durations (no `time` among them) compare in whole ticks and are
/// not for this function.
std::optional<model::Type> time_type(BinaryOp op, model::Type a, model::Type b) {
  using model::Type;
  switch (op) {
  case BinaryOp::Add:
  case BinaryOp::Sub:
    if (is_time(a) && is_time(b)) return Type::Time;
    return std::nullopt;
  case BinaryOp::Mul:
    if ((is_time(a) && model::is_integer(b)) || (model::is_integer(a) && is_time(b))) return Type::Time;
    return std::nullopt;
  case BinaryOp::Div:
    if (is_time(a) && model::is_integer(b)) return Type::Time;
    return std::nullopt;
  case BinaryOp::Lt:
  case BinaryOp::Le:
  case BinaryOp::Gt:
  case BinaryOp::Ge:
  case BinaryOp::Eq:
  case BinaryOp::Ne:
    if (is_time(a) && is_time(b)) return Type::Bool;
    return std::nullopt;
  default: return std::nullopt;
  }
}

}  // namespace

std::optional<model::Type> binary_type(BinaryOp op, model::Type a, model::Type b) {
  using model::Type;
  if ((is_time(a) || is_time(b)) && !(a == Type::Duration && b == Type::Duration && comparison_op(op)))
    return time_type(op, a, b);
  bool numbers = model::is_numeric(a) && model::is_numeric(b);
  bool durations = a == Type::Duration && b == Type::Duration;
  // Two integer types mix only when one holds every value of the other (docs/language.md §4).
  if (model::is_integer(a) && model::is_integer(b) && !constant::integer_common(a, b)) return std::nullopt;
  switch (op) {
  case BinaryOp::Mul:
  case BinaryOp::Div:
  case BinaryOp::Add:
  case BinaryOp::Sub:
    if (numbers) return promote(a, b);
    return std::nullopt;
  case BinaryOp::Mod:
    if (model::is_integer(a) && model::is_integer(b)) return promote(a, b);
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
  if (to == model::Type::Time) return from == model::Type::Time || from == model::Type::Duration;
  // An integer takes another only when it holds all its values; a floating value only `int`
  // takes, truncated, as C does (a sized integer takes it through a conversion, §4).
  if (model::is_integer(to) && model::is_integer(from)) return constant::holds(to, from);
  if (model::is_sized(to)) return false;
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
