#include "validate/expr.h"

#include "validate/blocks.h"
#include "validate/fold.h"
#include "validate/suggest.h"
#include "validate/types.h"

#include <fmt/format.h>

#include <cfloat>
#include <algorithm>
#include <cmath>

namespace gfec::validation {

namespace {

using K = model::Expr::Kind;
using model::Type;

model::Expr make(K kind, Type type, SourceRange range) {
  model::Expr e;
  e.kind = kind;
  e.type = type;
  e.range = range;
  return e;
}

/// The unknown names already reported where `s` stands.
std::set<std::string> &seen(ExprScope &s) { return s.chart ? s.chart->unknown : s.cx.file_unknown; }

/// A duration literal. Its period is required where it counts ticks (compared with a timer:
/// lower_binary); as a `time` (as_time) it counts milliseconds and needs none.
std::optional<model::Expr> lower_duration(const ast::Expr &e, ExprScope &s) {
  model::Expr d = make(K::Ticks, Type::Duration, e.range);
  d.float_value = e.duration_ms;
  d.text = e.text();
  if (s.chart) d.ticks = to_ticks(d.float_value, s.chart->out.period_ms);
  return d;
}

std::optional<model::Expr> const_ref(model::ConstId index, SourceRange at, ExprScope &s) {
  s.cx.consts[index].used = true;
  if (!fold_const(s.cx, index)) return std::nullopt;
  if (s.chart) s.chart->consts.insert(index);
  model::Expr e = make(K::Const, s.cx.model.consts[index].type, at);
  e.refer_to(index);
  return check_constant(std::move(e), s.cx.model, s.cx.diag);  // folded: the constant's value
}

/// A name that denotes something other than a value, used as one.
std::nullopt_t not_a_value(ExprScope &s, const ast::Name &name, const Symbol &sym) {
  auto &d = s.cx.diag.error(name.range, ErrorKind::TypeMismatch,
                            fmt::format("'{}' is {}, not a value", name.text, with_article(sym.kind)));
  if (sym.kind == Sym::Function) d.note(sym.range, fmt::format("to call it, write '{}()'", name.text));
  if (sym.kind == Sym::Place) {
    // A place as a condition: a beginner means "while it is active".
    d.fix(name.range, fmt::format("active({})", name.text))
        .note(fmt::format("to test whether it is active, write 'active({})'", name.text));
  }
  if (sym.kind == Sym::Place || sym.kind == Sym::State)
    d.note(fmt::format("'elapsed({})' is the time it has been active", name.text));
  return std::nullopt;
}

std::optional<model::Expr> lower_name(const ast::Expr &e, ExprScope &s) {
  const ast::Name &name = e.name;
  if (name.text.empty()) return std::nullopt;
  if (s.chart) {
    if (const Symbol *sym = s.chart->names.resolve(name)) {
      if (sym->kind == Sym::Const) return const_ref(sym->id<model::ConstId>(), e.range, s);
      if (sym->kind != Sym::Var) return not_a_value(s, name, *sym);
      if (s.constant) {
        s.cx.diag.error(name.range, ErrorKind::NotConstant,
                        fmt::format("a constant expression cannot read variable '{}'", name.text));
        return std::nullopt;
      }
      if (sym->index < 0) return std::nullopt;  // its declaration has an error
      const model::VarId var = sym->id<model::VarId>();
      model::Expr v = make(K::Var, s.chart->out.vars[var].type, e.range);
      v.refer_to(var);
      return v;
    }
  }
  if (const Symbol *sym = s.cx.c_names.resolve(name)) {
    if (sym->kind == Sym::Const) return const_ref(sym->id<model::ConstId>(), e.range, s);
    return not_a_value(s, name, *sym);
  }
  std::vector<const Symbol *> candidates;
  if (s.chart) candidates = s.chart->names.of({Sym::Var, Sym::Const});
  for (const Symbol *c : s.cx.c_names.of({Sym::Const})) candidates.push_back(c);
  report_unknown(s.cx.diag, seen(s), name, "name", candidates);
  return std::nullopt;
}

std::optional<model::Expr> lower_elapsed(const ast::Expr &e, ExprScope &s, bool statement) {
  Diagnostics &diag = s.cx.diag;
  if (!s.chart) {
    diag.error(e.range, ErrorKind::Elapsed, "'elapsed' can only be used inside an sfc or fsm");
    return std::nullopt;
  }
  if (s.constant) {
    diag.error(e.range, ErrorKind::NotConstant, "a constant expression cannot read 'elapsed()'");
    return std::nullopt;
  }
  if (e.args.size() != 1 || !e.args[0] || e.args[0]->kind != ast::Expr::Kind::Name) {
    diag.error(e.range, ErrorKind::Elapsed,
               fmt::format("'elapsed' takes one argument: the name of a {}", s.chart->place_word()));
    return std::nullopt;
  }
  model::PlaceId place = resolve_place(*s.chart, s.cx, e.args[0]->name);
  if (!place) return std::nullopt;
  require_period(s, e.range, fmt::format("'elapsed({})'", e.args[0]->name.text));
  s.chart->out.places[place].timed = true;
  if (statement) {
    diag.error(e.range, ErrorKind::TypeMismatch, "'elapsed()' as a statement has no effect");
    return std::nullopt;
  }
  model::Expr x = make(K::Elapsed, Type::Duration, e.range);
  x.refer_to(place);
  return x;
}

/// The kind of a misused built-in that reads a chart's state: each has its own.
ErrorKind builtin_kind(std::string_view f) {
  return f == "active" ? ErrorKind::Active : f == "succeeded" ? ErrorKind::Succeeded : ErrorKind::Failed;
}

/// The checks every built-in that reads a chart's state shares (`elapsed` has its own wording):
/// inside a chart, not in a constant, not as a statement, one argument.
bool builtin_allowed(const ast::Expr &e, ExprScope &s, bool statement, const char *argument) {
  Diagnostics &diag = s.cx.diag;
  std::string_view f = e.name.text;
  if (!s.chart) {
    diag.error(e.range, builtin_kind(f), fmt::format("'{}' can only be used inside an sfc or fsm", f));
    return false;
  }
  if (s.constant) {
    diag.error(e.range, ErrorKind::NotConstant, fmt::format("a constant expression cannot read '{}()'", f));
    return false;
  }
  if (statement) {
    diag.error(e.range, ErrorKind::TypeMismatch, fmt::format("'{}()' as a statement has no effect", f));
    return false;
  }
  if (e.args.size() != 1 || !e.args[0]) {
    diag.error(e.range, builtin_kind(f), fmt::format("'{}' takes one argument: {}", f, argument));
    return false;
  }
  return true;
}

/// Where a team built-in (`team(S)`, `agent()`) may stand: in a team machine's expressions, not
/// in an initialiser. False after reporting why not; silently false when the chart's own
/// `team` declaration has an error (reported already).
bool team_context(const ast::Expr &e, ExprScope &s, const std::string &what) {
  Diagnostics &diag = s.cx.diag;
  if (s.chart && s.chart->out.team == 0 && !s.chart->ast.teams.empty()) return false;
  if (!s.chart || s.chart->out.team == 0) {
    auto &d = diag.error(e.range, ErrorKind::Team, fmt::format("'{}' can only be used in a team machine", what));
    if (s.chart && s.chart->is_fsm())
      d.note(s.chart->ast.name.range,
             fmt::format("make fsm '{}' one by declaring its team size in it, e.g. 'team 2;'", s.chart->out.name));
    return false;
  }
  if (s.constant) {
    diag.error(e.range, ErrorKind::NotConstant, fmt::format("a constant expression cannot read '{}'", what));
    return false;
  }
  return true;
}

/// The named action of the chart that `arg` names (a plain name), or none.
model::ActionId named_action(const ast::Expr &arg, const ExprScope &s) {
  if (!s.chart || arg.kind != ast::Expr::Kind::Name) return {};
  const auto &actions = s.chart->ast.actions;
  for (std::size_t i = 0; i < actions.size(); ++i)
    if (actions[i].name.text == arg.name.text) return model::ActionId(i);
  return {};
}

/// `active(A)` and `running(A)` of a named action A: its Q, and whether its body runs, as the
/// latest action control left them (docs/iec.md "Action flags").
model::Expr action_flag(const ast::Expr &e, ExprScope &s, model::ActionId action, bool running) {
  model::Expr x = make(running ? K::ActionA : K::ActionQ, Type::Bool, e.range);
  x.refer_to(action);
  s.chart->out.reads_action_flags = true;
  return x;
}

/// `active(P)`, `active(P.Q.R)`: each name after the first is a place or state of the chart
/// the previous one runs. `active(A)` of a named action A is its Q.
std::optional<model::Expr> lower_active(const ast::Expr &e, ExprScope &s, bool statement) {
  if (!builtin_allowed(e, s, statement, "a place or state, or a path 'P.Q' into its sub-chart")) return std::nullopt;
  const ast::Expr &arg = *e.args[0];
  if (model::ActionId a = named_action(arg, s)) return action_flag(e, s, a, false);
  std::vector<ast::Name> names;
  if (arg.kind == ast::Expr::Kind::Name) names.push_back(arg.name);
  else if (arg.kind == ast::Expr::Kind::Path)
    for (const ast::Expr *part : arg.args) names.push_back(part->name);
  else {
    s.cx.diag.error(arg.range, ErrorKind::Active,
                    "'active' takes one argument: a place or state, or a path 'P.Q' into its sub-chart");
    return std::nullopt;
  }
  model::Expr x = make(K::Active, Type::Bool, e.range);
  model::PlaceId place = resolve_place(*s.chart, s.cx, names[0]);
  if (!place) return std::nullopt;
  x.path.push_back(place);
  model::ChartId chart = s.chart->index;
  for (std::size_t k = 1; k < names.size(); ++k) {
    const ast::Chart &holder = *s.cx.charts[chart];
    const ast::Place &via = holder.places[place.index()];
    model::ChartId sub = s.cx.runs[chart][place];
    if (!sub) {
      if (via.runs()) return std::nullopt;  // its `runs` has an error of its own
      s.cx.diag
          .error(names[k].range, ErrorKind::UnknownName,
                 fmt::format("'{}' runs no sub-chart, so '{}' names nothing in it", via.name.text, names[k].text))
          .note(via.name.range, fmt::format("'{}' declared here", via.name.text));
      return std::nullopt;
    }
    const ast::Chart &inner = *s.cx.charts[sub];
    const char *word = inner.kind == ast::Chart::Kind::Fsm ? "state" : "place";
    place = model::PlaceId();
    std::vector<Symbol> symbols;
    for (std::size_t i = 0; i < inner.places.size(); ++i) {
      const ast::Place &p = inner.places[i];
      if (p.name.text == names[k].text && !place) place = model::PlaceId(i);
      symbols.push_back({inner.kind == ast::Chart::Kind::Fsm ? Sym::State : Sym::Place, static_cast<int>(i),
                         p.name.text, p.name.range});
    }
    if (!place) {
      auto &d = s.cx.diag.error(names[k].range, ErrorKind::UnknownName,
                                fmt::format("unknown {} '{}' in {} '{}', which '{}' runs", word, names[k].text,
                                            inner.kind == ast::Chart::Kind::Fsm ? "fsm" : "sfc", inner.name.text,
                                            via.name.text));
      std::vector<const Symbol *> candidates;
      for (const Symbol &sym : symbols) candidates.push_back(&sym);
      suggest(d, names[k].text, candidates);
      return std::nullopt;
    }
    // Looked up in the sub-chart's tree, not a namespace: recorded here for the language server.
    if (s.cx.uses)
      s.cx.uses->list.push_back({names[k].range, inner.places[place.index()].name.range,
                                 inner.kind == ast::Chart::Kind::Fsm ? Sym::State : Sym::Place,
                                 static_cast<int>(place.index())});
    x.path.push_back(place);
    chart = sub;
  }
  return x;
}

/// `succeeded(P)` / `failed(P)`: P runs an fsm, which ends in a success or failure state.
std::optional<model::Expr> lower_outcome(const ast::Expr &e, ExprScope &s, bool statement) {
  std::string_view f = e.name.text;
  if (!builtin_allowed(e, s, statement, "a place or state that runs an fsm")) return std::nullopt;
  const ast::Expr &arg = *e.args[0];
  if (arg.kind != ast::Expr::Kind::Name) {
    s.cx.diag.error(arg.range, builtin_kind(f),
                    fmt::format("'{}' takes one argument: a place or state that runs an fsm", f));
    return std::nullopt;
  }
  model::PlaceId place = resolve_place(*s.chart, s.cx, arg.name);
  if (!place) return std::nullopt;
  const ast::Place &p = s.chart->ast.places[place.index()];
  model::ChartId sub = s.cx.runs[s.chart->index][place];
  if (p.runs() && !sub) return std::nullopt;  // its `runs` has an error of its own
  if (!sub || s.cx.model.charts[sub].kind != model::Chart::Kind::Fsm) {
    auto &d = s.cx.diag.error(
        e.range, ErrorKind::Subchart,
        !sub
            ? fmt::format("'{}({})': {} '{}' runs no sub-chart", f, arg.name.text, s.chart->place_word(), arg.name.text)
            : fmt::format("'{}({})': {} '{}' runs sfc '{}', which never {}", f, arg.name.text, s.chart->place_word(),
                          arg.name.text, p.runs()->text, f == "succeeded" ? "succeeds" : "fails"));
    d.note(
        !sub ? p.name.range : p.runs()->range,
        !sub ? fmt::format("only a place or state that runs an fsm succeeds or fails ('{} {} runs FSM')",
                           s.chart->place_word(), arg.name.text)
             : fmt::format("only an fsm succeeds or fails; 'active({}.P)' reads the places of an sfc", arg.name.text));
    return std::nullopt;
  }
  model::Expr x = make(f == "succeeded" ? K::Succeeded : K::Failed, Type::Bool, e.range);
  x.refer_to(place);
  return x;
}

/// `team(S)`: how many other agents last reported state S (docs/language.md "Teams").
std::optional<model::Expr> lower_team(const ast::Expr &e, ExprScope &s, bool statement) {
  if (!team_context(e, s, "team()")) return std::nullopt;
  Diagnostics &diag = s.cx.diag;
  if (e.args.size() != 1 || !e.args[0] || e.args[0]->kind != ast::Expr::Kind::Name) {
    diag.error(e.range, ErrorKind::Team, "'team' takes one argument: the name of a state");
    return std::nullopt;
  }
  model::PlaceId state = resolve_place(*s.chart, s.cx, e.args[0]->name);
  if (!state) return std::nullopt;
  if (statement) {
    diag.error(e.range, ErrorKind::TypeMismatch, "'team()' as a statement has no effect");
    return std::nullopt;
  }
  model::Expr x = make(K::TeamCount, Type::Int, e.range);
  x.refer_to(state);
  return x;
}

/// `agent()`: this engine's agent number.
std::optional<model::Expr> lower_agent(const ast::Expr &e, ExprScope &s, bool statement) {
  if (!team_context(e, s, "agent()")) return std::nullopt;
  if (!e.args.empty()) {
    s.cx.diag.error(e.range, ErrorKind::ArgumentCount,
                    fmt::format("'agent' takes no arguments (have {})", e.args.size()));
    return std::nullopt;
  }
  if (statement) {
    s.cx.diag.error(e.range, ErrorKind::TypeMismatch, "'agent()' as a statement has no effect");
    return std::nullopt;
  }
  return make(K::Agent, Type::Int, e.range);
}

/// `now()`: the time of the tick (docs/language.md §15), for the timers of blocks. In a block the
/// period is its holder's, asked for where the instance is declared.
std::optional<model::Expr> lower_now(const ast::Expr &e, ExprScope &s, bool statement) {
  if (!s.chart || s.constant) {
    s.cx.diag.error(e.range, ErrorKind::NotConstant, "'now()' is read only in a chart or a block, not in a constant");
    return std::nullopt;
  }
  if (!e.args.empty()) {
    s.cx.diag.error(e.range, ErrorKind::ArgumentCount,
                    fmt::format("'now' takes no arguments (have {})", e.args.size()));
    return std::nullopt;
  }
  if (statement) {
    s.cx.diag.error(e.range, ErrorKind::TypeMismatch, "'now()' as a statement has no effect");
    return std::nullopt;
  }
  if (s.chart->index.valid()) {
    require_period(s, e.range, "'now()'");
    for (const auto &runs : s.cx.runs)
      for (model::ChartId r : runs)
        if (r == s.chart->index) {
          s.cx.diag.error(e.range, ErrorKind::NotSupported,
                          "'now()' in a sub-chart is not supported yet: read it in the chart that runs it");
          return std::nullopt;
        }
  }
  s.chart->out.clock = true;
  return make(K::Now, Type::Time, e.range);
}

/// Checks the lowered arguments of a call of `f` against its prototype.
bool check_arguments(const ast::Expr &call, const model::Function &f,
                     const std::vector<std::optional<model::Expr>> &args, Diagnostics &diag) {
  if (args.size() != f.params.size()) {
    diag.error(call.range, ErrorKind::ArgumentCount,
               fmt::format("too {} arguments to function '{}' (expected {}, have {})",
                           args.size() > f.params.size() ? "many" : "few", f.name, f.params.size(), args.size()))
        .note(f.range, fmt::format("'{}' declared here", f.name));
    return false;
  }
  bool ok = true;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (!args[i]) {
      ok = false;
      continue;
    }
    Type want = f.params[i].type;
    if (assignable(want, args[i]->type)) continue;
    diag.error(args[i]->range, ErrorKind::TypeMismatch,
               fmt::format("incompatible type for argument {} of '{}': expected {}, have {}", i + 1, f.name,
                           quoted(want), quoted(args[i]->type)))
        .note(f.range, fmt::format("'{}' declared here", f.name));
    ok = false;
  }
  return ok;
}

/// The note every misuse of a duration gets: durations are for timers and times only.
void duration_note(Diagnostic &d, Type a, Type b) {
  if (a == Type::Time || b == Type::Time)
    d.note("a 'time' mixes only with times and durations (and is multiplied or divided by an integer), as in "
           "'t + 100ms'; a number is never a time");
  else if (a == Type::Duration || b == Type::Duration)
    d.note("a duration can only be compared with another duration, as in 'elapsed(P) >= 500ms'");
}

/// The largest number of milliseconds a `time` constant is kept exact in (a double's integers).
constexpr double kMaxTimeMs = 9007199254740992.0;

/// `x`, a duration or `elapsed(P)`, as a `time` (docs/language.md §4): a literal becomes its
/// milliseconds, which must be whole; `elapsed(P)` its ticks times the period, which must be a
/// whole number of milliseconds then. False after reporting why not.
bool as_time(model::Expr &x, ExprScope &s) {
  if (x.type != Type::Duration) return true;
  switch (x.kind) {
  case K::Ticks: {
    const double ms = x.float_value;
    if (ms != std::floor(ms) || std::fabs(ms) > kMaxTimeMs) {
      s.cx.diag.error(
          x.range, ErrorKind::TypeMismatch,
          ms != std::floor(ms)
              ? fmt::format("duration '{}' is not a whole number of milliseconds, which a 'time' counts", x.text.str())
              : fmt::format("duration '{}' is too large for a 'time' constant", x.text.str()));
      return false;
    }
    x.kind = K::Int;
    x.type = Type::Time;
    x.int_value = static_cast<std::int64_t>(ms);
    return true;
  }
  case K::Elapsed: {
    const double period = s.chart ? s.chart->out.period_ms : 0;
    if (period > 0 && period != std::floor(period)) {
      s.cx.diag.error(x.range, ErrorKind::TypeMismatch,
                      fmt::format("'{}' as a 'time' needs a period of whole milliseconds, not {}ms",
                                  source_text(s.cx.model, x.range), period));
      return false;
    }
    x.type = Type::Time;
    return true;
  }
  case K::Paren:
    if (x.args.empty() || !as_time(x.args[0], s)) return false;
    x.type = Type::Time;
    return true;
  default: return true;
  }
}

/// An `int` constant (a literal, a folded expression, a constant's name) that meets a sized
/// integer takes that type (§4), checked to fit: `x + 1` for an int16 `x` adds an int16 1, and
/// `u < -1` for a uint8 `u` is an error at the -1. False after reporting it.
bool retype_constant(model::Expr &x, Type to, ExprScope &s) {
  // A literal beyond int's range is an int64 literal that any integer type holding it takes.
  const bool big = x.kind == K::Int && !x.folded && x.type == Type::Int64 && !x.text.empty();
  if (big && (to == Type::Int || to == Type::Bool)) {
    s.cx.diag.error(x.range, ErrorKind::NotConstant,
                    fmt::format("integer constant '{}' is too large for 'int'", x.text.str()));
    return false;
  }
  if (!(x.type == Type::Int || big) || !model::is_sized(to)) return true;
  auto v = evaluate(x, s.cx.model, nullptr);
  if (!v) return true;  // not a constant: the typing rules decide
  auto literal = to_literal(*v, to, x.range, s.cx.diag, nullptr);
  if (!literal) return false;
  x = std::move(*literal);
  return true;
}

/// The message's advice where two integer types do not mix: the conversion that says which.
void conversion_note(Diagnostic &d, Type to, Type from) {
  if (model::is_integer(to) && (model::is_integer(from) || from == Type::Float || from == Type::Double))
    d.note(fmt::format("'{}' does not hold every value of '{}': convert explicitly, e.g. '{}(x)', which stops the "
                       "run where a value does not fit",
                       model::type_name(to), model::type_name(from), model::type_name(to)));
}

std::optional<model::Expr> lower_unary(const ast::Expr &e, ExprScope &s) {
  if (e.args.size() != 1) return std::nullopt;
  auto operand = lower_expr(e.args[0], s);
  if (!operand) return std::nullopt;
  auto type = unary_type(e.unary_op, operand->type);
  if (!type) {
    auto &d = s.cx.diag.error(e.range, ErrorKind::TypeMismatch,
                              fmt::format("invalid operand to unary '{}' (have {})", written_operator(e, s.cx.sources),
                                          quoted(operand->type)));
    duration_note(d, operand->type, operand->type);
    return std::nullopt;
  }
  if (*type == Type::Time && !as_time(*operand, s)) return std::nullopt;
  model::Expr x = make(K::Unary, *type, e.range);
  x.unary_op = e.unary_op;
  x.args.push_back(std::move(*operand));
  return x;
}

/// Timers count whole ticks (docs/language.md §5.3): a duration is rounded up to them, which is
/// exact for `elapsed(P) >= d` and `elapsed(P) < d` (and their mirror images) and not for the
/// other comparisons: at period 10ms, `elapsed(P) > 25ms` is `ticks > 3`, true from 40 ms on.
void warn_timer_rounding(const ast::Expr &e, const model::Expr &a, const model::Expr &b, ExprScope &s) {
  const bool right = b.kind == K::Ticks;
  const model::Expr &duration = right ? b : a;
  const double period = s.chart ? s.chart->out.period_ms : 0;
  if (duration.kind != K::Ticks || period <= 0 || duration.ticks >= kBeyondTimers) return;
  const BinaryOp op = e.binary_op;
  if (op == (right ? BinaryOp::Ge : BinaryOp::Le) || op == (right ? BinaryOp::Lt : BinaryOp::Gt)) return;
  const double periods = duration.float_value / period;
  if (std::fabs(periods - std::round(periods)) < 1e-9) return;
  const model::Model &m = s.cx.model;
  const std::string rounded = fmt::format("{}ms", static_cast<double>(duration.ticks) * period);
  const std::string written = written_operator(e, s.cx.sources);
  const std::string means = right ? fmt::format("{} {} {}", source_text(m, a.range), written, rounded)
                                  : fmt::format("{} {} {}", rounded, written, source_text(m, b.range));
  s.cx.diag.warning(Warning::TimerRounding, duration.range,
                    fmt::format("{} is not a whole number of periods ({}ms): timers count whole ticks, so '{}' "
                                "means '{}'",
                                source_text(m, duration.range), period, source_text(m, e.range), means));
}

std::optional<model::Expr> lower_binary(const ast::Expr &e, ExprScope &s) {
  if (e.args.size() != 2) return std::nullopt;
  auto a = lower_expr(e.args[0], s);
  auto b = lower_expr(e.args[1], s);
  if (!a || !b) return std::nullopt;
  if (!retype_constant(*b, a->type, s) || !retype_constant(*a, b->type, s)) return std::nullopt;
  auto type = binary_type(e.binary_op, a->type, b->type);
  if (!type) {
    auto &d = s.cx.diag.error(e.range, ErrorKind::TypeMismatch,
                              fmt::format("invalid operands to binary '{}' (have {} and {})",
                                          written_operator(e, s.cx.sources), quoted(a->type), quoted(b->type)));
    duration_note(d, a->type, b->type);
    if (model::is_integer(a->type) && model::is_integer(b->type))
      d.note(fmt::format("'{}' and '{}' do not mix: neither holds every value of the other; convert one, e.g. "
                         "'{}(x)' or '{}(x)'",
                         model::type_name(a->type), model::type_name(b->type), model::type_name(a->type),
                         model::type_name(b->type)));
    return std::nullopt;
  }
  if (a->type == Type::Duration && b->type == Type::Duration) {
    // Compared in whole ticks (§5.3): the period is needed ('elapsed' asked for it already).
    for (const model::Expr *d : {&*a, &*b})
      if (s.chart && d->kind == K::Ticks) require_period(s, d->range, fmt::format("duration '{}'", d->text.str()));
    warn_timer_rounding(e, *a, *b, s);
  } else if ((*type == Type::Time || a->type == Type::Time || b->type == Type::Time) &&
             (!as_time(*a, s) || !as_time(*b, s))) {
    return std::nullopt;
  }
  if (divides_by_zero(e.binary_op, *a, *b, e.range, s.cx)) return std::nullopt;
  model::Expr x = make(K::Binary, *type, e.range);
  x.binary_op = e.binary_op;
  x.args.push_back(std::move(*a));
  x.args.push_back(std::move(*b));
  return x;
}

/// A constant converted to `to` (an assignment, an argument) as C converts it: a double past
/// int's range, or past float's, would be undefined behaviour or -Woverflow in the C; an error
/// at the value instead, as for a constant's initialiser.
bool constant_fits(const model::Expr &x, Type to, ExprScope &s) {
  if (x.type == to || !model::is_numeric(x.type) || !model::is_numeric(to) || x.type == Type::Int) return true;
  auto v = evaluate(x, s.cx.model, nullptr);
  if (!v || v->type == Type::Int) return true;
  double d = v->f;
  if (to == Type::Int && !(d > -2147483649.0 && d < 2147483648.0)) {
    s.cx.diag.error(x.range, ErrorKind::NotConstant, fmt::format("value {} does not fit in 'int'", d));
    return false;
  }
  if (to == Type::Float && std::isfinite(d) && std::fabs(d) > static_cast<double>(FLT_MAX)) {
    s.cx.diag.error(x.range, ErrorKind::NotConstant, fmt::format("value {} is too large for 'float'", d));
    return false;
  }
  if (underflows_float(*v, to)) {
    s.cx.diag.error(x.range, ErrorKind::NotConstant,
                    fmt::format("value {} is too small for 'float': it would be 0", d));
    return false;
  }
  return true;
}

std::optional<model::Stmt> lower_assign(const ast::Stmt &st, ExprScope &s) {
  Diagnostics &diag = s.cx.diag;
  if (st.target && s.chart && st.target->text.find('.') != std::string_view::npos) return lower_member_assign(st, s);
  auto value = lower_expr(st.value.get(), s);  // first: its errors are independent of the target's
  if (!st.target || st.target->text.empty() || !s.chart) return std::nullopt;  // a recovered syntax error
  const ast::Name &target = *st.target;
  const Symbol *sym = s.chart->names.resolve(target);
  if (!sym) sym = s.cx.c_names.resolve(target);
  if (!sym) {
    report_unknown(s.cx.diag, seen(s), target, "variable", s.chart->names.of({Sym::Var}));
    return std::nullopt;
  }
  if (sym->kind != Sym::Var) {
    diag.error(target.range, ErrorKind::NotAssignable,
               fmt::format("cannot assign to {} '{}'", describe(sym->kind), target.text))
        .note(sym->range, fmt::format("'{}' declared here; only a 'var' can be assigned", target.text));
    return std::nullopt;
  }
  if (sym->index < 0) return std::nullopt;
  const model::Var &var = s.chart->out.vars[sym->id<model::VarId>()];
  if (var.role == model::VarRole::In) {  // an `inout` may be assigned: that is what it is for
    auto &d = diag.error(
        target.range, ErrorKind::NotAssignable,
        fmt::format("cannot assign to input '{}': the chart's caller sets it before each tick", target.text));
    // (An IEC program's %I variable that it assigns is lowered to an `inout`, never seen here.)
    d.note(var.range,
           fmt::format("'{}' declared 'in' here; declare it 'var', 'out' or 'inout' to assign it", target.text));
    return std::nullopt;
  }
  Type type = var.type;
  if (st.assign_op != AssignOp::Set && !model::is_numeric(type) && type != Type::Time) {
    diag.error(target.range, ErrorKind::TypeMismatch,
               fmt::format("operator '{}' needs a numeric variable; '{}' has type {}", spelling(st.assign_op),
                           target.text, quoted(type)));
    return std::nullopt;
  }
  if (!value) return std::nullopt;
  if (!retype_constant(*value, type, s)) return std::nullopt;
  if (!assignable(type, value->type)) {
    auto &d = diag.error(value->range, ErrorKind::TypeMismatch,
                         fmt::format("incompatible types when assigning to '{}' of type {} from type {}", target.text,
                                     quoted(type), quoted(value->type)));
    duration_note(d, value->type, type);
    conversion_note(d, type, value->type);
    return std::nullopt;
  }
  if (type == Type::Time && !as_time(*value, s)) return std::nullopt;
  if (!constant_fits(*value, type, s)) return std::nullopt;
  model::Stmt out;
  out.kind = model::Stmt::Kind::Assign;
  out.range = st.range;
  out.var = sym->id<model::VarId>();
  out.op = st.assign_op;
  out.expr = std::move(*value);
  return out;
}

}  // namespace

