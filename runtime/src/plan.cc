#include "afp/plan.h"

#include <algorithm>

#include "afp/sub_plan.h"

namespace afp {

Plan::Plan(std::string name) : name_(std::move(name)) {}

Plan::~Plan() = default;

void Plan::declare(std::string entry, Type type) { declare(std::move(entry), default_value(type)); }

void Plan::declare(std::string entry, Value initial) {
  for (const auto& declared : entries_)
    if (declared.first == entry)
      throw PlanError("configuration entry '" + entry + "' declared twice in plan '" + name_ + "'");
  entries_.emplace_back(std::move(entry), std::move(initial));
}

void Plan::declare_into(Configuration& config) const {
  for (const auto& [entry, initial] : entries_) config.declare(entry, initial);
  for (const auto& slot : actors_)
    if (const Plan* inner = slot.actor->nested_plan()) inner->declare_into(config);
}

void Plan::adopt_actor(std::string name, std::unique_ptr<Actor> actor) {
  if (!actor) throw PlanError("null actor '" + name + "' added to plan '" + name_ + "'");
  check_name_free(name);
  actors_.push_back(ActorSlot{std::move(name), std::move(actor), {}, {}});
}

void Plan::adopt_supervisor(std::string name, std::unique_ptr<Supervisor> supervisor) {
  if (!supervisor) throw PlanError("null supervisor '" + name + "' added to plan '" + name_ + "'");
  check_name_free(name);
  supervisors_.push_back(SupervisorSlot{std::move(name), std::move(supervisor)});
}

void Plan::define_first_actor(const Actor* actor) {
  if (has_first_) throw PlanError("plan '" + name_ + "' has two first actors");
  first_ = index_of(actor);
  has_first_ = true;
}

void Plan::define_subsequent(const Actor* actor, int state, Next next) {
  ActorSlot& slot = actors_[index_of(actor)];
  if (state < 0) throw PlanError("negative state of actor '" + slot.name + "'");
  auto kind = next.actor_ ? detail::Target::Kind::Actor : detail::Target::Kind::Terminate;
  if (!slot.next.emplace(state, target_of(next.actor_, kind)).second)
    throw PlanError("two rules for state " + std::to_string(state) + " of actor '" + slot.name + "'");
}

void Plan::define_supervision(const Actor* actor, const Supervisor* supervisor, int event, Reaction reaction) {
  ActorSlot& slot = actors_[index_of(actor)];
  std::size_t watcher = index_of(supervisor);
  if (slot.actor->is_computation()) throw PlanError("computation '" + slot.name + "' cannot have supervisors");
  auto is_watcher = [&](const detail::Supervision& s) { return s.supervisor == watcher; };
  if (std::any_of(global_.begin(), global_.end(), is_watcher))
    throw PlanError("supervisor '" + supervisors_[watcher].name + "' is already global");
  add_reaction(slot.supervised, watcher, event, target_of(reaction.actor_, reaction.kind_));
}

void Plan::define_global_supervision(const Supervisor* supervisor, int event, Reaction reaction) {
  std::size_t watcher = index_of(supervisor);
  auto is_watcher = [&](const detail::Supervision& s) { return s.supervisor == watcher; };
  for (const auto& slot : actors_)
    if (std::any_of(slot.supervised.begin(), slot.supervised.end(), is_watcher))
      throw PlanError("supervisor '" + supervisors_[watcher].name + "' already watches actor '" + slot.name + "'");
  add_reaction(global_, watcher, event, target_of(reaction.actor_, reaction.kind_));
}

void Plan::validate() const {
  if (!has_first_) throw PlanError("plan '" + name_ + "' has no first actor");
}

const std::string& Plan::name_of(const Actor* actor) const { return actors_[index_of(actor)].name; }

const std::string& Plan::name_of(const Supervisor* supervisor) const { return supervisors_[index_of(supervisor)].name; }

std::size_t Plan::index_of(const Actor* actor) const {
  for (std::size_t i = 0; i < actors_.size(); ++i)
    if (actors_[i].actor.get() == actor) return i;
  throw PlanError("an actor that is not part of plan '" + name_ + "'");
}

std::size_t Plan::index_of(const Supervisor* supervisor) const {
  for (std::size_t i = 0; i < supervisors_.size(); ++i)
    if (supervisors_[i].supervisor.get() == supervisor) return i;
  throw PlanError("a supervisor that is not part of plan '" + name_ + "'");
}

detail::Target Plan::target_of(const Actor* actor, detail::Target::Kind kind) const {
  return {kind, kind == detail::Target::Kind::Actor ? index_of(actor) : 0};
}

void Plan::check_name_free(const std::string& name) const {
  auto same = [&](const auto& slot) { return slot.name == name; };
  if (std::any_of(actors_.begin(), actors_.end(), same) || std::any_of(supervisors_.begin(), supervisors_.end(), same))
    throw PlanError("two instances named '" + name + "' in plan '" + name_ + "'");
}

void Plan::add_reaction(std::vector<detail::Supervision>& list, std::size_t supervisor, int event,
                        detail::Target target) {
  auto it =
      std::find_if(list.begin(), list.end(), [&](const detail::Supervision& s) { return s.supervisor == supervisor; });
  if (it == list.end()) it = list.insert(list.end(), detail::Supervision{supervisor, {}});
  const std::string& name = supervisors_[supervisor].name;
  if (event < 0) throw PlanError("negative event of supervisor '" + name + "'");
  if (!it->reactions.emplace(event, target).second)
    throw PlanError("two rules for event " + std::to_string(event) + " of supervisor '" + name + "'");
}

}  // namespace afp
