// The wiring of plan actors and supervisors (§8): rules from each result state or event to its
// target, and arguments bound to the template's parameters.
#pragma once

#include "validate/formula.h"

#include <string>
#include <vector>

namespace gfec::validation {

/// What an actor or supervisor instantiates: a template, or (actors only) a sub-plan.
struct Callee {
  std::string name;
  model::TemplateId templ;  ///< none for a sub-plan
  model::PlanId subplan;    ///< none for a template
  std::vector<std::string> outcomes;
  std::vector<const ast::Name *> outcome_decls;  ///< empty for a sub-plan's fixed states
  SourceRange range;
  bool events = false;
};

/// A toolbox template, or plan `index` used as a sub-plan (states OK, INTERRUPTED, ERROR).
Callee template_callee(Context &cx, model::TemplateId index);
Callee plan_callee(Context &cx, model::PlanId index);

/// The actor `name` refers to, or none after reporting why not.
model::ActorId resolve_actor(Context &cx, PlanScope &s, const ast::Name &name);

/// One rule per outcome of `c`, sorted by outcome (so rules[k] is outcome k once valid); every
/// outcome must be connected exactly once. `owner` is the actor or supervisor, where a missing
/// outcome is reported.
std::vector<model::Rule> lower_rules(Context &cx, PlanScope &s, const std::vector<ast::Rule> &rules, const Callee &c,
                                     const ast::Name &owner);

/// The arguments of an actor or supervisor of `c`; `call` is where a wrong count is reported.
std::vector<model::Arg> lower_args(Context &cx, PlanScope &s, const ast::ExprList &args, const Callee &c,
                                   SourceRange call);

}  // namespace gfec::validation
