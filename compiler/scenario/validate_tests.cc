// Checks the `test` blocks of the main file and lowers them to scenario::Test
// (docs/testing-charts.md). Chart expressions in `expect` go through the validator's own
// expression lowering (validate/expr.cc) in the chart's scope, so whatever a chart's
// conditions may read, an expectation may read too; only the test-only operands are handled
// here.
#include "scenario/validate_tests.h"

#include "interpreter/value.h"
#include "roots.h"
#include "validate/fold.h"
#include "validate/suggest.h"
#include "validate/types.h"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <set>

namespace gfec::validation {

namespace {

using model::Type;
using scenario::Expect;

/// The chart's names as its own validation saw them (rebuilt from the model: the scope of
/// validate_chart is gone by now). Clashes were reported then; they are not repeated.
void declare_chart_names(Context &cx, ChartScope &s) {
  Diagnostics quiet;
  const ast::Chart &a = s.ast;
  for (std::size_t i = 0; i < a.places.size(); ++i)
    s.names.declare(a.places[i].name, s.is_fsm() ? Sym::State : Sym::Place, model::PlaceId(i), quiet);
  for (const ast::ValueDecl &v : a.values) {
    if (v.is_const) {
      model::ConstId constant;
      for (model::ConstId c : cx.model.consts.ids())
        if (cx.model.consts[c].chart == s.index && cx.model.consts[c].name == v.name.text) constant = c;
      if (constant) s.names.declare(v.name, Sym::Const, constant, quiet);
      continue;
    }
    model::VarId var;
    for (model::VarId k : s.out.vars.ids())
      if (s.out.vars[k].name == v.name.text) var = k;
    s.names.declare(v.name, Sym::Var, var, quiet);
  }
  for (std::size_t i = 0; i < a.transitions.size(); ++i)
    if (a.transitions[i].named) s.names.declare(a.transitions[i].name, Sym::Transition, model::TransitionId(i), quiet);
}

/// Whether a lowered chart expression calls an interface function (which would run chart code).
const model::Expr *find_call(const model::Expr &e) {
  if (e.kind == model::Expr::Kind::Call) return &e;
  for (const auto &a : e.args)
    if (const model::Expr *c = find_call(a)) return c;
  return nullptr;
}

class TestLowering {
public:
  TestLowering(Context &cx, ChartScope &chart) : cx_(cx), chart_(chart), scope_{cx, &chart, false} {}

  std::optional<Expect> expect(const ast::Expr *e) {
    auto x = lower(e);
    if (!x || x->type == Type::Bool) return x;
    cx_.diag.error(x->range, ErrorKind::TypeMismatch,
                   fmt::format("an expectation must be bool, not {}", quoted(x->type)));
    return std::nullopt;
  }

  /// The function `name` names, or none after reporting why not.
  model::FunctionId function(const ast::Name &name) {
    if (name.text.empty()) return {};
    const Symbol *sym = cx_.c_names.resolve(name);
    if (sym && sym->kind == Sym::Function) {
      const auto f = sym->id<model::FunctionId>();
      return cx_.function_ok[f] ? f : model::FunctionId::none();
    }
    if (sym) {
      cx_.diag
          .error(name.range, ErrorKind::TypeMismatch,
                 fmt::format("'{}' is {}, not a function", name.text, with_article(sym->kind)))
          .note(sym->range, fmt::format("'{}' declared here", name.text));
      return {};
    }
    if (const Symbol *local = chart_.names.find(name.text)) {  // a variable, place...: not a function
      cx_.diag
          .error(
              name.range, ErrorKind::TypeMismatch,
              fmt::format("'{}' is {} of '{}', not a function", name.text, with_article(local->kind), chart_.out.name))
          .note(local->range, fmt::format("'{}' declared here", name.text));
      return {};
    }
    report_unknown(cx_.diag, chart_.unknown, name, "function", cx_.c_names.of({Sym::Function}));
    return {};
  }

