// Inside a Simulation: the ODE objects and the state between steps. Only core/*.cc include this.
#pragma once

#include <ode/ode.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "core/simulation.h"

namespace carbot {

/// One steerable driven wheel: body, hinge2 joint, and what it was told to do.
struct Wheel {
  double x = 0;  ///< position along the chassis centre line
  dBodyID body = nullptr;
  dGeomID geom = nullptr;
  dJointID joint = nullptr;
  double steer_target = 0;  ///< rad, CCW relative to the chassis
  double speed_target = 0;  ///< m/s ground speed along the wheel's rolling direction
};

/// Which surface a robot geom has; the contact callback picks friction from it.
enum class Part { Chassis, Wheel, Caster, Bumper };

/// One Carbot: its ODE bodies, joints and geoms, and its state between steps.
struct Robot {
  int index = 0;             ///< robot number in the world (its agent number in a team)
  dSpaceID space = nullptr;  ///< the robot's geoms (never collided with each other)
  dBodyID chassis = nullptr;
  dGeomID chassis_geom = nullptr;
  dGeomID bumper_geom = nullptr;
  std::array<dGeomID, 2> casters{};
  std::array<Wheel, 2> wheels{};  ///< [0] front, [1] rear

  double cmd_forward = 0, cmd_turn = 0;
  double sonar_angle = 0, sonar_target = 0;
  double odometer = 0;
  bool left_floor = false;

  bool bumper_touch_step = false;    ///< set by the contact callback in the current physics step
  bool bumper_touch_period = false;  ///< any touch during the running control period
  bool bumper_pressed = false;       ///< the last full control period had a touch
  int bumps = 0;
  std::vector<Bump> bump_log;

  int held = -1;        ///< the item in its gripper, -1 none
  bool lights = false;  ///< its signal lights (a robot library may switch them)
  int beeps = 0;        ///< how many times it beeped

  Vec2 gripper_point() const;

  // ode_robot.cc
  void build(dWorldID ode_world, const Start& start);
  void set_wheel_targets();
  void actuate();

  // sensors.cc
  Vec2 ir_spot(Side side) const;
  void move_sonar_mount(double physics_step);
};

struct Simulation::Impl {
  World world;
  SimConfig config;
  long steps_per_control = 10;
  long steps = 0;  ///< physics steps done; time = steps * physics_step

  dWorldID ode_world = nullptr;
  dSpaceID env_space = nullptr;  ///< floor, walls, boxes
  dJointGroupID contacts = nullptr;
  dGeomID floor = nullptr;
  dGeomID sonar_ray = nullptr;  ///< in no space: queried with dCollide, never pushes anything
  /// Several robots: a box in no space, moved onto another robot's sonar mast when a sonar
  /// ray is tested against that robot (no body, never collides with anything).
  dGeomID mast_probe = nullptr;

  std::vector<Robot> robots;  ///< in the world's order
  int selected = 0;           ///< the robot the public per-robot calls act on
  Robot& robot() { return robots[static_cast<size_t>(selected)]; }
  const Robot& robot() const { return robots[static_cast<size_t>(selected)]; }

  /// Robot-against-robot contacts: each a touch that began in a control period after one
  /// without it, per pair.
  std::vector<RobotContact> robot_contacts;
  std::vector<char> pair_touch_period, pair_touch_was;  ///< [a * robots + b], a < b
  void touch_pair(int a, int b) {
    pair_touch_period[static_cast<size_t>(std::min(a, b)) * robots.size() + static_cast<size_t>(std::max(a, b))] = 1;
  }

  double escape_until = -1;
  int escape_presses = 0;
  std::vector<bool> event_done;

  std::vector<ItemState> items;
  std::vector<SimNote> notes;

  // simulation.cc
  void build_environment();
  void run_due_events();
  void physics_step();
  double time() const { return static_cast<double>(steps) * config.physics_step; }
  void note(std::string text);
  void drop_held(Robot& r, const Vec2* to);
  /// "the robot" for one robot, "robot 2" in a team: how notes name a robot.
  std::string robot_name(const Robot& r) const;

  void destroy();

  // contacts.cc
  void collide();

  // sensors.cc
  bool line_black(const Robot& r, Side side) const;
  double sonar_range(const Robot& r) const;
};

/// Which part a robot geom is (stored as the geom's data pointer value).
Part part_of(dGeomID g);

}  // namespace carbot
