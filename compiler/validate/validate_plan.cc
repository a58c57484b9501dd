// Plans (§8): actors wired by their result states, supervisors wired by their events, a typed
// configuration, sub-plans; every state and event connected, nothing left dangling.
#include "validate/families.h"
#include "validate/fold.h"
#include "validate/plan_wiring.h"
#include "validate/suggest.h"
#include "validate/types.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <string_view>
#include <tuple>
#include <unordered_map>

namespace gfec::validation {

namespace {

using model::Type;

// ------------------------------------------------------------------ names

/// Lowers the config entries' types: each entry's id in Plan::config, or none if its type is
/// wrong (uses of it then stay silent).
std::vector<model::ConfigId> lower_config_types(Context &cx, PlanScope &s) {
  std::vector<model::ConfigId> index;
  for (const auto &block : s.ast.config_blocks) {
    for (const ast::ConfigEntry &e : block) {
      auto type = lower_type(e.type, kScalar | kString | kObject, "a config entry", cx.diag);
      index.push_back(type ? s.out.config.next_id() : model::ConfigId());
      if (type) s.out.config.push_back({std::string(e.name.text), *type, std::nullopt, e.range, e.name.range});
    }
  }
  return index;
}

/// Config entries, actors and supervisors, declared in textual order so a duplicate's note
/// points at the one that comes first.
void declare_members(Context &cx, PlanScope &s, const std::vector<model::ConfigId> &config_index) {
  struct Member {
    const ast::Name *name;
    Sym kind;
    int index;
  };
  std::vector<Member> members;
  std::size_t entry = 0;
  for (const auto &block : s.ast.config_blocks)
    for (const auto &e : block) members.push_back({&e.name, Sym::ConfigEntry, symbol_index(config_index[entry++])});
  for (const auto &g : s.ast.global_supervisors) members.push_back({&g.name, Sym::Supervisor, -1});
  for (std::size_t i = 0; i < s.ast.actors.size(); ++i) {
    members.push_back({&s.ast.actors[i].name, Sym::Actor, static_cast<int>(i)});
    for (const auto &sup : s.ast.actors[i].supervisors) members.push_back({&sup.name, Sym::Supervisor, -1});
  }
  std::stable_sort(members.begin(), members.end(),
                   [](const Member &a, const Member &b) { return a.name->range.begin < b.name->range.begin; });
  for (const Member &m : members) s.names.declare(*m.name, m.kind, m.index, cx.diag);
}

/// A config initialiser: a constant, folded to a literal of the entry's type.
std::optional<model::Expr> lower_config_init(Context &cx, PlanScope &s, const ast::ConfigEntry &e, Type type) {
  auto init = lower_formula(e.init.get(), cx, s, true);
  if (!init) return std::nullopt;
  bool fits =
      type != Type::Object && (assignable(type, init->type) || (type == Type::String && model::is_numeric(init->type)));
  if (!fits) {
    cx.diag.error(init->range, ErrorKind::TypeMismatch,
                  fmt::format("cannot initialize '{}' of type {} with a value of type {}", e.name.text, quoted(type),
                              quoted(init->type)));
    return std::nullopt;
  }
  auto v = evaluate(*init, cx.model, &cx.diag);
  if (!v) return std::nullopt;
  return to_literal(*v, type, init->range, cx.diag, &*init);
}

void lower_config_inits(Context &cx, PlanScope &s, const std::vector<model::ConfigId> &config_index) {
  std::size_t entry = 0;
  for (const auto &block : s.ast.config_blocks) {
    for (const ast::ConfigEntry &e : block) {
      const model::ConfigId index = config_index[entry++];
      if (!index || !e.init) continue;
      s.out.config[index].init = lower_config_init(cx, s, e, s.out.config[index].type);
    }
  }
}

void set_start(Context &cx, PlanScope &s) {
  const auto &starts = s.ast.starts;
  if (starts.empty()) {
    cx.diag.error(s.ast.name.range, ErrorKind::Start, fmt::format("plan '{}' has no start actor", s.out.name))
        .note("name the actor that runs first with 'start NAME;'");
    return;
  }
  for (std::size_t i = 1; i < starts.size(); ++i)
    cx.diag.error(starts[i].range, ErrorKind::Start, fmt::format("plan '{}' has more than one start actor", s.out.name))
        .note(starts[0].range, "the first 'start' is here");
  s.out.start = resolve_actor(cx, s, starts[0]);
}

// ------------------------------------------------------------------ rules
// ------------------------------------------------------------------ actors and supervisors

/// The template (or plan) `name` refers to, if it is one of `kinds`; reports why not.
std::optional<Callee> resolve_callee(Context &cx, PlanScope &s, const ast::Name &name, bool supervisor) {
  if (name.text.empty()) return std::nullopt;
  const Symbol *sym = cx.plan_names.resolve(name);
  if (!sym) {
    std::vector<const Symbol *> candidates;
    for (const Symbol *c : cx.plan_names.of({Sym::Template, Sym::Plan})) {
      bool is_supervisor = c->kind == Sym::Template &&
                           cx.model.templates[c->id<model::TemplateId>()].kind == model::Template::Kind::Supervisor;
      if (is_supervisor == supervisor) candidates.push_back(c);
    }
    report_unknown(cx.diag, s.unknown, name, supervisor ? "supervisor template" : "template", candidates);
    return std::nullopt;
  }
  if (sym->kind == Sym::Plan) {
    if (!supervisor) return plan_callee(cx, sym->id<model::PlanId>());
    cx.diag
        .error(name.range, ErrorKind::TemplateKind,
               fmt::format("'{}' is a plan; 'supervise' needs a supervisor template", name.text))
        .note(cx.model.plans[sym->id<model::PlanId>()].range, fmt::format("'{}' declared here", name.text));
    return std::nullopt;
  }
  const model::Template &t = cx.model.templates[sym->id<model::TemplateId>()];
  if ((t.kind == model::Template::Kind::Supervisor) != supervisor) {
    cx.diag
        .error(name.range, ErrorKind::TemplateKind,
               supervisor
                   ? fmt::format("'{}' is an actor template; 'supervise' needs a supervisor template", name.text)
                   : fmt::format("'{}' is a supervisor template; an actor needs an actor or computation", name.text))
        .note(t.range, fmt::format("'{}' declared here", name.text));
    return std::nullopt;
  }
  s.toolboxes.insert(t.toolbox);
  return template_callee(cx, sym->id<model::TemplateId>());
}

model::SupervisorUse lower_supervise(Context &cx, PlanScope &s, const ast::Supervise &sup) {
  model::SupervisorUse out;
  out.name = sup.name.text;
  out.range = sup.range;
  auto c = resolve_callee(cx, s, sup.template_name, true);
  if (!c) return out;
  out.templ = c->templ;
  out.args = lower_args(cx, s, sup.args, *c, sup.range);
  out.rules = lower_rules(cx, s, sup.rules, *c, sup.name);
  return out;
}

model::ActorUse lower_actor(Context &cx, PlanScope &s, const ast::ActorUse &a) {
  model::ActorUse out;
  out.name = a.name.text;
  out.range = a.range;
  out.name_range = a.name.range;
  auto c = resolve_callee(cx, s, a.template_name, false);
  bool computation = c && c->templ && cx.model.templates[c->templ].kind == model::Template::Kind::Computation;
  if (c && a.written_as_computation && !computation)
    cx.diag.error(a.template_name.range, ErrorKind::TemplateKind, fmt::format("'{}' is not a computation", c->name))
        .note(c->range, fmt::format("'{}' declared here", c->name));
  if (c) {
    out.templ = c->templ;
    out.subplan = c->subplan;
    out.args = lower_args(cx, s, a.args, *c, a.range);
    out.rules = lower_rules(cx, s, a.rules, *c, a.name);
  }
  for (const ast::Supervise &sup : a.supervisors) {
    if (computation)
      cx.diag
          .error(sup.name.range, ErrorKind::ComputationSupervisor,
                 fmt::format("computation '{}' cannot be supervised", a.name.text))
          .note("a computation runs to its result without interruption");
    out.supervisors.push_back(lower_supervise(cx, s, sup));
  }
  return out;
}

/// Global supervisors and actors, in textual order so that diagnostics come in it too.
void lower_members(Context &cx, PlanScope &s) {
  const auto &globals = s.ast.global_supervisors;
  const auto &actors = s.ast.actors;
  s.out.globals.resize(globals.size());
  s.out.actors.resize(actors.size());
  std::size_t g = 0, a = 0;
  while (g < globals.size() || a < actors.size()) {
    bool global_first = a == actors.size() || (g < globals.size() && globals[g].range.begin < actors[a].range.begin);
    if (global_first) {
      s.out.globals[g] = lower_supervise(cx, s, globals[g]);
      ++g;
    } else {
      s.out.actors[a] = lower_actor(cx, s, actors[a]);
      ++a;
    }
  }
}

// ------------------------------------------------------------------ warnings

/// Actors no path reaches from the start actor, following every rule of every actor reached
/// and of the global supervisors (which may interrupt any actor).
void warn_unreachable(Context &cx, PlanScope &s) {
  const model::Plan &p = s.out;
  if (!p.start) return;
  IdMap<model::ActorId, bool> reach(p.actors.size());
  std::vector<model::ActorId> work{p.start};
  reach[p.start] = true;
  auto follow = [&](const std::vector<model::Rule> &rules) {
    for (const auto &r : rules)
      if (r.target.kind == model::RuleTarget::Kind::Actor && !reach[r.target.actor]) {
        reach[r.target.actor] = true;
        work.push_back(r.target.actor);
      }
  };
  for (const auto &g : p.globals) follow(g.rules);
  while (!work.empty()) {
    const model::ActorUse &a = p.actors[work.back()];
    work.pop_back();
    follow(a.rules);
    for (const auto &sup : a.supervisors) follow(sup.rules);
  }
  for (model::ActorId i : p.actors.ids())
    if (!reach[i])
      cx.diag.warning(Warning::UnreachableActor, s.ast.actors[i.index()].name.range,
                      fmt::format("actor '{}' is never reached from the start actor '{}'", p.actors[i].name,
                                  p.actors[p.start].name));
}

// ------------------------------------------------------------------ recursion

struct PlanGraph {
  Context &cx;
  IdMap<model::PlanId, int> color;  ///< 0 unvisited, 1 on the path, 2 done
  /// The path being explored: (plan, its next actor to look at). An explicit stack, so a long
  /// chain of sub-plans cannot overflow the real one.
  std::vector<std::pair<model::PlanId, std::size_t>> stack;

