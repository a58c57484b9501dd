#include "validate/fold.h"

#include "validate/expr.h"

#include <fmt/format.h>

#include <cstdint>

namespace gfec::validation {

namespace {

using model::Type;
using K = model::Expr::Kind;

/// The value the model stores in `e`: a literal's, or the one check_constant() folded.
Value stored(const model::Expr &e) {
  if (model::is_sized(e.type) || e.type == Type::Time) return Value::of_integer(e.type, e.int_value);
  switch (e.type) {
  case Type::Bool: return Value::of_bool(e.bool_value);
  case Type::Int: return Value::of_int(e.int_value);
  case Type::Float: return Value::of_float(static_cast<float>(e.float_value));
  case Type::Double: return Value::of_double(e.float_value);
  default: return Value::of_string(e.text.str());
  }
}

/// Stores `v` in `e` (model.h, Expr::folded).
void store(model::Expr &e, const Value &v) {
  e.folded = true;
  switch (v.type) {
  case Type::Bool: e.bool_value = v.b; break;
  case Type::Float:
  case Type::Double: e.float_value = v.f; break;
  case Type::String: e.text = v.s; break;
  default: e.int_value = v.i; break;  // an integer, a time
  }
}

/// A literal, or an expression already folded: known without evaluating its operands again.
bool known(const model::Expr &e) {
  switch (e.kind) {
  case K::Bool:
  case K::Int:
  case K::Float:
  case K::String:
  case K::Const: return true;
  case K::Paren: return !e.args.empty() && known(e.args[0]);
  default: return e.folded;
  }
}

/// A value, or the fault reported at `at` as the validator words it.
std::optional<Value> checked(const constant::Outcome &r, SourceRange at, Diagnostics *diag) {
  if (r) return r.value;
  if (!diag) return std::nullopt;
  switch (r.fault) {
  case constant::Fault::IntOverflow:
    diag->error(at, ErrorKind::NotConstant, "integer overflow in constant expression");
    break;
  case constant::Fault::DivisionByZero:
    diag->error(at, ErrorKind::NotConstant, "division by zero in constant expression");
    break;
  case constant::Fault::NotFinite:
    diag->error(at, ErrorKind::NotConstant, "floating-point overflow in constant expression");
    break;
  default: break;  // operands the type checks reported already
  }
  return std::nullopt;
}

std::optional<Value> binary(const model::Expr &e, const model::Model &m, Diagnostics *diag) {
  auto a = evaluate(e.args[0], m, diag);
  // && and || short-circuit as in C, so `false && Sensor()` is constant too.
  if (a && a->type == Type::Bool && ((e.binary_op == BinaryOp::And && !a->b) || (e.binary_op == BinaryOp::Or && a->b)))
    return a;
  auto b = evaluate(e.args[1], m, diag);
  if (!a || !b) return std::nullopt;
  return checked(constant::binary(e.binary_op, *a, *b), e.range, diag);
}

}  // namespace

std::optional<Value> evaluate(const model::Expr &e, const model::Model &m, Diagnostics *diag) {
  if (e.folded) return stored(e);
  switch (e.kind) {
  case K::Bool: return Value::of_bool(e.bool_value);
  case K::Int:
  case K::Float: return stored(e);  // the value number_literal() parsed
  case K::String: return Value::of_string(e.text.str());
  case K::Const:
    if (!m.consts.contains(e.constant())) return std::nullopt;
    return evaluate(m.consts[e.constant()].value, m, diag);
  case K::Paren: return e.args.empty() ? std::nullopt : evaluate(e.args[0], m, diag);
  case K::Unary: {
    if (e.args.size() != 1) return std::nullopt;
    auto a = evaluate(e.args[0], m, diag);
    if (!a) return std::nullopt;
    return checked(constant::unary(e.unary_op, *a), e.range, diag);
  }
  case K::Binary: return e.args.size() == 2 ? binary(e, m, diag) : std::nullopt;
  case K::Convert: {
    if (e.args.size() != 1) return std::nullopt;
    auto a = evaluate(e.args[0], m, diag);
    if (!a) return std::nullopt;
    auto r = constant::conversion(*a, e.type);
    if (!r && diag && r.fault == constant::Fault::DoesNotFit)
      diag->error(e.range, ErrorKind::NotConstant,
                  fmt::format("value {} does not fit in '{}'", constant::text(*a), model::type_name(e.type)));
    if (!r) return std::nullopt;
    return r.value;
  }
  case K::Builtin: {
    std::vector<Value> args;
    for (const auto &a : e.args) {
      auto v = evaluate(a, m, diag);
      if (!v) return std::nullopt;
      args.push_back(std::move(*v));
    }
    return checked(constant::standard(e.builtin, args, e.type), e.range, diag);
  }
  default: return std::nullopt;  // runs on the robot: a var, a call, a timer, a config entry
  }
}

/// Whether a floating literal's digits before its exponent are other than zeros.
static bool has_nonzero_mantissa(std::string_view spelling) {
  for (char c : spelling) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') return true;
  }
  return false;
}

