// What a plan did, as its engine reports it: actor starts and interruptions, with plan time.
#pragma once

#include <string>
#include <vector>

namespace carbot::driver {

struct PlanEvent {
  double t = 0;
  std::string text;  ///< "start WallFollow.followWall", "WallFollow.searchFirstWall interrupted by touch"
};

/// The log of the current run (cleared before each run).
std::vector<PlanEvent>& plan_log();

}  // namespace carbot::driver

/// Called by a plan engine's shim (exported from carbot-sim).
extern "C" void carbot_sim_plan_event(double t, const char* text);
