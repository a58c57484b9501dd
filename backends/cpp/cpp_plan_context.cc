#include "cpp_plan_context.h"

#include "cpp_names.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace gfec::cpp_backend {

namespace {

/// The plans of the file in definition order: every sub-plan (transitively) before the plans
/// that use it, each once, found in actor order; the plan compiled last. The validator has
/// ruled out a plan that contains itself.
void collect_plans(PlanContext &c, model::PlanId plan, IdMap<model::PlanId, bool> &seen) {
  seen[plan] = true;
  for (const auto &a : c.model.plans.at(plan).actors)
    if (a.subplan && !seen[a.subplan]) collect_plans(c, a.subplan, seen);
  PlanWiring w;
  w.plan = plan;
  w.factory = "make_" + c.model.plans[plan].name;
  c.plans.push_back(std::move(w));
}

/// A factory takes the environments of its own toolboxes and of its sub-plans' (whose
/// factories it calls); sub-plans come first, so theirs are known.
void collect_toolboxes(PlanContext &c) {
  std::set<model::ToolboxId> all;
  for (auto &w : c.plans) {
    const model::Plan &p = c.plan_of(w);
    std::set<model::ToolboxId> boxes(p.toolboxes.begin(), p.toolboxes.end());
    for (const auto &a : p.actors)
      if (a.subplan)
        for (model::ToolboxId box : c.wiring_of(a.subplan).toolboxes) boxes.insert(box);
    w.toolboxes.assign(boxes.begin(), boxes.end());
    all.insert(boxes.begin(), boxes.end());
  }
  c.toolboxes.assign(all.begin(), all.end());
  // One toolbox (the usual case, and what carbot-sim's harness declares): `ee`, as docs/plans.md writes it.
  c.env_param.assign(c.model.toolboxes.size(), "ee");
  if (c.toolboxes.size() > 1)
    for (model::ToolboxId box : c.toolboxes) c.env_param[box] = "ee_" + environment_type(c.model.toolboxes[box]);
}

/// The classes and functions a factory's body names besides its locals: each plan's factory,
/// the templates' classes, the environments' types and (once named) the formula helpers.
std::set<std::string> global_names(const PlanContext &c) {
  std::set<std::string> names;
  for (const auto &w : c.plans) {
    names.insert(w.factory);
    const model::Plan &p = c.plan_of(w);
    auto use = [&](model::TemplateId templ) {
      if (templ) names.insert(class_name(c.templ(templ)));
    };
    for (const auto &g : p.globals) use(g.templ);
    for (const auto &a : p.actors) {
      use(a.templ);
      for (const auto &s : a.supervisors) use(s.templ);
    }
  }
  for (model::ToolboxId box : c.toolboxes) names.insert(environment_type(c.model.toolboxes[box]));
  if (c.helpers.text) names.insert(c.helpers.text_fn);
  if (c.helpers.divide) names.insert(c.helpers.divide_fn);
  return names;
}

/// The formula helpers' names, before the formulas that call them are written: apart from the
/// classes and factories of the file, which they would clash with at file scope.
void name_helpers(PlanContext &c) {
  NameSpace scope;
  for (const auto &n : global_names(c)) scope.claim(n);
  c.helpers.text_fn = scope.take(c.helpers.text_fn);
  c.helpers.divide_fn = scope.take(c.helpers.divide_fn);
}

/// `plan` and `ee`, unless a class or function of the file has that name: a local or a parameter
/// would hide it where the factory names it (`std::make_unique<plan>`).
void name_factory_locals(PlanContext &c) {
  NameSpace scope;
  for (const auto &n : global_names(c)) scope.claim(n);
  for (const char *fixed : {"afp", "std", "c"}) scope.claim(fixed);
  c.plan_var = scope.take("plan");
  for (model::ToolboxId box : c.toolboxes) c.env_param[box] = scope.take(c.env_param[box]);
}

std::vector<std::string> arguments(PlanContext &c, const model::Plan &p, model::TemplateId templ,
                                   const std::vector<model::Arg> &args) {
  std::vector<std::string> out;
  if (!templ) return out;  // a sub-plan takes no arguments
  const auto &params = c.templ(templ).params;
  for (std::size_t i = 0; i < args.size() && i < params.size(); ++i) {
    const auto &param = params[i];
    out.push_back(param.dir == model::ParamDir::Out ? out_argument(p, args[i].formula, param.type)
                                                    : in_argument(p, args[i].formula, param.type, c.helpers));
  }
  return out;
}

void convert_arguments(PlanContext &c) {
  for (auto &w : c.plans) {
    const model::Plan &p = c.plan_of(w);
    for (const auto &g : p.globals) w.global_args.push_back(arguments(c, p, g.templ, g.args));
    for (const auto &a : p.actors) {
      w.actor_args.push_back(arguments(c, p, a.templ, a.args));
      std::vector<std::vector<std::string>> local;
      for (const auto &s : a.supervisors) local.push_back(arguments(c, p, s.templ, s.args));
      w.local_args.push_back(std::move(local));
    }
  }
}

/// What a handle may not be called in any factory of the file: the names the factory body
/// refers to besides its handles (classes, factories, environments, helpers, `plan`), and `c`,
/// the formula lambdas' parameter, which would hide a handle of that name (-Wshadow).
std::set<std::string> file_names(const PlanContext &c) {
  std::set<std::string> names = global_names(c);
  for (const std::string &fixed : {c.plan_var, std::string("afp"), std::string("std"), std::string("c")})
    names.insert(fixed);
  for (model::ToolboxId box : c.toolboxes) names.insert(c.env_param[box]);
  return names;
}

/// Handles keep the plan's names (actors and supervisors share one namespace in a plan); a
/// name C++ or the file needs otherwise gets a trailing `_`, never taking a name of the plan's.
void name_handles(PlanContext &c) {
  const std::set<std::string> fixed = file_names(c);
  for (auto &w : c.plans) {
    const model::Plan &p = c.plan_of(w);
    NameSpace scope;
    for (const auto &n : fixed) scope.claim(n);
    std::vector<const std::string *> names;
    for (const auto &g : p.globals) names.push_back(&g.name);
    for (const auto &a : p.actors) {
      names.push_back(&a.name);
      for (const auto &s : a.supervisors) names.push_back(&s.name);
    }
    for (const std::string *n : names)
      if (!fixed.count(*n) && !is_reserved(*n)) scope.claim(*n);
    auto handle = [&](const std::string &n) { return fixed.count(n) || is_reserved(n) ? scope.take(n) : n; };
    for (const auto &g : p.globals) w.global.push_back(handle(g.name));
    for (const auto &a : p.actors) {
      w.actor.push_back(handle(a.name));
      std::vector<std::string> local;
      for (const auto &s : a.supervisors) local.push_back(handle(s.name));
      w.local.push_back(std::move(local));
    }
  }
}

}  // namespace

