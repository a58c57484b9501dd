// A loaded engine: the shared object from chart_build, its state, its entry points.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

struct CarbotRobot;  // sim/hal/carbot_hal.h

namespace carbot::driver {

struct LoadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class LoadedEngine {
 public:
  /// dlopen()s `library` with every symbol resolved now: an engine that calls a robot
  /// function carbot-sim does not have fails here, with the function's name.
  explicit LoadedEngine(const std::string& library);
  ~LoadedEngine();
  LoadedEngine(const LoadedEngine&) = delete;
  LoadedEngine& operator=(const LoadedEngine&) = delete;

  void init() {
    init_(state());
    initialised_ = true;
  }
  void run() { run_(state()); }
  /// Destroys the engine's state (a plan stops its actor, which halts the robot): call it
  /// while the robot is still there. The destructor does it if nobody did.
  void finish() {
    if (fini_ && initialised_) fini_(state());
    initialised_ = false;
  }
  /// 0 running, 1 succeeded, -1 failed, 2 terminated (a plan ended by a supervisor or stopped).
  int status() const { return status_(state()); }
  /// An fsm's current state index; -1 for engines without states.
  int current_state() const { return state_ ? state_(state()) : -1; }
  /// Every robot call of this engine is for `robot` (after init(), before the first run()): a
  /// C engine's X_set_context (its interface calls pass it on), a plan's toolbox environment.
  void set_context(CarbotRobot* robot) { set_context_(state(), robot); }
  /// A team machine's engine (docs/language.md "Teams") has set_agent and report.
  bool team() const { return set_agent_ && report_; }
  /// X_set_agent: this engine is agent `agent` (after init()).
  void set_agent(int agent) {
    if (set_agent_) set_agent_(state(), agent);
  }
  /// X_report: agent `agent` said it is in `state` (between ticks).
  void report(int agent, int state_index) {
    if (report_) report_(state(), agent, state_index);
  }
  /// A C engine's places (states), for reading activation; 0 for a plan.
  int places() const { return places_ ? places_() : 0; }
  /// X_activation of a C engine's place (read only: the run is not changed by looking).
  unsigned activation(int place) const { return activation_ ? activation_(state(), place) : 0; }
  /// Whether the engine has sub-chart instances (a C engine with gfec's X_instance_activation).
  bool has_instances() const { return instance_activation_ != nullptr; }
  /// The activation of place `place` of sub-chart instance `instance` (ChartInfo::instances),
  /// as the instance's state holds it; meaningful only while the place that runs it is active.
  unsigned instance_activation(int instance, int place) const {
    return instance_activation_ ? instance_activation_(state(), instance, place) : 0;
  }

 private:
  void* state() const { return const_cast<unsigned char*>(memory_.data()); }
  void* handle_ = nullptr;
  std::vector<unsigned char> memory_;  // the engine's struct, allocated by us
  void (*init_)(void*) = nullptr;
  void (*run_)(void*) = nullptr;
  int (*status_)(const void*) = nullptr;
  void (*fini_)(void*) = nullptr;                                     // optional
  int (*state_)(const void*) = nullptr;                               // optional
  int (*places_)() = nullptr;                                         // optional (C engines)
  unsigned (*activation_)(const void*, int) = nullptr;                // optional (C engines)
  unsigned (*instance_activation_)(const void*, int, int) = nullptr;  // optional (sub-charts)
  void (*set_agent_)(void*, int) = nullptr;                           // optional (team machines)
  void (*report_)(void*, int, int) = nullptr;                         // optional (team machines)
  void (*set_context_)(void*, CarbotRobot*) = nullptr;
  bool initialised_ = false;
};

}  // namespace carbot::driver
