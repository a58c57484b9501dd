// The deterministic executor: one thread, plan time advanced by the caller.
// The simulator and the tests use it.
#pragma once

#include <memory>
#include <string>

#include "afp/configuration.h"
#include "afp/context.h"
#include "afp/plan.h"
#include "afp/status.h"
#include "afp/trace.h"

namespace afp {

/// Runs a plan step by step. Each step, at the new plan time: the due
/// supervisors are checked in a fixed order (global before the actor's own,
/// outer plan before sub-plan, each list in declaration order) and the first
/// non-ignored event interrupts; otherwise the actor steps once. See
/// docs/runtime.md for the exact rules.
class SteppedExecutor {
 public:
  /// Prepares a run of `plan` on `config`, declaring the plan's entries there
  /// (existing entries keep their values). `trace` may be nullptr. Both
  /// `plan` and `config` must outlive the executor.
  SteppedExecutor(Plan& plan, Configuration& config, TraceObserver* trace = nullptr);
  ~SteppedExecutor();
  SteppedExecutor(const SteppedExecutor&) = delete;
  SteppedExecutor& operator=(const SteppedExecutor&) = delete;

  /// Starts the run at plan time 0: global supervisors, then the first actor.
  /// Throws PlanError if the plan cannot run, std::logic_error if started twice.
  void start();

  /// Advances plan time by `dt` and runs one step; returns the status.
  Status step(Duration dt);

  /// Sets plan time to `t` (not before now()) and runs one step.
  Status advance_to(Duration t);

  /// Ends a running plan from outside (status Stopped).
  void stop();

  /// The plan time of the last step (0 after start()).
  Duration now() const;

  /// The run's status.
  Status status() const;

  /// Why the run failed (empty unless status() is Failed).
  const std::string& error() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace afp
