// A hierarchy on the simulated Carbot: samples/mission.fsm runs the GFE line follower and ALICA's
// clean-up machine, both unchanged, as sub-charts (docs/language.md "Sub-charts").
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "core/geometry.h"
#include "support.h"

TEST_CASE("mission: patrols the line, leaves it on a straight after 20 s, tidies the cup up and succeeds",
          "[e2e][mission]") {
  const e2e::SimRun run = e2e::run_sim("samples/mission.fsm", "sim/worlds/mission.json", 150);
  INFO(run.output);
  if (e2e::skipped_for_missing_backend(run)) return;
  REQUIRE(run.exit_code == 0);
  CHECK(run.result["status"] == "succeeded");
  CHECK(run.result["bumps"] == 0);
  CHECK(run.result["left_floor"] == false);

  // Mission's own states, in order: the sub-charts' states are not Mission's.
  std::vector<std::string> states;
  double tidy_at = -1;
  for (const auto &e : run.result["state_log"]) {
    states.push_back(e["event"]);
    if (e["event"] == "state Tidy") tidy_at = e["t"].get<double>();
  }
  CHECK(states == std::vector<std::string>{"state Patrol", "state Tidy", "state Done"});
  // Patrol lasts at least its 20 s (2000 ticks of 10 ms: the 2000th starts at 19.99 s), and ends
  // at the first tick after them when the line follower has both sides driving — on the oval
  // that is never long.
  INFO("left the line at " << tidy_at << " s");
  CHECK(tidy_at >= 19.985);
  CHECK(tidy_at < 25.0);

  // While Patrol ran its LineFollower the robot followed the line as the line follower alone
  // does (tests/e2e/line_follower_test.cc), and went round some of the oval.
  const carbot::World w = e2e::world("sim/worlds/mission.json");
  double max_error = 0, first_along = -1, last_along = 0;
  for (const auto &r : run.trace) {
    if (r.t >= tidy_at) break;
    const auto at = carbot::locate_on_line(w.line, {r.x, r.y});
    max_error = std::max(max_error, at.distance);
    if (first_along < 0) first_along = at.along;
    last_along = at.along;
  }
  INFO("max lateral error on patrol " << max_error << " m");
  CHECK(max_error < 0.04);
  CHECK(std::fabs(last_along - first_along) > 1.0);  // 20 s at ~0.2 m/s: metres, not centimetres

  // Then Tidy's CleanUp carried the cup from the middle of the oval to its corner.
  REQUIRE(run.result["items"].size() == 1);
  const auto &item = run.result["items"][0];
  CHECK(item["held"] == false);
  CHECK(std::hypot(item["at"][0].get<double>() - item["destination"][0].get<double>(),
                   item["at"][1].get<double>() - item["destination"][1].get<double>()) < 0.10);
}