bool divides_by_zero(BinaryOp op, const model::Expr &a, const model::Expr &b, SourceRange whole, Context &cx) {
  if (op != BinaryOp::Div && op != BinaryOp::Mod) return false;
  // Both constant: folding reports it.
  auto divisor = evaluate(b, cx.model, nullptr);
  if (!divisor || (model::is_integer(divisor->type) ? divisor->i != 0 : divisor->f != 0) ||
      evaluate(a, cx.model, nullptr))
    return false;
  cx.diag.error(b.range, ErrorKind::DivisionByZero,
                fmt::format("{} by zero: '{}' is undefined in C", op == BinaryOp::Div ? "division" : "remainder",
                            source_text(cx.model, whole)));
  return true;
}

void require_period(ExprScope &s, SourceRange at, const std::string &what) {
  ChartScope &c = *s.chart;
  if (c.out.period_ms > 0 || c.period_reported) return;
  c.period_reported = true;
  auto &d =
      s.cx.diag.error(at, ErrorKind::MissingPeriod,
                      fmt::format("{} needs a period, but {} '{}' declares none", what, c.kind_word(), c.out.name));
  bool sub_chart = false;
  for (const auto &runs : s.cx.runs)
    for (model::ChartId r : runs) sub_chart = sub_chart || r == c.index;
  if (sub_chart)
    d.note(c.ast.name.range,
           "a sub-chart takes the period of the chart that runs it; declare one there, e.g. 'period 10ms;'");
  else d.note(c.ast.name.range, "declare one in the chart, e.g. 'period 10ms;'");
}