  /// What `set NAME` sets: one of the chart's `in` variables (docs/language.md §14), or else the
  /// function `name` names. Both none after reporting why neither.
  struct Settable {
    model::VarId input;
    model::FunctionId function;
  };
  Settable settable(const ast::Name &name) {
    if (name.text.empty()) return {};
    const Symbol *local = chart_.names.find(name.text);
    // An input is read by its bare name in the chart's expressions: so it is here, before a
    // function of the same name.
    if (local && input_var(*local)) {
      chart_.names.resolve(name);
      return {local->id<model::VarId>(), {}};
    }
    const std::vector<const Symbol *> ins = inputs();
    if (cx_.c_names.find(name.text) || (!local && ins.empty())) return {{}, function(name)};
    if (!local) {  // unknown: the did-you-mean offers the chart's inputs too
      std::vector<const Symbol *> candidates = cx_.c_names.of({Sym::Function});
      candidates.insert(candidates.end(), ins.begin(), ins.end());
      report_unknown(cx_.diag, chart_.unknown, name, "input or function", candidates);
      return {};
    }
    std::string what = with_article(local->kind);
    if (local->kind == Sym::Var && local->index >= 0 && static_cast<std::size_t>(local->index) < chart_.out.vars.size())
      what = chart_.out.vars[local->id<model::VarId>()].role == model::VarRole::Out ? "an output ('out')"
                                                                                    : "a variable ('var')";
    cx_.diag
        .error(
            name.range, ErrorKind::Test,
            fmt::format("'{}' is {} of '{}': 'set' sets only the chart's inputs ('in', 'inout') and sensing functions",
                        name.text, what, chart_.out.name))
        .note(local->range, fmt::format("'{}' declared here", name.text));
    return {};
  }

  /// `set` of input `var`: the constant taken as the variable's initialiser takes it (§14: the
  /// chart's types, a sized integer's range, a duration as a `time`), formatted as engines print it.
  std::optional<std::string> input_value(const ast::Expr *e, const model::Var &var) {
    ExprScope constant_scope{cx_, &chart_, true};
    auto x = lower_expr(e, constant_scope);
    if (!x) return std::nullopt;
    const std::string what = fmt::format("the value of '{}'", var.name);
    // An integer constant of another integer type is the initialiser's to judge (a literal
    // takes a sized type when it fits); any other mismatch is said here, in the words of `set`.
    if (!assignable(var.type, x->type) && !(model::is_integer(var.type) && model::is_integer(x->type))) {
      cx_.diag.error(x->range, ErrorKind::TypeMismatch,
                     fmt::format("{} must be {}, not {}", what, quoted(var.type), quoted(x->type)));
      return std::nullopt;
    }
    auto checked = lower_initializer(e, constant_scope, var.type, var.name);
    if (!checked) return std::nullopt;
    auto v = evaluate(*checked, cx_.model, &cx_.diag);
    if (!v) return std::nullopt;
    try {
      return interp::format_value(interp::convert(*v, var.type, checked->range));
    } catch (const interp::RuntimeError &err) {
      cx_.diag.error(checked->range, ErrorKind::TypeMismatch, fmt::format("{}: {}", what, err.what()));
      return std::nullopt;
    }
  }

