// The Carbot toolbox's geometry and actors, in process on the simulation (no gfec needed).
#include <catch2/catch.hpp>

#include <cmath>

#include "carbot_toolbox.h"
#include "core/geometry.h"
#include "core/simulation.h"
#include "hal/carbot_hal.h"
#include "hal/hal_binding.h"
#include "wall_fit.h"

using carbot::toolbox::fit_wall;
using carbot::toolbox::SonarSample;

namespace {

constexpr double kSonarX = 0.10;

/// A sweep from -100 to +100 degrees against straight walls given as n.p = d (unit n, robot
/// frame), with the simulator's incidence cut-off of 50 degrees.
std::vector<SonarSample> sweep(const std::vector<std::pair<carbot::Vec2, double>> &walls) {
  std::vector<SonarSample> out;
  for (int deg = -100; deg <= 100; deg += 10) {
    const double a = carbot::rad(deg);
    const double dx = std::cos(a), dy = std::sin(a);
    double best = 4.0;
    for (const auto &[n, d] : walls) {
      const double along = n.x * dx + n.y * dy;
      if (along < std::cos(carbot::rad(50))) continue;  // glancing or facing away
      best = std::min(best, (d - n.x * kSonarX) / along);
    }
    out.push_back({a, best});
  }
  return out;
}

}  // namespace

TEST_CASE("toolbox: a wall straight ahead means a left turn of 90 degrees (wall on the right)", "[e2e][toolbox]") {
  const auto fit = fit_wall(sweep({{{1, 0}, 0.5}}), kSonarX, 4.0);
  REQUIRE(fit.found);
  CHECK(carbot::deg(fit.turn) == Approx(90).margin(1));
  CHECK(fit.distance == Approx(0.5).margin(0.01));
}

TEST_CASE("toolbox: a wall on the right needs no turn, one on the left a half turn", "[e2e][toolbox]") {
  const auto right = fit_wall(sweep({{{0, -1}, 0.3}}), kSonarX, 4.0);
  REQUIRE(right.found);
  CHECK(carbot::deg(right.turn) == Approx(0).margin(1));
  const auto left = fit_wall(sweep({{{0, 1}, 0.3}}), kSonarX, 4.0);
  REQUIRE(left.found);
  CHECK(std::fabs(carbot::deg(left.turn)) == Approx(180).margin(1));
}

TEST_CASE("toolbox: in a corner the wall ahead wins over the one alongside", "[e2e][toolbox]") {
  const auto fit = fit_wall(sweep({{{0, -1}, 0.3}, {{1, 0}, 0.6}}), kSonarX, 4.0);
  REQUIRE(fit.found);
  CHECK(carbot::deg(fit.turn) == Approx(90).margin(2));
}

TEST_CASE("toolbox: no echo, no wall", "[e2e][toolbox]") { CHECK_FALSE(fit_wall(sweep({}), kSonarX, 4.0).found); }

TEST_CASE("toolbox: Forward and Turn move the simulated robot as asked", "[e2e][toolbox]") {
  using namespace std::chrono_literals;
  carbot::World w;
  w.size = {10, 10};
  carbot::Simulation sim(w);
  carbot::hal::bind(&sim);
  Env ee;
  afp::Plan plan("Moves");
  auto *fwd = plan.add_actor("fwd", std::make_unique<Forward>(ee, afp::in<float>(50)));
  auto *turn = plan.add_actor("turn", std::make_unique<Turn>(ee, afp::in<float>(-90)));
  auto *back = plan.add_actor("back", std::make_unique<Forward>(ee, afp::in<float>(-20)));
  plan.define_first_actor(fwd);
  plan.define_subsequent(fwd, Forward::FORWARD_OK, turn);
  plan.define_subsequent(turn, Turn::TURN_OK, back);
  plan.define_subsequent(back, Forward::FORWARD_OK, afp::terminate);
  afp::Configuration config;
  afp::SteppedExecutor exec(plan, config);
  exec.start();
  while (exec.status() == afp::Status::Running && sim.time() < 30) {
    sim.step_control();
    exec.step(10ms);
  }
  carbot::hal::bind(nullptr);
  CHECK(exec.status() == afp::Status::Succeeded);
  // 50 cm along +x, a right turn to face -y, 20 cm backwards: ends at (0.5, 0.2) facing -90.
  CHECK(sim.pose().x == Approx(0.5).margin(0.02));
  CHECK(sim.pose().y == Approx(0.2).margin(0.02));
  CHECK(carbot::deg(sim.pose().heading) == Approx(-90).margin(1.5));
}

TEST_CASE("toolbox: each environment drives the robot it was given, whichever is selected", "[e2e][toolbox]") {
  // As carbot-sim gives a plan its robot (docs/sim.md "Several robots"): two environments, one
  // per robot of one world, each Forward on its own robot; the simulation's selection plays no
  // part (it is left on robot 0 throughout).
  using namespace std::chrono_literals;
  carbot::World w;
  w.size = {10, 10};
  w.robots = {{{0, 0}, 0}, {{0, 2}, 90}};
  w.start = w.robots.front();
  carbot::Simulation sim(w);
  carbot::hal::bind(&sim);
  Env first, second;
  second.set_robot(carbot_robot_handle(1));
  afp::Plan a("A"), b("B");
  auto *fa = a.add_actor("fwd", std::make_unique<Forward>(first, afp::in<float>(40)));
  auto *fb = b.add_actor("fwd", std::make_unique<Forward>(second, afp::in<float>(20)));
  a.define_first_actor(fa);
  a.define_subsequent(fa, Forward::FORWARD_OK, afp::terminate);
  b.define_first_actor(fb);
  b.define_subsequent(fb, Forward::FORWARD_OK, afp::terminate);
  afp::Configuration config;
  afp::SteppedExecutor ea(a, config), eb(b, config);
  ea.start();
  eb.start();
  while ((ea.status() == afp::Status::Running || eb.status() == afp::Status::Running) && sim.time() < 20) {
    sim.select(0);
    sim.step_control();
    if (ea.status() == afp::Status::Running) ea.step(10ms);
    if (eb.status() == afp::Status::Running) eb.step(10ms);
  }
  carbot::hal::bind(nullptr);
  CHECK(ea.status() == afp::Status::Succeeded);
  CHECK(eb.status() == afp::Status::Succeeded);
  sim.select(0);  // 40 cm along +x
  CHECK(sim.pose().x == Approx(0.4).margin(0.02));
  CHECK(sim.pose().y == Approx(0).margin(0.02));
  sim.select(1);  // 20 cm along +y from (0, 2)
  CHECK(sim.pose().x == Approx(0).margin(0.02));
  CHECK(sim.pose().y == Approx(2.2).margin(0.02));
}
