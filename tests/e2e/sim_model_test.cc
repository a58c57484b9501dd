// The physics model, in process: commanded motion is what the robot does, and each sensor
// reads what the geometry says it should.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/carbot_model.h"
#include "core/geometry.h"
#include "core/simulation.h"

using namespace carbot;

namespace {

World open_floor() {
  World w;
  w.size = {20, 20};
  return w;
}

void run_for(Simulation &sim, double seconds) {
  const double end = sim.time() + seconds - 1e-9;
  while (sim.time() < end) sim.step_control();
}

}  // namespace

TEST_CASE("model: drives straight at the commanded speed", "[e2e][model]") {
  Simulation sim(open_floor());
  sim.drive(0.31, 0);
  run_for(sim, 3);
  CHECK(sim.forward_speed() == Approx(0.31).epsilon(0.02));
  CHECK(std::fabs(sim.pose().heading) < rad(0.5));
  CHECK(sim.pose().x == Approx(0.91).margin(0.03));
}

TEST_CASE("model: the top speed holds, keeping the curvature", "[e2e][model]") {
  Simulation sim(open_floor());
  sim.drive(1.0, 1.0);  // radius 1 m, far too fast
  run_for(sim, 3);
  CHECK(sim.forward_speed() <= model::kTopSpeed + 0.005);
  CHECK(sim.forward_speed() / sim.turn_rate() == Approx(1.0).epsilon(0.03));
}

TEST_CASE("model: turns in place", "[e2e][model]") {
  Simulation sim(open_floor());
  sim.drive(0, 1.5);
  run_for(sim, 2);
  CHECK(sim.turn_rate() == Approx(1.5).epsilon(0.03));
  CHECK(std::hypot(sim.pose().x, sim.pose().y) < 0.03);
}

TEST_CASE("model: drives a car-like curve and reverses", "[e2e][model]") {
  Simulation sim(open_floor());
  sim.drive(0.2, 0.5);
  run_for(sim, 4);
  CHECK(sim.turn_rate() == Approx(0.5).epsilon(0.03));
  CHECK(deg(sim.pose().heading) > 100);  // 0.5 rad/s for 4 s less the steering lag: ~113 deg
  sim.drive(-0.2, 0);
  run_for(sim, 2);
  CHECK(sim.forward_speed() == Approx(-0.2).epsilon(0.03));
}

TEST_CASE("model: the sonar measures the distance to a wall ahead, and not a glancing one", "[e2e][model]") {
  World w = open_floor();
  w.walls.push_back({{1.0, -2}, {1.0, 2}, 0.05, 0.3});  // face at x = 0.975
  Simulation sim(w);
  run_for(sim, 0.2);
  CHECK(sim.sonar_range() == Approx(0.975 - model::kSonarX).margin(0.01));
  sim.aim_sonar(rad(90));  // nothing to the left
  run_for(sim, 0.5);
  CHECK(sim.sonar_angle() == Approx(rad(90)).margin(1e-6));
  CHECK(sim.sonar_range() == model::kSonarRange);
  sim.aim_sonar(rad(-75));  // the wall at 75 degrees incidence returns no echo
  run_for(sim, 0.5);
  CHECK(sim.sonar_range() == model::kSonarRange);
}

TEST_CASE("model: the bumper notices a wall and counts one bump", "[e2e][model]") {
  World w = open_floor();
  w.walls.push_back({{0.8, -2}, {0.8, 2}, 0.05, 0.3});
  Simulation sim(w);
  sim.drive(0.2, 0);
  while (!sim.bumper() && sim.time() < 10) sim.step_control();
  REQUIRE(sim.bumper());
  CHECK(sim.bumps() == 1);
  // It touched with its front, before the chassis could pass the wall face.
  CHECK(sim.pose().x + model::kLength / 2 + model::kBumperDepth == Approx(0.775).margin(0.02));
  sim.drive(-0.2, 0);
  run_for(sim, 1);
  CHECK_FALSE(sim.bumper());
  CHECK(sim.bumps() == 1);
}

TEST_CASE("model: the IR sensors see a line between them as white, under them as black", "[e2e][model]") {
  World w = open_floor();
  w.line.width = 0.05;
  w.line.points = {{-2, 0}, {2, 0}};
  Simulation centred(w);
  CHECK_FALSE(centred.line_black(Side::Left));
  CHECK_FALSE(centred.line_black(Side::Right));
  w.start.position.y = -model::kIrY;  // left sensor right above the line
  Simulation shifted(w);
  CHECK(shifted.line_black(Side::Left));
  CHECK_FALSE(shifted.line_black(Side::Right));
}

TEST_CASE("model: the gripper takes an item in reach, carries it and puts it down", "[e2e][model]") {
  World w = open_floor();
  w.items.push_back({"cup", {model::kGripX + 0.05, 0}, {2, 0}});
  w.items.push_back({"far", {2, 2}, {0, 0}});
  Simulation sim(w);
  CHECK_FALSE(sim.grip(1));
  REQUIRE(sim.grip(0));
  CHECK(sim.held_item() == 0);
  sim.drive(0.2, 0);
  run_for(sim, 2);
  CHECK(sim.items()[0].held);
  CHECK(sim.items()[0].at.x == Approx(sim.gripper_point().x));
  sim.release();
  CHECK(sim.held_item() == -1);
  CHECK_FALSE(sim.items()[0].held);
  CHECK(sim.items()[0].at.x == Approx(model::kGripX + 0.4).margin(0.03));
}

TEST_CASE("model: the escape button is down for a moment after its event", "[e2e][model]") {
  World w = open_floor();
  w.events.push_back({Event::Kind::PressEscape, 1.0, "", false, {}});
  Simulation sim(w);
  run_for(sim, 0.5);
  CHECK_FALSE(sim.escape());
  run_for(sim, 0.5);
  CHECK(sim.escape());
  CHECK(sim.escape_presses() == 1);
  run_for(sim, 0.5);
  CHECK_FALSE(sim.escape());
}

TEST_CASE("model: the same commands give bit-identical poses", "[e2e][model][determinism]") {
  auto path = [] {
    World w = open_floor();
    w.boxes.push_back({{1.0, 0.3}, {0.4, 0.4}, 0.3});
    Simulation sim(w);
    std::vector<double> out;
    for (int i = 0; i < 600; ++i) {
      sim.drive(0.3 * std::sin(i * 0.01), std::cos(i * 0.013));
      sim.step_control();
      out.push_back(sim.pose().x);
      out.push_back(sim.pose().y);
      out.push_back(sim.pose().heading);
    }
    return out;
  };
  CHECK(path() == path());
}
