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

Value Value::of_integer(Type t, std::int64_t bits) {
  Value r;
  r.type = t;
  r.i = bits;
  return r;
}

Value Value::zero(Type t) {
  switch (t) {
  case Type::Bool: return of_bool(false);
  case Type::Float: return of_float(0);
  case Type::Double: return of_double(0);
  case Type::Duration: return of_ticks(0);
  default:
    if (model::is_integer(t) || t == Type::Time) return of_integer(t, 0);
    return of_int(0);
  }
}

Wide wide(const Value &v) {
  if (v.type == Type::UInt64) return static_cast<Wide>(static_cast<std::uint64_t>(v.i));
  return static_cast<Wide>(v.i);
}

Wide lowest(Type t) {
  if (model::is_unsigned(t)) return 0;
  const int bits = model::integer_bits(t);
  return -(static_cast<Wide>(1) << (bits - 1));
}

Wide highest(Type t) {
  const int bits = model::integer_bits(t);
  return (static_cast<Wide>(1) << (model::is_unsigned(t) ? bits : bits - 1)) - 1;
}

bool holds(Type big, Type small) { return lowest(big) <= lowest(small) && highest(big) >= highest(small); }

std::optional<Type> integer_common(Type a, Type b) {
  if (holds(a, b)) return a;
  if (holds(b, a)) return b;
  return std::nullopt;
}

std::string decimal(const Value &v) {
  Wide w = wide(v);
  if (w == 0) return "0";
  const bool negative = w < 0;
  std::string digits;
  for (; w != 0; w /= 10) digits.insert(digits.begin(), static_cast<char>('0' + (negative ? -(w % 10) : w % 10)));
  return negative ? "-" + digits : digits;
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

/// An integer (or time) result computed exactly: a range check decides.
Outcome integer_result(Wide v, Type t) {
  if (v < lowest(t) || v > highest(t)) return fault(Fault::IntOverflow);
  return ok(Value::of_integer(t, static_cast<std::int64_t>(static_cast<std::uint64_t>(v))));
}

/// Arithmetic on two integers of type `t` (Int keeps its own function, above, and C's faults).
Outcome wide_arithmetic(BinaryOp op, Wide a, Wide b, Type t) {
  switch (op) {
  case BinaryOp::Add: return integer_result(a + b, t);
  case BinaryOp::Sub: return integer_result(a - b, t);
  case BinaryOp::Mul: return integer_result(a * b, t);
  case BinaryOp::Div:
  case BinaryOp::Mod:
    if (b == 0) return fault(Fault::DivisionByZero);
    // INT64_MIN % -1 is undefined in C as INT64_MIN / -1 is; narrower types compute in int.
    if (t == Type::Int64 && a == lowest(t) && b == -1) return fault(Fault::IntOverflow);
    return integer_result(op == BinaryOp::Div ? a / b : a % b, t);  // truncates toward zero, as C99
  default: return fault(Fault::BadOperands);
  }
}

/// `a op b` with a time among the operands (docs/language.md §4): time ± time, time * integer,
/// integer * time, time / integer, and the comparisons of two times, in 64-bit milliseconds.
Outcome time_binary(BinaryOp op, const Value &a, const Value &b);

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
  if (model::is_integer(a) && model::is_integer(b))
    if (auto t = integer_common(a, b)) return *t;
  return Type::Int;
}

namespace {

Outcome time_binary(BinaryOp op, const Value &a, const Value &b) {
  const bool ta = a.type == Type::Time, tb = b.type == Type::Time;
  if (is_comparison(op)) {
    if (!ta || !tb) return fault(Fault::BadOperands);
    return ok(Value::of_bool(compare(op, a.i, b.i)));
  }
  switch (op) {
  case BinaryOp::Add:
  case BinaryOp::Sub:
    if (!ta || !tb) break;
    return integer_result(op == BinaryOp::Add ? wide(a) + wide(b) : wide(a) - wide(b), Type::Time);
  case BinaryOp::Mul:
    if (!(ta && model::is_integer(b.type)) && !(tb && model::is_integer(a.type))) break;
    return integer_result(wide(a) * wide(b), Type::Time);
  case BinaryOp::Div:
    if (!ta || !model::is_integer(b.type)) break;
    if (wide(b) == 0) return fault(Fault::DivisionByZero);
    return integer_result(wide(a) / wide(b), Type::Time);  // truncates toward zero, as C99
  default: break;
  }
  return fault(Fault::BadOperands);
}

/// A floating value truncated to integer type `to`, as C converts it.
Outcome truncated(double f, Type to) {
  const double t = std::trunc(f);  // truncation first: -0.9 becomes 0, which fits
  // Every bound of an integer type up to 64 bits is a power of two or one less: compared as
  // doubles, lowest() is exact and highest() + 1 is.
  if (!(t >= static_cast<double>(lowest(to)) && t < static_cast<double>(highest(to) + 1)))
    return fault(Fault::DoesNotFit);
  return ok(Value::of_integer(to, model::is_unsigned(to) ? static_cast<std::int64_t>(static_cast<std::uint64_t>(t))
                                                         : static_cast<std::int64_t>(t)));
}

/// An integer value as a floating one of type `to`, rounded as C converts it.
Value to_floating(const Value &v, Type to) {
  const double d =
      v.type == Type::UInt64 ? static_cast<double>(static_cast<std::uint64_t>(v.i)) : static_cast<double>(v.i);
  if (to == Type::Float) {
    const float f = v.type == Type::UInt64 ? static_cast<float>(static_cast<std::uint64_t>(v.i))
                                           : static_cast<float>(v.i);  // rounded once, as C does
    return Value::of_float(f);
  }
  return Value::of_double(d);
}

}  // namespace