unsigned long to_ticks(double ms, double period_ms) {
  if (period_ms <= 0 || ms <= 0) return 0;
  // Durations are read as decimals (0.1s is 100.00000000000001 ms): a hair under a whole tick
  // is that tick, not the next one.
  // But a positive duration is at least one tick, however short (1e-9ms is not "at once").
  double ticks = std::max(1.0, std::ceil(ms / period_ms - 1e-9));
  // Timers saturate at UINT32_MAX: any duration beyond is "never reached", and converting a
  // double past the integer's range would be undefined (1e18s once became 0 ticks).
  if (!(ticks < kBeyondTimers)) return kBeyondTimers;
  return static_cast<unsigned long>(ticks);
}

Diagnostic *report_unknown(Diagnostics &diag, std::set<std::string> &seen, const ast::Name &name, const char *what,
                           const std::vector<const Symbol *> &candidates) {
  if (!seen.insert(fmt::format("{} {}", what, name.text)).second) return nullptr;
  auto &d = diag.error(name.range, ErrorKind::UnknownName, fmt::format("unknown {} '{}'", what, name.text));
  suggest(d, name.text, candidates);
  return &d;
}

model::PlaceId resolve_place(ChartScope &chart, Context &cx, const ast::Name &name) {
  if (name.text.empty()) return {};
  const Symbol *sym = chart.names.resolve(name);
  if (sym && (sym->kind == Sym::Place || sym->kind == Sym::State)) return sym->id<model::PlaceId>();
  // A place that lost its name to an earlier declaration: the clash is reported already.
  for (std::size_t i = 0; sym && i < chart.ast.places.size(); ++i)
    if (chart.ast.places[i].name.text == name.text) return model::PlaceId(i);
  if (sym) {
    cx.diag
        .error(name.range, ErrorKind::TypeMismatch,
               fmt::format("'{}' is {}, not a {}", name.text, with_article(sym->kind), chart.place_word()))
        .note(sym->range, fmt::format("'{}' declared here", name.text));
    return {};
  }
  report_unknown(cx.diag, chart.unknown, name, chart.place_word(), chart.names.of({Sym::Place, Sym::State}));
  return {};
}

