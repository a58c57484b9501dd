// The simulation is bit-deterministic: the same chart in the same world writes the same
// trace, byte for byte, in separate processes.
#include <catch2/catch.hpp>

#include "support.h"

TEST_CASE("determinism: two runs of the clean-up with a drop give identical traces", "[e2e][determinism]") {
  const e2e::SimRun a = e2e::run_sim("samples/cleanup.fsm", "sim/worlds/cleanup_drop.json", 40);
  const e2e::SimRun b = e2e::run_sim("samples/cleanup.fsm", "sim/worlds/cleanup_drop.json", 40);
  INFO(a.output << b.output);
  if (e2e::skipped_for_missing_backend(a)) return;
  REQUIRE(a.exit_code == 0);
  REQUIRE(b.exit_code == 0);
  REQUIRE(a.trace.size() > 100);
  CHECK(a.trace_text == b.trace_text);
  CHECK(a.result == b.result);
}

TEST_CASE("determinism: two runs of the line follower give identical traces", "[e2e][determinism]") {
  const e2e::SimRun a = e2e::run_sim("samples/line_follower.sfc", "sim/worlds/rounded_square.json", 30);
  const e2e::SimRun b = e2e::run_sim("samples/line_follower.sfc", "sim/worlds/rounded_square.json", 30);
  if (e2e::skipped_for_missing_backend(a)) return;
  REQUIRE(a.exit_code == 0);
  REQUIRE(b.exit_code == 0);
  CHECK(a.trace_text == b.trace_text);
}

TEST_CASE("determinism: two runs of the wall-follow plan give identical traces", "[e2e][determinism][plan]") {
  const e2e::SimRun a = e2e::run_sim("samples/wall_follow.plan", "sim/worlds/room.json", 40);
  const e2e::SimRun b = e2e::run_sim("samples/wall_follow.plan", "sim/worlds/room.json", 40);
  INFO(a.output << b.output);
  if (e2e::skipped_for_missing_backend(a)) return;
  REQUIRE(a.exit_code == 0);
  REQUIRE(b.exit_code == 0);
  CHECK(a.trace_text == b.trace_text);
  CHECK(a.result == b.result);
}