  void visit(model::PlanId root) {
    color[root] = 1;
    stack.push_back({root, 0});
    while (!stack.empty()) {
      auto &[plan, next] = stack.back();
      const auto &actors = cx.model.plans[plan].actors;
      if (next == actors.size()) {
        color[plan] = 2;
        stack.pop_back();
        continue;
      }
      model::PlanId sub = actors[next++].subplan;
      if (!sub) continue;
      if (color[sub] == 1) report(sub);
      if (color[sub] != 0) continue;
      color[sub] = 1;
      stack.push_back({sub, 0});
    }
  }

  /// `plan` is on the path: the path from it to the top is the chain that contains it (each
  /// entry's actor just before `next` is the one that uses the following plan).
  void report(model::PlanId plan) {
    auto &d = cx.diag.error(cx.plans[plan]->name.range, ErrorKind::RecursivePlan,
                            fmt::format("plan '{}' contains itself", cx.model.plans[plan].name));
    auto first = std::find_if(stack.begin(), stack.end(), [&](const auto &e) { return e.first == plan; });
    for (auto it = first; it != stack.end(); ++it) {
      const ast::ActorUse &a = cx.plans[it->first]->actors[it->second - 1];
      d.note(a.name.range, fmt::format("'{}' uses '{}' as actor '{}'", cx.model.plans[it->first].name,
                                       a.template_name.text, a.name.text));
    }
  }
};

// ------------------------------------------------------------------ the shared configuration

/// A plan and the sub-plans it runs share one configuration, in which a name is one entry
/// (docs/runtime.md, "Sub-plans"). The runtime declares the plan's entries first, then each
/// sub-plan's, actor by actor and depth first; the first declaration gives the entry its type and
/// initial value, a later one of another type stops the program (afp::ConfigError) and a later
/// initial value is never used. This walks the same order, so both are found at compile time.
class SharedConfig {
public:
  explicit SharedConfig(Context &cx) : cx_(cx), on_path_(cx.model.plans.size()) {}

