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
void collect_plans(PlanContext &c, int plan, std::vector<bool> &seen) {
  seen[static_cast<std::size_t>(plan)] = true;
  for (const auto &a : c.model.plans.at(static_cast<std::size_t>(plan)).actors)
    if (a.subplan >= 0 && !seen[static_cast<std::size_t>(a.subplan)]) collect_plans(c, a.subplan, seen);
  PlanWiring w;
  w.plan = plan;
  w.factory = "make_" + c.model.plans[static_cast<std::size_t>(plan)].name;
  c.plans.push_back(std::move(w));
}

/// A factory takes the environments of its own toolboxes and of its sub-plans' (whose
/// factories it calls); sub-plans come first, so theirs are known.
void collect_toolboxes(PlanContext &c) {
  std::set<int> all;
  for (auto &w : c.plans) {
    const model::Plan &p = c.plan_of(w);
    std::set<int> boxes(p.toolboxes.begin(), p.toolboxes.end());
    for (const auto &a : p.actors)
      if (a.subplan >= 0)
        for (int box : c.wiring_of(a.subplan).toolboxes) boxes.insert(box);
    w.toolboxes.assign(boxes.begin(), boxes.end());
    all.insert(boxes.begin(), boxes.end());
  }
  c.toolboxes.assign(all.begin(), all.end());
  // One toolbox (the usual case, and what carbot-sim's harness declares): `ee`, as in the paper.
  c.env_param.assign(c.model.toolboxes.size(), "ee");
  if (c.toolboxes.size() > 1)
    for (int box : c.toolboxes)
      c.env_param[static_cast<std::size_t>(box)] =
          "ee_" + environment_type(c.model.toolboxes[static_cast<std::size_t>(box)]);
}

std::vector<std::string> arguments(PlanContext &c, const model::Plan &p, int templ,
                                   const std::vector<model::Arg> &args) {
  std::vector<std::string> out;
  if (templ < 0) return out;  // a sub-plan takes no arguments
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
      w.local_args.emplace_back();
      for (const auto &s : a.supervisors) w.local_args.back().push_back(arguments(c, p, s.templ, s.args));
    }
  }
}

/// What a handle may not be called in any factory of the file: the names the factory body
/// refers to besides its handles (classes, factories, environments, helpers, `plan`), and `c`,
/// the formula lambdas' parameter, which would hide a handle of that name (-Wshadow).
std::set<std::string> file_names(const PlanContext &c) {
  std::set<std::string> names{"plan", "afp", "std", "c"};
  for (const auto &w : c.plans) {
    names.insert(w.factory);
    const model::Plan &p = c.plan_of(w);
    auto use = [&](int templ) {
      if (templ >= 0) names.insert(class_name(c.templ(templ)));
    };
    for (const auto &g : p.globals) use(g.templ);
    for (const auto &a : p.actors) {
      use(a.templ);
      for (const auto &s : a.supervisors) use(s.templ);
    }
  }
  for (int box : c.toolboxes) {
    names.insert(environment_type(c.model.toolboxes[static_cast<std::size_t>(box)]));
    names.insert(c.env_param[static_cast<std::size_t>(box)]);
  }
  if (c.helpers.text) names.insert(FormulaHelpers::kText);
  if (c.helpers.divide) names.insert(FormulaHelpers::kDivide);
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
      w.local.emplace_back();
      for (const auto &s : a.supervisors) w.local.back().push_back(handle(s.name));
    }
  }
}

}  // namespace

const PlanWiring &PlanContext::wiring_of(int plan) const {
  for (const auto &w : plans)
    if (w.plan == plan) return w;
  throw std::logic_error("cpp back end: a sub-plan was not collected");
}

std::string PlanContext::factory_params(const PlanWiring &w) const {
  std::string params;
  for (int box : w.toolboxes)
    params += fmt::format("{}{}& {}", params.empty() ? "" : ", ",
                          environment_type(model.toolboxes[static_cast<std::size_t>(box)]),
                          env_param[static_cast<std::size_t>(box)]);
  return params;
}

std::string PlanContext::factory_args(const PlanWiring &w) const {
  std::string args;
  for (int box : w.toolboxes) args += (args.empty() ? "" : ", ") + env_param[static_cast<std::size_t>(box)];
  return args;
}

PlanContext make_plan_context(const model::Model &model, const model::Plan &plan, const EmitOptions &options) {
  PlanContext c(model, plan, options);
  c.source_file = options.output_path;
  c.header_file = base_name(replace_extension(options.output_path, ".hpp"));
  c.guard = include_guard(c.header_file);
  std::vector<bool> seen(model.plans.size());
  collect_plans(c, static_cast<int>(&plan - model.plans.data()), seen);
  for (std::size_t i = 0; i + 1 < c.plans.size(); ++i) c.plans[i].internal = true;
  collect_toolboxes(c);
  convert_arguments(c);
  name_handles(c);
  return c;
}

}  // namespace gfec::cpp_backend
