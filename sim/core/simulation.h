// The Carbot in its world, on ODE: headless, fixed step, bit-deterministic.
//
// One Simulation holds one world and its robots (one, or several that collide with each
// other). A controller selects a robot, calls its motion and sensor functions, then
// step_control() lets one control period of physics pass for all of them. Nothing here
// reads a clock or a random generator: the same world and the same calls give the same
// trajectory, bit for bit.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/world.h"

namespace carbot {

/// Where the robot is: centre of the chassis on the floor, heading in radians CCW from +x.
struct Pose {
  double x = 0;
  double y = 0;
  double heading = 0;
};

/// Timing. The physics step must divide the control period.
struct SimConfig {
  double physics_step = 0.001;    ///< s, one dWorldStep
  double control_period = 0.010;  ///< s, one step_control()
};

enum class Side { Left, Right };

/// An item as it is now.
struct ItemState {
  std::string name;
  Vec2 at;  ///< on the floor, or in the gripper while held
  Vec2 destination;
  bool held = false;
};

/// A bumper press: when, and where the front of the bumper was.
struct Bump {
  double t = 0;
  Vec2 at;
};

/// Two robots touched (a contact that began after a control period without one), and where:
/// the midpoint of their centres.
struct RobotContact {
  double t = 0;
  int a = 0, b = 0;  ///< robot numbers, a < b
  Vec2 at;
};

/// Something worth telling the person who watches a run (an event fired, the robot left the floor).
struct SimNote {
  double t = 0;
  std::string text;
};

class Simulation {
 public:
  /// Builds the world and puts each robot at its start (world.robots). Throws
  /// std::invalid_argument on a bad config.
  explicit Simulation(const World& world, SimConfig config = {});
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  const World& world() const;
  const SimConfig& config() const;

  // --- Robots ------------------------------------------------------------------------------
  // The motion, pose, sensor and gripper calls below act on the *selected* robot: robot 0
  // unless select() chose another. A world with one robot never needs to select.
  int robot_count() const;
  /// Makes `robot` (0 .. robot_count() - 1) the one the per-robot calls act on.
  void select(int robot);
  int selected() const;
  /// Robot-against-robot contacts so far, in time order.
  const std::vector<RobotContact>& robot_contacts() const;

  // --- Time -------------------------------------------------------------------------------
  /// Simulated seconds since the start (a multiple of the control period).
  double time() const;
  /// Runs the world's due events, then one control period of physics steps.
  void step_control();

  // --- Motion -----------------------------------------------------------------------------
  /// Commands the chassis motion: forward speed (m/s, negative = backwards) and turn rate
  /// (rad/s, positive = counter-clockwise). Inverse kinematics turns this into each wheel's
  /// steering angle and speed; if a wheel would exceed the top speed, both are scaled down
  /// together, so the path's curvature is kept. (0, w) turns in place.
  void drive(double forward, double turn_rate);
  void stop() { drive(0, 0); }
  double commanded_forward() const;
  double commanded_turn_rate() const;

  // --- Where it is ------------------------------------------------------------------------
  Pose pose() const;
  double forward_speed() const;  ///< measured, m/s along the heading
  double turn_rate() const;      ///< measured, rad/s
  double odometer() const;       ///< metres driven (forwards and backwards both count)
  bool left_floor() const;       ///< has the centre ever been outside the floor rectangle

  // --- Sensors ----------------------------------------------------------------------------
  /// Infrared line sensor: true while its floor spot is on the painted line.
  bool line_black(Side side) const;
  /// The floor spot an IR sensor looks at, world coordinates.
  Vec2 ir_spot(Side side) const;
  /// Ultrasonic range along the mount direction, metres; model::kSonarRange when no echo.
  double sonar_range() const;
  /// Turns the sonar mount towards `angle` (rad, relative to the heading, CCW); the servo
  /// moves at model::kSonarMountRate.
  void aim_sonar(double angle);
  double sonar_angle() const;   ///< where the mount points now
  double sonar_target() const;  ///< where it was told to point
  /// Front bumper: touched during the last control period.
  bool bumper() const;
  /// Bumper presses so far (a press is a control period touched after one not touched).
  int bumps() const;
  /// When and where each bump happened.
  const std::vector<Bump>& bump_log() const;
  /// The escape button is held down (for a short moment after a world "press" event).
  bool escape() const;
  int escape_presses() const;

  // --- Items and the gripper --------------------------------------------------------------
  const std::vector<ItemState>& items() const;
  /// The point in front of the bumper where a held item sits.
  Vec2 gripper_point() const;
  /// Index of the held item, or -1.
  int held_item() const;
  /// Takes item `index` if it lies within model::kGripReach of the gripper point and nothing
  /// is held; returns whether the robot now holds it.
  bool grip(int index);
  /// Puts the held item down under the gripper (no effect when holding nothing).
  void release();

  /// Which robot holds item `index`, or -1.
  int holder(int index) const;

  // --- Signals (seen by people, not by other robots) ------------------------------------------
  void set_lights(bool on);
  bool lights() const;
  /// Beeps `times` times (a note says so); the count is kept.
  void beep(int times);
  int beeps() const;

  /// What happened that a person would want to know (events that fired, leaving the floor).
  const std::vector<SimNote>& notes() const;

  /// The ODE side, defined in core/simulation_impl.h for the core's own files only.
  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace carbot
