// The trace hook: an observer told what the plan does, for logs, tests and
// debuggers. Executors hold a nullable pointer to it, so an unused hook costs
// one pointer test per event.
#pragma once

#include <string_view>

#include "afp/context.h"
#include "afp/status.h"

namespace afp {

class Plan;

/// Receives the plan's events. Called from the executor's thread only (never
/// from a supervisor thread), for the top plan and every sub-plan; `plan`
/// tells which. Override what you need; the defaults do nothing.
class TraceObserver {
 public:
  virtual ~TraceObserver() = default;

  /// `actor` (instance name) started.
  virtual void actor_started(const Plan& plan, std::string_view actor, Duration now) {
    (void)plan, (void)actor, (void)now;
  }

  /// `actor` finished normally in `state`; its outputs were committed.
  virtual void actor_finished(const Plan& plan, std::string_view actor, int state, Duration now) {
    (void)plan, (void)actor, (void)state, (void)now;
  }

  /// `supervisor` raised `event` and interrupted `actor`; the supervisor's
  /// outputs were committed, the actor's discarded.
  virtual void actor_interrupted(const Plan& plan, std::string_view actor, std::string_view supervisor, int event,
                                 Duration now) {
    (void)plan, (void)actor, (void)supervisor, (void)event, (void)now;
  }

  /// `component` (an actor or supervisor name) failed with message `what`.
  virtual void component_failed(const Plan& plan, std::string_view component, std::string_view what, Duration now) {
    (void)plan, (void)component, (void)what, (void)now;
  }

  /// The plan ended with `status`.
  virtual void plan_finished(const Plan& plan, Status status, Duration now) { (void)plan, (void)status, (void)now; }
};

}  // namespace afp
