// The one evaluator of the language's values with C's semantics (docs/language.md, "Constants";
// docs/architecture.md, "Constants and literal values"). The validator folds constant expressions with it, the
// interpreter computes with it at run time, and the literals' values the model stores come from
// its parsers: compiler, interpreter and generated C can only disagree where C itself would.
//
// Arithmetic happens in the type C's usual arithmetic conversions give: `int` (32 bits), `float`
// (every result rounded to float, as C computes float operands with FLT_EVAL_METHOD 0) or
// `double`. What C leaves undefined — int overflow, INT_MIN / -1 and INT_MIN % -1, division by
// zero — and a floating result that is not a finite number are faults, never values.
#pragma once

#include "model.h"
#include "operators.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gfec::constant {

/// A value of the language; `type` says which member holds it.
struct Value {
  model::Type type = model::Type::Int;
  bool b = false;  ///< Bool
  /// An integer type: the value, always within the type's range (a uint64 above INT64_MAX is kept
  /// as its bit pattern: wide() reads it); Time: milliseconds; Duration (the interpreter): ticks.
  std::int64_t i = 0;
  double f = 0;   ///< Float: always a value a float holds; Double
  std::string s;  ///< String (plan formulas only)

  static Value of_bool(bool v);
  static Value of_int(std::int32_t v);
  static Value of_float(float v);
  static Value of_double(double v);
  static Value of_string(std::string v);
  static Value of_ticks(std::uint64_t v);
  /// A value of integer type `t` (or Time), given as its bit pattern in 64 bits.
  static Value of_integer(model::Type t, std::int64_t bits);
  static Value of_time(std::int64_t ms) { return of_integer(model::Type::Time, ms); }
  /// Zero (false) of type `t`: an unset var, a missing input column.
  static Value zero(model::Type t);
};

/// Wide enough for every integer type's values and for the exact product of two of them.
using Wide = __int128;

/// The mathematical value of an integer (or Time) value.
Wide wide(const Value &v);

/// The values an integer type (or Time) holds.
Wide lowest(model::Type t);
Wide highest(model::Type t);

/// Whether integer type `big` holds every value of integer type `small` (docs/language.md §4).
bool holds(model::Type big, model::Type small);

/// The type two integer types mix in: the one that holds every value of the other; nothing when
/// neither does (an int16 with a uint16, an int with a uint32).
std::optional<model::Type> integer_common(model::Type a, model::Type b);

/// Why an operation has no value.
enum class Fault {
  None,
  IntOverflow,     ///< the integer (or time) result does not fit its type (INT_MIN / -1 and INT_MIN % -1 too)
  DivisionByZero,  ///< `/` or `%` by zero, int or floating
  NotFinite,       ///< a floating result that is an infinity or a NaN
  DoesNotFit,      ///< a conversion to a type that cannot hold the value (3e9 to int, 1e39 to float)
  BadOperands,     ///< operands the validator never lets through (a bool in arithmetic...)
};

struct Outcome {
  Value value;
  Fault fault = Fault::None;
  explicit operator bool() const { return fault == Fault::None; }
};

/// A decimal int literal's value ("010" is 10: chart literals are decimal); nothing if it has
/// characters other than digits or is above INT_MAX.
std::optional<std::int32_t> int_literal(std::string_view spelling);

/// A floating literal's value as C reads it (a double); nothing if it is malformed or beyond
/// double's range (`1e999`).
std::optional<double> float_literal(std::string_view spelling);

/// `v` converted to `to` as C converts on assignment: int to floating rounds, floating to int
/// truncates (DoesNotFit beyond int's range), double to float rounds (DoesNotFit beyond float's
/// range), a number to a string as it would be printed (plan formulas).
Outcome convert(const Value &v, model::Type to);

/// `T(v)`, the language's explicit conversion (model::Expr::Kind::Convert): exact between
/// integer types and between an integer and `time` (milliseconds), rounded to nearest (ties away
/// from zero) from a floating value to an integer, as C converts to a floating type; DoesNotFit
/// where the value is beyond T.
Outcome conversion(const Value &v, model::Type to);

/// C's usual arithmetic conversions: the type `a op b` computes in.
model::Type common_type(model::Type a, model::Type b);

/// `op a`: `!` on a bool, `-` on a number.
Outcome unary(UnaryOp op, const Value &a);

/// `a op b` for arithmetic and comparisons, in the common type; `&&` and `||` on two bools (the
/// caller short-circuits); `+` with a string operand joins text (plan formulas).
Outcome binary(BinaryOp op, const Value &a, const Value &b);

/// `a OP b` for a comparison operator (<, <=, >, >=, ==, !=), both sides of type T: the one
/// comparison of the evaluator and the interpreter.
template <typename T> bool compare(BinaryOp op, T a, T b) {
  switch (op) {
  case BinaryOp::Lt: return a < b;
  case BinaryOp::Le: return a <= b;
  case BinaryOp::Gt: return a > b;
  case BinaryOp::Ge: return a >= b;
  case BinaryOp::Eq: return a == b;
  case BinaryOp::Ne: return a != b;
  default: return false;  // not a comparison
  }
}

/// A standard function `f` (model::Expr::Kind::Builtin) of `args`, each of the type the validator
/// gave them, in the result type `to`: each value operand converted to `to`, then chosen as
/// MatIEC's library chooses (docs/language.md §4, "Standard functions"): max keeps the first of
/// equal values, `limit(mn, x, mx)` is `x > mn ? (x < mx ? x : mx) : mn`, a `mux` selector out of
/// range gives zero of `to`. IntOverflow for `abs` of a type's lowest value.
Outcome standard(model::Expr::Builtin f, const std::vector<Value> &args, model::Type to);

/// An integer value in decimal (a uint64 above INT64_MAX too).
std::string decimal(const Value &v);

/// A value as text: strings as they are, integers in decimal, times as `500ms`, floats with the shortest digits that
/// read back as the same float (or double), bools as `true`/`false`.
std::string text(const Value &v);

/// A floating value as a C floating literal without suffix: the shortest digits that read back
/// as the same value of type `t` (float or double), always with a '.' or an exponent.
std::string float_spelling(double f, model::Type t);

/// A short description of a fault, for messages: "integer overflow", "division by zero", ...
const char *describe(Fault f);

}  // namespace gfec::constant
