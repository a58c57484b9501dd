// Actors: the steps of a plan. A toolbox developer derives one class per
// actor template (see docs/runtime.md for the contract).
#pragma once

#include "afp/context.h"

namespace afp {

class Plan;

/// What Actor::step() returns: still running, or finished in a result state.
/// Converts from a state, so step() can `return FORWARD_OK;` or `return afp::running;`.
class StepResult {
 public:
  /// Finished in `state` (a value of the actor's state enum, >= 0).
  constexpr StepResult(int state) : state_(state), running_(false) {}

  /// Not finished yet.
  static constexpr StepResult still_running() { return StepResult(); }

  /// True while the actor has not finished.
  constexpr bool is_running() const { return running_; }

  /// The result state (meaningful once !is_running()).
  constexpr int state() const { return state_; }

 private:
  constexpr StepResult() : state_(0), running_(true) {}
  int state_;
  bool running_;
};

/// The actor has not finished yet.
inline constexpr StepResult running = StepResult::still_running();

/// An actor: started once, stepped until it returns a result state, stopped
/// once. Exceptions thrown from start/step/stop make the actor end in error.
class Actor {
 public:
  virtual ~Actor() = default;

  /// Begins the action; read the In parameters here.
  virtual void start(Context& ctx) { (void)ctx; }

  /// Advances the action; returns afp::running or a result state. Called every
  /// executor step (stepped) or every actor period (threaded).
  virtual StepResult step(Context& ctx) = 0;

  /// Called exactly once after start(), whatever ended the actor (finished,
  /// interrupted, failed, plan stopped): halt motion, release resources.
  virtual void stop() {}

  /// What a plan asks of its actors without RTTI (the runtime builds with
  /// -fno-rtti): the plan a sub-plan wraps (else null), whether the actor is a
  /// computation. Only SubPlan and Computation override them.
  virtual Plan* nested_plan() const { return nullptr; }
  virtual bool is_computation() const { return false; }
};

/// An actor that only reads and writes the configuration and has no
/// supervisors (a plan rejects them). It computes when it starts (so inputs
/// are read at start) and reports its state at its first step.
class Computation : public Actor {
 public:
  /// Reads inputs, writes outputs, returns the result state.
  virtual int compute(Context& ctx) = 0;

  /// Runs compute().
  void start(Context& ctx) final { state_ = compute(ctx); }

  /// Returns the state compute() returned.
  StepResult step(Context&) final { return state_; }

  bool is_computation() const final { return true; }

 private:
  int state_ = 0;
};

}  // namespace afp