std::optional<model::Expr> lower_expr(const ast::Expr *e, ExprScope &s) {
  if (!e) return std::nullopt;  // the parser reported what is missing
  switch (e->kind) {
  case ast::Expr::Kind::Bool: {
    model::Expr x = make(K::Bool, Type::Bool, e->range);
    x.bool_value = e->bool_value;
    return x;
  }
  case ast::Expr::Kind::Int:
  case ast::Expr::Kind::Float: return number_literal(*e, s.cx.diag);
  case ast::Expr::Kind::String: {
    model::Expr x = make(K::String, Type::String, e->range);
    x.text = e->text();
    return x;
  }
  case ast::Expr::Kind::Duration: return lower_duration(*e, s);
  case ast::Expr::Kind::Name: return lower_name(*e, s);
  case ast::Expr::Kind::Call: return lower_call(*e, s, false);
  case ast::Expr::Kind::Unary: return check_constant(lower_unary(*e, s), s.cx.model, s.cx.diag);
  case ast::Expr::Kind::Binary: return check_constant(lower_binary(*e, s), s.cx.model, s.cx.diag);
  case ast::Expr::Kind::Path:
    // `inst.q`: a block's output; `active(...)` reads a path to a place itself.
    return lower_member(*e, s);
  case ast::Expr::Kind::Paren: {
    if (e->args.size() != 1) return std::nullopt;
    auto inner = lower_expr(e->args[0], s);
    if (!inner) return std::nullopt;
    model::Expr x = make(K::Paren, inner->type, e->range);
    x.args.push_back(std::move(*inner));
    return check_constant(std::move(x), s.cx.model, s.cx.diag);  // folded with its operand
  }
  }
  return std::nullopt;
}

