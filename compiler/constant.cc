#include "constant.h"

#include <fmt/format.h>

#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdlib>

namespace gfec::constant {

using model::Type;

Value Value::of_bool(bool v) {
  Value r;
  r.type = Type::Bool;
  r.b = v;
  return r;
}

Value Value::of_int(std::int32_t v) {
  Value r;
  r.type = Type::Int;
  r.i = v;
  return r;
}

Value Value::of_float(float v) {
  Value r;
  r.type = Type::Float;
  r.f = v;
  return r;
}

Value Value::of_double(double v) {
  Value r;
  r.type = Type::Double;
  r.f = v;
  return r;
}

Value Value::of_string(std::string v) {
  Value r;
  r.type = Type::String;
  r.s = std::move(v);
  return r;
}

Value Value::of_ticks(std::uint64_t v) {
  Value r;
  r.type = Type::Duration;
  r.i = static_cast<std::int64_t>(v);
  return r;
}

Value Value::zero(Type t) {
  switch (t) {
  case Type::Bool: return of_bool(false);
  case Type::Float: return of_float(0);
  case Type::Double: return of_double(0);
  case Type::Duration: return of_ticks(0);
  default: return of_int(0);
  }
}

namespace {

Outcome ok(Value v) { return {std::move(v), Fault::None}; }
Outcome fault(Fault f) { return {Value{}, f}; }

bool is_floating(Type t) { return t == Type::Float || t == Type::Double; }

/// A floating result: rounded to `t` (C computes float operands in float), finite or a fault.
Outcome floating(double v, Type t) {
  if (!std::isfinite(v)) return fault(Fault::NotFinite);
  return ok(t == Type::Float ? Value::of_float(static_cast<float>(v)) : Value::of_double(v));
}

/// An int result computed in 64 bits from 32-bit operands: exact, so a range check decides.
Outcome int_result(std::int64_t v) {
  if (v < INT_MIN || v > INT_MAX) return fault(Fault::IntOverflow);
  return ok(Value::of_int(static_cast<std::int32_t>(v)));
}

Outcome int_arithmetic(BinaryOp op, std::int64_t a, std::int64_t b) {
  switch (op) {
  case BinaryOp::Add: return int_result(a + b);
  case BinaryOp::Sub: return int_result(a - b);
  case BinaryOp::Mul: return int_result(a * b);
  case BinaryOp::Div:
  case BinaryOp::Mod:
    if (b == 0) return fault(Fault::DivisionByZero);
    // INT_MIN / -1 does not fit, and C makes INT_MIN % -1 undefined with it (C11 6.5.5p6),
    // although the remainder 0 would.
    if (a == INT_MIN && b == -1) return fault(Fault::IntOverflow);
    return int_result(op == BinaryOp::Div ? a / b : a % b);  // truncates toward zero, as C99
  default: return fault(Fault::BadOperands);
  }
}

/// Floating arithmetic in `T`: float operands are computed in float, as C does.
template <typename T> Outcome float_arithmetic(BinaryOp op, T a, T b, Type t) {
  switch (op) {
  case BinaryOp::Add: return floating(a + b, t);
  case BinaryOp::Sub: return floating(a - b, t);
  case BinaryOp::Mul: return floating(a * b, t);
  case BinaryOp::Div:
    if (b == 0) return fault(Fault::DivisionByZero);
    return floating(a / b, t);
  default: return fault(Fault::BadOperands);  // `%` takes ints only
  }
}

bool is_comparison(BinaryOp op) {
  return op == BinaryOp::Lt || op == BinaryOp::Le || op == BinaryOp::Gt || op == BinaryOp::Ge || op == BinaryOp::Eq ||
         op == BinaryOp::Ne;
}

}  // namespace

std::optional<std::int32_t> int_literal(std::string_view spelling) {
  if (spelling.empty()) return std::nullopt;
  std::int64_t v = 0;
  for (char c : spelling) {
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + (c - '0');
    if (v > INT_MAX) return std::nullopt;
  }
  return static_cast<std::int32_t>(v);
}

std::optional<double> float_literal(std::string_view spelling) {
  const std::string text(spelling);  // strtod needs the terminating NUL
  char *end = nullptr;
  double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

Type common_type(Type a, Type b) {
  if (a == Type::Double || b == Type::Double) return Type::Double;
  if (a == Type::Float || b == Type::Float) return Type::Float;
  return Type::Int;
}

Outcome convert(const Value &v, Type to) {
  if (v.type == to) return ok(v);
  const bool number = model::is_numeric(v.type);
  switch (to) {
  case Type::Int: {
    if (v.type == Type::Bool) return ok(Value::of_int(v.b ? 1 : 0));
    if (!is_floating(v.type)) break;
    double t = std::trunc(v.f);  // truncation first: -0.9 becomes 0, which fits
    if (!(t >= static_cast<double>(INT_MIN) && t <= static_cast<double>(INT_MAX))) return fault(Fault::DoesNotFit);
    return ok(Value::of_int(static_cast<std::int32_t>(t)));
  }
  case Type::Float:
    if (v.type == Type::Int) return ok(Value::of_float(static_cast<float>(v.i)));
    if (v.type != Type::Double) break;
    // A finite double beyond float's range does not convert (C11 6.3.1.5); one that rounds to
    // the largest float does.
    if (std::isfinite(v.f) && !std::isfinite(static_cast<float>(v.f))) return fault(Fault::DoesNotFit);
    return ok(Value::of_float(static_cast<float>(v.f)));
  case Type::Double:
    if (v.type == Type::Int) return ok(Value::of_double(static_cast<double>(v.i)));
    if (v.type == Type::Float) return ok(Value::of_double(v.f));
    break;
  case Type::String:
    if (number) return ok(Value::of_string(text(v)));
    break;
  case Type::Bool:
    // The validator keeps numbers out of bools; a stray one converts as C's _Bool would.
    if (v.type == Type::Int) return ok(Value::of_bool(v.i != 0));
    if (is_floating(v.type)) return ok(Value::of_bool(v.f != 0));
    break;
  default: break;
  }
  return fault(Fault::BadOperands);
}

Outcome unary(UnaryOp op, const Value &a) {
  if (op == UnaryOp::Not) {
    if (a.type != Type::Bool) return fault(Fault::BadOperands);
    return ok(Value::of_bool(!a.b));
  }
  switch (a.type) {
  case Type::Int: return int_result(-a.i);  // -INT_MIN overflows
  case Type::Float: return ok(Value::of_float(-static_cast<float>(a.f)));
  case Type::Double: return ok(Value::of_double(-a.f));
  default: return fault(Fault::BadOperands);
  }
}

Outcome binary(BinaryOp op, const Value &a, const Value &b) {
  if (op == BinaryOp::And || op == BinaryOp::Or) {
    if (a.type != Type::Bool || b.type != Type::Bool) return fault(Fault::BadOperands);
    return ok(Value::of_bool(op == BinaryOp::And ? a.b && b.b : a.b || b.b));
  }
  if (op == BinaryOp::Add && (a.type == Type::String || b.type == Type::String)) {
    auto x = convert(a, Type::String), y = convert(b, Type::String);
    if (!x || !y) return fault(Fault::BadOperands);
    return ok(Value::of_string(x.value.s + y.value.s));
  }
  if (is_comparison(op) && a.type == Type::Bool && b.type == Type::Bool)
    return ok(Value::of_bool(compare(op, a.b, b.b)));
  if (!model::is_numeric(a.type) || !model::is_numeric(b.type)) return fault(Fault::BadOperands);
  const Type t = common_type(a.type, b.type);
  const Value x = convert(a, t).value, y = convert(b, t).value;  // int to floating always converts
  if (is_comparison(op)) {
    if (t == Type::Int) return ok(Value::of_bool(compare(op, x.i, y.i)));
    return ok(Value::of_bool(compare(op, x.f, y.f)));  // a float's value is exact in a double
  }
  switch (t) {
  case Type::Int: return int_arithmetic(op, x.i, y.i);
  case Type::Float: return float_arithmetic<float>(op, static_cast<float>(x.f), static_cast<float>(y.f), t);
  default: return float_arithmetic<double>(op, x.f, y.f, t);
  }
}

std::string text(const Value &v) {
  switch (v.type) {
  case Type::String: return v.s;
  case Type::Int: return std::to_string(v.i);
  case Type::Bool: return v.b ? "true" : "false";
  case Type::Float: return fmt::format("{}", static_cast<float>(v.f));
  default: return fmt::format("{}", v.f);
  }
}

std::string float_spelling(double f, Type t) {
  std::string s = t == Type::Float ? fmt::format("{}", static_cast<float>(f)) : fmt::format("{}", f);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

const char *describe(Fault f) {
  switch (f) {
  case Fault::None: return "no fault";
  case Fault::IntOverflow: return "integer overflow";
  case Fault::DivisionByZero: return "division by zero";
  case Fault::NotFinite: return "floating-point overflow";
  case Fault::DoesNotFit: return "value does not fit";
  case Fault::BadOperands: return "invalid operands";
  }
  return "?";
}

}  // namespace gfec::constant