  void check(model::PlanId root) {
    first_.clear();
    std::vector<bool> done(cx_.model.plans.size());
    enter(root);
    while (!path_.empty()) {
      auto &[plan, next] = path_.back();
      const auto &actors = cx_.model.plans[plan].actors;
      if (next == actors.size()) {
        on_path_[plan] = 0;
        done[plan.index()] = true;
        path_.pop_back();
        continue;
      }
      model::PlanId sub = actors[model::ActorId(next++)].subplan;
      // A plan met again declares what it declared before; a cycle is recursive-plan's error.
      if (sub && !on_path_[sub] && !done[sub.index()]) enter(sub);
    }
  }

private:
  struct Declared {
    model::PlanId plan;
    model::ConfigId entry;
  };

  void enter(model::PlanId plan) {
    on_path_[plan] = 1;
    path_.push_back({plan, 0});
    const model::Plan &p = cx_.model.plans[plan];
    for (model::ConfigId e : p.config.ids()) {
      auto [it, fresh] = first_.emplace(std::string_view(p.config[e].name), Declared{plan, e});
      if (!fresh) compare(it->second, {plan, e});
    }
  }

  const model::ConfigEntry &entry(Declared d) const { return cx_.model.plans[d.plan].config[d.entry]; }

  void compare(Declared first, Declared later) {
    const model::ConfigEntry &a = entry(first), &b = entry(later);
    const bool conflict = a.type != b.type;
    if (!conflict && (!b.init || same_initial_value(a, b))) return;
    if (!reported_.insert({first.plan.index(), first.entry.index(), later.plan.index(), later.entry.index()}).second)
      return;
    const std::string &outer = cx_.model.plans[first.plan].name;
    const std::string &inner = cx_.model.plans[later.plan].name;
    Diagnostic *d = nullptr;
    if (conflict) {
      d = &cx_.diag.error(b.name_range, ErrorKind::ConfigType,
                          fmt::format("config entry '{}' is '{}' in plan '{}' but '{}' in plan '{}', which share one "
                                      "configuration",
                                      b.name, model::type_name(b.type), inner, model::type_name(a.type), outer));
      d->note(a.name_range, fmt::format("'{}' is declared '{}' here, first", a.name, model::type_name(a.type)));
    } else {
      d = &cx_.diag.warning(
          Warning::ConfigInitial, b.init->range,
          fmt::format("initial value of config entry '{}' is not used when plan '{}' runs plan '{}': "
                      "'{}' declares the entry first, {}",
                      b.name, root_name(), inner, outer,
                      a.init ? "with another initial value" : "without one (it starts at its type's default)"));
      d->note(a.name_range, fmt::format("'{}' is declared here, first", a.name));
    }
    for (std::size_t i = 0; i + 1 < path_.size(); ++i) {
      const model::ActorUse &use = cx_.model.plans[path_[i].first].actors[model::ActorId(path_[i].second - 1)];
      d->note(use.name_range,
              fmt::format("plan '{}' runs plan '{}' as actor '{}'", cx_.model.plans[path_[i].first].name,
                          cx_.model.plans[use.subplan].name, use.name));
    }
  }