std::optional<model::Expr> number_literal(const ast::Expr &e, Diagnostics &diag) {
  model::Expr x;
  x.range = e.range;
  x.text = e.text();
  if (e.kind == ast::Expr::Kind::Int) {
    x.kind = K::Int;
    x.type = Type::Int;
    if (auto v = constant::int_literal(e.text())) {
      x.int_value = *v;
      return x;
    }
    // Beyond int: an int64 literal, which only a type that holds it takes (expr.cc,
    // retype_constant; docs/language.md §4).
    constant::Wide big = 0;  // chart text has at most 18 digits; an IEC LINT literal up to INT64_MAX
    bool digits = !e.text().empty();
    for (char c : e.text()) {
      digits = digits && c >= '0' && c <= '9' && big <= INT64_MAX;
      if (digits) big = big * 10 + (c - '0');
    }
    digits = digits && big <= INT64_MAX;
    if (!digits) {
      diag.error(e.range, ErrorKind::NotConstant,
                 fmt::format("integer constant '{}' is too large for 'int'", e.text()));
      return std::nullopt;
    }
    x.type = Type::Int64;
    x.int_value = static_cast<std::int64_t>(big);
    return x;
  }
  auto v = constant::float_literal(e.text());
  if (!v) {
    diag.error(e.range, ErrorKind::NotConstant,
               fmt::format("floating constant '{}' is too large for 'double'", e.text()));
    return std::nullopt;
  }
  // `1e-999` reads as 0, which C compilers refuse to do silently ("floating constant truncated
  // to zero"): the same rule as for a constant too large.
  if (*v == 0 && has_nonzero_mantissa(e.text())) {
    diag.error(e.range, ErrorKind::NotConstant,
               fmt::format("floating constant '{}' is too small for 'double': it would be 0", e.text()));
    return std::nullopt;
  }
  x.kind = K::Float;
  x.type = Type::Double;  // a floating literal is a double, as in C
  x.float_value = *v;
  return x;
}

std::optional<model::Expr> check_constant(std::optional<model::Expr> x, const model::Model &m, Diagnostics &diag) {
  if (!x || x->kind == K::Int || x->kind == K::Float) return x;
  for (const auto &a : x->args)
    if (!known(a)) return x;  // not constant: evaluated on the robot
  std::size_t errors = diag.error_count();
  auto v = evaluate(*x, m, &diag);
  if (diag.error_count() != errors) return std::nullopt;
  if (v) store(*x, *v);
  return x;
}

bool underflows_float(const Value &v, model::Type to) {
  return to == Type::Float && v.type == Type::Double && v.f != 0 && static_cast<float>(v.f) == 0.0f;
}

