#include "validate/fold.h"

#include "validate/expr.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace gfec::validation {

namespace {

using model::Type;

// Generated code computes in C's `int`, which is 32 bits on every target gfec supports.
constexpr long long kIntMin = INT32_MIN;
constexpr long long kIntMax = INT32_MAX;

std::optional<Value> fail(Diagnostics *diag, SourceRange at, const char *message) {
  if (diag) diag->error(at, ErrorKind::NotConstant, message);
  return std::nullopt;
}

std::optional<Value> int_value(long long x, SourceRange at, Diagnostics *diag) {
  if (x < kIntMin || x > kIntMax) return fail(diag, at, "integer overflow in constant expression");
  Value v;
  v.type = Type::Int;
  v.i = x;
  return v;
}

Value bool_value(bool b) {
  Value v;
  v.type = Type::Bool;
  v.b = b;
  return v;
}

double as_double(const Value &v) { return v.type == Type::Int ? static_cast<double>(v.i) : v.f; }

/// A double as a C floating literal: shortest round-trip digits, always with '.' or an exponent.
std::string float_text(double f) {
  std::string s = fmt::format("{}", f);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

/// A value as text, for string concatenation and number-to-string conversion.
std::string as_text(const Value &v) {
  switch (v.type) {
  case Type::String: return v.s;
  case Type::Int: return std::to_string(v.i);
  case Type::Bool: return v.b ? "true" : "false";
  default: return fmt::format("{}", v.f);
  }
}

std::optional<Value> compare(BinaryOp op, const Value &a, const Value &b) {
  int order;
  if (a.type == Type::Bool) order = static_cast<int>(a.b) - static_cast<int>(b.b);
  else if (a.type == Type::Int && b.type == Type::Int) order = (a.i > b.i) - (a.i < b.i);
  else order = (as_double(a) > as_double(b)) - (as_double(a) < as_double(b));
  switch (op) {
  case BinaryOp::Lt: return bool_value(order < 0);
  case BinaryOp::Le: return bool_value(order <= 0);
  case BinaryOp::Gt: return bool_value(order > 0);
  case BinaryOp::Ge: return bool_value(order >= 0);
  case BinaryOp::Eq: return bool_value(order == 0);
  case BinaryOp::Ne: return bool_value(order != 0);
  default: return std::nullopt;
  }
}

std::optional<Value> arithmetic(const model::Expr &e, const Value &a, const Value &b, Diagnostics *diag) {
  BinaryOp op = e.binary_op;
  if (op == BinaryOp::Add && (a.type == Type::String || b.type == Type::String)) {
    Value v;
    v.type = Type::String;
    v.s = as_text(a) + as_text(b);
    return v;
  }
  bool zero = b.type == Type::Int ? b.i == 0 : b.f == 0;
  if ((op == BinaryOp::Div || op == BinaryOp::Mod) && zero)
    return fail(diag, e.range, "division by zero in constant expression");
  if (a.type == Type::Int && b.type == Type::Int) {
    switch (op) {
    case BinaryOp::Add: return int_value(a.i + b.i, e.range, diag);
    case BinaryOp::Sub: return int_value(a.i - b.i, e.range, diag);
    case BinaryOp::Mul: return int_value(a.i * b.i, e.range, diag);
    case BinaryOp::Div: return int_value(a.i / b.i, e.range, diag);
    case BinaryOp::Mod: return int_value(a.i % b.i, e.range, diag);
    default: return std::nullopt;
    }
  }
  Value v;
  v.type = e.type;
  double x = as_double(a), y = as_double(b);
  switch (op) {
  case BinaryOp::Add: v.f = x + y; break;
  case BinaryOp::Sub: v.f = x - y; break;
  case BinaryOp::Mul: v.f = x * y; break;
  case BinaryOp::Div: v.f = x / y; break;
  default: return std::nullopt;
  }
  if (!std::isfinite(v.f)) return fail(diag, e.range, "floating-point overflow in constant expression");
  return v;
}

std::optional<Value> binary(const model::Expr &e, const model::Model &m, Diagnostics *diag) {
  auto a = evaluate(e.args[0], m, diag);
  // && and || short-circuit as in C, so `false && Sensor()` is constant too.
  if (a && a->type == Type::Bool && ((e.binary_op == BinaryOp::And && !a->b) || (e.binary_op == BinaryOp::Or && a->b)))
    return a;
  auto b = evaluate(e.args[1], m, diag);
  if (!a || !b) return std::nullopt;
  switch (e.binary_op) {
  case BinaryOp::And:
  case BinaryOp::Or: return b;  // `a` did not decide, so `b` does
  case BinaryOp::Lt:
  case BinaryOp::Le:
  case BinaryOp::Gt:
  case BinaryOp::Ge:
  case BinaryOp::Eq:
  case BinaryOp::Ne: return compare(e.binary_op, *a, *b);
  default: return arithmetic(e, *a, *b, diag);
  }
}

std::optional<Value> unary(const model::Expr &e, const model::Model &m, Diagnostics *diag) {
  auto a = evaluate(e.args[0], m, diag);
  if (!a) return std::nullopt;
  if (e.unary_op == UnaryOp::Not) return bool_value(!a->b);
  if (a->type == Type::Int) return int_value(-a->i, e.range, diag);
  a->f = -a->f;
  return a;
}

} // namespace

std::optional<Value> evaluate(const model::Expr &e, const model::Model &m, Diagnostics *diag) {
  using K = model::Expr::Kind;
  Value v;
  v.type = e.type;
  switch (e.kind) {
  case K::Bool: return bool_value(e.bool_value);
  case K::Int: {
    long long x = std::strtoll(e.text.c_str(), nullptr, 10);
    if (x > kIntMax) {
      if (diag) diag->error(e.range, ErrorKind::NotConstant, fmt::format("integer constant '{}' is too large for 'int'", e.text));
      return std::nullopt;
    }
    v.i = x;
    return v;
  }
  case K::Float: v.f = std::strtod(e.text.c_str(), nullptr); return v;
  case K::String: v.s = e.text; return v;
  case K::Const:
    if (e.index < 0 || e.index >= static_cast<int>(m.consts.size())) return std::nullopt;
    return evaluate(m.consts[e.index].value, m, diag);
  case K::Paren: return e.args.empty() ? std::nullopt : evaluate(e.args[0], m, diag);
  case K::Unary: return e.args.size() == 1 ? unary(e, m, diag) : std::nullopt;
  case K::Binary: return e.args.size() == 2 ? binary(e, m, diag) : std::nullopt;
  default: return std::nullopt;  // runs on the robot: a var, a call, a timer, a config entry
  }
}

std::optional<model::Expr> check_constant(std::optional<model::Expr> x, const model::Model &m, Diagnostics &diag) {
  if (!x) return x;
  for (const auto &a : x->args)
    if (!evaluate(a, m, nullptr)) return x;  // not constant: evaluated on the robot
  std::size_t errors = diag.error_count();
  auto v = evaluate(*x, m, &diag);
  if (diag.error_count() != errors) return std::nullopt;
  if (v && x->kind == model::Expr::Kind::Float && !std::isfinite(v->f)) {
    diag.error(x->range, ErrorKind::NotConstant, fmt::format("floating constant '{}' is too large for 'double'", x->text));
    return std::nullopt;
  }
  return x;
}

std::optional<model::Expr> to_literal(const Value &v, model::Type to, SourceRange range, Diagnostics &diag,
                                      const model::Expr *spelling) {
  using K = model::Expr::Kind;
  model::Expr e;
  e.type = to;
  e.range = range;
  if (to == Type::Bool && v.type == Type::Bool) {
    e.kind = K::Bool;
    e.bool_value = v.b;
  } else if (to == Type::Int && model::is_numeric(v.type)) {
    double x = as_double(v);  // C converts by truncation toward zero
    if (v.type != Type::Int && (x < kIntMin || x > kIntMax)) {
      diag.error(range, ErrorKind::NotConstant, fmt::format("value {} does not fit in 'int'", x));
      return std::nullopt;
    }
    e.kind = K::Int;
    e.text = std::to_string(v.type == Type::Int ? v.i : static_cast<long long>(x));
  } else if ((to == Type::Float || to == Type::Double) && model::is_numeric(v.type)) {
    e.kind = K::Float;
    e.text = spelling && spelling->kind == K::Float ? spelling->text : float_text(as_double(v));
  } else if (to == Type::String) {
    e.kind = K::String;
    e.text = as_text(v);
  } else {
    return std::nullopt;  // the caller reported the type mismatch
  }
  return e;
}

const model::Expr *fold_const(Context &cx, int index) {
  using State = ConstSource::State;
  if (index < 0 || index >= static_cast<int>(cx.consts.size())) return nullptr;
  ConstSource &src = cx.consts[index];
  model::Const &c = cx.model.consts[index];
  switch (src.state) {
  case State::Done: return &c.value;
  case State::Failed: return nullptr;
  case State::Busy:
    cx.diag.error(src.decl->name.range, ErrorKind::NotConstant, fmt::format("constant '{}' is defined in terms of itself", c.name));
    src.state = State::Failed;
    return nullptr;
  case State::Pending: break;
  }
  // A chart's constants are only visible inside that chart, so it is the one being validated.
  ChartScope *chart = c.chart >= 0 ? cx.chart : nullptr;
  if (c.chart >= 0 && (!chart || chart->index != c.chart)) return nullptr;
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
      cx.diag.error(e->range, ErrorKind::NotConstant, fmt::format("initializer of '{}' is not a constant expression", c.name));
  }
  --cx.const_depth;
  if (src.state == State::Failed) return nullptr;  // a cycle through it was reported meanwhile
  src.state = literal ? State::Done : State::Failed;
  if (!literal) return nullptr;
  c.value = std::move(*literal);
  return &c.value;
}

} // namespace gfec::validation
