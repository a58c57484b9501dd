// Inside a Simulation: the ODE objects and the state between steps. Only core/*.cc include this.
#pragma once

#include <ode/ode.h>

#include <array>
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

struct Simulation::Impl {
  World world;
  SimConfig config;
  long steps_per_control = 10;
  long steps = 0;  ///< physics steps done; time = steps * physics_step

  dWorldID ode_world = nullptr;
  dSpaceID robot_space = nullptr;  ///< the robot's geoms (never collided with each other)
  dSpaceID env_space = nullptr;    ///< floor, walls, boxes
  dJointGroupID contacts = nullptr;
  dGeomID floor = nullptr;
  dGeomID sonar_ray = nullptr;  ///< in no space: queried with dCollide, never pushes anything

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

  double escape_until = -1;
  int escape_presses = 0;
  std::vector<bool> event_done;

  std::vector<ItemState> items;
  int held = -1;
  std::vector<SimNote> notes;

  // simulation.cc
  void build_environment();
  void run_due_events();
  void physics_step();
  double time() const { return static_cast<double>(steps) * config.physics_step; }
  void note(std::string text);
  void drop_held(const Vec2* to);

  // ode_robot.cc
  void build_robot();
  void set_wheel_targets();
  void actuate();
  void destroy();

  // contacts.cc
  void collide();

  // sensors.cc
  Vec2 ir_spot(Side side) const;
  bool line_black(Side side) const;
  double sonar_range() const;
  void move_sonar_mount();
};

/// Which part a robot geom is (stored as the geom's data pointer value).
Part part_of(dGeomID g);

}  // namespace carbot
