#include "c_expr.h"

#include "c_form.h"
#include "constant.h"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <utility>

namespace gfec::c_backend {

namespace {

using model::Expr;
using model::Type;

// Binding strength of what an expression renders to: binary operators use precedence() (1-7).
constexpr int kUnary = 90;
constexpr int kPrimary = 100;

struct Rendered {
  Rendered() = default;
  // Not explicit: `return {"true"};` reads well.
  Rendered(std::string t, int p = kPrimary, std::vector<std::string> b = {})
      : text(std::move(t)), prec(p), before(std::move(b)) {}

  std::string text;
  int prec = kPrimary;
  /// Assignments to temporaries that must be evaluated before `text`, in this order (c_expr.h).
  std::vector<std::string> before;
};

std::string bracket(const std::string &s) { return "(" + s + ")"; }

/// `r` as one expression: its assignments first, by the comma operator.
Rendered closed(Rendered r) {
  if (r.before.empty()) return r;
  std::string s = "(";
  for (const auto &b : r.before) s += "(void)(" + b + "), ";  // void: the value is meant to go (clang's -Wcomma)
  return {s + r.text + ")"};
}

bool is_floating(Type t) { return t == Type::Float || t == Type::Double; }

bool is_comparison(BinaryOp op) {
  switch (op) {
  case BinaryOp::Lt:
  case BinaryOp::Le:
  case BinaryOp::Gt:
  case BinaryOp::Ge:
  case BinaryOp::Eq:
  case BinaryOp::Ne: return true;
  default: return false;
  }
}

/// Brackets C does not need but gcc and clang ask for at -Wall (-Wparentheses,
/// -Wlogical-not-parentheses): `a || (b && c)`, `(a < b) == c`, `(!a) == b`. They change nothing.
bool wanted_by_compilers(BinaryOp op, const Expr &operand, bool left) {
  if (operand.kind == Expr::Kind::Binary) {
    if (op == BinaryOp::Or && operand.binary_op == BinaryOp::And) return true;
    if (is_comparison(op) && is_comparison(operand.binary_op)) return true;
  }
  return left && is_comparison(op) && operand.kind == Expr::Kind::Unary && operand.unary_op == UnaryOp::Not;
}

const Expr &unbracketed(const Expr &e) { return e.kind == Expr::Kind::Paren ? unbracketed(e.args.at(0)) : e; }

/// active()/succeeded()/failed(): rendered already bracketed.
bool is_activity(const Expr &e) {
  return e.kind == Expr::Kind::Active || e.kind == Expr::Kind::Succeeded || e.kind == Expr::Kind::Failed;
}

bool has_call(const Expr &e) {
  if (e.kind == Expr::Kind::Call) return true;
  for (const auto &a : e.args)
    if (has_call(a)) return true;
  return false;
}

/// The value of a floating expression known at compile time (a literal, a constant, folded
/// arithmetic), as a double: converted to its type it is the expression's value.
std::optional<double> floating_constant(const EngineContext &c, const Expr &e) {
  if (e.type != Type::Float && e.type != Type::Double) return std::nullopt;
  if (e.kind == Expr::Kind::Float || e.folded) return e.float_value;
  if (e.kind == Expr::Kind::Const) {
    const Expr &value = c.model.consts.at(e.constant()).value;
    if (value.type == Type::Float || value.type == Type::Double) return value.float_value;
  }
  return std::nullopt;
}

/// The value of an int expression the validator folded (a literal, a constant, arithmetic on
/// them), if it is one: the model's value, computed once with C's semantics (compiler/constant.h).
std::optional<long long> int_constant(const EngineContext &c, const Expr &e) {
  if (e.type != Type::Int) return std::nullopt;
  if (e.kind == Expr::Kind::Int || e.folded) return e.int_value;
  if (e.kind == Expr::Kind::Const) {
    const Expr &value = c.model.consts.at(e.constant()).value;
    if (value.kind == Expr::Kind::Int) return value.int_value;
  }
  return std::nullopt;
}

/// An int literal as C reads it: its value in decimal (the validator parsed the spelling, so
/// `010` is 10). INT_MIN (a folded constant) is written so that it stays an int: `-2147483648`
/// is the long `-(2147483648)` in C.
Rendered int_literal(std::int32_t v) {
  if (v == INT_MIN) return {"(-2147483647 - 1)"};
  return {std::to_string(v), v < 0 ? kUnary : kPrimary};
}

/// A literal of a sized integer type or of `time` (milliseconds): its value as a C constant
/// every target reads as that value (a decimal constant takes the first of int, long, long long
/// that holds it; only INT64_MIN and the uint64 values above INT64_MAX need more).
Rendered wide_literal(const Expr &e) {
  const constant::Value v = constant::Value::of_integer(e.type, e.int_value);
  std::string text = constant::decimal(v);
  if (e.type == Type::UInt64 && e.int_value < 0) text = fmt::format("UINT64_C({})", text);
  else if (e.int_value == INT64_MIN) text = "(-INT64_C(9223372036854775807) - 1)";
  // A time is written in milliseconds without the spelling it had (`2s`, IEC's `T#2s`): chart
  // text converted from another language compiles to the same engine.
  return {text, e.int_value < 0 && e.type != Type::UInt64 ? kUnary : kPrimary};
}

bool is_wide(Type t) { return model::is_sized(t) || t == Type::Time; }

/// A float as a C literal that every compiler reads as exactly this float: the shortest
/// decimal that rounds back to it, with an `f`, which a compiler rounds once, straight to float.
/// (`(float)1.00000005960464478` would round twice where double is binary64 and once where it
/// is 32 bits, as on the AVR: two different floats.)
Rendered float_value_literal(float v) {
  std::string text = fmt::format("{}", v);
  if (text.find_first_of(".eE") == std::string::npos) text += ".0";
  return {text + "f", v < 0 ? kUnary : kPrimary};
}

/// A floating literal of type float (a folded float constant): its spelling with an `f` when
/// that reads as the model's value, else the value itself.
Rendered float_literal(const Expr &e) {
  const std::string text = e.text.str();
  const bool negative = !text.empty() && text[0] == '-';
  float direct = std::strtof(text.c_str(), nullptr);  // how C reads the spelling with an `f`
  float converted = static_cast<float>(e.float_value);
  if (std::memcmp(&direct, &converted, sizeof direct) == 0) return {text + "f", negative ? kUnary : kPrimary};
  return float_value_literal(converted);
}

/// A literal; a folded constant may be negative, and then binds like a unary minus.
Rendered literal(const Expr &e) {
  switch (e.kind) {
  case Expr::Kind::Bool: return {e.bool_value ? "true" : "false"};
  case Expr::Kind::String: return {c_string_literal(e.text.str())};
  case Expr::Kind::Int: return is_wide(e.type) ? wide_literal(e) : int_literal(static_cast<std::int32_t>(e.int_value));
  default:
    if (e.type == Type::Float) return float_literal(e);
    return {e.text.str(), !e.text.empty() && e.text.data()[0] == '-' ? kUnary : kPrimary};
  }
}

BinaryOp mirrored(BinaryOp op) {
  switch (op) {
  case BinaryOp::Lt: return BinaryOp::Gt;
  case BinaryOp::Le: return BinaryOp::Ge;
  case BinaryOp::Gt: return BinaryOp::Lt;
  case BinaryOp::Ge: return BinaryOp::Le;
  default: return op;
  }
}

/// A comparison of a duration with a constant that the compilers can decide, and warn about
/// (-Wtype-limits): timers are uint32_t, so `elapsed(P) >= 0ms` always holds, and a constant
/// beyond UINT32_MAX ticks is never reached (timers saturate there). Such a comparison is written
/// as its value; durations are read from timers and have no side effects to keep.
std::optional<bool> settled(const Expr &e) {
  if (!is_comparison(e.binary_op)) return std::nullopt;
  const Expr *l = &unbracketed(e.args.at(0)), *r = &unbracketed(e.args.at(1));
  BinaryOp op = e.binary_op;
  if (l->kind == Expr::Kind::Ticks) {
    std::swap(l, r);
    op = mirrored(op);
  }
  if (r->kind != Expr::Kind::Ticks || l->kind == Expr::Kind::Ticks || l->type != model::Type::Duration)
    return std::nullopt;
  if (r->ticks == 0 && (op == BinaryOp::Ge || op == BinaryOp::Lt)) return op == BinaryOp::Ge;
  if (r->ticks > 0xFFFFFFFFul) return op == BinaryOp::Lt || op == BinaryOp::Le || op == BinaryOp::Ne;
  return std::nullopt;
}

/// A comparison the compilers see as `subject OP constant` (or mirrored), with a subject that
/// reads without side effects: a timer, an int or bool var, an fsm's state or status.
struct ConstantTest {
  std::string subject;  ///< the subject's C text: the same text is the same subject
  BinaryOp op = BinaryOp::Eq;
  long long k = 0;
  long long lowest = INT_MIN, highest = INT_MAX;  ///< every value the subject can hold (or more)
  std::string shown;                              ///< the test as the chart says it, for comments
  bool in_ticks = false;                          ///< a timer's: `shown` counts ticks

