// carbot-sim as a command: how runs end, and what it says when a chart cannot run.
#include <catch2/catch.hpp>

#include <fstream>

#include "support.h"

namespace {

/// The oval, plus whatever else a test needs, written into `dir`.
std::string oval_with(const e2e::TempDir& dir, const std::string& extra_fields) {
  const carbot::World oval = e2e::world("sim/worlds/oval.json");
  std::string points;
  for (const auto& p : oval.line.points) points += (points.empty() ? "" : ", ") + ("[" + std::to_string(p.x) + ", " + std::to_string(p.y) + "]");
  const std::string path = dir.file("oval_plus.json");
  std::ofstream(path) << R"({"size": [4, 2.6], "line": {"width": 0.05, "closed": true, "points": [)" << points
                      << R"(]}, "start": {"pose": [-0.4, -0.7, 0]})" << extra_fields << "}";
  return path;
}

}  // namespace

TEST_CASE("carbot-sim: the escape button stops an sfc run", "[e2e][cli]") {
  e2e::TempDir dir;
  const std::string world = oval_with(dir, R"(, "events": [{"at": 12.5, "press": "escape"}])");
  const e2e::SimRun run = e2e::run_sim("samples/line_follower.sfc", world, 60);
  INFO(run.output);
  if (e2e::skipped_for_missing_backend(run)) return;
  REQUIRE(run.exit_code == 0);
  CHECK(run.result["status"] == "terminated");
  CHECK(run.result["sim_time_s"].get<double>() == Approx(12.5).margin(0.011));
  CHECK(run.result["escape_presses"] == 1);
  REQUIRE(!run.trace.empty());
  CHECK(run.trace.back().t == Approx(12.5).margin(0.011));
}

TEST_CASE("carbot-sim: a chart calling a function the Carbot lacks is refused by name", "[e2e][cli]") {
  e2e::TempDir dir;
  std::ofstream(dir.file("beeper.sfc")) << R"(interface Beeper { void Beep(); }
sfc Beeps {
  period 10ms;
  initial place Beeping { Beep(); }
}
)";
  const e2e::SimRun run = e2e::run_sim(dir.file("beeper.sfc"), "sim/worlds/oval.json", 1);
  INFO(run.output);
  if (e2e::skipped_for_missing_backend(run)) return;
  CHECK(run.exit_code == 1);
  CHECK(run.output.find("Beep") != std::string::npos);
  CHECK(run.output.find("cannot load the engine") != std::string::npos);
  CHECK(run.trace.empty());
}

TEST_CASE("carbot-sim: a chart gfec rejects stops it with gfec's diagnostics", "[e2e][cli]") {
  e2e::TempDir dir;
  std::ofstream(dir.file("broken.sfc")) << "import \"" << e2e::source("samples/linebot.iface") << R"(";
sfc Broken {
  initial place A { Left_FWD(); }
}
)";
  const e2e::SimRun run = e2e::run_sim(dir.file("broken.sfc"), "sim/worlds/oval.json", 1);
  INFO(run.output);
  CHECK(run.exit_code == 1);
  CHECK(run.output.find("Left_FWD") != std::string::npos);  // gfec's own message
  CHECK(run.output.find("broken.sfc: gfec rejected the chart") != std::string::npos);
}
