#include "validate/plan_wiring.h"

#include "validate/expr.h"
#include "validate/suggest.h"

#include <fmt/format.h>

#include <algorithm>

namespace gfec::validation {

namespace {

using model::Type;

/// `STATE -> target` of one rule; nothing if the target is wrong (reported).
std::optional<model::RuleTarget> lower_target(Context &cx, PlanScope &s, const ast::Rule &r, const Callee &c) {
  model::RuleTarget t;
  switch (r.target) {
  case ast::Rule::Target::Terminate: t.kind = model::RuleTarget::Kind::Terminate; return t;
  case ast::Rule::Target::Ignore:
    if (!c.events) {
      cx.diag
          .error(r.target_name.range, ErrorKind::IgnoreState,
                 fmt::format("result state '{}' cannot be ignored: only supervisor events can", r.outcome.text))
          .note("a result state leads to an actor or to 'terminate'");
      return std::nullopt;
    }
    t.kind = model::RuleTarget::Kind::Ignore;
    return t;
  case ast::Rule::Target::Actor:
    t.actor = resolve_actor(cx, s, r.target_name);
    if (!t.actor) return std::nullopt;
    return t;
  }
  return std::nullopt;
}

/// The index of the outcome a rule names, or -1 after reporting it as unknown; then `guess`
/// is the outcome offered as "did you mean", or -1.
int find_outcome(Context &cx, PlanScope &s, const ast::Name &name, const Callee &c, int &guess) {
  guess = -1;
  for (std::size_t k = 0; k < c.outcomes.size(); ++k)
    if (c.outcomes[k] == name.text) {
      // Found in the template's list, not a namespace: recorded here for the language server.
      if (cx.uses && k < c.outcome_decls.size())
        cx.uses->list.push_back(
            {name.range, c.outcome_decls[k]->range, c.events ? Sym::Event : Sym::ResultState, static_cast<int>(k)});
      return static_cast<int>(k);
    }
  if (name.text.empty()) return -1;
  std::vector<Symbol> symbols;
  for (std::size_t k = 0; k < c.outcomes.size(); ++k)
    symbols.push_back({Sym::ResultState, static_cast<int>(k), c.outcomes[k],
                       c.outcome_decls.empty() ? SourceRange{} : c.outcome_decls[k]->range});
  std::vector<const Symbol *> candidates;
  for (const Symbol &sym : symbols) candidates.push_back(&sym);
  const Symbol *best = closest(name.text, candidates);
  if (best) guess = best->index;
  const char *what = c.events ? "event" : "result state";
  if (!s.unknown.insert(fmt::format("{} {} {}", what, c.name, name.text)).second) return -1;
  auto &d = cx.diag.error(name.range, ErrorKind::UnknownName,
                          fmt::format("unknown {} '{}' of '{}'", what, name.text, c.name));
  if (best) d.fix(name.range, best->name());
  if (best && c.outcome_decls.empty()) d.note(fmt::format("did you mean '{}'?", best->name()));
  else if (best) d.note(best->range, fmt::format("did you mean '{}'?", best->name()));
  return -1;
}

std::string outcome_list(const Callee &c) {
  std::string list;
  for (const auto &o : c.outcomes) list += (list.empty() ? "" : ", ") + o;
  return list;
}

/// An `out` argument: a plain config entry, whose type the parameter's value converts to.
std::optional<model::Expr> lower_out_arg(Context &cx, PlanScope &s, const ast::Expr *arg, const model::TemplateParam &p,
                                         const Callee &c) {
  if (!arg) return std::nullopt;
  const Symbol *sym = arg->kind == ast::Expr::Kind::Name ? s.names.resolve(arg->name) : nullptr;
  if (arg->kind == ast::Expr::Kind::Name && !sym && !cx.c_names.find(arg->name.text))
    return lower_formula(arg, cx, s, false);  // reports the unknown name
  if (!sym || sym->kind != Sym::ConfigEntry) {
    cx.diag
        .error(arg->range, ErrorKind::OutArgument,
               fmt::format("out parameter '{}' of '{}' must be bound to a config entry", p.name, c.name))
        .note(c.range, fmt::format("'{}' declared here", c.name));
    return std::nullopt;
  }
  auto x = lower_formula(arg, cx, s, false);
  if (x && !convertible(x->type, p.type)) {
    cx.diag
        .error(arg->range, ErrorKind::TypeMismatch,
               fmt::format("out parameter '{}' of '{}' has type {}, which config entry "
                           "'{}' of type {} cannot hold",
                           p.name, c.name, quoted(p.type), arg->name.text, quoted(x->type)))
        .note(c.range, fmt::format("'{}' declared here", c.name));
    return std::nullopt;
  }
  return x;
}

std::optional<model::Expr> lower_in_arg(Context &cx, PlanScope &s, const ast::Expr *arg, const model::TemplateParam &p,
                                        const Callee &c, std::size_t position) {
  auto x = lower_formula(arg, cx, s, false);
  if (x && !convertible(p.type, x->type)) {
    cx.diag
        .error(x->range, ErrorKind::TypeMismatch,
               fmt::format("incompatible type for argument {} ('{}') of '{}': expected {}, have {}", position, p.name,
                           c.name, quoted(p.type), quoted(x->type)))
        .note(c.range, fmt::format("'{}' declared here", c.name));
    return std::nullopt;
  }
  return x;
}

}  // namespace

Callee template_callee(Context &cx, model::TemplateId index) {
  const model::Template &t = cx.model.templates[index];
  Callee c{t.name, index, {}, t.outcomes, {}, t.range, t.kind == model::Template::Kind::Supervisor};
  for (const ast::Name &n : cx.templates[index]->outcomes) c.outcome_decls.push_back(&n);
  return c;
}

Callee plan_callee(Context &cx, model::PlanId index) {
  const model::Plan &p = cx.model.plans[index];
  return {p.name, {}, index, {std::begin(model::kSubPlanStates), std::end(model::kSubPlanStates)}, {}, p.range, false};
}

model::ActorId resolve_actor(Context &cx, PlanScope &s, const ast::Name &name) {
  if (name.text.empty()) return {};
  const Symbol *sym = s.names.resolve(name);
  if (sym && sym->kind == Sym::Actor) return sym->id<model::ActorId>();
  // An actor that lost its name to an earlier declaration: the clash is reported already.
  for (std::size_t i = 0; sym && i < s.ast.actors.size(); ++i)
    if (s.ast.actors[i].name.text == name.text) return model::ActorId(i);
  if (sym) {
    cx.diag
        .error(name.range, ErrorKind::TypeMismatch,
               fmt::format("'{}' is {}, not an actor", name.text, with_article(sym->kind)))
        .note(sym->range, fmt::format("'{}' declared here", name.text));
    return {};
  }
  report_unknown(cx.diag, s.unknown, name, "actor", s.names.of({Sym::Actor}));
  return {};
}

std::vector<model::Rule> lower_rules(Context &cx, PlanScope &s, const std::vector<ast::Rule> &rules, const Callee &c,
                                     const ast::Name &owner) {
  std::vector<model::Rule> out;
  std::vector<const ast::Rule *> connected(c.outcomes.size(), nullptr);
  const char *what = c.events ? "event" : "result state";
  for (const ast::Rule &r : rules) {
    int guess;
    int k = find_outcome(cx, s, r.outcome, c, guess);
    // A misspelt outcome most likely meant the one offered: not also "not connected".
    if (k < 0 && guess >= 0 && !connected[guess]) connected[guess] = &r;
    if (k < 0) continue;
    if (connected[k]) {
      cx.diag
          .error(r.outcome.range, ErrorKind::DuplicateRule,
                 fmt::format("{} '{}' is connected twice", what, r.outcome.text))
          .note(connected[k]->range, "first connected here");
      continue;
    }
    connected[k] = &r;
    if (auto target = lower_target(cx, s, r, c)) out.push_back({k, *target, r.range});
  }
  for (std::size_t k = 0; k < c.outcomes.size(); ++k) {
    if (connected[k]) continue;
    auto &d = cx.diag.error(owner.range, ErrorKind::NotConnected,
                            fmt::format("{} '{}' of '{}' is not connected", what, c.outcomes[k], c.name));
    if (c.subplan) d.note(fmt::format("a sub-plan's result states are {}", outcome_list(c)));
    else d.note(c.range, fmt::format("'{}' has the {}s {}", c.name, what, outcome_list(c)));
  }
  std::sort(out.begin(), out.end(), [](const model::Rule &a, const model::Rule &b) { return a.outcome < b.outcome; });
  return out;
}

std::vector<model::Arg> lower_args(Context &cx, PlanScope &s, const ast::ExprList &args, const Callee &c,
                                   SourceRange call) {
  std::vector<model::Arg> out;
  if (c.subplan) {
    if (!args.empty())
      cx.diag.error(call, ErrorKind::ArgumentCount, fmt::format("sub-plan '{}' takes no arguments", c.name));
    return out;
  }
  const auto &params = cx.model.templates[c.templ].params;
  if (args.size() != params.size()) {
    cx.diag
        .error(call, ErrorKind::ArgumentCount,
               fmt::format("too {} arguments to '{}' (expected {}, have {})",
                           args.size() > params.size() ? "many" : "few", c.name, params.size(), args.size()))
        .note(c.range, fmt::format("'{}' declared here", c.name));
    return out;
  }
  if (!cx.template_ok[c.templ]) return out;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const model::TemplateParam &p = params[i];
    auto x =
        p.dir == model::ParamDir::Out ? lower_out_arg(cx, s, args[i], p, c) : lower_in_arg(cx, s, args[i], p, c, i + 1);
    if (x) out.push_back({std::move(*x), p.dir});
  }
  return out;
}

}  // namespace gfec::validation