  bool holds(long long x) const {
    switch (op) {
    case BinaryOp::Lt: return x < k;
    case BinaryOp::Le: return x <= k;
    case BinaryOp::Gt: return x > k;
    case BinaryOp::Ge: return x >= k;
    case BinaryOp::Eq: return x == k;
    default: return x != k;
    }
  }
};

/// `a OP b` (`&&` or `||`) of two tests of one subject, if it decides the same for every value
/// the subject can hold. The result can only change at a constant: trying each, its neighbours
/// and the ends decides.
std::optional<bool> decided(const ConstantTest &a, const ConstantTest &b, BinaryOp op) {
  const bool both = op == BinaryOp::And;
  auto value = [&](long long x) { return both ? a.holds(x) && b.holds(x) : a.holds(x) || b.holds(x); };
  const long long lowest = std::max(a.lowest, b.lowest), highest = std::min(a.highest, b.highest);
  const bool first = value(lowest);
  for (long long k : {a.k, b.k})
    for (long long x : {k - 1, k, k + 1, highest})
      if (x >= lowest && x <= highest && value(x) != first) return std::nullopt;
  return first;
}

/// Both operands of a comparison are the same value read twice, with no call: `v == v`,
/// `elapsed(P) < elapsed(P)`, `v + 1 >= (v + 1)`. The user's brackets do not count; constants
/// count by value (`v + K` is `v + 3` for `const int K = 3`), as the compilers see them.
bool same_value(const EngineContext &c, const Expr &x, const Expr &y) {
  const Expr &a = unbracketed(x), &b = unbracketed(y);
  if (a.type != b.type) return false;
  if (auto ka = int_constant(c, a)) return int_constant(c, b) == ka;
  if (a.kind != b.kind) return false;
  switch (a.kind) {
  case Expr::Kind::Bool: return a.bool_value == b.bool_value;
  case Expr::Kind::Ticks: return a.ticks == b.ticks;
  case Expr::Kind::Var: return a.var() == b.var();
  case Expr::Kind::Agent: return true;  // the engine's own agent number, a field
  case Expr::Kind::ActionQ:
  case Expr::Kind::ActionA: return a.action() == b.action();
  case Expr::Kind::Now: return true;  // one tick, one time
  case Expr::Kind::Elapsed: return a.place() == b.place();
  case Expr::Kind::Succeeded:
  case Expr::Kind::Failed: return a.place() == b.place();
  case Expr::Kind::Active: return a.path.get() == b.path.get();
  case Expr::Kind::Unary: return a.unary_op == b.unary_op && same_value(c, a.args.at(0), b.args.at(0));
  case Expr::Kind::Binary:
    return a.binary_op == b.binary_op && same_value(c, a.args.at(0), b.args.at(0)) &&
           same_value(c, a.args.at(1), b.args.at(1));
  default: return false;  // calls, floating literals, constants of other types: not compared
  }
}

/// A comparison of a value with itself, which gcc and clang decide and reject under -Werror
/// (-Wtautological-compare): `==`, `<=` and `>=` hold, the others do not. Not of floating
/// values, where NaN compares unequal to itself (and the compilers say nothing).
std::optional<bool> self_comparison(const EngineContext &c, const Expr &e) {
  if (!is_comparison(e.binary_op) || is_floating(e.args.at(0).type) || is_floating(e.args.at(1).type))
    return std::nullopt;
  if (has_call(e) || !same_value(c, e.args.at(0), e.args.at(1))) return std::nullopt;
  return e.binary_op == BinaryOp::Eq || e.binary_op == BinaryOp::Le || e.binary_op == BinaryOp::Ge;
}

/// A condition of `&&`, `||` and `!` over tests that read without side effects, whose value
/// those tests cannot change: `!active(D) || !active(B) || active(D)`. gcc decides such a
/// condition at -O1 and up ("'or' of unmatched not-equal tests is always 1", a warning no switch
/// turns off). Each distinct test (same_value) is taken as free to be true or false, which is
/// what the compilers see; at most kMaxTests of them, beyond which nothing is decided.
class Tautology {
public:
  static constexpr std::size_t kMaxTests = 12;

  static std::optional<bool> of(const EngineContext &c, const Expr &e) {
    const Expr &u = unbracketed(e);
    if (!is_logic(u) || u.type != Type::Bool || has_call(u)) return std::nullopt;  // u is no Paren
    Tautology t(c);
    if (!t.collect(u)) return std::nullopt;
    const bool first = t.value(u, 0);
    for (std::uint32_t mask = 1; mask < (1u << t.tests_.size()); ++mask)
      if (t.value(u, mask) != first) return std::nullopt;
    return first;
  }

private:
  explicit Tautology(const EngineContext &c) : c_(c) {}

  static bool is_logic(const Expr &e) {
    return (e.kind == Expr::Kind::Binary && (e.binary_op == BinaryOp::And || e.binary_op == BinaryOp::Or)) ||
           (e.kind == Expr::Kind::Unary && e.unary_op == UnaryOp::Not) || e.kind == Expr::Kind::Paren;
  }

  /// A test's number: the same node, or one that reads the same value. A test same_value cannot
  /// compare (a call-free expression of another kind) is a test of its own.
  std::size_t index(const Expr &test) const {
    for (std::size_t i = 0; i < tests_.size(); ++i)
      if (tests_[i] == &test || same_value(c_, *tests_[i], test)) return i;
    return tests_.size();
  }

  /// The value of a bool known at compile time: a literal, a constant, a folded expression.
  std::optional<bool> known(const Expr &e) const {
    if (e.type != Type::Bool) return std::nullopt;
    if (e.kind == Expr::Kind::Bool || e.folded) return e.bool_value;
    if (e.kind == Expr::Kind::Const) {
      const Expr &v = c_.model.consts.at(e.constant()).value;
      if (v.kind == Expr::Kind::Bool) return v.bool_value;
    }
    return std::nullopt;
  }

  bool collect(const Expr &e) {
    if (is_logic(e)) {
      for (const auto &a : e.args)
        if (!collect(a)) return false;
      return true;
    }
    if (known(e) || index(e) < tests_.size()) return true;
    tests_.push_back(&e);
    return tests_.size() <= kMaxTests;
  }

