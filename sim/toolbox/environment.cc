// The toolbox's environment: the HAL in the units the toolbox computes in (m, rad, s).
#include <cmath>

#include "carbot_toolbox.h"
#include "hal/carbot_hal.h"

namespace carbot::toolbox {

void Environment::drive(double forward, double turn_rate) { carbot_drive(forward, turn_rate); }
double Environment::x() const { return carbot_pose().x; }
double Environment::y() const { return carbot_pose().y; }
double Environment::heading() const { return carbot_pose().heading; }
double Environment::time() const { return carbot_time(); }
double Environment::sonar_range() const { return carbot_sonar_range(); }
double Environment::max_range() const { return carbot_sonar_max(); }
void Environment::aim_sonar(double angle) { carbot_sonar_aim(angle); }
double Environment::sonar_angle() const { return carbot_sonar_angle(); }
bool Environment::sonar_at(double angle) const { return std::fabs(carbot_sonar_angle() - angle) < 0.009; }
bool Environment::bumper() const { return carbot_bumper(); }
bool Environment::escape() const { return carbot_escape(); }

}  // namespace carbot::toolbox
