// A plan used as an actor of another plan.
#pragma once

#include <memory>

#include "afp/actor.h"
#include "afp/plan.h"

namespace afp {

namespace detail {
class Level;
}

/// Runs a plan as one actor of the plan above, in the same executor and on
/// the same configuration. Its result states are fixed by the language. The
/// sub-plan's global supervisors watch only the sub-plan's own actors.
class SubPlan final : public Actor {
 public:
  /// The states of every sub-plan.
  enum State {
    OK,           ///< reached terminate from an actor's result state (Status::Succeeded)
    INTERRUPTED,  ///< reached terminate from a supervisor's event (Status::Interrupted)
    ERROR,        ///< an actor or supervisor inside failed (Status::Failed)
  };

  /// Wraps (and owns) `plan`.
  explicit SubPlan(std::unique_ptr<Plan> plan);
  ~SubPlan() override;

  /// The wrapped plan.
  Plan& plan() const { return *plan_; }
  Plan* nested_plan() const override { return plan_.get(); }

  /// Starts the inner plan: its global supervisors and first actor.
  void start(Context& ctx) override;

  /// Runs one step of the inner plan; its end maps to OK, INTERRUPTED or ERROR.
  StepResult step(Context& ctx) override;

  /// Stops the inner plan if it still runs (the sub-plan was interrupted).
  void stop() override;

 private:
  std::unique_ptr<Plan> plan_;
  std::unique_ptr<detail::Level> level_;
};

}  // namespace afp