  bool value(const Expr &e, std::uint32_t mask) const {
    if (e.kind == Expr::Kind::Paren) return value(e.args.at(0), mask);
    if (e.kind == Expr::Kind::Unary) return !value(e.args.at(0), mask);
    if (e.kind == Expr::Kind::Binary && e.binary_op == BinaryOp::And)
      return value(e.args.at(0), mask) && value(e.args.at(1), mask);
    if (e.kind == Expr::Kind::Binary && e.binary_op == BinaryOp::Or)
      return value(e.args.at(0), mask) || value(e.args.at(1), mask);
    if (auto k = known(e)) return *k;
    return ((mask >> index(e)) & 1u) != 0u;
  }

  const EngineContext &c_;
  std::vector<const Expr *> tests_;
};

/// Renders one expression or statement of a chart, adding the temporaries it needs to `temps`.
class Renderer {
public:
  /// `at_start`: the expression is a transition's condition, where active()/succeeded()/
  /// failed() read this chart's activation at the start of the tick (docs/language.md, "Sub-charts").
  /// `from`: in an fsm or a sequential sfc, the one state the condition can be tried in (or
  /// none), which decides active(S) of this chart at the start of the tick.
  Renderer(const EngineContext &c, Temporaries &temps, bool at_start = false, model::PlaceId from = {})
      : c_(c), temps_(temps), at_start_(at_start), from_(from) {}

  Rendered render(const Expr &e) {
    if (&e == replaced_) return {replacement_};
    // A folded sized integer or time is its value alone: chart text converted from another
    // language spells large ones as arithmetic (chart_expr.cc), which must give the same engine.
    if (written_as_value(e) && is_wide(e.type)) return wide_literal(e);
    if (written_as_value(e)) {
      in_folded_ = true;
      Rendered spelled = render(e);
      in_folded_ = false;
      Rendered value = is_wide(e.type)       ? wide_literal(e)
                       : e.type == Type::Int ? int_literal(static_cast<std::int32_t>(e.int_value))
                                             : float_value_literal(static_cast<float>(e.float_value));
      return annotated(std::move(value), e, spelled.text);
    }
    switch (e.kind) {
    case Expr::Kind::Bool:
    case Expr::Kind::Int:
    case Expr::Kind::Float:
    case Expr::Kind::String: return literal(e);
    case Expr::Kind::Ticks: return {fmt::format("{}u /* {}ms */", e.ticks, e.float_value)};
    case Expr::Kind::Var: return {c_.field(c_.var_field.at(e.var()))};
    case Expr::Kind::Const: return constant(e);
    case Expr::Kind::Call: return call(e);
    case Expr::Kind::Elapsed:
      // As a time: ticks times the period in milliseconds (docs/language.md §4), in 64 bits.
      if (e.type == Type::Time)
        return {fmt::format("((int64_t){} * {})", c_.timer_of(e.place()), static_cast<long long>(c_.chart.period_ms))};
      return {c_.timer_of(e.place())};
    case Expr::Kind::Now:  // the tick's number times the period (docs/language.md §15)
      return {fmt::format("({} * {})", c_.field(c_.clock), static_cast<long long>(c_.chart.period_ms))};
    case Expr::Kind::Unary: return unary(e);
    case Expr::Kind::Binary: return binary(e);
    case Expr::Kind::Active:
    case Expr::Kind::Succeeded:
    case Expr::Kind::Failed: return activity(e);
    case Expr::Kind::Paren: {
      if (is_activity(e.args.at(0))) return render(e.args.at(0));  // already bracketed
      Rendered inner = render(e.args.at(0));
      return {bracket(inner.text), kPrimary, std::move(inner.before)};
    }
    case Expr::Kind::TeamCount:  // no side effect: the order of calls is not its concern
      return {fmt::format("{}({}, {})", c_.team_fn, c_.self, c_.place_const.at(e.place()))};
    case Expr::Kind::Agent: return {c_.field(c_.agent)};
    // An action no Q can hold (only P1, P0, R) is never active; one that never runs, never running.
    case Expr::Kind::ActionQ: {
      const std::string &f = c_.action_q.at(e.action());
      return {f.empty() ? "false" : c_.field(f)};
    }
    case Expr::Kind::ActionA: {
      const std::string &f = c_.action_a.at(e.action());
      return {f.empty() ? "false" : c_.field(f)};
    }
    case Expr::Kind::Convert: return conversion(e);
    case Expr::Kind::Builtin: return standard(e);
    case Expr::Kind::Config: break;  // plans only: the validator keeps it out of charts
    default: break;                  // team machines: not in this back end's charts
    }
    return {"0"};
  }

  /// `r`, the rendering of `e`, as a value of type `to` where C converts implicitly: explicitly
  /// when a floating value becomes an int (clang -Wliteral-conversion), and when an int constant
  /// becomes a float that cannot hold it exactly (-Wimplicit-const-int-float-conversion). The
  /// conversion is the one C (and the language) makes anyway.
  Rendered converted(Rendered r, const Expr &e, Type to) const {
    // A floating constant that meets an int or a float is written as the value it becomes: the
    // target's compiler would convert it in its own double, 32 bits on the AVR.
    if ((to == Type::Int || to == Type::Float) && e.type == Type::Double) {
      if (auto v = floating_constant(c_, e)) {
        Rendered value =
            to == Type::Int ? int_literal(static_cast<std::int32_t>(*v)) : float_value_literal(static_cast<float>(*v));
        return annotated(std::move(value), e, r.text);
      }
    }
    const char *cast = nullptr;
    if (is_floating(to) && model::is_sized(e.type)) {
      cast = to == Type::Float ? "(float)" : "(double)";  // -Wimplicit-int-float-conversion
    } else if (model::is_sized(to) && model::integer_bits(to) < 32 && e.type == to && e.kind != Expr::Kind::Var &&
               e.kind != Expr::Kind::Int && !e.folded && e.kind != Expr::Kind::Const &&
               e.kind != Expr::Kind::Builtin) {  // standard(): cast already
      // C computes an int8/int16/uint8/uint16 expression in int; the language's value fits the
      // type (gfec run checks it), so the conversion back is written out (-Wconversion).
      r.text = fmt::format("({})({})", model::c_integer_type(to), r.text);
      r.prec = kUnary;
      return r;
    } else if (to == Type::Int && is_floating(e.type)) {
      cast = "(int32_t)";
    } else if (to == Type::Float && e.type == Type::Int) {
      // A value read at run time may not fit a float exactly (gcc's -Wconversion, clang's
      // -Wimplicit-int-float-conversion): the conversion is written out. A constant only when
      // it does not fit.
      auto v = int_constant(c_, e);
      if (!v || static_cast<long long>(static_cast<float>(*v)) != *v) cast = "(float)";
    } else if (to == Type::Float && e.type == Type::Double) {
      cast = "(float)";  // -Wfloat-conversion, -Wimplicit-float-conversion
    } else if (to == Type::Double && e.type == Type::Float) {
      cast = "(double)";  // -Wdouble-promotion
    }
    if (!cast) return r;
    if (r.prec < kPrimary) r.text = bracket(r.text);
    r.text = cast + r.text;
    r.prec = kUnary;
    return r;
  }