  /// `e`, a constant, as a value of type `to` formatted as engines print it (§12: "converted as
  /// C converts"). `Conversion::C` lets `set` take any scalar for any scalar function, as a C
  /// assignment to the function's return type would (`set Black = 1;` is true, `set Speed = true;`
  /// is 1); arguments of `called F(ARGS)` follow the chart's own rule, where bool and numbers do not
  /// mix.
  enum class Conversion { Chart, C };
  std::optional<std::string> constant(const ast::Expr *e, Type to, const std::string &what,
                                      Conversion conversion = Conversion::Chart) {
    ExprScope constant_scope{cx_, &chart_, true};
    auto x = lower_expr(e, constant_scope);
    if (!x) return std::nullopt;
    if (!(conversion == Conversion::C
              ? (to == Type::Bool || is_numeric(to)) && (x->type == Type::Bool || is_numeric(x->type))
              : assignable(to, x->type))) {
      cx_.diag.error(x->range, ErrorKind::TypeMismatch,
                     fmt::format("{} must be {}, not {}", what, quoted(to), quoted(x->type)));
      return std::nullopt;
    }
    auto v = evaluate(*x, cx_.model, &cx_.diag);
    if (!v) return std::nullopt;
    interp::Value value;
    switch (v->type) {
    case Type::Bool: value = interp::Value::of_bool(v->b); break;
    case Type::Int: value = interp::Value::of_int(static_cast<std::int32_t>(v->i)); break;
    case Type::Float: value = interp::Value::of_float(static_cast<float>(v->f)); break;
    case Type::Double: value = interp::Value::of_double(v->f); break;
    default: return std::nullopt;
    }
    // `called Act(3.7)` for an int parameter: every call passes a whole number, so the
    // expectation could never hold with "exactly these arguments" (§12).
    if (conversion == Conversion::Chart && to == Type::Int && (v->type == Type::Float || v->type == Type::Double) &&
        std::trunc(v->f) != v->f) {
      cx_.diag.error(x->range, ErrorKind::TypeMismatch,
                     fmt::format("{} is an 'int': no call passes {}", what, source_text(cx_.model, x->range)));
      return std::nullopt;
    }
    try {
      return interp::format_value(interp::convert(value, to, x->range));
    } catch (const interp::RuntimeError &err) {
      cx_.diag.error(x->range, ErrorKind::TypeMismatch, fmt::format("{}: {}", what, err.what()));
      return std::nullopt;
    }
  }

private:
  bool input_var(const Symbol &sym) const {
    return sym.kind == Sym::Var && sym.index >= 0 && static_cast<std::size_t>(sym.index) < chart_.out.vars.size() &&
           model::set_by_caller(chart_.out.vars[sym.id<model::VarId>()].role);
  }

  /// The chart's `in` variables, as did-you-mean candidates.
  std::vector<const Symbol *> inputs() const {
    std::vector<const Symbol *> out;
    for (const Symbol *v : chart_.names.of({Sym::Var}))
      if (input_var(*v)) out.push_back(v);
    return out;
  }

  static Expect make(Expect::Kind kind, Type type, SourceRange range) {
    Expect x;
    x.kind = kind;
    x.type = type;
    x.range = range;
    return x;
  }

  bool fsm_only(const ast::Expr &e, const char *what) {
    if (chart_.is_fsm()) return true;
    cx_.diag.error(e.range, ErrorKind::Test,
                   fmt::format("'{}' needs an fsm, but '{}' is an sfc", what, chart_.out.name));
    return false;
  }

