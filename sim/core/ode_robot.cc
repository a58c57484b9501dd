// The Carbot's ODE bodies and joints, and the servos that turn drive commands into joint motors.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/carbot_model.h"
#include "core/geometry.h"
#include "core/simulation_impl.h"

namespace carbot {
namespace {

void tag(dGeomID g, Part p) { dGeomSetData(g, reinterpret_cast<void*>(static_cast<std::intptr_t>(p) + 1)); }

}  // namespace

Part part_of(dGeomID g) { return static_cast<Part>(reinterpret_cast<std::intptr_t>(dGeomGetData(g)) - 1); }

void Robot::build(dWorldID ode_world, const Start& start) {
  using namespace model;
  const double x0 = start.position.x, y0 = start.position.y;
  const double h = rad(start.heading_deg);
  dMatrix3 R;
  dRFromAxisAndAngle(R, 0, 0, 1, h);
  const double c = std::cos(h), s = std::sin(h);
  auto at = [&](double bx, double by, double z, dReal out[3]) {  // body xy -> world
    out[0] = x0 + c * bx - s * by;
    out[1] = y0 + s * bx + c * by;
    out[2] = z;
  };

  // Chassis: one box body; the centre of mass stays at the body origin (ODE requires it),
  // every other chassis part is an offset geom on the same body.
  chassis = dBodyCreate(ode_world);
  dMass m;
  dMassSetBoxTotal(&m, kChassisMass, kLength, kWidth, kChassisHeight);
  dBodySetMass(chassis, &m);
  dBodySetPosition(chassis, x0, y0, kChassisZ);
  dBodySetRotation(chassis, R);
  chassis_geom = dCreateBox(space, kLength, kWidth, kChassisHeight);
  dGeomSetBody(chassis_geom, chassis);
  tag(chassis_geom, Part::Chassis);

  // Bumper: sensor only (the contact callback makes no joint for it), across the whole front.
  bumper_geom = dCreateBox(space, kBumperDepth, kBumperWidth, kBumperHeight);
  dGeomSetBody(bumper_geom, chassis);
  dGeomSetOffsetPosition(bumper_geom, kLength / 2 + kBumperDepth / 2, 0,
                         kClearance + 0.01 + kBumperHeight / 2 - kChassisZ);
  tag(bumper_geom, Part::Bumper);

  // Frictionless caster balls, left and right, touching the floor.
  for (int i = 0; i < 2; ++i) {
    casters[i] = dCreateSphere(space, kCasterRadius);
    dGeomSetBody(casters[i], chassis);
    dGeomSetOffsetPosition(casters[i], 0, i == 0 ? kCasterY : -kCasterY, kCasterRadius - kChassisZ);
    tag(casters[i], Part::Caster);
  }

  // Wheels: disc inertia, sphere collision shape (cylinders scrub when turning in place).
  const double wheel_x[2] = {kWheelOffset, -kWheelOffset};
  for (int i = 0; i < 2; ++i) {
    Wheel& w = wheels[i];
    w.x = wheel_x[i];
    w.body = dBodyCreate(ode_world);
    dMassSetCylinderTotal(&m, kWheelMass, 2, kWheelRadius, kWheelWidth);  // axis along body y
    dBodySetMass(w.body, &m);
    dReal p[3];
    at(w.x, 0, kWheelRadius, p);
    dBodySetPosition(w.body, p[0], p[1], p[2]);
    dBodySetRotation(w.body, R);
    w.geom = dCreateSphere(space, kWheelRadius);
    dGeomSetBody(w.geom, w.body);
    tag(w.geom, Part::Wheel);

    // hinge2: chassis = body1; axis 1 vertical (steering), axis 2 the wheel's spin axis.
    w.joint = dJointCreateHinge2(ode_world, nullptr);
    dJointAttach(w.joint, chassis, w.body);
    dJointSetHinge2Anchor(w.joint, p[0], p[1], p[2]);
    const dReal up[3] = {0, 0, 1};
    const dReal spin[3] = {-s, c, 0};
    dJointSetHinge2Axes(w.joint, up, spin);
    dJointSetHinge2Param(w.joint, dParamLoStop, -kSteerStop);
    dJointSetHinge2Param(w.joint, dParamHiStop, kSteerStop);
    // A stiff suspension: the wheel carries load like a rigid axle, softly enough to share
    // it with the casters.
    dJointSetHinge2Param(w.joint, dParamSuspensionERP, 0.4);
    dJointSetHinge2Param(w.joint, dParamSuspensionCFM, 2e-4);
    dJointSetHinge2Param(w.joint, dParamFMax, kSteerTorque);
    dJointSetHinge2Param(w.joint, dParamFMax2, kDriveTorque);
  }
}

// Inverse kinematics: the wheel at x on the centre line moves at (v, w*x) in the body frame
// when the chassis moves at v and turns at w about its centre. Each wheel is steered along
// that velocity; of the two ways to point a wheel along a line (forwards or reversed), the
// one nearer its present angle is taken, so reversing never swings a wheel round by 180 deg.
void Robot::set_wheel_targets() {
  double v = cmd_forward, w = cmd_turn;
  const double fastest = std::hypot(v, w * model::kWheelOffset);
  if (fastest > model::kTopSpeed) {
    v *= model::kTopSpeed / fastest;
    w *= model::kTopSpeed / fastest;
  }
  for (Wheel& wh : wheels) {
    const double vx = v, vy = w * wh.x;
    const double speed = std::hypot(vx, vy);
    if (speed < 1e-9) {  // standing still: keep the wheel where it points
      wh.speed_target = 0;
      continue;
    }
    const double now = -dJointGetHinge2Angle1(wh.joint);
    const double a = std::atan2(vy, vx);
    double best = a, best_speed = speed;
    for (double cand : {a - kPi, a + kPi}) {
      if (std::fabs(cand) <= model::kSteerStop &&
          (std::fabs(best) > model::kSteerStop || std::fabs(cand - now) < std::fabs(best - now))) {
        best = cand;
        best_speed = -speed;
      }
    }
    wh.steer_target = best;
    wh.speed_target = best_speed;
  }
}

// Runs every physics step: the steering servo (P control with a rate limit) and the drive
// motor, whose speed is scaled by cos(steering error) so a wheel still turning does not
// push the robot sideways. hinge2 angles and rates are chassis relative to wheel: a positive
// joint angle is a right (clockwise) steer and a positive spin rate rolls backwards.
void Robot::actuate() {
  for (Wheel& wh : wheels) {
    const double now = -dJointGetHinge2Angle1(wh.joint);
    const double err = wh.steer_target - now;
    const double rate = std::clamp(model::kSteerGain * err, -model::kSteerRate, model::kSteerRate);
    dJointSetHinge2Param(wh.joint, dParamVel, -rate);
    const double align = std::max(0.0, std::cos(err));
    dJointSetHinge2Param(wh.joint, dParamVel2, -wh.speed_target * align / model::kWheelRadius);
  }
}

void Simulation::Impl::destroy() {
  if (sonar_ray) dGeomDestroy(sonar_ray);
  if (mast_probe) dGeomDestroy(mast_probe);
  if (contacts) dJointGroupDestroy(contacts);
  // Destroying a space destroys the geoms in it (cleanup mode is on by default).
  for (Robot& r : robots)
    if (r.space) dSpaceDestroy(r.space);
  if (env_space) dSpaceDestroy(env_space);
  if (ode_world) dWorldDestroy(ode_world);  // and its bodies and joints
}

}  // namespace carbot