  /// A statement: the assignments to temporaries that must come first are statements of their
  /// own, on the same line (`gfec_t0 = S2(); A(gfec_t0, S0() < 2);`).
  std::string statement(const model::Stmt &s) {
    Rendered r;
    if (s.kind == model::Stmt::Kind::Call) {
      r = render(s.expr);
      r.text += ";";
    } else {
      const Type to = c_.chart.vars.at(s.var).type;
      const std::string target = c_.field(c_.var_field.at(s.var));
      r = render(s.expr);
      if (s.op != AssignOp::Set && to == Type::Int && is_floating(s.expr.type)) {
        // `v += f` is `v = v + f` computed in f's type, then converted: written out, so that
        // the conversion is explicit.
        BinaryOp op = s.op == AssignOp::Add ? BinaryOp::Add : BinaryOp::Sub;
        if (r.prec <= precedence(op)) r.text = bracket(r.text);
        r.text = fmt::format("{} = (int32_t)({}{} {} {});", target, s.expr.type == Type::Float ? "(float)" : "", target,
                             spelling(op), r.text);
      } else if (s.op != AssignOp::Set && to == Type::Float && s.expr.type == Type::Double) {
        // `f += d` is computed in double, then rounded to float: written out (-Wfloat-conversion,
        // -Wdouble-promotion). Not `f += (float)d`, which would round d first.
        BinaryOp op = s.op == AssignOp::Add ? BinaryOp::Add : BinaryOp::Sub;
        if (r.prec <= precedence(op)) r.text = bracket(r.text);
        r.text = fmt::format("{} = (float)((double){} {} {});", target, target, spelling(op), r.text);
      } else if (s.op != AssignOp::Set && model::is_sized(to) && model::integer_bits(to) < 32) {
        // `v += e` computes in int: written out with its conversion back (-Wconversion).
        BinaryOp op = s.op == AssignOp::Add ? BinaryOp::Add : BinaryOp::Sub;
        if (r.prec <= precedence(op)) r.text = bracket(r.text);
        r.text = fmt::format("{} = ({})({} {} {});", target, model::c_integer_type(to), target, spelling(op), r.text);
      } else {
        r = converted(std::move(r), s.expr, to);
        r.text = fmt::format("{} {} {};", target, spelling(s.op), r.text);
      }
    }
    std::string text;
    for (const auto &b : r.before) text += b + "; ";
    return text + r.text;
  }

private:
  /// `active(P.Q.R)`, `succeeded(P)`, `failed(P)`: each level of the path active (this chart's
  /// at the start of the tick in a condition; the instances as they are, they are never in the
  /// middle of a tick when the parent's code runs), then the fsm instance's status. Bracketed.
  Rendered activity(const Expr &e) const {
    std::vector<model::PlaceId> path =
        e.kind == Expr::Kind::Active ? e.path.get() : std::vector<model::PlaceId>{e.place()};
    const EngineContext *c = &c_;
    std::string obj, text;
    for (std::size_t k = 0; k < path.size(); ++k) {
      if (!c) return {"false"};  // a path the validator let through into nothing: never active
      if (k == 0 && at_start_ && from_ && c_.form().one_active()) {
        // The transition is tried only in state `from`: the first level is known (and testing
        // the state twice would be an overlapping comparison to clang).
        if (path[0] != from_) return {fmt::format("false /* {}: not in {} */", what(e), c_.place(path[0]).name)};
      } else {
        text += (text.empty() ? "" : " && ") + c->active_test(obj, path[k], k == 0 && at_start_);
      }
      if (k + 1 < path.size() || e.kind != Expr::Kind::Active) {
        obj = c->member(obj, c->sub_field.at(path[k]));
        c = c->sub_of(path[k]);
      }
    }
    if (e.kind != Expr::Kind::Active) {
      if (!c || !c->fsm) return {"false"};
      text += fmt::format("{}{} == {}", text.empty() ? "" : " && ", c->member(obj, c->status),
                          e.kind == Expr::Kind::Succeeded ? "1" : "-1");
    }
    if (text.empty()) return {fmt::format("true /* {}: in {} */", what(e), c_.place(path[0]).name)};
    return {bracket(text)};
  }

  /// `active(P.Q)`, as the chart says it, for comments.
  std::string what(const Expr &e) const {
    if (e.kind != Expr::Kind::Active)
      return fmt::format("{}({})", e.kind == Expr::Kind::Succeeded ? "succeeded" : "failed", c_.place(e.place()).name);
    std::string s;
    const EngineContext *c = &c_;
    for (model::PlaceId p : e.path) {
      if (!c) break;
      s += (s.empty() ? "" : ".") + c->place(p).name;
      c = c->sub_of(p);
    }
    return "active(" + s + ")";
  }

  /// Int and float arithmetic the validator folded is written as its value, the chart's
  /// expression in a comment: computed by the target's compiler in C's `int` it could overflow
  /// where int is 16 bits (`200 * 200` on the AVR).
  bool written_as_value(const Expr &e) const {
    if (in_folded_ || !e.folded || (e.type != Type::Int && e.type != Type::Float && !is_wide(e.type))) return false;
    return e.kind != Expr::Kind::Int && e.kind != Expr::Kind::Float && e.kind != Expr::Kind::Const;
  }

  /// `value` with what the chart wrote in a comment, when that says more than the value.
  Rendered annotated(Rendered value, const Expr &e, const std::string &spelled) const {
    std::string origin = spelled;
    if (e.kind == Expr::Kind::Const) origin = std::string(c_.model.consts.at(e.constant()).name);
    if (origin != value.text && origin + "f" != value.text && origin.find("/*") == std::string::npos &&
        origin.find("*/") == std::string::npos)
      value.text += fmt::format(" /* {} */", origin);
    return value;
  }

  /// `T(x)`: a cast where C's conversion is the language's (between integer types, which the
  /// interpreter checks to fit; to a floating type); a floating value to an integer through
  /// gfec_round (c_source.cc), rounded to nearest, ties away from zero.
  Rendered conversion(const Expr &e) {
    Rendered x = render(e.args.at(0));
    const Type from = e.args.at(0).type;
    const char *to = e.type == Type::Float ? "float" : e.type == Type::Double ? "double" : c_type(e.type);
    if (model::is_integer(e.type) || e.type == Type::Time) {
      if (is_floating(from))
        return {fmt::format("({})gfec_round((double){})", to, bracket(x.text)), kUnary, std::move(x.before)};
    }
    if (x.prec < kUnary) x.text = bracket(x.text);
    return {fmt::format("({}){}", to, x.text), kUnary, std::move(x.before)};
  }

  /// An operand a standard function may read more than once: a read without side effects.
  static bool plain_read(const Expr &e) {
    switch (e.kind) {
    case Expr::Kind::Paren: return plain_read(e.args.at(0));
    case Expr::Kind::Bool:
    case Expr::Kind::Int:
    case Expr::Kind::Float:
    case Expr::Kind::Var:
    case Expr::Kind::Const: return true;
    default: return e.folded;
    }
  }

  /// `text`, of type `t` computed in C's int, cast back to `t` where `t` is narrower than int
  /// (-Wconversion; the language's value fits: gfec run checks abs()).
  static std::string narrowed(const std::string &text, Type t) {
    if (model::is_sized(t) && model::integer_bits(t) < 32)
      return fmt::format("({})({})", model::c_integer_type(t), text);
    return text;
  }

