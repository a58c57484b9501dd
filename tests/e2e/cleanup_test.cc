// ALICA's clean-up machine (samples/cleanup.fsm, unchanged) on the simulated Carbot.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "support.h"

namespace {

double distance(const nlohmann::json &a, const nlohmann::json &b) {
  return std::hypot(a[0].get<double>() - b[0].get<double>(), a[1].get<double>() - b[1].get<double>());
}

/// Runs the clean-up chart in `world_file` and checks it ended well: succeeded, the item
/// down (not held) within 10 cm of its destination, nothing bumped.
e2e::SimRun check_cleans_up(const char *world_file) {
  e2e::SimRun run = e2e::run_sim("samples/cleanup.fsm", world_file, 120);
  INFO(run.output);
  if (e2e::skipped_for_missing_backend(run)) return run;
  REQUIRE(run.exit_code == 0);
  CHECK(run.result["status"] == "succeeded");
  CHECK(run.result["sim_time_s"].get<double>() < 120);
  CHECK(run.result["bumps"] == 0);
  REQUIRE(run.result["items"].size() == 1);
  const auto &item = run.result["items"][0];
  CHECK(item["held"] == false);
  CHECK(distance(item["at"], item["destination"]) < 0.10);
  return run;
}

}  // namespace

TEST_CASE("clean-up: carries the cup to its destination and succeeds", "[e2e][cleanup]") {
  check_cleans_up("sim/worlds/cleanup.json");
}

TEST_CASE("clean-up: the same chart fetches a book from behind in another room", "[e2e][cleanup]") {
  check_cleans_up("sim/worlds/cleanup_hall.json");
}

TEST_CASE("clean-up: recovers when the cup is dropped on the way", "[e2e][cleanup]") {
  const e2e::SimRun run = check_cleans_up("sim/worlds/cleanup_drop.json");
  if (run.exit_code != 0) return;  // skipped, or already failed
  // The world drops the cup at 15 s and it lands at (0.2, 0.6): the drop happened, and after
  // it the robot went back there (its gripper within reach means its centre within ~0.4 m).
  CHECK(run.output.find("'cup' dropped") != std::string::npos);
  bool went_back = false;
  for (const auto &r : run.trace) went_back = went_back || (r.t > 15 && std::hypot(r.x - 0.2, r.y - 0.6) < 0.45);
  CHECK(went_back);
  // And the machine took the chart's recovery path: Z2 (Transport) -> Z1 (PickUp) at the drop,
  // then Z2 again, Z3 (PlaceItem), Done.
  std::vector<std::string> states;
  for (const auto &e : run.result["state_log"]) states.push_back(e["event"]);
  const std::vector<std::string> expected = {"state Z0 DriveToItem()",
                                             "state Z1 PickUp()",
                                             "state Z2 Transport()",
                                             "state Z1 PickUp()",
                                             "state Z2 Transport()",
                                             "state Z3 PlaceItem()",
                                             "state Done"};
  CHECK(states == expected);
}

// Without a reachable goal the machine must end in its failure state, not run forever.
TEST_CASE("clean-up: a room without items ends in failure", "[e2e][cleanup]") {
  e2e::TempDir dir;
  const std::string world_file = dir.file("empty.json");
  std::FILE *f = std::fopen(world_file.c_str(), "w");
  std::fputs(R"({"size": [3, 3], "start": {"pose": [0, 0, 0]}})", f);
  std::fclose(f);
  const e2e::SimRun run = e2e::run_sim("samples/cleanup.fsm", world_file, 30);
  INFO(run.output);
  if (e2e::skipped_for_missing_backend(run)) return;
  REQUIRE(run.exit_code == 0);
  CHECK(run.result["status"] == "failed");
}