  std::optional<Expect> lower(const ast::Expr *e) {
    if (!e) return std::nullopt;
    using AK = ast::Expr::Kind;
    switch (e->kind) {
    case AK::Name:
      if (e->name.text == "status") {  // a keyword inside a test: never a chart name
        if (!fsm_only(*e, "status")) return std::nullopt;
        return make(Expect::Kind::Status, Type::Int, e->range);
      }
      break;
    case AK::Call:
      if (e->name.text == "called" || e->name.text == "calls") return called(*e);
      if (e->name.text == "state") return place_operand(*e, Expect::Kind::State);
      // `active(P)` of a place of this chart; deeper paths are the sub-charts' lowering.
      if (e->name.text == "active" && e->args.size() == 1 && e->args[0] && e->args[0]->kind == AK::Name)
        return place_operand(*e, Expect::Kind::Active);
      if (void_call(*e)) return std::nullopt;
      break;
    case AK::Unary: {
      if (e->args.size() != 1) return std::nullopt;
      auto operand = lower(e->args[0]);
      if (!operand) return std::nullopt;
      if (operand->kind == Expect::Kind::Chart) break;  // all chart: the chart's lowering types it
      auto type = unary_type(e->unary_op, operand->type);
      if (!type) {
        cx_.diag.error(e->range, ErrorKind::TypeMismatch,
                       fmt::format("invalid operand to unary '{}' (have {})", written_operator(*e, cx_.sources),
                                   quoted(operand->type)));
        return std::nullopt;
      }
      Expect x = make(Expect::Kind::Unary, *type, e->range);
      x.unary_op = e->unary_op;
      x.args.push_back(std::move(*operand));
      return x;
    }
    case AK::Binary: {
      if (e->args.size() != 2) return std::nullopt;
      auto a = lower(e->args[0]);
      auto b = lower(e->args[1]);
      if (!a || !b) return std::nullopt;
      if (a->kind == Expect::Kind::Chart && b->kind == Expect::Kind::Chart) break;
      auto type = binary_type(e->binary_op, a->type, b->type);
      if (!type) {
        cx_.diag.error(e->range, ErrorKind::TypeMismatch,
                       fmt::format("invalid operands to binary '{}' (have {} and {})",
                                   written_operator(*e, cx_.sources), quoted(a->type), quoted(b->type)));
        return std::nullopt;
      }
      Expect x = make(Expect::Kind::Binary, *type, e->range);
      x.binary_op = e->binary_op;
      x.args.push_back(std::move(*a));
      x.args.push_back(std::move(*b));
      return x;
    }
    case AK::Paren: {
      if (e->args.size() != 1) return std::nullopt;
      auto inner = lower(e->args[0]);
      if (!inner) return std::nullopt;
      if (inner->kind == Expect::Kind::Chart) break;
      Expect x = make(Expect::Kind::Paren, inner->type, e->range);
      x.args.push_back(std::move(*inner));
      return x;
    }
    default: break;
    }
    return chart_expression(*e);
  }

  /// `expect Led(true);` of a void function: the test means `called Led(true)` (a beginner's
  /// reading of "the chart called it"), which the fix-it writes.
  bool void_call(const ast::Expr &e) {
    const Symbol *sym = cx_.c_names.find(e.name.text);
    if (!sym || sym->kind != Sym::Function || sym->index < 0 || !cx_.function_ok[sym->index]) return false;
    const model::Function &f = cx_.model.functions[sym->id<model::FunctionId>()];
    if (f.result != Type::Void) return false;
    const SourceRange at{e.range.file, e.range.begin, e.range.begin};
    cx_.diag
        .error(e.range, ErrorKind::Test,
               fmt::format("'{}' returns nothing: an expectation cannot call it", std::string(f.name)))
        .fix(at, "called ")
        .note(fmt::format("to expect that the chart called it in the last tick, write 'called {}'", text_of(e.range)));
    return true;
  }

  std::string text_of(SourceRange r) const {
    const std::string &t = cx_.sources.file(r.file).text();
    return t.substr(r.begin, r.end - r.begin);
  }

  /// A part that uses no test-only operand: the chart's own expression lowering.
  std::optional<Expect> chart_expression(const ast::Expr &e) {
    auto x = lower_expr(&e, scope_);
    if (!x) return std::nullopt;
    if (const model::Expr *call = find_call(*x)) {
      const std::string &f = cx_.model.functions[call->function()].name;
      cx_.diag
          .error(call->range, ErrorKind::Test,
                 fmt::format("an expectation calls no chart code: '{}' cannot be called here", f))
          .note(
              fmt::format("'called {0}' says whether the chart called it in the last tick, 'calls {0}' how often", f));
      return std::nullopt;
    }
    Expect out = make(Expect::Kind::Chart, x->type, e.range);
    out.chart = std::move(*x);
    return out;
  }

