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
  int plan = -1;                                     ///< index into Model::plans
  std::string factory;                               ///< make_<Plan>
  bool internal = false;                             ///< a sub-plan: defined in an anonymous namespace of this file
  std::vector<int> toolboxes;                        ///< environments it takes: its own toolboxes and its sub-plans'
  std::vector<std::string> actor;                    ///< handle of each actor
  std::vector<std::vector<std::string>> local;       ///< handle of each actor's supervisors
  std::vector<std::string> global;                   ///< handle of each global supervisor
  std::vector<std::vector<std::string>> actor_args;  ///< each actor's arguments as C++
  std::vector<std::vector<std::vector<std::string>>> local_args;
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

  std::vector<PlanWiring> plans;       ///< sub-plans first, each before the plans that use it; the plan compiled last
  std::vector<int> toolboxes;          ///< every toolbox the file's plans use, by index
  std::vector<std::string> env_param;  ///< by toolbox index: the factories' parameter for its environment
  FormulaHelpers helpers;              ///< what the formulas of the file need

  const model::Plan &plan_of(const PlanWiring &w) const { return model.plans.at(static_cast<std::size_t>(w.plan)); }
  const PlanWiring &wiring_of(int plan) const;
  const model::Template &templ(int index) const { return model.templates.at(static_cast<std::size_t>(index)); }
  /// `Carbot& ee`, `Carbot& ee_Carbot, Vision& ee_Vision`: a factory's parameters.
  std::string factory_params(const PlanWiring &w) const;
  /// `ee`: the arguments that pass a factory's environments on.
  std::string factory_args(const PlanWiring &w) const;
};

/// Decides every name and converts every argument for compiling `plan`.
PlanContext make_plan_context(const model::Model &model, const model::Plan &plan, const EmitOptions &options);

}  // namespace gfec::cpp_backend