  /// abs, min, max, limit, sel, mux (docs/language.md §4): every operand evaluated once, in
  /// order: one that is not a plain read goes into a temporary first, each value converted to
  /// the result type; then C's conditional operator chooses as the interpreter does
  /// (constant::standard). No helper functions, no <math.h>: the same C on every target.
  Rendered standard(const Expr &e) {
    using B = Expr::Builtin;
    if (e.folded && e.type == Type::Bool) return {e.bool_value ? "true" : "false"};
    if (e.folded && e.type == Type::Double) {
      Rendered v{constant::float_spelling(e.float_value, Type::Double), e.float_value < 0 ? kUnary : kPrimary};
      return v;
    }
    if (in_folded_) {  // the comment of a folded value: the chart's call
      std::string text = std::string(model::builtin_name(e.builtin)) + "(";
      for (std::size_t i = 0; i < e.args.size(); ++i) text += (i ? ", " : "") + render(e.args[i]).text;
      return {text + ")"};
    }
    const bool selects = e.builtin == B::Sel || e.builtin == B::Mux;
    std::vector<std::string> before, v;
    for (std::size_t i = 0; i < e.args.size(); ++i) {
      const Expr &a = e.args[i];
      const Type to = selects && i == 0 ? a.type : e.type;
      const bool plain = plain_read(a);
      Rendered r = render(plain ? a : unbracketed(a));
      for (auto &b : r.before) before.push_back(std::move(b));
      r.before.clear();
      r = converted(std::move(r), a, to);
      if (plain) {
        v.push_back(r.prec < kPrimary ? bracket(r.text) : r.text);
        continue;
      }
      std::string name = temps_.add(to);
      before.push_back(fmt::format("{} = {}", name, r.text));
      v.push_back(std::move(name));
    }
    const Type t = e.type;
    const char *zero = t == Type::Bool ? "false" : t == Type::Float ? "0.0f" : t == Type::Double ? "0.0" : "0";
    if (e.builtin == B::Abs && model::is_unsigned(t)) return {v[0], kPrimary, std::move(before)};
    std::string choice;  // a conditional expression, not bracketed
    switch (e.builtin) {
    case B::Abs: choice = fmt::format("({} < {}) ? -{} : {}", v[0], zero, v[0], v[0]); break;
    case B::Min:
    case B::Max: {
      // The first of equal values stays, as MatIEC's MIN and MAX keep it.
      const char *op = e.builtin == B::Max ? "<" : ">";
      std::string best = v[0];
      if (v.size() > 2) {  // the best so far in a temporary of its own
        best = temps_.add(t);
        before.push_back(fmt::format("{} = {}", best, v[0]));
        for (std::size_t i = 1; i + 1 < v.size(); ++i)
          before.push_back(fmt::format("{} = {}", best,
                                       narrowed(fmt::format("({} {} {}) ? {} : {}", best, op, v[i], v[i], best), t)));
      }
      choice = fmt::format("({} {} {}) ? {} : {}", best, op, v.back(), v.back(), best);
      break;
    }
    case B::Limit:
      choice = fmt::format("({} > {}) ? (({} < {}) ? {} : {}) : {}", v[1], v[0], v[1], v[2], v[1], v[2], v[0]);
      break;
    case B::Sel: choice = fmt::format("{} ? {} : {}", v[0], v[2], v[1]); break;
    case B::Mux:
      // A selector out of range gives zero, as MatIEC's MUX does.
      choice = zero;
      for (std::size_t i = v.size() - 1; i >= 1; --i)
        choice = fmt::format("({} == {}) ? {} : {}", v[0], i - 1, v[i], i + 1 == v.size() ? choice : bracket(choice));
      break;
    }
    if (model::is_sized(t) && model::integer_bits(t) < 32) return {narrowed(choice, t), kUnary, std::move(before)};
    return {bracket(choice), kPrimary, std::move(before)};
  }

  /// A constant is written as its folded value, named in a comment: no C name of the chart's can
  /// collide with it (a constant called `m` would otherwise hide the engine parameter). Inside a
  /// folded expression's comment, only its name.
  Rendered constant(const Expr &e) const {
    const auto &k = c_.model.consts.at(e.constant());
    if (in_folded_) return {std::string(k.name)};
    Rendered v = literal(k.value);
    v.text += fmt::format(" /* {} */", k.name);
    return v;
  }

  /// The operands of one operator or call, rendered left to right. When two or more of them
  /// call functions, all but the last of those go into temporaries (`in_temporary`), assigned
  /// in order in `before`, which also collects the operands' own assignments.
  struct Operands {
    std::vector<Rendered> items;
    std::vector<bool> in_temporary;
    std::vector<std::string> before;
  };
  Operands operands(const CompactVector<Expr> &args) {
    std::size_t calling = 0, last = 0;
    for (std::size_t i = 0; i < args.size(); ++i)
      if (has_call(args[i])) {
        ++calling;
        last = i;
      }
    Operands o;
    for (std::size_t i = 0; i < args.size(); ++i) {
      bool temporary = calling >= 2 && i != last && has_call(args[i]);
      // A temporary takes the value without the user's outer brackets.
      Rendered r = render(temporary ? unbracketed(args[i]) : args[i]);
      for (auto &b : r.before) o.before.push_back(std::move(b));
      r.before.clear();
      if (temporary) {
        std::string name = temps_.add(args[i].type);
        o.before.push_back(fmt::format("{} = {}", name, r.text));
        r = {name};
      }
      o.items.push_back(std::move(r));
      o.in_temporary.push_back(temporary);
    }
    return o;
  }

  Rendered call(const Expr &e) {
    const model::Function &f = c_.model.functions.at(e.function());
    Operands o = operands(e.args);
    // --context: the instance's context first (docs/c-engine.md "Instance context"); reading a
    // field calls nothing, so the order of the calls is untouched.
    std::string args = c_.has_context() ? c_.field(c_.ctx_field) : "";
    for (std::size_t i = 0; i < o.items.size(); ++i) {
      Rendered a =
          i < f.params.size() ? converted(std::move(o.items[i]), e.args[i], f.params[i].type) : std::move(o.items[i]);
      args += (args.empty() ? "" : ", ") + a.text;
    }
    // --trace=calls: through the file-local wrapper that records the call (c_trace.cc).
    const std::string &name =
        c_.call_wrapper.empty() || c_.call_wrapper.at(e.function()).empty() ? f.name : c_.call_wrapper.at(e.function());
    return {fmt::format("{}({})", name, args), kPrimary, std::move(o.before)};
  }

  Rendered unary(const Expr &e) {
    if (auto value = tautology(e)) return std::move(*value);
    Rendered operand = render(e.args.at(0));
    // `- -x` must not become the decrement `--x`.
    bool minus_minus = e.unary_op == UnaryOp::Neg && !operand.text.empty() && operand.text[0] == '-';
    if (operand.prec < kUnary || minus_minus) operand.text = bracket(operand.text);
    return {spelling(e.unary_op) + operand.text, kUnary, std::move(operand.before)};
  }

  /// A condition its tests cannot change (Tautology), written as its value with the chart's
  /// text in a comment.
  std::optional<Rendered> tautology(const Expr &e) const {
    auto value = Tautology::of(c_, e);
    if (!value) return std::nullopt;
    std::string text = model::source_text(c_.model, e.range);
    const bool shown = !text.empty() && text.size() <= 120 && text.find_first_of("\r\n") == std::string::npos &&
                       text.find("/*") == std::string::npos && text.find("*/") == std::string::npos;
    return Rendered{fmt::format("{} /* {}, whatever its tests read{}{} */", *value ? "true" : "false",
                                *value ? "always" : "never", shown ? ": " : "", shown ? text : "")};
  }

