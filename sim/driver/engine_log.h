// What an engine did: a plan's actor starts and interruptions (reported by its shim), an fsm's
// state changes (noted by the run loop), with the time.
#pragma once

#include <string>
#include <vector>

namespace carbot::driver {

struct EngineEvent {
  double t = 0;
  std::string
      text;  ///< "start WallFollow.followWall", "WallFollow.searchFirstWall interrupted by touch", "state Z1 PickUp()"
};

/// The log of the current run (cleared before each run).
std::vector<EngineEvent>& engine_log();

/// The interface calls of the current tick, as "Left_IR_Black() = true" (a recording build's
/// wrappers report them; the run loop takes them after each tick).
std::vector<std::string>& call_log();

}  // namespace carbot::driver

/// Called by a recording build's call wrappers (exported from carbot-sim).
extern "C" void carbot_sim_call(const char* text);

/// Called by a plan engine's shim (exported from carbot-sim).
extern "C" void carbot_sim_plan_event(double t, const char* text);
