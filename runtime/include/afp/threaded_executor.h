// The real-time executor (docs/runtime.md 2.2): the actor runs in the executor's thread, each
// supervisor polls in its own thread, and the first to claim an interruption
// wins.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "afp/configuration.h"
#include "afp/context.h"
#include "afp/plan.h"
#include "afp/status.h"
#include "afp/trace.h"

namespace afp {

/// Timing of the threaded executor.
struct ThreadedOptions {
  /// Time between two steps of the active actor (a claim wakes it earlier).
  Duration actor_period = std::chrono::milliseconds(1);
  /// Poll period of supervisors declared without one.
  Duration supervisor_period = std::chrono::milliseconds(1);
};

/// Runs a plan in real time with one thread per active supervisor. The
/// application may read and write the configuration from any thread meanwhile.
/// Toolbox classes used with it must tolerate a supervisor's check() running
/// concurrently with the actor's step().
class ThreadedExecutor {
 public:
  /// Prepares a run of `plan` on `config`, declaring the plan's entries there.
  /// `trace` (may be nullptr) is called from the executor's thread only.
  ThreadedExecutor(Plan& plan, Configuration& config, TraceObserver* trace = nullptr, ThreadedOptions options = {});
  /// Stops a run still going and joins every thread.
  ~ThreadedExecutor();
  ThreadedExecutor(const ThreadedExecutor&) = delete;
  ThreadedExecutor& operator=(const ThreadedExecutor&) = delete;

  /// Runs the plan in the calling thread until it ends or request_stop().
  /// Throws PlanError if the plan cannot run, std::logic_error if run twice.
  Status run();

  /// Runs the plan in a background thread (run() there).
  void start();

  /// Asks the run to stop (status Stopped); thread-safe, returns at once.
  void request_stop();

  /// Waits for a start()ed run to end; returns its status.
  Status wait();

  /// The run's status; thread-safe.
  Status status() const;

  /// Why the run failed (empty unless Failed); thread-safe.
  std::string error() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace afp