/// A call of an unknown name that is a built-in or a standard function misspelt (`acitve(P)`,
/// `maks(a, b)`): reported as such, with the fix, and its arguments left unread (a place is no
/// value: that error would be noise).
bool misspelt_builtin(const ast::Name &name, ExprScope &s) {
  if (name.text.empty() || name.text.size() > kMaxSuggestedLength || s.cx.c_names.find(name.text)) return false;
  const std::size_t limit = typo_limit(name.text.size());
  std::vector<std::string_view> builtins(std::begin(kBuiltinFunctions), std::end(kBuiltinFunctions));
  for (int f = 0; f <= static_cast<int>(model::Expr::Builtin::Mux); ++f)
    builtins.push_back(model::builtin_name(static_cast<model::Expr::Builtin>(f)));
  for (std::string_view builtin : builtins) {
    // The built-ins first: they are few, and the search among the interface functions only
    // matters for a name close to one of them.
    if (edit_distance_within(name.text, builtin, limit) > limit) continue;
    if (closest(name.text, s.cx.c_names.of({Sym::Function}))) return false;  // an interface function is closer
    if (!seen(s).insert(fmt::format("function {}", name.text)).second) return true;
    auto &d = s.cx.diag.error(name.range, ErrorKind::UnknownName, fmt::format("unknown function '{}'", name.text));
    d.fix(d.range, builtin).note(fmt::format("did you mean the built-in '{}'?", builtin));
    return true;
  }
  return false;
}

