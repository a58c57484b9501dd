// The run loop: one engine tick per control period, until the time limit, the end of an fsm,
// or the escape button.
#pragma once

#include <string>
#include <vector>

#include "core/simulation.h"
#include "driver/chart_build.h"
#include "driver/engine_loader.h"

namespace carbot::driver {

/// One control tick of the robot's path: time and pose before the engine's tick.
struct TraceRow {
  double t = 0;
  double x = 0, y = 0;
  double heading_deg = 0;
};

struct RunResult {
  std::string status = "running";  ///< running | succeeded | failed | terminated
  std::vector<TraceRow> trace;
  double wall_seconds = 0;         ///< real time the run took (not in any output file)
};

/// Runs `engine` on `sim` for at most `seconds` (progress on stderr when it is a terminal).
RunResult run_engine(Simulation& sim, Engine& engine, const ChartInfo& chart, double seconds, bool quiet);

}  // namespace carbot::driver