const PlanWiring &PlanContext::wiring_of(model::PlanId plan) const {
  for (const auto &w : plans)
    if (w.plan == plan) return w;
  throw std::logic_error("cpp back end: a sub-plan was not collected");
}

std::string PlanContext::factory_params(const PlanWiring &w) const {
  std::string params;
  for (model::ToolboxId box : w.toolboxes)
    params +=
        fmt::format("{}{}& {}", params.empty() ? "" : ", ", environment_type(model.toolboxes[box]), env_param[box]);
  return params;
}

std::string PlanContext::factory_args(const PlanWiring &w) const {
  std::string args;
  for (model::ToolboxId box : w.toolboxes) args += (args.empty() ? "" : ", ") + env_param[box];
  return args;
}

PlanContext make_plan_context(const model::Model &model, const model::Plan &plan, const EmitOptions &options) {
  PlanContext c(model, plan, options);
  c.source_file = options.output_path;
  c.header_file = base_name(replace_extension(options.output_path, ".hpp"));
  c.guard = include_guard(c.header_file);
  IdMap<model::PlanId, bool> seen(model.plans.size());
  collect_plans(c, model.plans.id_of(plan), seen);
  for (std::size_t i = 0; i + 1 < c.plans.size(); ++i) c.plans[i].internal = true;
  collect_toolboxes(c);
  name_helpers(c);
  convert_arguments(c);
  name_factory_locals(c);
  name_handles(c);
  return c;
}

}  // namespace gfec::cpp_backend