namespace {

/// The type a conversion `T(x)` names, if `name` is one (docs/language.md §4).
std::optional<Type> conversion_type(std::string_view name) {
  static const Type kTargets[] = {Type::Int,    Type::Int8,   Type::Int16, Type::Int64,  Type::UInt8, Type::UInt16,
                                  Type::UInt32, Type::UInt64, Type::Float, Type::Double, Type::Time};
  for (Type t : kTargets)
    if (name == model::type_name(t)) return t;
  return std::nullopt;
}

/// `T(x)`: between the integer types, from and to `time` (its milliseconds) and to and from
/// the floating types; the value is checked where it is known (check_constant folds it).
std::optional<model::Expr> lower_conversion(const ast::Expr &e, Type to, ExprScope &s, bool statement) {
  if (statement) {
    s.cx.diag.error(e.range, ErrorKind::TypeMismatch,
                    fmt::format("the conversion '{}()' as a statement has no effect", e.name.text));
    return std::nullopt;
  }
  if (e.args.size() != 1) {
    s.cx.diag.error(e.range, ErrorKind::ArgumentCount,
                    fmt::format("the conversion '{}' takes one value (have {})", e.name.text, e.args.size()));
    return std::nullopt;
  }
  auto x = lower_expr(e.args[0], s);
  if (!x) return std::nullopt;
  if (x->type == Type::Duration && !as_time(*x, s)) return std::nullopt;
  const Type from = x->type;
  const bool integer_from = model::is_integer(from), integer_to = model::is_integer(to);
  const bool floating_from = from == Type::Float || from == Type::Double;
  // A time converts as its count of milliseconds, to and from floating values too (IEC's
  // TIME_TO_REAL and REAL_TO_TIME, docs/iec.md "Reading structured text").
  const bool ok = (integer_to && (integer_from || floating_from || from == Type::Time)) ||
                  (to == Type::Time && (integer_from || floating_from)) ||
                  ((to == Type::Float || to == Type::Double) && (integer_from || floating_from || from == Type::Time));
  if (!ok) {
    s.cx.diag.error(e.range, ErrorKind::TypeMismatch,
                    fmt::format("cannot convert a value of type {} to {}", quoted(from), quoted(to)));
    return std::nullopt;
  }
  model::Expr c = make(K::Convert, to, e.range);
  c.args.push_back(std::move(*x));
  return check_constant(std::move(c), s.cx.model, s.cx.diag);
}

using Builtin = model::Expr::Builtin;

/// The standard function `name` spells (docs/language.md §4, "Standard functions"), if any.
std::optional<Builtin> standard_function(std::string_view name) {
  for (Builtin f : {Builtin::Abs, Builtin::Min, Builtin::Max, Builtin::Limit, Builtin::Sel, Builtin::Mux})
    if (name == model::builtin_name(f)) return f;
  return std::nullopt;
}

/// The type the values `xs` of a standard function mix in, as `a + b` would (§4): an `int`
/// constant takes the first sized integer type among them, two integer types mix only when one
/// holds the other, a duration meeting a `time` is a `time`. `selects`: sel and mux, which also
/// choose among bools. Nothing after reporting why not.
std::optional<Type> mixed_type(std::vector<model::Expr> &xs, const ast::Expr &e, ExprScope &s, bool selects) {
  const std::string_view f = e.name.text;
  for (const model::Expr &x : xs)
    if (model::is_sized(x.type)) {
      const Type sized = x.type;
      for (model::Expr &y : xs)
        if (!retype_constant(y, sized, s)) return std::nullopt;
      break;
    }
  const bool time = std::any_of(xs.begin(), xs.end(), [](const model::Expr &x) { return x.type == Type::Time; });
  for (model::Expr &x : xs)
    if (time && x.type == Type::Duration && !as_time(x, s)) return std::nullopt;
  auto fits = [&](Type t) { return model::is_numeric(t) || t == Type::Time || (selects && t == Type::Bool); };
  for (const model::Expr &x : xs)
    if (!fits(x.type)) {
      auto &d = s.cx.diag.error(x.range, ErrorKind::TypeMismatch,
                                fmt::format("'{}' takes {}, not {}", f,
                                            selects ? "numbers, times or bools" : "numbers or times", quoted(x.type)));
      duration_note(d, x.type, x.type);
      return std::nullopt;
    }
  Type acc = xs[0].type;
  for (std::size_t i = 1; i < xs.size(); ++i) {
    const Type t = xs[i].type;
    if (t == acc && !model::is_numeric(t)) continue;  // two times, two bools
    if (model::is_numeric(acc) && model::is_numeric(t))
      if (auto r = binary_type(BinaryOp::Add, acc, t)) {
        acc = *r;
        continue;
      }
    auto &d = s.cx.diag.error(xs[i].range, ErrorKind::TypeMismatch,
                              fmt::format("the values of '{}' do not mix: {} and {}", f, quoted(acc), quoted(t)));
    if (model::is_integer(acc) && model::is_integer(t))
      d.note(fmt::format("neither '{}' nor '{}' holds every value of the other; convert one, e.g. '{}(x)'",
                         model::type_name(acc), model::type_name(t), model::type_name(acc)));
    else duration_note(d, acc, t);
    return std::nullopt;
  }
  return acc;
}

/// `abs(x)`, `min(a, b, ...)`, `max(a, b, ...)`, `limit(mn, x, mx)`, `sel(g, a, b)`,
/// `mux(k, a, b, ...)`: IEC 61131-3's standard functions ABS, MIN, MAX, LIMIT, SEL and MUX. Every
/// operand is evaluated, in order; constant operands fold.
std::optional<model::Expr> lower_standard(const ast::Expr &e, Builtin f, ExprScope &s, bool statement) {
  const std::string_view name = e.name.text;
  std::vector<std::optional<model::Expr>> lowered;
  for (const auto &a : e.args) lowered.push_back(lower_expr(a, s));
  const std::size_t n = e.args.size();
  const char *wanted = nullptr;
  switch (f) {
  case Builtin::Abs: wanted = n == 1 ? nullptr : "one value"; break;
  case Builtin::Min:
  case Builtin::Max: wanted = n >= 2 ? nullptr : "two or more values"; break;
  case Builtin::Limit: wanted = n == 3 ? nullptr : "three values: the lowest, the value and the highest"; break;
  case Builtin::Sel: wanted = n == 3 ? nullptr : "a bool and two values: 'sel(g, a, b)' is a when g is false"; break;
  case Builtin::Mux: wanted = n >= 3 ? nullptr : "an integer and two or more values: 'mux(k, a, b, ...)'"; break;
  }
  if (wanted) {
    s.cx.diag.error(e.range, ErrorKind::ArgumentCount, fmt::format("'{}' takes {} (have {})", name, wanted, n));
    return std::nullopt;
  }
  if (statement) {
    s.cx.diag.error(e.range, ErrorKind::TypeMismatch, fmt::format("'{}()' as a statement has no effect", name));
    return std::nullopt;
  }
  for (const auto &a : lowered)
    if (!a) return std::nullopt;
  const bool selects = f == Builtin::Sel || f == Builtin::Mux;
  if (f == Builtin::Sel && lowered[0]->type != Type::Bool) {
    s.cx.diag.error(lowered[0]->range, ErrorKind::TypeMismatch,
                    fmt::format("the selector of 'sel' must be bool, not {}", quoted(lowered[0]->type)));
    return std::nullopt;
  }
  if (f == Builtin::Mux && !model::is_integer(lowered[0]->type)) {
    s.cx.diag.error(lowered[0]->range, ErrorKind::TypeMismatch,
                    fmt::format("the selector of 'mux' must be an integer, not {}", quoted(lowered[0]->type)));
    return std::nullopt;
  }
  std::vector<model::Expr> values;
  for (std::size_t i = selects ? 1 : 0; i < n; ++i) values.push_back(std::move(*lowered[i]));
  if (f == Builtin::Abs && !model::is_numeric(values[0].type)) {
    auto &d = s.cx.diag.error(values[0].range, ErrorKind::TypeMismatch,
                              fmt::format("'abs' takes a number, not {}", quoted(values[0].type)));
    duration_note(d, values[0].type, values[0].type);
    return std::nullopt;
  }
  auto type = mixed_type(values, e, s, selects);
  if (!type) return std::nullopt;
  model::Expr x = make(K::Builtin, *type, e.range);
  x.builtin = f;
  if (selects) x.args.push_back(std::move(*lowered[0]));
  for (auto &v : values) x.args.push_back(std::move(v));
  return check_constant(std::move(x), s.cx.model, s.cx.diag);
}

}  // namespace