  std::optional<Expect> place_operand(const ast::Expr &e, Expect::Kind kind) {
    const char *word = kind == Expect::Kind::State ? "state" : "active";
    if (kind == Expect::Kind::State && !fsm_only(e, "state()")) return std::nullopt;
    if (e.args.size() != 1 || !e.args[0] || e.args[0]->kind != ast::Expr::Kind::Name) {
      cx_.diag.error(e.range, ErrorKind::Test,
                     fmt::format("'{}' takes one argument: the name of a {}", word, chart_.place_word()));
      return std::nullopt;
    }
    model::PlaceId place = resolve_place(chart_, cx_, e.args[0]->name);
    if (!place) return std::nullopt;
    Expect x = make(kind, Type::Bool, e.range);
    x.place = place;
    return x;
  }

  std::optional<Expect> called(const ast::Expr &e) {
    bool count = e.name.text == "calls";
    if (e.args.size() != 1 || !e.args[0]) return std::nullopt;
    const ast::Expr &target = *e.args[0];
    model::FunctionId f = function(target.name);
    if (!f) return std::nullopt;
    Expect x = make(count ? Expect::Kind::Calls : Expect::Kind::Called, count ? Type::Int : Type::Bool, e.range);
    x.function = f;
    if (target.kind != ast::Expr::Kind::Call) return x;
    const model::Function &fn = cx_.model.functions[f];
    if (target.args.size() != fn.params.size()) {
      cx_.diag
          .error(target.range, ErrorKind::ArgumentCount,
                 fmt::format("too {} arguments to function '{}' (expected {}, have {})",
                             target.args.size() > fn.params.size() ? "many" : "few", fn.name, fn.params.size(),
                             target.args.size()))
          .note(fn.range, fmt::format("'{}' declared here", fn.name));
      return std::nullopt;
    }
    std::vector<std::string> args;
    bool ok = true;
    for (std::size_t i = 0; i < target.args.size(); ++i) {
      auto v = constant(target.args[i], fn.params[i].type, fmt::format("argument {} of '{}'", i + 1, fn.name));
      if (v) args.push_back(*v);
      else ok = false;
    }
    if (!ok) return std::nullopt;
    x.call_args = std::move(args);
    return x;
  }

