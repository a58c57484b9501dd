// What sfc and fsm share (§4, §5, §7): the chart's namespace, its period, vars and constants,
// place bodies and transition conditions. The rules of each kind follow in validate_sfc.cc and
// validate_fsm.cc.
#include "validate/blocks.h"
#include "validate/families.h"
#include "validate/fold.h"
#include "validate/types.h"

#include "naming/naming.h"

#include <fmt/format.h>

#include <algorithm>

namespace gfec::validation {

namespace {

constexpr double kMinPeriodMs = 0.001;         // a microsecond
constexpr double kMaxPeriodMs = 4294967295.0;  // UINT32_MAX milliseconds

void set_period(Context &cx, ChartScope &s) {
  const auto &periods = s.ast.periods;
  for (std::size_t i = 0; i < periods.size(); ++i) {
    const ast::Period &p = periods[i];
    if (i > 0) {
      cx.diag.error(p.range, ErrorKind::Period, fmt::format("second 'period' in {} '{}'", s.kind_word(), s.out.name))
          .note(periods[0].range, "the first one is here");
    } else if (p.ms <= 0) {
      cx.diag.error(p.range, ErrorKind::Period, "the period must be positive");
    } else if (p.ms < kMinPeriodMs || p.ms > kMaxPeriodMs) {
      // Beyond these no controller ticks, and the ticks of a duration stop meaning anything.
      cx.diag.error(p.range, ErrorKind::Period,
                    fmt::format("the period must be from {}ms to {}ms (about 49 days)", kMinPeriodMs, kMaxPeriodMs));
    } else {
      s.out.period_ms = p.ms;
    }
  }
  // A sub-chart that declares none runs at the period of the chart that runs it (§9).
  if (periods.empty()) s.out.period_ms = cx.inherited_period[s.index];
  // A bad period was reported: "needs a period" would only repeat it.
  if (!periods.empty() && s.out.period_ms <= 0) s.period_reported = true;
}

/// `team N;` (docs/language.md "Teams"): only in an fsm, once, N from 2 to kMaxTeam.
void set_team(Context &cx, ChartScope &s) {
  const auto &teams = s.ast.teams;
  for (std::size_t i = 0; i < teams.size(); ++i) {
    const auto &[n, range] = teams[i];
    if (i > 0) {
      cx.diag
          .error(range, ErrorKind::Team, fmt::format("second 'team' declaration in {} '{}'", s.kind_word(), s.out.name))
          .note(teams[0].second, "the first one is here");
    } else if (!s.is_fsm()) {
      cx.diag.error(range, ErrorKind::Team,
                    fmt::format("'team' in sfc '{}': only an fsm can be a team machine", s.out.name));
    } else if (n < 2 || n > kMaxTeam) {
      auto &d = cx.diag.error(range, ErrorKind::Team,
                              n < 2 ? fmt::format("a team has at least 2 agents, not {}",
                                                  n < 0 ? std::string("that many") : std::to_string(n))
                                    : fmt::format("a team has at most {} agents", kMaxTeam));
      if (n >= 0 && n < 2) d.note("an fsm without 'team' is run by one agent");
    } else {
      s.out.team = static_cast<int>(n);
    }
  }
}

/// Places and transitions become enum constants `<Chart>_<Name>` (§5.2): they must not clash
/// with the engine's own names or with a global C name.
void check_generated_name(Context &cx, ChartScope &s, const ast::Name &name, const char *what) {
  std::string generated = fmt::format("{}_{}", s.out.name, name.text);
  // The names every engine defines (naming::engine_names): the constant cannot move aside. A
  // team machine's engine has an API of its own (docs/c-engine.md "Team machines").
  const naming::EngineName *api = naming::engine_name(s.out.name, generated);
  if (api && api->always && !api->team) {
    cx.diag.error(
        name.range, ErrorKind::ReservedName,
        fmt::format("{} '{}' would generate '{}', which the engine already defines", what, name.text, generated));
    return;
  }
  if (api && api->always && !s.ast.teams.empty()) {
    cx.diag.error(name.range, ErrorKind::ReservedName,
                  fmt::format("{} '{}' would generate '{}', which the engine of a team "
                              "machine already defines",
                              what, name.text, generated));
    return;
  }
  if (const Symbol *clash = cx.c_names.find(generated)) {
    cx.diag
        .error(name.range, ErrorKind::ReservedName,
               fmt::format("{} '{}' would generate '{}', the name of {}", what, name.text, generated,
                           with_article(clash->kind)))
        .note(clash->range, fmt::format("'{}' declared here", generated));
  }
}

void declare_place(Context &cx, ChartScope &s, const ast::Place &p, model::PlaceId index) {
  model::Place out;
  out.name = p.name.text;
  out.initial = p.initial;
  out.terminal = p.terminal == ast::StateKind::Success   ? model::Terminal::Success
                 : p.terminal == ast::StateKind::Failure ? model::Terminal::Failure
                                                         : model::Terminal::None;
  out.runs = cx.runs[s.index][index];
  out.range = p.range;
  out.name_range = p.name.range;
  s.out.places.push_back(std::move(out));
  if (s.names.declare(p.name, s.is_fsm() ? Sym::State : Sym::Place, index, cx.diag))
    check_generated_name(cx, s, p.name, s.place_word());
}

void declare_value(Context &cx, ChartScope &s, const ast::ValueDecl &v) {
  if (declare_instance(cx, s, v)) return;
  if (!v.is_const) {
    auto type = lower_type(v.type, kValue, "a variable", cx.diag);
    const auto role = static_cast<model::VarRole>(v.role);
    // An fsm's caller steers it through sensing functions and reads its state; inputs and
    // outputs are an IEC program's, and an sfc's (docs/language.md §14).
    if (role != model::VarRole::Local && s.is_fsm())
      cx.diag.error(v.range, ErrorKind::ChartIo,
                    fmt::format("'{}' declares an '{}' variable in an fsm; only an sfc has inputs and outputs",
                                v.name.text, model::role_keyword(role)));
    model::VarId index;
    if (type) {
      index = s.out.vars.next_id();
      s.out.vars.push_back({std::string(v.name.text), *type, role, std::nullopt, v.range, std::string(v.address)});
    }
    s.names.declare(v.name, Sym::Var, index, cx.diag);
    return;
  }
  auto type = lower_type(v.type, kValue, "a constant", cx.diag);
  const model::ConstId index = cx.model.consts.next_id();
  model::Const c;
  c.name = v.name.text;
  c.type = type.value_or(model::Type::Int);
  c.chart = s.index;
  c.range = v.range;
  cx.model.consts.push_back(std::move(c));
  cx.consts.push_back({&v, type ? ConstSource::State::Pending : ConstSource::State::Failed});
  // Like a C block scope, the chart's constant hides a global one of the same name; back ends
  // write constants as their folded values, so no generated name can clash.
  s.names.declare(v.name, Sym::Const, index, cx.diag);
}

/// Declares places, vars, constants and named transitions in textual order, so a duplicate's
/// note points at the declaration that really comes first.
void declare_names(Context &cx, ChartScope &s) {
  // One small record a declaration rather than a std::function (40 bytes plus a heap-allocated
  // closure): a chart may declare two million names, and this runs while the whole tree is still
  // alive (docs/performance.md).
  enum class What : std::uint8_t { Place, Value, Transition };
  struct Decl {
    std::uint32_t begin;
    std::uint32_t index;
    What what;
  };
  std::vector<Decl> decls;
  const ast::Chart &a = s.ast;
  s.out.places.reserve(a.places.size());
  decls.reserve(a.places.size() + a.values.size() + a.transitions.size());
  for (std::size_t i = 0; i < a.places.size(); ++i)
    decls.push_back({a.places[i].range.begin, static_cast<std::uint32_t>(i), What::Place});
  for (std::size_t i = 0; i < a.values.size(); ++i)
    decls.push_back({a.values[i].range.begin, static_cast<std::uint32_t>(i), What::Value});
  for (std::size_t i = 0; i < a.transitions.size(); ++i)
    if (a.transitions[i].named)
      decls.push_back({a.transitions[i].range.begin, static_cast<std::uint32_t>(i), What::Transition});
  // Each kind is in source order already: two stable merges put them all in source order in
  // linear time, where a sort of two million declarations took n log n.
  auto by_position = [](const Decl &x, const Decl &y) { return x.begin < y.begin; };
  const auto values_begin = decls.begin() + static_cast<std::ptrdiff_t>(a.places.size());
  const auto transitions_begin = values_begin + static_cast<std::ptrdiff_t>(a.values.size());
  std::inplace_merge(decls.begin(), values_begin, transitions_begin, by_position);
  std::inplace_merge(decls.begin(), transitions_begin, decls.end(), by_position);
  s.names.reserve(decls.size());
  for (const Decl &d : decls) {
    switch (d.what) {
    case What::Place: declare_place(cx, s, a.places[d.index], model::PlaceId(d.index)); break;
    case What::Value: declare_value(cx, s, a.values[d.index]); break;
    case What::Transition: {
      const ast::Name &name = a.transitions[d.index].name;
      if (s.names.declare(name, Sym::Transition, model::TransitionId(d.index), cx.diag))
        check_generated_name(cx, s, name, "transition");
      break;
    }
    }
  }
}

/// An `else` transition comes after another that leaves one of its places (§5): otherwise it
/// states an order that nothing follows. One pass with a mark per place, linear in the chart.
void check_else(Context &cx, ChartScope &s) {
  IdMap<model::PlaceId, bool> left(s.out.places.size());
  for (const model::Transition &t : s.out.transitions) {
    bool follows = false;
    for (model::PlaceId p : t.inputs) follows = follows || left[p];
    if (t.otherwise && !follows && !t.inputs.empty())
      cx.diag.error(t.name_range, ErrorKind::ElseTransition,
                    fmt::format("'else' on transition '{}', but no transition declared before it leaves {}", t.name,
                                t.inputs.size() == 1 ? fmt::format("'{}'", s.out.places[t.inputs[0]].name)
                                                     : std::string("any of its input places")));
    for (model::PlaceId p : t.inputs) left[p] = true;
  }
}

/// Names the transitions: the user's name, or T<position> (§5) unless that name is taken; and
/// resolves their places.
void name_transitions(Context &cx, ChartScope &s) {
  s.out.transitions.reserve(s.ast.transitions.size());
  for (std::size_t i = 0; i < s.ast.transitions.size(); ++i) {
    const ast::Transition &t = s.ast.transitions[i];
    model::Transition out;
    out.named = t.named;
    out.otherwise = t.otherwise;
    out.name = out.named ? t.name.text : fmt::format("T{}", i);
    out.range = t.range;
    out.name_range = out.named ? t.name.range : t.range;
    if (!out.named) {
      if (const Symbol *clash = s.names.find(out.name)) {
        cx.diag
            .error(t.range, ErrorKind::DuplicateName,
                   fmt::format("this unnamed transition is named '{}' by its position, "
                               "which is already the name of {}",
                               out.name, with_article(clash->kind)))
            .note(clash->range,
                  fmt::format("'{}' declared here; name the transition ('name: A -> B') or rename it", out.name));
      }
    }
    s.out.transitions.push_back(std::move(out));
    if (s.is_fsm()) resolve_fsm_places(cx, s, i);
    else resolve_sfc_places(cx, s, i);
    if (!cx.keep_tree) s.ast.transitions[i].release_places();
  }
  check_else(cx, s);
}

void lower_values(Context &cx, ChartScope &s) {
  for (const ast::ValueDecl &v : s.ast.values) {
    const Symbol *sym = s.names.find(v.name.text);
    if (!sym || sym->range.begin != v.name.range.begin) continue;  // a duplicate, already reported
    if (sym->kind == Sym::Instance) continue;
    if (v.is_const) {
      fold_const(cx, sym->id<model::ConstId>());  // used or not, so each error is reported
      continue;
    }
    if (sym->index < 0 || !v.init) continue;
    ExprScope scope{cx, &s, true};
    model::Var &var = s.out.vars[sym->id<model::VarId>()];
    var.init = lower_initializer(v.init.get(), scope, var.type, var.name);
    if (var.init) evaluate(*var.init, cx.model, &cx.diag);  // _init computes it: no division by zero
  }
}

void lower_bodies(Context &cx, ChartScope &s) {
  ExprScope scope{cx, &s, false};
  for (std::size_t i = 0; i < s.ast.places.size(); ++i) {
    ast::Place &p = s.ast.places[i];
    model::Place &out = s.out.places[i];
    out.action = lower_block(p.action, scope);
    if (p.extras && p.extras->entry) out.entry = lower_block(*p.extras->entry, scope);
    if (p.extras && p.extras->exit) out.exit = lower_block(*p.extras->exit, scope);
    // Lowered: the tree's statements are no longer needed, and a chart of a million places
    // should not hold both forms at once (docs/performance.md).
    if (cx.keep_tree) continue;
    ast::Block().swap(p.action);
    if (p.extras) {
      p.extras->entry.reset();
      p.extras->exit.reset();
    }
  }
}

}  // namespace

void lower_transition_condition(Context &cx, ChartScope &s, std::size_t index) {
  ast::Transition &t = s.ast.transitions[index];
  if (!t.condition) return;
  ExprScope scope{cx, &s, false};
  s.out.transitions[index].condition = lower_condition(t.condition.get(), scope, "condition");
  if (!cx.keep_tree) t.condition.reset();  // lowered: see lower_bodies
}

std::optional<bool> constant_condition(const HeapOptional<model::Expr> &condition, const model::Model &model) {
  if (!condition) return true;
  auto v = evaluate(*condition, model, nullptr);
  if (!v || v->type != model::Type::Bool) return std::nullopt;
  return v->b;
}

void declare_chart(Context &cx, ast::Chart &chart) {
  model::Chart out;
  out.kind = chart.kind == ast::Chart::Kind::Fsm ? model::Chart::Kind::Fsm : model::Chart::Kind::Sfc;
  out.name = chart.name.text;
  out.in_main_file = cx.in_main_file(chart.range);
  out.range = chart.range;
  out.name_range = chart.name.range;
  const model::ChartId index = cx.model.charts.next_id();
  cx.model.charts.push_back(std::move(out));
  cx.charts.push_back(&chart);
  cx.declare_global(cx.c_names, chart.name, Sym::Chart, index);
  // The engine's names begin with the chart's and a `_`: a chart `_` would define `__init`.
  const std::string init = std::string(chart.name.text) + "_init";
  if (!chart.name.text.empty() && naming::reserved(init) == naming::Reserved::Implementation &&
      naming::reserved(chart.name.text) == naming::Reserved::None)
    cx.diag.error(chart.name.range, ErrorKind::ReservedName,
                  fmt::format("chart '{}' would generate '{}', which C reserves for its compilers (it begins with "
                              "'__')",
                              chart.name.text, init));
}

void validate_chart(Context &cx, model::ChartId index) {
  ErrorWatch watch(cx.diag);
  ChartScope scope(*cx.charts[index], cx.model.charts[index], index);
  scope.names.uses = cx.uses;
  cx.chart = &scope;
  set_period(cx, scope);
  set_team(cx, scope);
  declare_names(cx, scope);
  name_transitions(cx, scope);
  lower_values(cx, scope);
  lower_bodies(cx, scope);
  if (!scope.ast.actions.empty() ||
      scope.ast.places.end() != std::find_if(scope.ast.places.begin(), scope.ast.places.end(), [](const ast::Place &p) {
        return p.extras && !p.extras->associations.empty();
      }))
    check_named_actions(cx, scope);
  if (scope.is_fsm()) check_fsm(cx, scope, watch);
  else check_sfc(cx, scope, watch);
  scope.out.functions.assign(scope.functions.begin(), scope.functions.end());
  scope.out.consts.assign(scope.consts.begin(), scope.consts.end());
  cx.chart = nullptr;
}

}  // namespace gfec::validation
