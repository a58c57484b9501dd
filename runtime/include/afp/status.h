// The outcome of a plan run.
#pragma once

namespace afp {

/// Where a plan run stands. The three ends of a terminated plan are the three
/// fixed states of a sub-plan: Succeeded = OK, Interrupted = INTERRUPTED,
/// Failed = ERROR.
enum class Status {
  NotStarted,   ///< the executor has not started the plan
  Running,      ///< an actor is active
  Succeeded,    ///< reached `terminate` from an actor's result state
  Interrupted,  ///< reached `terminate` from a supervisor's event
  Failed,       ///< an actor or supervisor failed (threw, a conversion failed, no rule)
  Stopped,      ///< stopped from outside before it terminated
};

/// The status's name ("running", "succeeded", ...).
const char* to_string(Status status);

/// True once the run is over (any status but NotStarted and Running).
constexpr bool is_finished(Status status) { return status != Status::NotStarted && status != Status::Running; }

}  // namespace afp
