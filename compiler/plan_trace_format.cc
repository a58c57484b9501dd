#include "plan_trace_format.h"

namespace gfec::trace {

namespace {

/// `path`: the level's own path ("" for the plan, "nav", "nav.side").
void describe(const model::Model &model, model::PlanId id, const std::string &path, PlanLayout &layout,
              std::string &text) {
  const model::Plan &plan = model.plans.at(id);
  const std::size_t index = layout.levels.size();
  layout.levels.push_back(PlanLevel{path, id, {}, {}, {}});
  text += "plan " + plan.name + "\n";
  for (const model::ActorUse &a : plan.actors) {
    layout.levels[index].actors.push_back(a.name);
    text += "actor " + a.name + (a.subplan ? " runs" : "") + "\n";
  }
  // The order the cpp back end adds them in: the globals, then each actor's.
  std::vector<std::string> supervisors;
  for (const model::SupervisorUse &s : plan.globals) supervisors.push_back(s.name);
  for (const model::ActorUse &a : plan.actors)
    for (const model::SupervisorUse &s : a.supervisors) supervisors.push_back(s.name);
  for (const std::string &s : supervisors) text += "supervisor " + s + "\n";
  layout.levels[index].supervisors = std::move(supervisors);
  layout.levels[index].children.assign(plan.actors.size(), std::string::npos);
  std::size_t k = 0;
  for (const model::ActorUse &a : plan.actors) {
    const std::size_t actor = k++;
    if (!a.subplan) continue;
    const std::string inner = path.empty() ? a.name : path + "." + a.name;
    text += "instance " + inner + "\n";
    layout.levels[index].children[actor] = layout.levels.size();
    describe(model, a.subplan, inner, layout, text);
  }
}

}  // namespace

PlanLayout plan_layout_of(const model::Model &model, model::PlanId plan) {
  PlanLayout layout;
  layout.plan = plan;
  std::string text = "gfec plan trace 1\n";
  describe(model, plan, "", layout, text);
  std::uint32_t h = 2166136261u;
  for (unsigned char ch : text) h = (h ^ ch) * 16777619u;
  layout.fingerprint = h;
  return layout;
}

}  // namespace gfec::trace