  Context &cx_;
  ChartScope &chart_;
  ExprScope scope_;
};

/// The chart `name` names, or none after reporting why not.
model::ChartId resolve_chart(Context &cx, const ast::Name &name, std::set<std::string> &seen) {
  if (name.text.empty()) return {};
  const Symbol *sym = cx.c_names.resolve(name);
  if (sym && sym->kind == Sym::Chart) return sym->id<model::ChartId>();
  if (const Symbol *plan = cx.plan_names.resolve(name); plan && plan->kind == Sym::Plan) {
    cx.diag.error(name.range, ErrorKind::Test, fmt::format("'{}' is a plan; tests run an sfc or fsm", name.text))
        .note(plan->range, fmt::format("'{}' declared here", name.text));
    return {};
  }
  if (sym) {
    cx.diag
        .error(name.range, ErrorKind::TypeMismatch,
               fmt::format("'{}' is {}, not an sfc or fsm", name.text, with_article(sym->kind)))
        .note(sym->range, fmt::format("'{}' declared here", name.text));
    return {};
  }
  report_unknown(cx.diag, seen, name, "chart", cx.c_names.of({Sym::Chart}));
  return {};
}

/// `of CHART agents N` and the agents of `agent K { ... }`: only for a team machine, within its size.
/// `tick 5s;`: the duration in ticks of the chart's period, or -1 after an error (no period, not a
/// whole number of periods, more than a step may run).
long long duration_ticks(Context &cx, const ast::Expr &d, const model::Chart &chart) {
  if (chart.period_ms <= 0) {
    cx.diag
        .error(d.range, ErrorKind::Test,
               fmt::format("'tick {}' needs the chart's period, and '{}' has no 'period'", d.name.text, chart.name))
        .note("write the number of ticks ('tick 5;'), or give the chart a 'period'");
    return -1;
  }
  const double ticks = d.duration_ms / chart.period_ms;
  const double whole = std::round(ticks);
  if (std::fabs(ticks - whole) > 1e-9 * std::max(1.0, whole) || whole < 1) {
    cx.diag
        .error(
            d.range, ErrorKind::Test,
            fmt::format("'{}' is {:g} ticks of {:g} ms: 'tick' runs whole ticks", d.name.text, ticks, chart.period_ms))
        .note(fmt::format("write 'tick {:.0f};' ({:g} ms) or 'tick {:.0f};'", std::max(1.0, std::floor(ticks)),
                          std::max(1.0, std::floor(ticks)) * chart.period_ms, std::ceil(ticks)));
    return -1;
  }
  if (whole > static_cast<double>(kMaxTicksPerStep)) {
    cx.diag.error(d.range, ErrorKind::Test,
                  fmt::format("'{}' is {:.0f} ticks; 'tick' runs at most {} ticks at a time", d.name.text, whole,
                              kMaxTicksPerStep));
    return -1;
  }
  return static_cast<long long>(whole);
}

bool check_agents(Context &cx, const ast::Test &t, const model::Chart &chart, scenario::Test &test) {
  bool ok = true;
  test.agents = chart.team > 0 ? chart.team : 1;
  if (t.agents != -1) {
    if (chart.team <= 0) {
      cx.diag.error(t.agents_range, ErrorKind::Test,
                    fmt::format("'agents' needs a team machine, but '{}' declares no 'team N'", chart.name));
      ok = false;
    } else if (t.agents < 1 || t.agents > chart.team) {
      cx.diag.error(t.agents_range, ErrorKind::Test,
                    fmt::format("'{}' is a team of at most {} agents: 'agents' must be 1 to {}", chart.name, chart.team,
                                chart.team));
      ok = false;
    } else {
      test.agents = static_cast<int>(t.agents);
    }
  }
  std::set<std::uint32_t> reported;  // one error per `agent K` block
  for (const ast::TestStep &in : t.steps) {
    if (in.agent < 0 || !reported.insert(in.agent_range.begin).second) continue;
    if (chart.team <= 0) {
      cx.diag.error(in.agent_range, ErrorKind::Test,
                    fmt::format("'agent' steps need a team machine, but '{}' declares no 'team N'", chart.name));
      ok = false;
    } else if (in.agent >= test.agents) {
      cx.diag.error(in.agent_range, ErrorKind::Test,
                    fmt::format("the test runs agents 0 to {}: there is no agent {}", test.agents - 1, in.agent));
      ok = false;
    }
  }
  for (const ast::TestStep &in : t.steps)
    if (in.agent >= 0 && in.kind == ast::TestStep::Kind::Tick) {
      cx.diag.error(in.range, ErrorKind::Test, "a tick runs every agent: write 'tick' outside the 'agent' block")
          .note(in.agent_range, "the agent's block begins here");
      ok = false;
    }
  return ok;
}

/// `set F = CONST;`: F is a parameterless sensing function of the chart's interface, or one of
/// the chart's `in` variables.
bool lower_set(Context &cx, TestLowering &lowering, model::ChartId chart_id, const ast::TestStep &in,
               scenario::Step &out) {
  const model::Chart &chart = cx.model.charts[chart_id];
  const TestLowering::Settable target = lowering.settable(in.function);
  if (target.input) {
    auto v = lowering.input_value(in.value.get(), chart.vars[target.input]);
    if (!v) return false;
    out.input = target.input;
    out.value = *v;
    return true;
  }
  model::FunctionId f = target.function;
  if (!f) return false;
  const model::Function &fn = cx.model.functions[f];
  if (fn.result == Type::Void || !fn.params.empty()) {
    cx.diag
        .error(in.function.range, ErrorKind::Test,
               fmt::format("'set' needs a sensing function without parameters; '{}' {}", fn.name,
                           fn.result == Type::Void ? "returns void" : "takes parameters"))
        .note(fn.range, fmt::format("'{}' declared here", fn.name));
    return false;
  }
  // The chart's interfaces and its sub-charts': a sensing function only a sub-chart calls is
  // still an input of the engine under test.
  bool ours = false;
  const IdMap<model::ChartId, bool> tree = charts_in_tree(cx.model, chart_id);
  for (model::ChartId c : tree.ids())
    for (model::FunctionId used : cx.model.charts[c].functions)
      ours = ours || (tree[c] && cx.model.functions[used].interface_name == fn.interface_name);
  if (!ours) {
    cx.diag
        .error(in.function.range, ErrorKind::Test,
               fmt::format("'{}' belongs to interface '{}', which chart '{}' and its sub-charts do not use", fn.name,
                           fn.interface_name, chart.name))
        .note(fn.range, fmt::format("'{}' declared here", fn.name));
    return false;
  }
  auto v = lowering.constant(in.value.get(), fn.result, fmt::format("the value of '{}'", fn.name),
                             TestLowering::Conversion::C);
  if (!v) return false;
  out.function = f;
  out.value = *v;
  return true;
}

}  // namespace

void validate_tests(Context &cx, scenario::Suite &out) {
  if (cx.program.files.empty() || !cx.program.files.front()) return;
  long long file_ticks = 0;  // every test's ticks so far, for kMaxTicksPerFile
  bool over_budget = false;
  for (const ast::Test &t : cx.program.files.front()->tests) {
    model::ChartId chart = resolve_chart(cx, t.chart, cx.file_unknown);
    if (!chart) continue;
    ChartScope scope(*cx.charts[chart], cx.model.charts[chart], chart);
    scope.names.uses = cx.uses;
    declare_chart_names(cx, scope);
    TestLowering lowering(cx, scope);
    scenario::Test test;
    test.name = t.name;
    test.chart = chart;
    test.range = t.range;
    bool ok = check_agents(cx, t, scope.out, test);
    for (const ast::TestStep &in : t.steps) {
      scenario::Step step;
      step.range = in.range;
      step.agent = in.agent >= 0 && in.agent <= INT_MAX ? static_cast<int>(in.agent) : -1;
      switch (in.kind) {
      case ast::TestStep::Kind::Tick:
        step.kind = scenario::Step::Kind::Tick;
        if (in.value && in.value->kind == ast::Expr::Kind::Duration) {
          const long long ticks = duration_ticks(cx, *in.value, scope.out);
          if (ticks < 0) {
            ok = false;
            break;
          }
          step.count = static_cast<unsigned long>(ticks);
          break;
        }
        if (in.count < 1 || in.count > kMaxTicksPerStep) {
          cx.diag.error(in.value ? in.value->range : in.range, ErrorKind::Test,
                        in.count == 0 ? std::string("'tick 0' runs no tick: the count must be at least 1")
                                      : fmt::format("'tick N' runs at most {} ticks at a time", kMaxTicksPerStep));
          ok = false;
        }
        step.count = static_cast<unsigned long>(std::max(in.count, 1LL));
        file_ticks += std::min(in.count, kMaxTicksPerStep);  // an over-long step is its own error
        if (file_ticks > kMaxTicksPerFile && !over_budget) {
          cx.diag.error(in.value ? in.value->range : in.range, ErrorKind::Test,
                        fmt::format("the tests of this file run more than {} ticks in all: split them over "
                                    "several files",
                                    kMaxTicksPerFile));
          over_budget = true;
          ok = false;
        }
        break;
      case ast::TestStep::Kind::Set:
        step.kind = scenario::Step::Kind::Set;
        ok = lower_set(cx, lowering, chart, in, step) && ok;
        break;
      case ast::TestStep::Kind::Expect: {
        step.kind = scenario::Step::Kind::Expect;
        auto x = lowering.expect(in.value.get());
        if (x) step.expect = std::move(*x);
        else ok = false;
        break;
      }
      }
      test.steps.push_back(std::move(step));
    }
    if (ok) out.tests.push_back(std::move(test));
  }
}

}  // namespace gfec::validation
