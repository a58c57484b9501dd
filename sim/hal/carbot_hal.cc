// The C HAL over the bound Simulation.
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
int g_robot = 0;
}  // namespace

void bind(Simulation* sim, int robot) {
  g_sim = sim;
  g_robot = robot;
  if (sim) sim->select(robot);
}

int bound_robot() { return g_robot; }

Simulation& bound() {
  if (!g_sim) {
    std::fputs("carbot HAL: a robot function was called with no simulation bound\n", stderr);
    std::abort();
  }
  // Whoever else selected a robot meanwhile (a report reading every robot), the HAL acts on its own.
  if (g_sim->selected() != g_robot) g_sim->select(g_robot);
  return *g_sim;
}

}  // namespace carbot::hal

using carbot::hal::bound;

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

void carbot_act_on(CarbotRobot* robot) {
  if (!robot) {
    std::fputs("carbot HAL: an interface function was called without its robot (no instance context)\n", stderr);
    std::abort();
  }
  carbot::hal::bind(&bound(), robot->index);
}

int carbot_robot(void) {
  (void)bound();
  return carbot::hal::bound_robot();
}
int carbot_robot_count(void) { return bound().robot_count(); }

double carbot_time(void) { return bound().time(); }
double carbot_control_period(void) { return bound().config().control_period; }

void carbot_drive(double forward, double turn_rate) { bound().drive(forward, turn_rate); }
double carbot_top_speed(void) { return carbot::model::kTopSpeed; }

CarbotPose carbot_pose(void) {
  const carbot::Pose p = bound().pose();
  return {p.x, p.y, p.heading};
}
double carbot_speed(void) { return bound().forward_speed(); }
double carbot_odometer(void) { return bound().odometer(); }

bool carbot_ir_black(int side) { return bound().line_black(side_of(side)); }
double carbot_sonar_range(void) { return bound().sonar_range(); }
double carbot_sonar_max(void) { return carbot::model::kSonarRange; }
void carbot_sonar_aim(double angle) { bound().aim_sonar(angle); }
double carbot_sonar_angle(void) { return bound().sonar_angle(); }
bool carbot_bumper(void) { return bound().bumper(); }
int carbot_bumps(void) { return bound().bumps(); }
bool carbot_escape(void) { return bound().escape(); }

int carbot_item_count(void) { return static_cast<int>(bound().items().size()); }

CarbotItem carbot_item(int index) {
  const auto& items = bound().items();
  if (index < 0 || index >= static_cast<int>(items.size())) return {"", 0, 0, 0, 0, false};
  const carbot::ItemState& it = items[index];
  return {it.name.c_str(), it.at.x, it.at.y, it.destination.x, it.destination.y, it.held};
}

void carbot_gripper_point(double* x, double* y) {
  const carbot::Vec2 g = bound().gripper_point();
  *x = g.x;
  *y = g.y;
}
double carbot_grip_reach(void) { return carbot::model::kGripReach; }
bool carbot_grip(int index) { return bound().grip(index); }
void carbot_release(void) { bound().release(); }
int carbot_held_item(void) { return bound().held_item(); }
int carbot_item_holder(int index) { return bound().holder(index); }

void carbot_lights(bool on) { bound().set_lights(on); }
void carbot_beep(int times) { bound().beep(times); }

}  // extern "C"