std::optional<model::Expr> lower_call(const ast::Expr &e, ExprScope &s, bool statement) {
  const ast::Name &name = e.name;
  if (auto to = conversion_type(name.text)) return lower_conversion(e, *to, s, statement);
  if (name.text == "elapsed") return lower_elapsed(e, s, statement);
  if (name.text == "active") return lower_active(e, s, statement);
  // `running(A)` is a built-in only of a named action, so that an interface may still declare
  // a function `running`.
  if (name.text == "running" && e.args.size() == 1 && e.args[0])
    if (model::ActionId a = named_action(*e.args[0], s)) {
      if (!builtin_allowed(e, s, statement, "a named action")) return std::nullopt;
      return action_flag(e, s, a, true);
    }
  if (name.text == "succeeded" || name.text == "failed") return lower_outcome(e, s, statement);
  if (name.text == "team") return lower_team(e, s, statement);
  if (name.text == "agent") return lower_agent(e, s, statement);
  if (name.text == "now") return lower_now(e, s, statement);
  // A standard function unless an interface declares a function of its name, which a call
  // then means, as C would (docs/language.md §4).
  if (auto f = standard_function(name.text)) {
    const Symbol *declared = s.cx.c_names.find(name.text);
    if (!declared || declared->kind != Sym::Function) return lower_standard(e, *f, s, statement);
  }
  if (misspelt_builtin(name, s)) return std::nullopt;
  std::vector<std::optional<model::Expr>> args;
  for (const auto &a : e.args) args.push_back(lower_expr(a, s));
  if (name.text.empty()) return std::nullopt;
  if (s.constant) {
    s.cx.diag.error(e.range, ErrorKind::NotConstant, fmt::format("a constant expression cannot call '{}'", name.text));
    return std::nullopt;
  }
  const Symbol *sym = s.cx.c_names.resolve(name);
  if (!sym) {
    Diagnostic *d = report_unknown(s.cx.diag, seen(s), name, "function", s.cx.c_names.of({Sym::Function}));
    // A beginner's usual cause: the chart does not import the interface that declares it.
    if (d && s.cx.declaring_files)
      for (const std::string &file : s.cx.declaring_files(std::string(name.text)))
        d->note(fmt::format("'{}' declares '{}': add 'import \"{}\";'", file, name.text, file));
    return std::nullopt;
  }
  if (sym->kind != Sym::Function) {
    s.cx.diag
        .error(name.range, ErrorKind::TypeMismatch,
               fmt::format("called object '{}' is {}, not a function", name.text, with_article(sym->kind)))
        .note(sym->range, fmt::format("'{}' declared here", name.text));
    return std::nullopt;
  }
  if (!s.cx.function_ok[sym->index]) return std::nullopt;
  const model::FunctionId function = sym->id<model::FunctionId>();
  const model::Function &f = s.cx.model.functions[function];
  for (std::size_t i = 0; i < args.size() && i < f.params.size(); ++i)
    if (args[i] && !retype_constant(*args[i], f.params[i].type, s)) return std::nullopt;
  if (!check_arguments(e, f, args, s.cx.diag)) return std::nullopt;
  for (std::size_t i = 0; i < args.size(); ++i)
    if (!constant_fits(*args[i], f.params[i].type, s)) return std::nullopt;
  if (!statement && f.result == Type::Void) {
    s.cx.diag
        .error(e.range, ErrorKind::TypeMismatch, fmt::format("'{}' returns void; it cannot be used as a value", f.name))
        .note(f.range, fmt::format("'{}' declared here", f.name));
    return std::nullopt;
  }
  if (s.chart) s.chart->functions.insert(function);
  model::Expr x = make(K::Call, f.result, e.range);
  x.refer_to(function);
  for (auto &a : args) x.args.push_back(std::move(*a));
  return x;
}

std::optional<model::Expr> lower_condition(const ast::Expr *e, ExprScope &s, const char *what) {
  auto x = lower_expr(e, s);
  if (!x || x->type == Type::Bool) return x;
  auto &d =
      s.cx.diag.error(x->range, ErrorKind::TypeMismatch, fmt::format("{} must be bool, not {}", what, quoted(x->type)));
  duration_note(d, x->type, x->type);
  return std::nullopt;
}

std::optional<model::Expr> lower_initializer(const ast::Expr *e, ExprScope &s, Type type, const std::string &name) {
  auto x = lower_expr(e, s);
  if (!x) return x;
  if (!retype_constant(*x, type, s)) return std::nullopt;
  // As an assignment's value: a constant that does not fit the variable is an error.
  if (assignable(type, x->type)) {
    if (type == Type::Time && !as_time(*x, s)) return std::nullopt;
    return constant_fits(*x, type, s) ? x : std::nullopt;
  }
  auto &d = s.cx.diag.error(
      x->range, ErrorKind::TypeMismatch,
      fmt::format("cannot initialize '{}' of type {} with a value of type {}", name, quoted(type), quoted(x->type)));
  duration_note(d, x->type, type);
  conversion_note(d, type, x->type);
  return std::nullopt;
}

