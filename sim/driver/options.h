// carbot-sim's command line, parsed once and passed down (docs/sim.md, "carbot-sim").
#pragma once

#include <string>

namespace carbot::driver {

struct Options {
  std::string chart;             ///< the chart file (.sfc, .fsm or .plan)
  std::string world;             ///< the world file (JSON)
  double seconds = 60;           ///< simulated time limit
  std::string trace;             ///< t,x,y,heading per control tick ("" = none)
  std::string json;              ///< result summary ("" = none)
  std::string svg;               ///< picture of the world and the path ("" = none)
  std::string html;              ///< the run viewer page ("" = none)
  std::string record;            ///< the run viewer's recording as JSON ("" = none)
  std::string trace_to;          ///< tcp:HOST:PORT: each robot's engine trace, live (docs/live.md; "" = none)
  double physics_step = 0.002;   ///< s
  double period = 0.010;         ///< s, control period
  std::string gfec;              ///< the chart compiler
  std::string cc;                ///< C compiler for engines
  std::string cxx;               ///< C++ compiler for plan engines
  bool plans_supported = false;  ///< carbot-sim has the toolbox and the afp runtime
  std::string runtime_include;   ///< afp headers, for plan engines
  std::string toolbox_include;   ///< carbot_toolbox.h, for plan engines
  std::string cache_dir;         ///< compiled engines kept here for reuse ("" = no cache)
  std::string work_dir;          ///< keep the generated engine here ("" = a temporary folder, removed)
  bool quiet = false;            ///< no progress, no summary
  /// Record calls for the viewer: the engine is built with call wrappers (docs/viewer.md).
  bool recording() const { return !html.empty() || !record.empty(); }
  double timeout = 0;  ///< wall-clock budget in seconds (0 = none)
  // Several robots running a team machine: how their states travel (docs/sim.md, "Several robots").
  bool no_exchange = false;     ///< no reports at all: each robot runs alone (team(S) stays 0)
  int exchange_delay = 0;       ///< ticks a report is late (0: the reference exchange)
  double exchange_loss = 0;     ///< probability that one report is lost
  unsigned long long seed = 1;  ///< of the losses
};

/// The tick budget: at most this many control ticks (a trace row each) and physics steps.
constexpr double kMaxControlTicks = 1e7;
constexpr double kMaxPhysicsSteps = 1e9;

/// Exit codes, as for gfec: 0 the run happened, 1 bad input (chart, world), 2 usage or I/O;
/// kTimeout: the run outlived --timeout.
enum Exit { kOk = 0, kBadInput = 1, kUsage = 2, kTimeout = 3 };

}  // namespace carbot::driver
