// From a chart file to a loadable engine: ask gfec what the chart is, have it generate the
// engine, wrap the engine in a fixed entry point (the shim) and compile both into a shared
// object that carbot-sim dlopen()s. The engine's calls to robot functions resolve against
// carbot-sim itself, which exports its robot libraries (docs/sim.md, "How a chart is run").
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "driver/options.h"

namespace carbot::driver {

/// What gfec says about a chart (`gfec --emit=json`: top-level "kind" and "name").
struct ChartInfo {
  std::string name;
  std::string kind;  ///< "sfc", "fsm" or "plan"
  /// Every file the chart was read from, imports included (gfec's "files"): never an output.
  std::vector<std::string> files;
  double period = 0;  ///< s, the chart's `period` (0: it gives none)
  int team = 0;       ///< a team machine's `team N` (0: not a team machine)
  /// fsm: a label per state index, "Z1 PickUp()" (the name and the first action's text).
  std::vector<std::string> states;
  /// The rows of the run viewer's timeline: the places (sfc), states (fsm) or actors (plan) in
  /// declaration order, each with the id of its node in gfec's DOT/SVG picture ("p3", "a1");
  /// then the places of each sub-chart instance, depth first ("Patrol/LeftFw", node "s0_p0").
  struct Row {
    std::string name;
    std::string node;
    bool terminal = false;  ///< an fsm's success or failure state
    std::string group;      ///< the instance path of a sub-chart's row ("" for the chart's own)
  };
  std::vector<Row> rows;
  /// The sub-chart instances (docs/c-engine.md "Sub-charts"), depth first in declaration order
  /// (the numbers of the engine's X_instance), each with its rows rows[first, first + count) and
  /// the row of the place that runs it.
  struct Instance {
    std::string path;   ///< "Patrol", "Search.Grab"
    std::string chart;  ///< the chart it runs
    std::size_t first = 0, count = 0;
    std::size_t parent_row = 0;
  };
  std::vector<Instance> instances;
  /// The rows of the compiled chart itself (rows beyond are instances').
  std::size_t own_rows = 0;
  /// A plan's supervisors: "actor/name" (or "name" for a global one) -> node id ("s0_1", "g0").
  std::map<std::string, std::string> supervisor_nodes;
  /// An interface function the chart calls: its C result and parameter types (for recording).
  struct Function {
    std::string name;
    std::string result;
    std::vector<std::string> params;
    std::string interface;  ///< the interface that declares it ("FetchBot")
  };
  std::vector<Function> functions;
};

struct BuiltEngine {
  ChartInfo chart;
  std::string library;  ///< path of the shared object
};

/// A step of the build failed; `code` is the exit code carbot-sim should end with.
struct BuildError : std::runtime_error {
  BuildError(const std::string& what, Exit code) : std::runtime_error(what), code(code) {}
  Exit code;
};

/// Builds the engine of `options.chart` in `dir` (which must exist).
BuiltEngine build_engine(const Options& options, const std::string& dir);

/// The shim's C source for a C engine of `chart` (exposed for tests).
std::string c_shim(const ChartInfo& chart, bool traced = false);
/// A header renaming each interface function the engine calls to its robot library's name, the
/// interface's name and the function's (CleanBot's `PickUp` is `CleanBot_PickUp`: FetchBot has
/// a `PickUp` too, and carbot-sim links both libraries).
std::string robot_names(const ChartInfo& chart);
/// For a recording build (docs/viewer.md): a header renaming each interface function F the
/// engine calls to carbot_rec_F, and the C source of those wrappers, which call F and report
/// the call and its result to carbot-sim. The engine makes the same calls in the same order.
std::string record_renames(const ChartInfo& chart);
std::string record_wrappers(const ChartInfo& chart);
/// The shim's C++ source for a plan engine: the stepped executor around make_NAME(ee), declared
/// by gfec's engine.hpp when `has_header`.
std::string cpp_shim(const ChartInfo& chart, bool has_header);

}  // namespace carbot::driver