  const std::string &root_name() const { return cx_.model.plans[path_.front().first].name; }

  /// Whether `b`'s initial value is the one `a`'s declaration gives the entry: `a`'s own, or
  /// its type's default (false, 0, "", which a default Expr holds).
  static bool same_initial_value(const model::ConfigEntry &a, const model::ConfigEntry &b) {
    static const model::Expr kDefault;
    const model::Expr &x = a.init ? *a.init : kDefault, &y = *b.init;
    switch (a.type) {
    case Type::Bool: return x.bool_value == y.bool_value;
    case Type::Int: return x.int_value == y.int_value;
    case Type::String: return x.text == y.text;
    default: return x.float_value == y.float_value;
    }
  }

  Context &cx_;
  IdMap<model::PlanId, int> on_path_;  ///< 1: on path_
  /// The plans from the root down to the one being walked: (plan, its next actor to look at).
  std::vector<std::pair<model::PlanId, std::size_t>> path_;
  std::unordered_map<std::string_view, Declared> first_;
  std::set<std::tuple<std::size_t, std::size_t, std::size_t, std::size_t>> reported_;
};

}  // namespace

void declare_plan(Context &cx, const ast::Plan &plan) {
  model::Plan out;
  out.name = plan.name.text;
  out.in_main_file = cx.in_main_file(plan.range);
  out.range = plan.range;
  const model::PlanId index = cx.model.plans.next_id();
  cx.model.plans.push_back(std::move(out));
  cx.plans.push_back(&plan);
  cx.declare_global(cx.plan_names, plan.name, Sym::Plan, index);
}

void validate_plan(Context &cx, model::PlanId index) {
  ErrorWatch watch(cx.diag);
  PlanScope s(*cx.plans[index], cx.model.plans[index]);
  s.names.uses = cx.uses;
  std::vector<model::ConfigId> config_index = lower_config_types(cx, s);
  declare_members(cx, s, config_index);
  lower_config_inits(cx, s, config_index);
  set_start(cx, s);
  lower_members(cx, s);
  s.out.toolboxes.assign(s.toolboxes.begin(), s.toolboxes.end());
  if (watch.clean()) warn_unreachable(cx, s);
}

void check_plan_recursion(Context &cx) {
  PlanGraph g{cx, IdMap<model::PlanId, int>(cx.model.plans.size()), {}};
  for (model::PlanId p : cx.model.plans.ids())
    if (g.color[p] == 0) g.visit(p);
}

void check_shared_config(Context &cx) {
  SharedConfig shared(cx);
  for (model::PlanId p : cx.model.plans.ids()) shared.check(p);
}

}  // namespace gfec::validation
