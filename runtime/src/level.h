// Internal: the main loop (docs/runtime.md 1) for one plan level (the top plan or a
// sub-plan), turned inside out so that an executor drives it step by step.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "afp/plan.h"
#include "afp/status.h"
#include "services.h"

namespace afp::detail {

/// Runs one plan: exactly one active actor, its supervisors and the global
/// ones watching it, outputs through shadow copies. Single-threaded: only the
/// executor's thread calls it (supervisor threads talk to its Watchers).
class Level {
 public:
  /// A level running `plan` on the executor's `services`.
  Level(Plan& plan, Services& services);
  /// Stops a plan still running.
  ~Level();
  Level(const Level&) = delete;
  Level& operator=(const Level&) = delete;

  /// Starts the global supervisors and the first actor. Throws PlanError.
  void begin();

  /// One step: a winning claim interrupts the actor, else the actor steps.
  void advance();

  /// Stops a running plan from outside (status Stopped).
  void abort();

  /// Where the run stands.
  Status status() const { return status_; }

  /// Why the level failed ("component: message"), empty otherwise.
  const std::string& error() const { return error_; }

 private:
  void start_actor(std::size_t index);
  void finish_actor(int state);
  void interrupt(Claim claim);
  void fail(const std::string& component, const std::string& what);
  void end(Status status);
  std::optional<std::string> stop_actor();
  std::vector<Watch> watches(const std::vector<Supervision>& list) const;
  const std::string& actor_name() const;

  // Calls the trace hook if there is one: the only cost when there is none. A hook that
  // throws is not called again and its message is kept for the executor (Services::
  // trace_error), which fails the run: an exception must not unwind through the level, whose
  // destructor calls the hook again (std::terminate).
  template <class F>
  void trace(F&& call) {
    TraceObserver* observer = services_.trace();
    if (!observer || services_.trace_error()) return;
    if (auto what = capture([&] { call(*observer); })) services_.set_trace_error(*what);
  }

  Plan& plan_;
  Services& services_;
  std::unique_ptr<Watchers> watchers_;
  Status status_ = Status::NotStarted;
  std::string error_;
  std::size_t current_ = 0;
  bool actor_active_ = false;  // started and not yet stopped
  Shadow shadow_;              // the active actor's outputs
};

}  // namespace afp::detail