  Rendered binary(const Expr &e) {
    if (auto value = tautology(e)) return std::move(*value);
    if (auto decided = overlapping(e)) return std::move(*decided);
    if (auto value = settled(e))
      return {*value ? "true /* always: timers count from 0 to UINT32_MAX */"
                     : "false /* never: timers count from 0 to UINT32_MAX */"};
    if (auto value = self_comparison(c_, e))
      return {*value ? "true /* always: both sides are the same */" : "false /* never: both sides are the same */"};
    const BinaryOp op = e.binary_op;
    const int prec = precedence(op);
    Rendered l, r;
    bool l_plain = false, r_plain = false;  // a temporary's name, or already bracketed
    std::vector<std::string> before;
    if (op == BinaryOp::And || op == BinaryOp::Or) {
      // C evaluates the left operand first, and the right one only if the left does not decide:
      // the right operand's assignments stay inside it.
      l = render(e.args.at(0));
      before = std::move(l.before);
      l.before.clear();
      r = render(e.args.at(1));
      r_plain = !r.before.empty();  // closed: one bracketed expression
      r = closed(std::move(r));
    } else {
      Operands o = operands(e.args);
      l = std::move(o.items.at(0));
      r = std::move(o.items.at(1));
      l_plain = o.in_temporary[0];
      r_plain = o.in_temporary[1];
      before = std::move(o.before);
      // The usual arithmetic conversions written out where they may round or widen a float (the
      // stricter warnings of docs/c-engine.md): an int meeting a float becomes a float, a float
      // meeting a double a double; an int meeting a double converts exactly and stays implicit.
      const Type a = e.args[0].type, b = e.args[1].type;
      if (model::is_numeric(a) && model::is_numeric(b) && a != b && (is_floating(a) || is_floating(b))) {
        const Type common = a == Type::Double || b == Type::Double ? Type::Double : Type::Float;
        if (!(common == Type::Double && a == Type::Int)) l = converted(std::move(l), e.args[0], common);
        if (!(common == Type::Double && b == Type::Int)) r = converted(std::move(r), e.args[1], common);
      }
    }
    // The model keeps the user's brackets as Paren nodes; these only restore what the tree says
    // (operators are left-associative) and quiet the compilers.
    // MISRA C:2012 rule 12.1 also wants the precedence explicit: an operand that is itself a
    // binary operation of another precedence is bracketed (`(a * b) + c`, `(x >= 1) && y`).
    auto other = [prec](int p) { return p < kUnary && p != prec; };
    if (!l_plain && (l.prec < prec || other(l.prec) || wanted_by_compilers(op, e.args[0], true)))
      l.text = bracket(l.text);
    if (!r_plain && (r.prec <= prec || other(r.prec) || wanted_by_compilers(op, e.args[1], false)))
      r.text = bracket(r.text);
    return {fmt::format("{} {} {}", l.text, spelling(op), r.text), prec, std::move(before)};
  }

  /// `e` as a test the compilers can decide: a timer, an int or bool var or (where the test is
  /// rendered as one comparison) an fsm's state or status, compared with a constant.
  std::optional<ConstantTest> constant_test(const Expr &e) const {
    const Expr &u = unbracketed(e);
    if (is_activity(u)) return activity_test(u);
    if (u.kind != Expr::Kind::Binary || !is_comparison(u.binary_op)) return std::nullopt;
    for (int side = 0; side < 2; ++side) {
      const Expr &x = unbracketed(u.args.at(static_cast<std::size_t>(side)));
      const Expr &k = unbracketed(u.args.at(static_cast<std::size_t>(1 - side)));
      ConstantTest t;
      t.op = side == 0 ? u.binary_op : mirrored(u.binary_op);
      if (x.kind == Expr::Kind::Elapsed && k.kind == Expr::Kind::Ticks) {  // timers stop at UINT32_MAX
        t.subject = c_.timer_of(x.place());
        t.k = static_cast<long long>(std::min(k.ticks, 0x100000000ul));
        t.lowest = 0;
        t.highest = 0xFFFFFFFFll;
        t.in_ticks = true;
        t.shown = fmt::format("elapsed({}) {} {}", c_.place(x.place()).name, spelling(t.op), t.k);
        return t;
      }
      if (x.kind != Expr::Kind::Var || (x.type != Type::Int && x.type != Type::Bool)) continue;
      if (x.type == Type::Int) {
        auto v = int_constant(c_, k);
        if (!v) continue;
        t.k = *v;
      } else {
        if (k.kind != Expr::Kind::Bool) continue;
        t.k = k.bool_value ? 1 : 0;
        t.lowest = 0;
        t.highest = 1;
      }
      t.subject = c_.field(c_.var_field.at(x.var()));
      t.shown = fmt::format("{} {} {}", c_.chart.vars.at(x.var()).name, spelling(t.op),
                            x.type == Type::Bool ? (t.k ? "true" : "false") : std::to_string(t.k));
      return t;
    }
    return std::nullopt;
  }

  /// An activity test that activity() renders as one comparison, `state == X_K_Z0` or
  /// `status == -1`: of this chart's one active state outside a transition's condition, or of
  /// the instance the state a condition is tried in runs.
  std::optional<ConstantTest> activity_test(const Expr &e) const {
    std::vector<model::PlaceId> path =
        e.kind == Expr::Kind::Active ? e.path.get() : std::vector<model::PlaceId>{e.place()};
    const bool first_known = at_start_ && from_ && c_.form().one_active();
    const std::size_t tests = (first_known ? 0 : 1) + (e.kind == Expr::Kind::Active ? path.size() - 1 : 1);
    if (tests != 1 || path.empty() || (first_known && path[0] != from_)) return std::nullopt;
    const EngineContext *c = &c_;
    std::string obj;
    if (path.size() > 1 || e.kind != Expr::Kind::Active) {
      obj = c_.member("", c_.sub_field.at(path[0]));
      c = c_.sub_of(path[0]);
    }
    if (!c) return std::nullopt;
    ConstantTest t;
    t.shown = what(e);
    if (e.kind != Expr::Kind::Active) {
      if (!c->fsm) return std::nullopt;
      t.subject = c->member(obj, c->status);
      t.k = e.kind == Expr::Kind::Succeeded ? 1 : -1;
      return t;
    }
    // A one-active form tests `subject == constant` (c_forms.cc); the constants of distinct
    // places differ, as their numbers do.
    if (!c->form().one_active()) return std::nullopt;
    const std::string text = c->active_test(obj, path.back());
    const auto at = text.find(" == ");
    if (at == std::string::npos) return std::nullopt;
    t.subject = text.substr(0, at);
    t.k = static_cast<long long>(path.back().index());
    return t;
  }

  /// Two tests of one subject joined by `&&` or `||` that decide the same for every value:
  /// `v >= 0 || v < 4` is always true, `failed(K) && succeeded(K)` never, and so is
  /// `elapsed(P) >= 15ms && elapsed(P) <= 5ms` at period 20ms. clang says so
  /// (-Wtautological-overlap-compare), and gcc as well where the first test ends a chain of the
  /// same operator (`x && v == 1 && v == 2`: "'and' of mutually exclusive equal-tests"). Such a
  /// pair is written as its value, the tests in a comment, in place of the first test (the
  /// second goes: `x && false`, which is `(x && v == 1) && v == 2`). Nothing is lost: the
  /// subjects are read without side effects.
  std::optional<Rendered> overlapping(const Expr &e) {
    const BinaryOp op = e.binary_op;
    if (op != BinaryOp::And && op != BinaryOp::Or) return std::nullopt;
    const Expr *first = &unbracketed(e.args.at(0));
    while (first->kind == Expr::Kind::Binary && first->binary_op == op) first = &unbracketed(first->args.at(1));
    auto a = constant_test(*first), b = constant_test(e.args.at(1));
    if (!a || !b || a->subject != b->subject) return std::nullopt;
    auto value = decided(*a, *b, op);
    if (!value) return std::nullopt;
    std::string text = fmt::format("{} /* {}: {} {} {}{} */", *value ? "true" : "false", *value ? "always" : "never",
                                   a->shown, spelling(op), b->shown, a->in_ticks ? ", in ticks" : "");
    if (first == &unbracketed(e.args.at(0))) return Rendered{text};
    replaced_ = first;
    replacement_ = std::move(text);
    Rendered chain = render(e.args.at(0));
    replaced_ = nullptr;
    return chain;
  }

