// Running carbot-sim from a test and reading back what it wrote.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/world.h"

namespace e2e {

/// A file of the source tree: "samples/line_follower.sfc", "sim/worlds/oval.json".
std::string source(const std::string &relative);

/// A fresh folder under the system's temporary directory, removed with the object.
class TempDir {
public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir &) = delete;
  TempDir &operator=(const TempDir &) = delete;
  std::string file(const std::string &name) const { return path_ + "/" + name; }

private:
  std::string path_;
};

/// One row of trace.csv.
struct TraceRow {
  double t, x, y, heading;
};

/// What one carbot-sim run produced.
struct SimRun {
  int exit_code = -1;
  std::string output;      ///< stdout and stderr together
  std::string trace_text;  ///< trace.csv as written
  std::vector<TraceRow> trace;
  nlohmann::json result;  ///< result.json (null if not written)
  std::string svg;        ///< path.svg as written ("" if not)
};

/// Runs `carbot-sim CHART --world WORLD --seconds S` (paths relative to the source tree, or
/// absolute) with --trace, --json and --svg into a temporary folder, plus `extra` arguments.
SimRun run_sim(const std::string &chart, const std::string &world, double seconds, const std::string &extra = "");

/// True (and says so on stdout, which ctest reads as "skipped") when gfec could not compile
/// the chart because it has no back end for it yet: the e2e tests wait for the compiler then,
/// rather than fail. Any other failure is not skipped.
bool skipped_for_missing_backend(const SimRun &run);

/// The world file, loaded with the simulator's own reader.
carbot::World world(const std::string &relative);

}  // namespace e2e
