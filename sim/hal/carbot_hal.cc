// The C HAL over the bound Simulation: each call acts on the robot it names.
#include "hal/carbot_hal.h"

#include <cstdio>
#include <cstdlib>

#include "core/carbot_model.h"
#include "core/simulation.h"
#include "core/world.h"
#include "hal/hal_binding.h"

static_assert(CARBOT_MAX_ROBOTS == carbot::kMaxRobots, "the libraries keep state for every robot a world may hold");

namespace carbot::hal {
namespace {
Simulation* g_sim = nullptr;
}  // namespace

void bind(Simulation* sim) { g_sim = sim; }

}  // namespace carbot::hal

namespace {
carbot::Side side_of(int side) { return side == CARBOT_LEFT ? carbot::Side::Left : carbot::Side::Right; }
}  // namespace

// A handle is the robot's number behind an opaque pointer: the context an engine passes back.
struct CarbotRobot {
  int index;
};

namespace {
CarbotRobot g_handles[carbot::kMaxRobots] = {{0}, {1}, {2}, {3}, {4}, {5}, {6}, {7}};
static_assert(carbot::kMaxRobots == 8, "one handle per robot a world may hold");

/// The bound simulation with `robot` selected: every call acts on the robot it names.
carbot::Simulation& bound(const CarbotRobot* robot) {
  if (!carbot::hal::g_sim) {
    std::fputs("carbot HAL: a robot function was called with no simulation bound\n", stderr);
    std::abort();
  }
  if (!robot) {
    std::fputs("carbot HAL: a robot function was called without its robot (no instance context)\n", stderr);
    std::abort();
  }
  if (carbot::hal::g_sim->selected() != robot->index) carbot::hal::g_sim->select(robot->index);
  return *carbot::hal::g_sim;
}
}  // namespace

extern "C" {

CarbotRobot* carbot_robot_handle(int index) {
  if (index < 0 || index >= carbot::kMaxRobots) {
    std::fprintf(stderr, "carbot HAL: no robot %d\n", index);
    std::abort();
  }
  return &g_handles[index];
}

int carbot_robot_of(const CarbotRobot* robot) { return robot ? robot->index : -1; }

int carbot_robot_count(CarbotRobot* robot) { return bound(robot).robot_count(); }

double carbot_time(CarbotRobot* robot) { return bound(robot).time(); }
double carbot_control_period(CarbotRobot* robot) { return bound(robot).config().control_period; }

void carbot_drive(CarbotRobot* robot, double forward, double turn_rate) { bound(robot).drive(forward, turn_rate); }
double carbot_top_speed(CarbotRobot*) { return carbot::model::kTopSpeed; }

CarbotPose carbot_pose(CarbotRobot* robot) {
  const carbot::Pose p = bound(robot).pose();
  return {p.x, p.y, p.heading};
}
double carbot_speed(CarbotRobot* robot) { return bound(robot).forward_speed(); }
double carbot_odometer(CarbotRobot* robot) { return bound(robot).odometer(); }

bool carbot_ir_black(CarbotRobot* robot, int side) { return bound(robot).line_black(side_of(side)); }
double carbot_sonar_range(CarbotRobot* robot) { return bound(robot).sonar_range(); }
double carbot_sonar_max(CarbotRobot*) { return carbot::model::kSonarRange; }
void carbot_sonar_aim(CarbotRobot* robot, double angle) { bound(robot).aim_sonar(angle); }
double carbot_sonar_angle(CarbotRobot* robot) { return bound(robot).sonar_angle(); }
bool carbot_bumper(CarbotRobot* robot) { return bound(robot).bumper(); }
int carbot_bumps(CarbotRobot* robot) { return bound(robot).bumps(); }
bool carbot_escape(CarbotRobot* robot) { return bound(robot).escape(); }

int carbot_item_count(CarbotRobot* robot) { return static_cast<int>(bound(robot).items().size()); }

CarbotItem carbot_item(CarbotRobot* robot, int index) {
  const auto& items = bound(robot).items();
  if (index < 0 || index >= static_cast<int>(items.size())) return {"", 0, 0, 0, 0, false};
  const carbot::ItemState& it = items[index];
  return {it.name.c_str(), it.at.x, it.at.y, it.destination.x, it.destination.y, it.held};
}

void carbot_gripper_point(CarbotRobot* robot, double* x, double* y) {
  const carbot::Vec2 g = bound(robot).gripper_point();
  *x = g.x;
  *y = g.y;
}
double carbot_grip_reach(CarbotRobot*) { return carbot::model::kGripReach; }
bool carbot_grip(CarbotRobot* robot, int index) { return bound(robot).grip(index); }
void carbot_release(CarbotRobot* robot) { bound(robot).release(); }
int carbot_held_item(CarbotRobot* robot) { return bound(robot).held_item(); }
int carbot_item_holder(CarbotRobot* robot, int index) { return bound(robot).holder(index); }

void carbot_lights(CarbotRobot* robot, bool on) { bound(robot).set_lights(on); }
void carbot_beep(CarbotRobot* robot, int times) { bound(robot).beep(times); }

}  // extern "C"