  const EngineContext &c_;
  Temporaries &temps_;
  bool at_start_ = false;
  model::PlaceId from_;
  /// overlapping(): the test rendered as `replacement_` (its pair's value) instead.
  const Expr *replaced_ = nullptr;
  std::string replacement_;
  bool in_folded_ = false;  ///< rendering a folded expression for its comment
};

}  // namespace

const char *c_type(model::Type type) {
  switch (type) {
  case model::Type::Bool: return "bool";
  case model::Type::Int: return "int32_t";
  case model::Type::Time:
  case model::Type::Int8:
  case model::Type::Int16:
  case model::Type::Int64:
  case model::Type::UInt8:
  case model::Type::UInt16:
  case model::Type::UInt32:
  case model::Type::UInt64: return model::c_integer_type(type);
  case model::Type::Float: return "float";
  case model::Type::Double: return "double";
  case model::Type::Void: return "void";
  default: return "int";  // strings, objects and durations never reach a chart's C
  }
}

std::string Temporaries::add(model::Type type) {
  std::string name = prefix_ + std::to_string(count_++);
  pending_.emplace_back(type, name);
  return name;
}

void Temporaries::declare(CodeWriter &w) {
  for (const auto &line : declarations()) w.line(std::string_view(line));
}

std::vector<std::string> Temporaries::declarations() {
  std::vector<std::string> lines;
  std::vector<bool> done(pending_.size(), false);
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    if (done[i]) continue;
    std::string names;
    for (std::size_t j = i; j < pending_.size(); ++j)
      if (!done[j] && pending_[j].first == pending_[i].first) {
        names += (names.empty() ? "" : ", ") + pending_[j].second;
        done[j] = true;
      }
    lines.push_back(
        fmt::format("{} {}; /* temporaries: the chart calls left to right */", c_type(pending_[i].first), names));
  }
  pending_.clear();
  return lines;
}

std::string c_expr(const EngineContext &c, const Expr &e, Temporaries &temps) {
  return closed(Renderer(c, temps).render(e)).text;
}

std::string c_condition(const EngineContext &c, const Expr &e, Temporaries &temps, bool at_start, model::PlaceId from) {
  Rendered r = Renderer(c, temps, at_start, from).render(e);
  if (!r.before.empty()) return closed(std::move(r)).text;  // a bracketed comma expression
  return e.kind == Expr::Kind::Paren || is_activity(e) ? r.text : bracket(r.text);
}

namespace {

/// An activity test (an fsm's `(m->state == X)`) as the whole test of an `if`: without its
/// brackets, which clang -Wparentheses-equality takes for a mistyped `=`.
std::string bare_activity(const EngineContext &c, const Expr &activity, Temporaries &temps, bool at_start,
                          model::PlaceId from) {
  std::string text = Renderer(c, temps, at_start, from).render(activity).text;
  return text.size() > 2 && text.front() == '(' ? text.substr(1, text.size() - 2) : text;
}

}  // namespace

std::string c_test(const EngineContext &c, const Expr &e, Temporaries &temps, bool at_start, model::PlaceId from) {
  const Expr &u = unbracketed(e);
  if (is_activity(u)) return bare_activity(c, u, temps, at_start, from);
  if (u.kind != Expr::Kind::Binary || u.binary_op != BinaryOp::Eq || settled(u))
    return c_condition(c, e, temps, at_start, from);
  return closed(Renderer(c, temps, at_start, from).render(u)).text;
}

std::string c_if_test(const EngineContext &c, const Expr &e, Temporaries &temps) {
  // `if ((a == b))` is what clang -Wparentheses-equality takes for a mistyped `=`.
  const Expr &u = unbracketed(e);
  if (is_activity(u)) return bare_activity(c, u, temps, false, {});
  const bool equality = u.kind == Expr::Kind::Binary && u.binary_op == BinaryOp::Eq && !settled(u);
  return closed(Renderer(c, temps).render(equality ? u : e)).text;
}

std::string c_assertion(const EngineContext &c, const Expr &e, Temporaries &temps) {
  const int before = temps.count();
  Rendered r = Renderer(c, temps).render(e);
  if (temps.count() == before) return fmt::format("{}({});", c.assert_macro, r.text);
  std::string text;
  for (const auto &b : r.before) text += b + "; ";
  std::string holds = temps.add(Type::Bool);
  return text + fmt::format("{} = {}; {}({});", holds, r.text, c.assert_macro, holds);
}

bool written_as_constant(const EngineContext &c, const Expr &e) { return Tautology::of(c, e).has_value(); }

std::string c_value(const EngineContext &c, const Expr &e, model::Type to) {
  Temporaries none(c.temp_prefix);  // a constant expression calls nothing: it needs none
  Renderer r(c, none);
  return closed(r.converted(r.render(e), e, to)).text;
}

std::string c_prototype(const model::Function &f, const std::string &first, const std::vector<std::string> &names) {
  std::string params = first;
  for (std::size_t i = 0; i < f.params.size(); ++i) {
    const auto &p = f.params[i];
    const std::string &name = i < names.size() ? names[i] : p.name;
    params += params.empty() ? "" : ", ";
    params += name.empty() ? c_type(p.type) : fmt::format("{} {}", c_type(p.type), name);
  }
  return fmt::format("{} {}({})", c_type(f.result), f.name, params.empty() ? "void" : params);
}

namespace {

void render_statements(const EngineContext &c, const std::vector<model::Stmt> &stmts, Temporaries &temps, Renderer &r,
                       std::vector<std::string> &text);

/// A block of its own (a loop's body): the declarations of its temporaries, then its statements.
void render_block(const EngineContext &c, const std::vector<model::Stmt> &stmts, Temporaries &temps, Renderer &r,
                  std::vector<std::string> &text) {
  auto outer = temps.take();
  std::size_t at = text.size();
  text.emplace_back();
  render_statements(c, stmts, temps, r, text);
  std::string declared;
  for (const auto &line : temps.declarations()) declared += (declared.empty() ? "" : "\n") + line;
  text[at] = declared;
  temps.restore(std::move(outer));
}

void render_statements(const EngineContext &c, const std::vector<model::Stmt> &stmts, Temporaries &temps, Renderer &r,
                       std::vector<std::string> &text) {
  for (const auto &s : stmts) {
    switch (s.kind) {
    case model::Stmt::Kind::Verbatim: text.emplace_back(); break;
    case model::Stmt::Kind::Break: text.emplace_back("break;"); break;
    case model::Stmt::Kind::Return: text.emplace_back(); break;  // a goto to the label emit_statements() places
    case model::Stmt::Kind::While:
    case model::Stmt::Kind::DoWhile:
      // The test's temporaries belong to the enclosing block: it is evaluated before each pass.
      text.push_back(c_if_test(c, s.expr, temps));
      render_block(c, s.then_block, temps, r, text);
      break;
    case model::Stmt::Kind::For:
      text.push_back(r.statement(s.else_block.front()));
      text.push_back(c_if_test(c, s.expr, temps));
      text.push_back(r.statement(s.else_block.back()));
      render_block(c, s.then_block, temps, r, text);
      break;
    case model::Stmt::Kind::Invoke: render_statements(c, s.then_block, temps, r, text); break;  // inlined
    case model::Stmt::Kind::If: {
      // The test (its temporaries belong to the enclosing block), then each branch: the
      // declarations of its own temporaries, then its statements. An `else if` is the one If
      // of its else block, and declares in the enclosing block like any other test there.
      text.push_back(c_if_test(c, s.expr, temps));
      for (const auto *branch : {&s.then_block, &s.else_block}) {
        if (branch == &s.else_block && s.else_if) {  // `} else if (test) {`: no block of its own
          text.emplace_back();
          render_statements(c, *branch, temps, r, text);
          continue;
        }
        auto outer = temps.take();
        std::size_t at = text.size();
        text.emplace_back();
        render_statements(c, *branch, temps, r, text);
        std::string declared;
        for (const auto &line : temps.declarations()) declared += (declared.empty() ? "" : "\n") + line;
        text[at] = declared;
        temps.restore(std::move(outer));
      }
      break;
    }
    default: text.push_back(r.statement(s)); break;
    }
  }
}

/// Whether `block` holds a `return` that ends the block it is written in: a `return` in a block
/// call's inlined body ends that call only, so it does not count here.
template <typename Stmts> bool returns(const Stmts &block) {
  for (const model::Stmt &s : block) {
    if (s.kind == model::Stmt::Kind::Invoke) continue;
    if (s.kind == model::Stmt::Kind::Return || returns(s.then_block) || returns(s.else_block)) return true;
  }
  return false;
}

/// Writes statements from `text`, consuming it from `at` in the order render_statements() filled it.
class StatementWriter {
public:
  StatementWriter(CodeWriter &w, const EngineContext &c, const std::vector<std::string> &text)
      : w_(w), sources_(c.model.sources()), text_(text) {}

