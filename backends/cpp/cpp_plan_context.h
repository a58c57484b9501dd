// What the `cpp` back end decides before it writes a plan's wiring: which plans the file holds
// (the plan compiled and, before it, every sub-plan it uses), the C++ name of every instance,
// the environment parameters of each factory, and each argument already as C++ (so that the
// file knows which formula helpers it must define).
#pragma once

#include "backend.h"
#include "cpp_formula.h"
#include "model.h"

#include <string>
#include <vector>

namespace gfec::cpp_backend {

/// One plan's factory and its instances, as the wiring names them.
struct PlanWiring {
  model::PlanId plan;
  std::string factory;                       ///< make_<Plan>
  bool internal = false;                     ///< a sub-plan: defined in an anonymous namespace of this file
  std::vector<model::ToolboxId> toolboxes;   ///< environments it takes: its own toolboxes and its sub-plans'
  IdMap<model::ActorId, std::string> actor;  ///< handle of each actor
  IdMap<model::ActorId, std::vector<std::string>> local;       ///< handle of each actor's supervisors
  std::vector<std::string> global;                             ///< handle of each global supervisor
  IdMap<model::ActorId, std::vector<std::string>> actor_args;  ///< each actor's arguments as C++
  IdMap<model::ActorId, std::vector<std::vector<std::string>>> local_args;
  std::vector<std::vector<std::string>> global_args;
};

struct PlanContext {
  PlanContext(const model::Model &m, const model::Plan &p, const EmitOptions &o) : model(m), plan(p), options(o) {}

  const model::Model &model;
  const model::Plan &plan;  ///< the plan compiled
  const EmitOptions &options;

  std::string source_file;  ///< plan.cpp, as #line names it (the output path as the user gave it)
  std::string header_file;  ///< plan.hpp beside it (base name, as plan.cpp includes it)
  std::string guard;        ///< the header's include guard
  /// The factories' local holding the plan (`plan`) and, in env_param, their parameters (`ee`):
  /// named apart from the classes and functions the factories name (a template `plan`).
  std::string plan_var;

  std::vector<PlanWiring> plans;  ///< sub-plans first, each before the plans that use it; the plan compiled last
  std::vector<model::ToolboxId> toolboxes;         ///< every toolbox the file's plans use, in model order
  IdMap<model::ToolboxId, std::string> env_param;  ///< the factories' parameter for each toolbox's environment
  FormulaHelpers helpers;                          ///< what the formulas of the file need

  const model::Plan &plan_of(const PlanWiring &w) const { return model.plans.at(w.plan); }
  const PlanWiring &wiring_of(model::PlanId plan) const;
  const model::Template &templ(model::TemplateId id) const { return model.templates.at(id); }
  /// `Carbot& ee`, `Carbot& ee_Carbot, Vision& ee_Vision`: a factory's parameters.
  std::string factory_params(const PlanWiring &w) const;
  /// `ee`: the arguments that pass a factory's environments on.
  std::string factory_args(const PlanWiring &w) const;
};

/// Decides every name and converts every argument for compiling `plan`.
PlanContext make_plan_context(const model::Model &model, const model::Plan &plan, const EmitOptions &options);

}  // namespace gfec::cpp_backend
