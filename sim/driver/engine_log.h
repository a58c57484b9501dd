// What an engine did: a plan's actor starts and interruptions (reported by its shim), an fsm's
// state changes (noted by the run loop), with the time.
#pragma once

#include <string>
#include <vector>

namespace carbot::driver {

struct EngineEvent {
  double t = 0;
  std::string text;  ///< "start WallFollow.followWall", "WallFollow.searchFirstWall interrupted by touch", "state Z1 PickUp()"
};

/// The log of the current run (cleared before each run).
std::vector<EngineEvent>& engine_log();

}  // namespace carbot::driver

/// Called by a plan engine's shim (exported from carbot-sim).
extern "C" void carbot_sim_plan_event(double t, const char* text);