std::optional<model::Expr> to_literal(const Value &v, model::Type to, SourceRange range, Diagnostics &diag,
                                      const model::Expr *spelling) {
  model::Expr e;
  e.type = to;
  e.range = range;
  if (to == Type::Bool && v.type == Type::Bool) {
    e.kind = K::Bool;
    e.bool_value = v.b;
    return e;
  }
  if (to == Type::Time) {
    if (v.type != Type::Time) return std::nullopt;  // the caller reported the type mismatch
    e.kind = K::Int;
    e.int_value = v.i;
    e.text = constant::text(v);
    return e;
  }
  if (!(model::is_numeric(to) && model::is_numeric(v.type)) && to != Type::String)
    return std::nullopt;  // the caller reported the type mismatch
  auto c = constant::convert(v, to);
  if (!c && model::is_sized(to)) {
    if (c.fault == constant::Fault::DoesNotFit)
      diag.error(range, ErrorKind::NotConstant,
                 fmt::format("value {} does not fit in '{}'", constant::text(v), model::type_name(to)));
    return std::nullopt;
  }
  if (!c) {
    if (c.fault == constant::Fault::DoesNotFit)
      diag.error(
          range, ErrorKind::NotConstant,
          fmt::format(to == Type::Int ? "value {} does not fit in 'int'" : "value {} is too large for 'float'", v.f));
    return std::nullopt;
  }
  if (underflows_float(v, to)) {
    diag.error(range, ErrorKind::NotConstant, fmt::format("value {} is too small for 'float': it would be 0", v.f));
    return std::nullopt;
  }
  const Value &w = c.value;
  if (model::is_sized(to)) {
    e.kind = K::Int;
    e.int_value = w.i;
    e.text = constant::decimal(w);
    return e;
  }
  switch (to) {
  case Type::Int:
    e.kind = K::Int;
    e.int_value = static_cast<std::int32_t>(w.i);
    e.text = std::to_string(w.i);
    break;
  case Type::Float:
  case Type::Double:
    e.kind = K::Float;
    // A literal the user wrote keeps its spelling, so generated code shows `0.6` rather than
    // `0.59999999999999998`; its value is the spelling's (converted to `to` where it is read).
    if (spelling && spelling->kind == K::Float && !spelling->folded) {
      e.text = spelling->text;
      e.float_value = spelling->float_value;
    } else {
      e.text = constant::float_spelling(w.f, to);
      e.float_value = w.f;
    }
    break;
  default:
    e.kind = K::String;
    e.text = w.s;
    break;
  }
  return e;
}

const model::Expr *fold_const(Context &cx, model::ConstId index) {
  using State = ConstSource::State;
  if (!cx.consts.contains(index)) return nullptr;
  ConstSource &src = cx.consts[index];
  model::Const &c = cx.model.consts[index];
  switch (src.state) {
  case State::Done: return &c.value;
  case State::Failed: return nullptr;
  case State::Busy:
    cx.diag.error(src.decl->name.range, ErrorKind::NotConstant,
                  fmt::format("constant '{}' is defined in terms of itself", c.name));
    src.state = State::Failed;
    return nullptr;
  case State::Pending: break;
  }
  // A chart's constants are only visible inside that chart, so it is the one being validated.
  ChartScope *chart = c.chart ? cx.chart : nullptr;
  if (c.chart && (!chart || chart->index != c.chart)) return nullptr;
  // Folding recurses through the constants an initialiser reads: bound it, never the stack.
  if (cx.const_depth >= kMaxConstDepth) {
    cx.diag.error(src.decl->name.range, ErrorKind::NotConstant,
                  fmt::format("constant '{}' is defined through more than {} other constants", c.name, kMaxConstDepth));
    src.state = State::Failed;
    return nullptr;
  }
  ++cx.const_depth;
  src.state = State::Busy;
  std::size_t errors = cx.diag.error_count();
  ExprScope scope{cx, chart, true};
  std::optional<model::Expr> literal;
  if (auto e = lower_initializer(src.decl->init.get(), scope, c.type, c.name)) {
    if (auto v = evaluate(*e, cx.model, &cx.diag)) literal = to_literal(*v, c.type, e->range, cx.diag, &*e);
    if (!literal && cx.diag.error_count() == errors)
      cx.diag.error(e->range, ErrorKind::NotConstant,
                    fmt::format("initializer of '{}' is not a constant expression", c.name));
  }
  --cx.const_depth;
  if (src.state == State::Failed) return nullptr;  // a cycle through it was reported meanwhile
  src.state = literal ? State::Done : State::Failed;
  if (!literal) return nullptr;
  c.value = std::move(*literal);
  return &c.value;
}

}  // namespace gfec::validation