namespace {

std::vector<model::Stmt> lower_statements(ast::Stmt *first, ast::Stmt *last, ExprScope &s);

/// `if (c) { } else if (d) { } else { }`: the condition must be bool; both branches are checked
/// whatever the condition, so every mistake in them is reported.
std::optional<model::Stmt> lower_if(ast::Stmt &st, ExprScope &s) {
  auto condition = lower_condition(st.value.get(), s, "the condition of 'if'");
  std::vector<model::Stmt> then_block = lower_statements(st.then_block.begin(), st.then_block.end(), s);
  std::vector<model::Stmt> else_block = lower_statements(st.else_block.begin(), st.else_block.end(), s);
  if (!condition) return std::nullopt;
  model::Stmt m;
  m.kind = model::Stmt::Kind::If;
  m.range = st.range;
  m.expr = std::move(*condition);
  m.then_block = std::move(then_block);
  m.else_block = std::move(else_block);
  // An `else if` whose own condition failed lowers to nothing: then this is a plain else.
  m.else_if = st.else_if && m.else_block.size() == 1 && m.else_block[0].kind == model::Stmt::Kind::If;
  return m;
}

/// Whether `block` holds a `return`, at any depth.
bool returns(const HeapVector<model::Stmt> &block) {
  for (const model::Stmt &s : block)
    if (s.kind == model::Stmt::Kind::Return || returns(s.then_block) || returns(s.else_block)) return true;
  return false;
}

/// Whether `block` leaves the loop whose body it is: a `break` not inside a nested loop, or a
/// `return` anywhere.
bool leaves_loop(const HeapVector<model::Stmt> &block) {
  for (const model::Stmt &s : block) {
    switch (s.kind) {
    case model::Stmt::Kind::Break:
    case model::Stmt::Kind::Return: return true;
    case model::Stmt::Kind::If:
      if (leaves_loop(s.then_block) || leaves_loop(s.else_block)) return true;
      break;
    case model::Stmt::Kind::While:
    case model::Stmt::Kind::DoWhile:
    case model::Stmt::Kind::For:
      if (returns(s.then_block)) return true;
      break;
    default: break;
    }
  }
  return false;
}

/// `while (c) { }`, `do { } while (c);`, `for (i = a; c; i += s) { }`: the condition must be
/// bool, and a condition that is always true needs a way out of the body: gfec promises that
/// what it compiles does not hang (docs/language.md §10).
std::optional<model::Stmt> lower_loop(ast::Stmt &st, ExprScope &s) {
  const char *keyword = st.kind == ast::Stmt::Kind::For ? "for" : "while";
  std::vector<model::Stmt> header;
  if (st.kind == ast::Stmt::Kind::For && st.else_block.size() == 2)
    if (auto init = lower_assign(st.else_block[0], s)) header.push_back(std::move(*init));
  auto condition = lower_condition(st.value.get(), s, fmt::format("the condition of '{}'", keyword).c_str());
  ++s.loops;
  std::vector<model::Stmt> body = lower_statements(st.then_block.begin(), st.then_block.end(), s);
  --s.loops;
  if (st.kind == ast::Stmt::Kind::For && st.else_block.size() == 2)
    if (auto step = lower_assign(st.else_block[1], s)) header.push_back(std::move(*step));
  if (!condition || (st.kind == ast::Stmt::Kind::For && header.size() != 2)) return std::nullopt;
  model::Stmt m;
  m.kind = st.kind == ast::Stmt::Kind::While     ? model::Stmt::Kind::While
           : st.kind == ast::Stmt::Kind::DoWhile ? model::Stmt::Kind::DoWhile
                                                 : model::Stmt::Kind::For;
  m.range = st.range;
  m.expr = std::move(*condition);
  m.then_block = std::move(body);
  m.else_block = std::move(header);
  const bool always = (m.expr.kind == model::Expr::Kind::Bool || m.expr.folded) && m.expr.bool_value;
  if (always && !leaves_loop(m.then_block)) {
    s.cx.diag
        .error(m.expr.range, ErrorKind::Loop,
               fmt::format("this '{}' loop never ends: its condition is always true and its body has no 'break' or "
                           "'return'",
                           keyword))
        .note("a tick must end: add a 'break' or 'return' that the body reaches, or a condition that becomes false");
    return std::nullopt;
  }
  return m;
}

std::vector<model::Stmt> lower_statements(ast::Stmt *first, ast::Stmt *last, ExprScope &s) {
  std::vector<model::Stmt> out;
  for (ast::Stmt *it = first; it != last; ++it) {
    ast::Stmt &st = *it;
    switch (st.kind) {
    case ast::Stmt::Kind::While:
    case ast::Stmt::Kind::DoWhile:
    case ast::Stmt::Kind::For:
      if (auto m = lower_loop(st, s)) out.push_back(std::move(*m));
      break;
    case ast::Stmt::Kind::Break:
    case ast::Stmt::Kind::Return: {
      const bool is_break = st.kind == ast::Stmt::Kind::Break;
      if (is_break && s.loops == 0) {
        s.cx.diag.error(st.range, ErrorKind::Loop, "'break' outside a loop")
            .note("'break' ends the innermost 'while', 'do' or 'for' it is written in; 'return' ends the whole block");
        break;
      }
      model::Stmt m;
      m.kind = is_break ? model::Stmt::Kind::Break : model::Stmt::Kind::Return;
      m.range = st.range;
      out.push_back(std::move(m));
      break;
    }
    case ast::Stmt::Kind::If:
      if (auto m = lower_if(st, s)) out.push_back(std::move(*m));
      break;
    case ast::Stmt::Kind::Invoke:
      if (auto m = lower_invoke(st, s)) out.push_back(std::move(*m));
      break;
    case ast::Stmt::Kind::Call:
      if (!st.call || st.call->kind != ast::Expr::Kind::Call) break;
      if (names_instance(st.call->name, s)) {  // `inst();`
        if (auto m = lower_invoke(st, s)) out.push_back(std::move(*m));
        break;
      }
      if (auto call = lower_call(*st.call, s, true)) {
        model::Stmt m;
        m.kind = model::Stmt::Kind::Call;
        m.range = st.range;
        m.expr = std::move(*call);
        out.push_back(std::move(m));
      }
      break;
    case ast::Stmt::Kind::Assign:
      if (auto m = lower_assign(st, s)) out.push_back(std::move(*m));
      break;
    case ast::Stmt::Kind::Verbatim: {
      s.cx.diag.warning(Warning::Verbatim, st.range, "verbatim code is copied unchecked: gfec cannot check it");
      model::Stmt m;
      m.kind = model::Stmt::Kind::Verbatim;
      m.range = st.range;
      // The tree's copy is released next, unless it is kept.
      m.verbatim = !st.verbatim ? std::string() : s.cx.keep_tree ? *st.verbatim : std::move(*st.verbatim);
      m.code_begin = st.range.begin + 2;  // the lexer's range starts at `%{`
      out.push_back(std::move(m));
      break;
    }
    }
  }
  return out;
}

}  // namespace

bool assignable_value(model::Expr &value, Type to, ExprScope &s) {
  if (!retype_constant(value, to, s)) return false;
  if (!assignable(to, value.type)) return true;  // the caller reports the mismatch
  if (to == Type::Time && !as_time(value, s)) return false;
  return constant_fits(value, to, s);
}

std::vector<model::Stmt> lower_block(ast::Block &b, ExprScope &s) {
  return lower_statements(b.data(), b.data() + b.size(), s);
}

}  // namespace gfec::validation
