// The run loop: one engine tick per control period, until the time limit, the end of an fsm,
// or the escape button.
#pragma once

#include <string>
#include <vector>

#include "core/simulation.h"
#include "driver/chart_build.h"
#include "driver/engine_loader.h"
#include "driver/engine_log.h"

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
  /// engine call: a place of an instance whose own place is active. Kept
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
  /// Several robots: per frame, per item, the robot holding it (-1: none).
  std::vector<std::vector<int>> holders;
};

/// One robot of a run with several (docs/sim.md, "Several robots"): its path, what its engine
/// did, and how the robot ended.
struct RobotRun {
  std::string status = "running";        ///< of its engine: running | succeeded | failed | terminated
  std::vector<TraceRow> trace;           ///< as RunResult::trace, every robot in every tick
  std::vector<std::vector<int>> active;  ///< per trace row, as Recording::active
  std::vector<EngineEvent> state_log;    ///< an fsm's "state Grab PickUp()" changes
  /// Per trace row, the interface calls of the robot's engine in that tick (a recording build
  /// only, docs/viewer.md; else empty).
  std::vector<std::vector<std::string>> calls;
  long ended = -1;  ///< the trace row of the tick its engine ended in (-1: it did not)
  int state = -1;   ///< an fsm's state at the end
  // The robot at the end.
  Pose final_pose;
  double distance_m = 0;
  int bumps = 0;
  std::vector<Bump> bump_log;
  bool left_floor = false;
  int held = -1;
  bool lights = false;
  int beeps = 0;
};

/// How a team machine's states travel between the robots' engines.
struct Exchange {
  bool enabled = true;          ///< false: no reports at all
  int delay_ticks = 0;          ///< a report sent after tick t arrives after tick t + delay_ticks
  double loss = 0;              ///< each report is lost with this probability ...
  unsigned long long seed = 1;  ///< ... drawn from a generator seeded with this
  long sent = 0, lost = 0;      ///< counted by the run
};

struct RunResult {
  std::string status = "running";  ///< running | succeeded | failed | terminated
  std::vector<TraceRow> trace;
  Recording recording;
  double wall_seconds = 0;  ///< real time the run took (not in any output file)
  /// A run with several robots: one entry per robot (then `trace` is unused, and `recording`
  /// holds only the items, per frame, for the run viewer).
  std::vector<RobotRun> robots;
  bool team_machine = false;  ///< the engines exchanged states
  Exchange exchange;
};

// What the single-robot and the team run loops read the same way.

/// The selected robot's row of the trace, now.
TraceRow trace_row(const Simulation& sim);
/// A C engine's places (states) with activation > 0, in order; none for a plan.
std::vector<int> active_places(const LoadedEngine& engine);
/// An engine's status() as result.json writes it: "succeeded", "failed" or "terminated" (not 0).
std::string status_text(int status);
/// An fsm's state change since `last` (which it updates): "state Z1 PickUp()", the state's
/// label (ChartInfo::states), or "" when the state stayed or the engine has none.
std::string state_change(const LoadedEngine& engine, const ChartInfo& chart, int& last);
/// Forgets what the robot libraries keep of every robot, before a run.
void reset_robot_libraries();

/// Runs `engine` on `sim` for at most `seconds` (progress on stderr when it is a terminal).
RunResult run_engine(Simulation& sim, LoadedEngine& engine, const ChartInfo& chart, double seconds, bool quiet);

/// Runs one engine per robot of `sim` (engines[i] drives robot i, its instance context, which is
/// agent i of a team machine) for at most `seconds`: every tick all engines run in robot order;
/// then a team machine's states are exchanged as `exchange` says.
/// The run ends at the time limit, on escape, or when every engine has ended.
RunResult run_team(Simulation& sim, std::vector<LoadedEngine*> engines, const ChartInfo& chart, double seconds,
                   Exchange exchange);

}  // namespace carbot::driver
