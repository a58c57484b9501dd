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

/// What the run viewer needs beyond the path (docs/viewer.md), one entry per trace row ("frame"):
/// row k holds the pose before tick k's engine call and what that call did.
struct Recording {
  /// The timeline rows (ChartInfo::rows) active after the frame's engine call: the places
  /// with activation > 0 (sfc), the current state (fsm), the running actor (plan).
  std::vector<std::vector<int>> active;
  /// The rows of sub-chart instances (beyond ChartInfo::own_rows) active after the frame's
  /// engine call: a place of an instance whose own place is active (a recording build only). Kept
  /// apart from `active`, which the trace's `active` column names, so that the trace stays the
  /// same with or without recording.
  std::vector<std::vector<int>> instances_active;
  /// A plan's sub-plan actors, as their starts reveal them: rows numbered after ChartInfo::rows
  /// (in `instances_active`), named "actor/subActor", `group` the top-level actor running the
  /// sub-plan, no node (gfec's picture of a plan does not draw the sub-plans' insides).
  std::vector<ChartInfo::Row> sub_rows;
  std::vector<std::string> sub_plans;  ///< per sub_rows entry: the sub-plan's name ("Side")
  /// The frame's interface calls with their results (a recording build only; else empty).
  std::vector<std::vector<std::string>> calls;
  /// The frame of each engine_log() entry (same order).
  std::vector<long> log_frames;
  /// A plan's supervisor firings: frame, node id in the picture, "touch (searchFirstWall)".
  struct Fired {
    long frame;
    std::string node;
    std::string text;
  };
  std::vector<Fired> fired;
  /// Per item, per frame: held, and where it lies when not held.
  std::vector<std::vector<ItemState>> items;
};

struct RunResult {
  std::string status = "running";  ///< running | succeeded | failed | terminated
  std::vector<TraceRow> trace;
  Recording recording;
  double wall_seconds = 0;  ///< real time the run took (not in any output file)
};

/// Runs `engine` on `sim` for at most `seconds` (progress on stderr when it is a terminal).
RunResult run_engine(Simulation& sim, Engine& engine, const ChartInfo& chart, double seconds, bool quiet);

}  // namespace carbot::driver
