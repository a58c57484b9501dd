// A plan: actor and supervisor instances (owned by the plan) and the rules
// that wire them, as the code generator emits them (docs/plans.md):
//
//   auto* fwd = plan.add_actor("searchFirstWall", std::make_unique<Forward>(ee, afp::in<float>(100000)));
//   plan.define_first_actor(fwd);
//   plan.define_subsequent(fwd, Forward::FORWARD_OK, fwd);
//   plan.define_supervision(fwd, touch, CheckTouch::TOUCHED, backup);
//   plan.define_global_supervision(escape, CheckEscape::ESCAPE, afp::terminate);
//
// Executors run a plan; the plan itself holds no run state.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "afp/actor.h"
#include "afp/configuration.h"
#include "afp/supervisor.h"
#include "afp/value.h"

namespace afp {

/// The plan is wired wrongly (unknown instance, rule defined twice, ...).
class PlanError : public Error {
 public:
  using Error::Error;
};

/// The `terminate` target of a state or event rule.
struct Terminate {};
inline constexpr Terminate terminate{};

/// The `ignore` target of an event rule.
struct Ignore {};
inline constexpr Ignore ignore{};

namespace detail {
class Level;

/// Where a rule leads, with the actor resolved to its index in the plan.
struct Target {
  enum class Kind { Actor, Terminate, Ignore };
  Kind kind;
  std::size_t actor;  // when kind == Actor
};

/// One supervisor watching (one actor, or globally) and its event rules.
struct Supervision {
  std::size_t supervisor;
  std::map<int, Target> reactions;
};
}  // namespace detail

/// Where an actor's result state leads: the next actor or afp::terminate.
class Next {
 public:
  /// Leads to `actor` (an instance of the same plan).
  Next(const Actor* actor) : actor_(actor) {}
  /// Leads to the end of the plan.
  Next(Terminate) {}

 private:
  friend class Plan;
  const Actor* actor_ = nullptr;  // nullptr = terminate
};

/// Where a supervisor's event leads: the next actor, afp::terminate or afp::ignore.
class Reaction {
 public:
  /// Interrupts and continues with `actor` (an instance of the same plan).
  Reaction(const Actor* actor) : kind_(detail::Target::Kind::Actor), actor_(actor) {}
  /// Interrupts and ends the plan.
  Reaction(Terminate) : kind_(detail::Target::Kind::Terminate) {}
  /// Does not interrupt: the event is dropped.
  Reaction(Ignore) : kind_(detail::Target::Kind::Ignore) {}

 private:
  friend class Plan;
  detail::Target::Kind kind_;
  const Actor* actor_ = nullptr;
};

/// A plan: owns its actors and supervisors, declares its configuration
/// entries, and holds the rules. Wiring errors throw PlanError.
class Plan {
 public:
  /// An empty plan named `name` (the chart's name, used in traces).
  explicit Plan(std::string name);
  ~Plan();
  Plan(const Plan&) = delete;
  Plan& operator=(const Plan&) = delete;

  /// The plan's name.
  const std::string& name() const { return name_; }

  /// Declares a configuration entry holding the type's default value.
  void declare(std::string entry, Type type);

  /// Declares a configuration entry with an initial value.
  void declare(std::string entry, Value initial);

  /// Declares this plan's and its sub-plans' entries in `config`; existing
  /// entries keep their values (see Configuration::declare).
  void declare_into(Configuration& config) const;

  /// Adds an actor instance named `name`; returns it, as the handle for rules.
  template <class A>
  A* add_actor(std::string name, std::unique_ptr<A> actor) {
    static_assert(std::is_base_of_v<Actor, A>, "add_actor takes an afp::Actor");
    A* handle = actor.get();
    adopt_actor(std::move(name), std::move(actor));
    return handle;
  }

  /// Adds a supervisor instance named `name`; returns it, as the handle for rules.
  template <class S>
  S* add_supervisor(std::string name, std::unique_ptr<S> supervisor) {
    static_assert(std::is_base_of_v<Supervisor, S>, "add_supervisor takes an afp::Supervisor");
    S* handle = supervisor.get();
    adopt_supervisor(std::move(name), std::move(supervisor));
    return handle;
  }

  /// The actor that runs first.
  void define_first_actor(const Actor* actor);

  /// When `actor` finishes in `state`, `next` follows.
  void define_subsequent(const Actor* actor, int state, Next next);

  /// `supervisor` watches `actor`; its `event` leads to `reaction`. An actor's
  /// supervisors are checked in the order of their first rule.
  void define_supervision(const Actor* actor, const Supervisor* supervisor, int event, Reaction reaction);

  /// `supervisor` watches every actor of this plan (not of a plan above);
  /// its `event` leads to `reaction`. Checked before the actor's own.
  void define_global_supervision(const Supervisor* supervisor, int event, Reaction reaction);

  /// Throws PlanError unless the plan can run (it has a first actor).
  void validate() const;

  /// The instance name of one of this plan's actors or supervisors.
  const std::string& name_of(const Actor* actor) const;
  const std::string& name_of(const Supervisor* supervisor) const;

  /// The actors and supervisors in the order they were added (for observers that number them,
  /// such as afp::LinkTrace).
  std::size_t actor_count() const { return actors_.size(); }
  const std::string& actor_name(std::size_t index) const { return actors_.at(index).name; }
  const Actor& actor_at(std::size_t index) const { return *actors_.at(index).actor; }
  std::size_t supervisor_count() const { return supervisors_.size(); }
  const std::string& supervisor_name(std::size_t index) const { return supervisors_.at(index).name; }

 private:
  friend class detail::Level;

  struct ActorSlot {
    std::string name;
    std::unique_ptr<Actor> actor;
    std::map<int, detail::Target> next;           // by result state
    std::vector<detail::Supervision> supervised;  // in declaration order
  };
  struct SupervisorSlot {
    std::string name;
    std::unique_ptr<Supervisor> supervisor;
  };

  void adopt_actor(std::string name, std::unique_ptr<Actor> actor);
  void adopt_supervisor(std::string name, std::unique_ptr<Supervisor> supervisor);
  std::size_t index_of(const Actor* actor) const;
  std::size_t index_of(const Supervisor* supervisor) const;
  detail::Target target_of(const Actor* actor, detail::Target::Kind kind) const;
  void check_name_free(const std::string& name) const;
  void add_reaction(std::vector<detail::Supervision>& list, std::size_t supervisor, int event, detail::Target target);

  std::string name_;
  std::vector<std::pair<std::string, Value>> entries_;
  std::vector<ActorSlot> actors_;
  std::vector<SupervisorSlot> supervisors_;
  std::vector<detail::Supervision> global_;
  std::size_t first_ = 0;
  bool has_first_ = false;
};

}  // namespace afp
