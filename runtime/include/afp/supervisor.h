// Supervisors: watch the active actor and raise events that interrupt it.
#pragma once

#include "afp/context.h"

namespace afp {

/// What Supervisor::check() returns: no event, or an event of the supervisor's
/// event enum. Converts from an event, so check() can `return TOUCHED;`.
class CheckResult {
 public:
  /// The event `event` (a value of the supervisor's event enum, >= 0).
  constexpr CheckResult(int event) : event_(event), raised_(true) {}

  /// Nothing to report.
  static constexpr CheckResult nothing() { return CheckResult(); }

  /// True if an event was raised.
  constexpr bool raised() const { return raised_; }

  /// The event (meaningful when raised()).
  constexpr int event() const { return event_; }

 private:
  constexpr CheckResult() : event_(0), raised_(false) {}
  int event_;
  bool raised_;
};

/// No event.
inline constexpr CheckResult no_event = CheckResult::nothing();

/// A supervisor: started when the watch begins (with its actor, or with the
/// plan for a global one), checked every period, stopped when the watch ends.
/// Outputs written during a check are committed only if that check's event
/// interrupts the actor. Exceptions from start/check make the plan level fail.
class Supervisor {
 public:
  /// A supervisor checked every `period` of plan time; zero means every
  /// executor step (stepped) or the executor's default period (threaded).
  explicit Supervisor(Duration period = Duration::zero()) : period_(period) {}
  virtual ~Supervisor() = default;

  /// The time between two checks.
  Duration period() const { return period_; }

  /// Begins watching; read the In parameters here.
  virtual void start(Context& ctx) { (void)ctx; }

  /// Checks once; returns afp::no_event or an event. Write Out parameters
  /// before returning the event they belong to.
  virtual CheckResult check(Context& ctx) = 0;

  /// Ends the watch. Should not throw: an exception from it is ignored.
  virtual void stop() {}

 private:
  Duration period_;
};

}  // namespace afp
