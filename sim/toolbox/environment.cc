// The toolbox's environment: the HAL for its robot, in the units the toolbox computes in (m, rad, s).
#include <cmath>

#include "carbot_toolbox.h"
#include "hal/carbot_hal.h"

namespace carbot::toolbox {

Environment::Environment() : robot_(carbot_robot_handle(0)) {}

void Environment::drive(double forward, double turn_rate) { carbot_drive(robot_, forward, turn_rate); }
double Environment::x() const { return carbot_pose(robot_).x; }
double Environment::y() const { return carbot_pose(robot_).y; }
double Environment::heading() const { return carbot_pose(robot_).heading; }
double Environment::time() const { return carbot_time(robot_); }
double Environment::sonar_range() const { return carbot_sonar_range(robot_); }
double Environment::max_range() const { return carbot_sonar_max(robot_); }
void Environment::aim_sonar(double angle) { carbot_sonar_aim(robot_, angle); }
double Environment::sonar_angle() const { return carbot_sonar_angle(robot_); }
bool Environment::sonar_at(double angle) const { return std::fabs(carbot_sonar_angle(robot_) - angle) < 0.009; }
bool Environment::bumper() const { return carbot_bumper(robot_); }
bool Environment::escape() const { return carbot_escape(robot_); }

}  // namespace carbot::toolbox
