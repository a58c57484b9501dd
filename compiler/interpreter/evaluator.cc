#include "evaluator.h"

#include "machine.h"

#include "constant.h"

#include <fmt/format.h>

namespace gfec::interp {

namespace {

using model::Expr;
using model::Type;

bool is_arithmetic(BinaryOp op) {
  return op == BinaryOp::Mul || op == BinaryOp::Div || op == BinaryOp::Mod || op == BinaryOp::Add ||
         op == BinaryOp::Sub;
}

/// An operand as the message shows it: in the type the operation computes in.
std::string operand_text(const Value &v, Type t) {
  if (t == Type::Float)
    return fmt::format("{}", static_cast<float>(v.type == Type::Int ? static_cast<double>(v.i) : v.f));
  if (t == Type::Double) return fmt::format("{}", v.type == Type::Int ? static_cast<double>(v.i) : v.f);
  return fmt::format("{}", v.i);
}

/// `a op b` computed by the one evaluator (compiler/constant.h), as the validator folds it and
/// as the generated C computes it. What C leaves undefined stops the run, at `r`.
Value arith(BinaryOp op, const Value &a, const Value &b, SourceRange r) {
  constant::Outcome v = constant::binary(op, a, b);
  if (v) return v.value;
  const Type t = constant::common_type(a.type, b.type);
  switch (v.fault) {
  case constant::Fault::DivisionByZero: throw RuntimeError(r, "division by zero (undefined behaviour in C)");
  case constant::Fault::IntOverflow: {
    // INT_MIN / -1 and INT_MIN % -1 overflow in C even though the 64-bit result looks harmless.
    const Type in = a.type == Type::Time || b.type == Type::Time ? Type::Time : t;
    if (in == Type::Int)
      throw RuntimeError(r, fmt::format("int overflow: {} {} {} (undefined behaviour in C)", a.i, spelling(op), b.i));
    throw RuntimeError(r, fmt::format("{} overflow: {} {} {} does not fit in '{}'", model::type_name(in),
                                      constant::text(a), spelling(op), constant::text(b), model::type_name(in)));
  }
  case constant::Fault::NotFinite:
    // Results C would print or compare differently across platforms (infinities, NaNs).
    throw RuntimeError(r, fmt::format("the result of {} {} {} is not a finite number", operand_text(a, t), spelling(op),
                                      operand_text(b, t)));
  default:
    throw RuntimeError(r, fmt::format("invalid operands to '{}' (types '{}' and '{}')", spelling(op),
                                      model::type_name(a.type), model::type_name(b.type)));
  }
}

Value comparison(BinaryOp op, const Value &a, const Value &b, SourceRange r) {
  if (a.type == Type::Bool || b.type == Type::Bool) {
    Value x = convert(a, Type::Bool, r), y = convert(b, Type::Bool, r);
    return Value::of_bool(constant::compare(op, x.b, y.b));
  }
  if (a.type == Type::Duration && b.type == Type::Duration)  // both unsigned tick counts
    return Value::of_bool(constant::compare(op, static_cast<std::uint64_t>(a.i), static_cast<std::uint64_t>(b.i)));
  return arith(op, a, b, r);  // numbers: compared in their common type
}

/// A literal's value: the validator parsed its spelling once (model.h). A floating literal is
/// a double, as in C, unless the model types it otherwise (a folded float constant).
Value literal_float(const Expr &e) {
  return convert(Value::of_double(e.float_value), e.type == Type::Float ? Type::Float : Type::Double, e.range);
}

Value literal(const Expr &e) {
  switch (e.kind) {
  case Expr::Kind::Bool: return Value::of_bool(e.bool_value);
  case Expr::Kind::Int: return Value::of_integer(e.type, e.int_value);  // an integer or a time
  case Expr::Kind::Float: return literal_float(e);
  case Expr::Kind::Ticks: return Value::of_ticks(e.ticks);
  default: throw RuntimeError(e.range, "a string has no value in a chart");
  }
}

std::string call_text(const model::Function &fn, const std::vector<Value> &args) {
  std::string text = "call " + fn.name + "(";
  for (std::size_t i = 0; i < args.size(); ++i) text += (i ? ", " : "") + format_value(args[i]);
  return text + ")";
}

Value call(const Expr &e, Frame &f) {
  const model::Function &fn = f.model.functions.at(e.function());
  std::vector<Value> args;
  for (std::size_t i = 0; i < e.args.size(); ++i) {
    Value v = evaluate(e.args[i], f);
    args.push_back(i < fn.params.size() ? convert(v, fn.params[i].type, e.args[i].range) : v);
  }
  if (!f.env) throw RuntimeError(e.range, fmt::format("'{}' is called in a constant expression", fn.name));
  Value result = f.env->call(e.function(), args, f.tick);
  std::string text = call_text(fn, args);
  if (fn.result != Type::Void) {
    result = convert(result, fn.result, e.range);
    text += " = " + format_value(result);
  } else {
    result = Value::zero(Type::Void);
    result.type = Type::Void;
  }
  if (f.log) f.log->add(EventKind::Call, f.depth, std::move(text));
  return result;
}

Value unary(const Expr &e, Frame &f) {
  Value v = evaluate(e.args.at(0), f);
  if (e.unary_op == UnaryOp::Not) return Value::of_bool(!convert(v, Type::Bool, e.range).b);
  constant::Outcome r = constant::unary(e.unary_op, v);
  if (r) return r.value;
  if (r.fault == constant::Fault::IntOverflow) {
    if (v.type == Type::Int) throw RuntimeError(e.range, "int overflow: -(-2147483648) (undefined behaviour in C)");
    throw RuntimeError(e.range, fmt::format("{} overflow: -({}) does not fit in '{}'", model::type_name(v.type),
                                            constant::text(v), model::type_name(v.type)));
  }
  throw RuntimeError(e.range, "'-' needs a number");
}

Value binary(const Expr &e, Frame &f) {
  const BinaryOp op = e.binary_op;
  if (op == BinaryOp::And || op == BinaryOp::Or) {
    bool left = convert(evaluate(e.args.at(0), f), Type::Bool, e.args[0].range).b;
    if (op == BinaryOp::And ? !left : left) return Value::of_bool(left);
    return Value::of_bool(convert(evaluate(e.args.at(1), f), Type::Bool, e.args[1].range).b);
  }
  Value a = evaluate(e.args.at(0), f);
  Value b = evaluate(e.args.at(1), f);
  if (is_arithmetic(op)) return arith(op, a, b, e.range);
  return comparison(op, a, b, e.range);
}

/// A standard function: every operand evaluated, in order, then computed by the one evaluator;
/// `abs` of a type's lowest value overflows as `-x` does.
Value standard(const Expr &e, Frame &f) {
  std::vector<Value> args;
  for (const auto &a : e.args) args.push_back(evaluate(a, f));
  constant::Outcome r = constant::standard(e.builtin, args, e.type);
  if (r) return r.value;
  if (r.fault == constant::Fault::IntOverflow) {
    if (e.type == Type::Int) throw RuntimeError(e.range, "int overflow: abs(-2147483648) (undefined behaviour in C)");
    throw RuntimeError(e.range, fmt::format("{} overflow: abs({}) does not fit in '{}'", model::type_name(e.type),
                                            constant::text(args.at(0)), model::type_name(e.type)));
  }
  throw RuntimeError(e.range, fmt::format("invalid operands to '{}'", model::builtin_name(e.builtin)));
}

}  // namespace

Value evaluate(const Expr &e, Frame &f) {
  switch (e.kind) {
  case Expr::Kind::Bool:
  case Expr::Kind::Int:
  case Expr::Kind::Float:
  case Expr::Kind::String:
  case Expr::Kind::Ticks: return literal(e);
  case Expr::Kind::Var: return f.vars.at(e.var());
  case Expr::Kind::Const: {
    const model::Const &k = f.model.consts.at(e.constant());
    return convert(literal(k.value), k.type, e.range);
  }
  case Expr::Kind::Elapsed:
    // As a time (docs/language.md §4): its ticks times the period, a whole number of ms.
    if (e.type == Type::Time)
      return Value::of_time(static_cast<std::int64_t>(f.timers.at(e.place())) *
                            static_cast<std::int64_t>(f.chart.period_ms));
    return Value::of_ticks(f.timers.at(e.place()));
  case Expr::Kind::Now:  // the tick's number times the period: the first tick is at one period
    return Value::of_time(static_cast<std::int64_t>(f.tick) * static_cast<std::int64_t>(f.chart.period_ms));
  case Expr::Kind::Call: return call(e, f);
  case Expr::Kind::Unary: return unary(e, f);
  case Expr::Kind::Binary: return binary(e, f);
  case Expr::Kind::Paren: return evaluate(e.args.at(0), f);
  case Expr::Kind::Active:
  case Expr::Kind::Succeeded:
  case Expr::Kind::Failed: {
    // Sub-charts (docs/language.md "Sub-charts"): the state as it is now.
    if (!f.engine) throw RuntimeError(e.range, "a sub-chart's state cannot be read here");
    if (e.kind == Expr::Kind::Active) return Value::of_bool(f.engine->active(e.path));
    return Value::of_bool(f.engine->outcome(e.place(), e.kind == Expr::Kind::Succeeded ? 1 : -1));
  }
  case Expr::Kind::TeamCount: {
    // The other agents whose last report is the state, as the reports stand now.
    if (!f.reports) throw RuntimeError(e.range, "'team()' is read outside a team machine");
    int n = 0;
    for (std::size_t a = 0; a < f.reports->size(); ++a)
      if (static_cast<int>(a) != f.agent && (*f.reports)[a] == e.place()) ++n;
    return Value::of_int(n);
  }
  case Expr::Kind::Agent: return Value::of_int(f.agent);
  case Expr::Kind::ActionQ:
  case Expr::Kind::ActionA:
    if (!f.engine) throw RuntimeError(e.range, "an action's flags cannot be read here");
    return Value::of_bool(f.engine->action_flag(e.action(), e.kind == Expr::Kind::ActionA));
  case Expr::Kind::Convert: {
    const Value v = evaluate(e.args.at(0), f);
    constant::Outcome r = constant::conversion(v, e.type);
    if (r) return r.value;
    throw RuntimeError(
        e.range, fmt::format("{}({}): the value does not fit in '{}'", model::type_name(e.type),
                             v.type == Type::Float || v.type == Type::Double ? constant::text(v) : format_value(v),
                             model::type_name(e.type)));
  }
  case Expr::Kind::Builtin: return standard(e, f);
  case Expr::Kind::Config: break;
  default: throw RuntimeError(e.range, "this expression is not supported by the interpreter yet");
  }
  throw RuntimeError(e.range, "a config entry has no value in a chart");
}

namespace {

/// How a block ended: at its end, or by a `break` or `return` that the blocks around it honour.
enum class Flow { Next, Break, Return };

Flow run(const std::vector<model::Stmt> &block, Frame &f);
Flow run_one(const model::Stmt &s, Frame &f);

bool holds(const model::Stmt &s, Frame &f) { return convert(evaluate(s.expr, f), Type::Bool, s.expr.range).b; }

/// One pass more of loop `s`: a loop that runs away stops the run with a located error, so
/// that `gfec run` never hangs (docs/language.md §10).
void count_pass(const model::Stmt &s, std::uint64_t &passes) {
  if (++passes > kMaxLoopPasses)
    throw RuntimeError(s.range, fmt::format("this loop ran more than {} times in one tick: gfec run stops it "
                                            "(an engine on a target would hang)",
                                            kMaxLoopPasses));
}

Flow loop(const model::Stmt &s, Frame &f) {
  std::uint64_t passes = 0;
  if (s.kind == model::Stmt::Kind::For) run_one(s.else_block.front(), f);
  if (s.kind != model::Stmt::Kind::DoWhile && !holds(s, f)) return Flow::Next;
  for (;;) {
    count_pass(s, passes);
    Flow flow = run(s.then_block, f);
    if (flow == Flow::Return) return flow;
    if (flow == Flow::Break) return Flow::Next;
    if (s.kind == model::Stmt::Kind::For) run_one(s.else_block.back(), f);
    if (!holds(s, f)) return Flow::Next;
  }
}

Flow run(const std::vector<model::Stmt> &block, Frame &f) {
  for (const model::Stmt &s : block) {
    Flow flow = run_one(s, f);
    if (flow != Flow::Next) return flow;
  }
  return Flow::Next;
}

Flow run_one(const model::Stmt &s, Frame &f) {
  switch (s.kind) {
  case model::Stmt::Kind::While:
  case model::Stmt::Kind::DoWhile:
  case model::Stmt::Kind::For: return loop(s, f);
  case model::Stmt::Kind::Break: return Flow::Break;
  case model::Stmt::Kind::Return: return Flow::Return;
  case model::Stmt::Kind::Call: evaluate(s.expr, f); break;
  case model::Stmt::Kind::Assign: {
    Value &slot = f.vars.at(s.var);
    Value v = evaluate(s.expr, f);
    if (s.op != AssignOp::Set) v = arith(s.op == AssignOp::Add ? BinaryOp::Add : BinaryOp::Sub, slot, v, s.range);
    slot = convert(v, slot.type, s.range);
    if (f.log)
      f.log->add(EventKind::Assign, f.depth,
                 fmt::format("set {} = {}", f.chart.vars.at(s.var).name, format_value(slot)));
    break;
  }
  case model::Stmt::Kind::Verbatim:
    if (f.log) f.log->add(EventKind::Note, f.depth, "note verbatim code is not run by the interpreter");
    break;
  case model::Stmt::Kind::If: return run(holds(s, f) ? s.then_block : s.else_block, f);
  case model::Stmt::Kind::Invoke:
    // The block's body, inlined: a `return` in it ends this call only.
    run(s.then_block, f);
    break;
  }
  return Flow::Next;
}

}  // namespace

void execute(const std::vector<model::Stmt> &block, Frame &f) { run(block, f); }

}  // namespace gfec::interp