Outcome convert(const Value &v, Type to) {
  if (v.type == to) return ok(v);
  const bool number = model::is_numeric(v.type);
  if (model::is_sized(to) || (to == Type::Int && model::is_sized(v.type))) {
    if (v.type == Type::Bool) return ok(Value::of_integer(to, v.b ? 1 : 0));
    if (model::is_integer(v.type)) {
      if (!(wide(v) >= lowest(to) && wide(v) <= highest(to))) return fault(Fault::DoesNotFit);
      return ok(Value::of_integer(to, static_cast<std::int64_t>(static_cast<std::uint64_t>(wide(v)))));
    }
    if (is_floating(v.type)) return truncated(v.f, to);
    return fault(Fault::BadOperands);
  }
  if ((to == Type::Float || to == Type::Double) && model::is_sized(v.type)) return ok(to_floating(v, to));
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
    if (model::is_integer(v.type)) return ok(Value::of_bool(v.i != 0));
    if (is_floating(v.type)) return ok(Value::of_bool(v.f != 0));
    break;
  default: break;
  }
  return fault(Fault::BadOperands);
}

Outcome conversion(const Value &v, Type to) {
  const bool from_integer = model::is_integer(v.type) || v.type == Type::Time;
  if (model::is_integer(to) || to == Type::Time) {
    if (from_integer) {
      const Wide w = wide(v);
      if (w < lowest(to) || w > highest(to)) return fault(Fault::DoesNotFit);
      return ok(Value::of_integer(to, static_cast<std::int64_t>(static_cast<std::uint64_t>(w))));
    }
    if (is_floating(v.type)) {
      const double r = std::round(v.f);  // ties away from zero
      if (!std::isfinite(r)) return fault(Fault::DoesNotFit);
      return truncated(r, to == Type::Time ? Type::Int64 : to).fault == Fault::None
                 ? ok(Value::of_integer(to, truncated(r, to == Type::Time ? Type::Int64 : to).value.i))
                 : fault(Fault::DoesNotFit);
    }
    return fault(Fault::BadOperands);
  }
  if (to == Type::Float || to == Type::Double) {
    if (is_floating(v.type)) return convert(v, to);
    if (model::is_integer(v.type) || v.type == Type::Time) return ok(to_floating(v, to));
  }
  return fault(Fault::BadOperands);
}

Outcome unary(UnaryOp op, const Value &a) {
  if (op == UnaryOp::Not) {
    if (a.type != Type::Bool) return fault(Fault::BadOperands);
    return ok(Value::of_bool(!a.b));
  }
  if (model::is_sized(a.type) || a.type == Type::Time) return integer_result(-wide(a), a.type);
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
  if (a.type == Type::Time || b.type == Type::Time) return time_binary(op, a, b);
  if (!model::is_numeric(a.type) || !model::is_numeric(b.type)) return fault(Fault::BadOperands);
  const Type t = common_type(a.type, b.type);
  if (model::is_integer(a.type) && model::is_integer(b.type)) {
    // Integers compare and compute as the mathematical values they are: exact, then a range
    // check in the type they mix in (the validator lets only types mix of which one holds the
    // other, so the C of the engine computes the same).
    if (is_comparison(op)) return ok(Value::of_bool(compare(op, wide(a), wide(b))));
    if (t == Type::Int) return int_arithmetic(op, a.i, b.i);
    return wide_arithmetic(op, wide(a), wide(b), t);
  }
  const Value x = convert(a, t).value, y = convert(b, t).value;  // integer to floating always converts
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

namespace {

/// `a < b` in their common type (both of the result type here).
bool less(const Value &a, const Value &b) {
  Outcome r = binary(BinaryOp::Lt, a, b);
  return r && r.value.b;
}

}  // namespace

Outcome standard(model::Expr::Builtin f, const std::vector<Value> &args, Type to) {
  using B = model::Expr::Builtin;
  // The operands chosen among: all but the selector of sel and mux.
  const std::size_t first = f == B::Sel || f == B::Mux ? 1 : 0;
  if (args.size() <= first) return fault(Fault::BadOperands);
  std::vector<Value> v;
  for (std::size_t i = first; i < args.size(); ++i) {
    Outcome c = convert(args[i], to);
    if (!c) return c;
    v.push_back(std::move(c.value));
  }
  switch (f) {
  case B::Abs: {
    if (!less(v[0], Value::zero(to))) return ok(v[0]);  // -0.0 stays -0.0, as in MatIEC's ABS
    return unary(UnaryOp::Neg, v[0]);                   // the lowest value of a type overflows
  }
  case B::Min:
  case B::Max: {
    Value best = v[0];
    for (std::size_t i = 1; i < v.size(); ++i)
      if (f == B::Max ? less(best, v[i]) : less(v[i], best)) best = v[i];
    return ok(best);
  }
  case B::Limit:
    if (v.size() != 3) return fault(Fault::BadOperands);
    return ok(less(v[0], v[1]) ? (less(v[1], v[2]) ? v[1] : v[2]) : v[0]);
  case B::Sel:
    if (v.size() != 2 || args[0].type != Type::Bool) return fault(Fault::BadOperands);
    return ok(args[0].b ? v[1] : v[0]);
  case B::Mux: {
    if (!model::is_integer(args[0].type)) return fault(Fault::BadOperands);
    const Wide k = wide(args[0]);
    if (k < 0 || k >= static_cast<Wide>(v.size())) return ok(Value::zero(to));
    return ok(v[static_cast<std::size_t>(k)]);
  }
  }
  return fault(Fault::BadOperands);
}

std::string text(const Value &v) {
  if (model::is_integer(v.type)) return decimal(v);
  if (v.type == Type::Time) return decimal(v) + "ms";
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
