// Internal: what a plan level needs from the executor that runs it, and the
// interface through which it has its supervisors watched. Not installed.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "afp/configuration.h"
#include "afp/context.h"
#include "afp/plan.h"
#include "afp/supervisor.h"
#include "afp/trace.h"

namespace afp::detail {

/// A report from a watch: a supervisor's event that interrupts the actor
/// (never an ignored one), or the supervisor's failure.
struct Claim {
  std::size_t supervisor = 0;  // index in the plan
  int event = 0;
  Target target{Target::Kind::Terminate, 0};
  Shadow outputs;  // the check's writes, committed if the claim wins
  bool failed = false;
  std::string error;  // when failed
};

/// One supervisor to watch, with its rules for the watched actor (or global).
struct Watch {
  Supervisor* supervisor;
  const Supervision* rules;
};

/// How one plan level's supervisors are watched: checked inside the level's
/// step (stepped executor) or polled by threads (threaded executor).
class Watchers {
 public:
  virtual ~Watchers() = default;
  /// Starts the global supervisors, for the whole run.
  virtual void start_global(const std::vector<Watch>& watches) = 0;
  /// A new actor has started: claims for it are possible from now on; starts
  /// its own supervisors.
  virtual void start_local(const std::vector<Watch>& watches) = 0;
  /// The claim that ends the actor now, if any (checks the due supervisors
  /// when stepped).
  virtual std::optional<Claim> poll() = 0;
  /// The actor has finished: refuses claims from now on and returns one that
  /// won before, if any (it then takes precedence over the finish).
  virtual std::optional<Claim> close() = 0;
  /// Stops the actor's own supervisors.
  virtual void stop_local() = 0;
  /// Stops the global supervisors.
  virtual void stop_global() = 0;
};

/// What an executor provides to every plan level it runs (the top plan and
/// its sub-plans).
class Services {
 public:
  Services(Configuration& config, TraceObserver* trace) : config_(config), trace_(trace) {}
  virtual ~Services() = default;

  /// The run's configuration.
  Configuration& config() const { return config_; }
  /// The trace hook, or nullptr.
  TraceObserver* trace() const { return trace_; }
  /// What the trace hook threw, if it did (it is not called again); executor thread only.
  const std::optional<std::string>& trace_error() const { return trace_error_; }
  void set_trace_error(std::string what) { trace_error_ = std::move(what); }
  /// The plan time now.
  virtual Duration now() const = 0;
  /// The watchers for one plan level.
  virtual std::unique_ptr<Watchers> make_watchers() = 0;

 private:
  Configuration& config_;
  TraceObserver* trace_;
  std::optional<std::string> trace_error_;
};

/// Runs `f`; returns the message of what it threw, if it threw.
template <class F>
std::optional<std::string> capture(F&& f) {
  try {
    f();
    return std::nullopt;
  } catch (const std::exception& e) { return std::string(*e.what() ? e.what() : "exception"); } catch (...) {
    return std::string("unknown exception");
  }
}

/// Starts a supervisor (writes made there are discarded); a failure claim if it threw.
std::optional<Claim> start_watch(const Watch& watch, Services& services);

/// Checks a supervisor once: a claim for an event that interrupts or for a
/// failure (it threw, or raised an event without a rule); nothing otherwise.
std::optional<Claim> check_watch(const Watch& watch, Services& services);

/// Stops a supervisor; what it throws is ignored (its watch is over anyway).
void stop_watch(const Watch& watch);

}  // namespace afp::detail