  /// `done`: the label that ends the block, where a `return` goes.
  void list(const std::vector<model::Stmt> &stmts, const std::string &done = {}) {
    if (!done.empty()) done_ = done;
    for (const auto &s : stmts) {
      if (s.kind == model::Stmt::Kind::Verbatim) {
        w_.verbatim(sources_, s.range, *s.verbatim, s.code_begin);
        next_ = 0;
        ++at_;
        continue;
      }
      if (s.kind == model::Stmt::Kind::Invoke) {  // a block call: its body inlined, in line
        // A `return` in the block's body ends this call: a label of its own after the body.
        if (!returns(s.then_block)) {
          list(s.then_block);
          continue;
        }
        const std::string outer = done_, call_done = fmt::format("gfec_return_{}", w_.new_label());
        done_ = call_done;
        list(s.then_block);
        done_ = outer;
        line(fmt::format("{}:;", call_done));
        continue;
      }
      point_at(s.range);
      switch (s.kind) {
      case model::Stmt::Kind::If: branches(s, ""); break;
      case model::Stmt::Kind::While:
      case model::Stmt::Kind::DoWhile:
      case model::Stmt::Kind::For: loop(s); break;
      case model::Stmt::Kind::Return:
        ++at_;
        line(fmt::format("goto {};", done_));
        break;
      default: line(text_.at(at_++)); break;
      }
    }
  }

private:
  /// `while (test) {`, `do {` ... `} while (test);`, or for a `for`, `for (init; test; step) {`
  /// where the two assignments need no temporaries, else the init, then a `while` whose body
  /// ends with the step (the same in C without `continue`, which the language does not have).
  void loop(const model::Stmt &s) {
    if (s.kind == model::Stmt::Kind::DoWhile) {
      const std::string &test = text_.at(at_++);
      line("do {");
      {
        CodeWriter::Scope body(w_);
        branch(s.then_block);
      }
      line(fmt::format("}} while ({});", test));
      return;
    }
    if (s.kind == model::Stmt::Kind::While) {
      line(fmt::format("while ({}) {{", text_.at(at_++)));
      {
        CodeWriter::Scope body(w_);
        branch(s.then_block);
      }
      line("}");
      return;
    }
    const std::string &init = text_.at(at_++);
    const std::string &test = text_.at(at_++);
    const std::string &step = text_.at(at_++);
    auto one = [](const std::string &t) { return t.find(';') == t.size() - 1; };
    if (one(init) && one(step)) {
      line(fmt::format("for ({}; {}; {}) {{", init.substr(0, init.size() - 1), test, step.substr(0, step.size() - 1)));
      {
        CodeWriter::Scope body(w_);
        branch(s.then_block);
      }
      line("}");
      return;
    }
    line(init);
    line(fmt::format("while ({}) {{", test));
    {
      CodeWriter::Scope body(w_);
      branch(s.then_block);
      line(step);
    }
    line("}");
  }

  /// `if (test) {`, the branches, and the closing brace; `prefix` is `} else ` in an else-if chain.
  void branches(const model::Stmt &s, const char *prefix) {
    line(fmt::format("{}if ({}) {{", prefix, text_.at(at_++)));
    {
      CodeWriter::Scope then(w_);
      branch(s.then_block);
    }
    if (s.else_if) {
      ++at_;  // the else block declares nothing: its one `if` declares where it stands
      const model::Stmt &next = s.else_block.front();
      point_at(next.range);
      branches(next, "} else ");
      return;
    }
    if (!s.else_block.empty()) {
      line("} else {");
      CodeWriter::Scope otherwise(w_);
      branch(s.else_block);
    } else {
      ++at_;
    }
    line("}");
  }

  /// A branch: its temporaries' declarations, then its statements.
  void branch(const std::vector<model::Stmt> &stmts) {
    const std::string &declared = text_.at(at_++);
    if (!declared.empty()) {
      std::size_t start = 0;
      for (std::size_t nl; (nl = declared.find('\n', start)) != std::string::npos; start = nl + 1)
        line(declared.substr(start, nl - start));
      line(declared.substr(start));
    }
    list(stmts);
  }

  /// A `#line` to the statement's line unless the next output line stands for it already.
  void point_at(const SourceRange &range) {
    if (!sources_.knows(range.file)) return;
    std::uint32_t chart_line = sources_.begin_of(range).line;
    if (next_ == 0 || range.file != file_ || chart_line != next_) w_.line_from(sources_, range);
    file_ = range.file;
    next_ = chart_line;
  }

  void line(const std::string &text) {
    w_.line(std::string_view(text));
    if (next_ != 0) ++next_;
  }

  CodeWriter &w_;
  const SourceManager &sources_;
  const std::vector<std::string> &text_;
  std::size_t at_ = 0;
  std::string done_;
  // The chart line the next output line stands for (0: unknown); a #line is needed only when it
  // is not the statement's own line.
  FileId file_ = 0;
  std::uint32_t next_ = 0;
};

}  // namespace

std::vector<std::string> c_statements(const EngineContext &c, const std::vector<model::Stmt> &stmts,
                                      Temporaries &temps) {
  Renderer r(c, temps);
  std::vector<std::string> text;
  render_statements(c, stmts, temps, r, text);
  return text;
}

void emit_statements(CodeWriter &w, const EngineContext &c, const std::vector<model::Stmt> &stmts,
                     const std::vector<std::string> &text) {
  // `return` ends the chart's block, not the engine function it is written into: a forward
  // `goto` to a label after the block's last statement, placed only where a `return` needs it.
  const bool any = returns(stmts);
  // Labels have a name space of their own in C: no variable or function can collide with it.
  const std::string done = any ? fmt::format("gfec_return_{}", w.new_label()) : std::string();
  StatementWriter(w, c, text).list(stmts, done);
  if (any) w.line("{}:;", done);
}

}  // namespace gfec::c_backend
