/* The Carbot's hardware as a robot library sees it: a C99 API, SI units.
 *
 * A robot library (sim/robots/) implements a chart interface (samples/NAME.iface) on top of
 * these calls, the way firmware sits on a board's HAL. Every call names the robot it is for,
 * as firmware passes a device: its first argument is the robot's handle, which is what
 * carbot-sim gives each engine as its instance context, so an interface function passes on the
 * context it received (docs/sim.md "Several robots"). In the simulator the calls act on that
 * robot of the simulation carbot-sim bound with carbot::hal::bind(); calling them with none
 * bound, or without a robot, is a programming error and aborts with a message.
 *
 * Angles are radians, counter-clockwise positive; distances metres; times seconds.
 */
#ifndef CARBOT_HAL_H
#define CARBOT_HAL_H

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

enum { CARBOT_LEFT = 0, CARBOT_RIGHT = 1 };

/* --- which robot (several Carbots may share a world; each has its own number) ----------- */
enum { CARBOT_MAX_ROBOTS = 8 }; /* a library keeping per-robot state keeps this many */

/* A robot's handle: what carbot-sim gives each C engine as its instance context (gfec
 * --context-type='struct CarbotRobot *', docs/c-engine.md "Instance context") and a plan's
 * toolbox as its robot, so every interface call names the robot it is for. */
struct CarbotRobot;
struct CarbotRobot* carbot_robot_handle(int index);   /* robot `index`'s handle (0 .. CARBOT_MAX_ROBOTS - 1) */
int carbot_robot_of(const struct CarbotRobot* robot); /* the handle's robot number */
int carbot_robot_count(struct CarbotRobot* robot);    /* robots in the world */

/* --- time ------------------------------------------------------------------------------- */
double carbot_time(struct CarbotRobot* robot);           /* simulated seconds since the start */
double carbot_control_period(struct CarbotRobot* robot); /* seconds between two calls of the engine */

/* --- motion ----------------------------------------------------------------------------- */
/* Chassis motion: forward speed (m/s) and turn rate (rad/s, + = left). The wheels steer and
 * spin to match (inverse kinematics); (0, w) turns in place; top wheel speed 0.31 m/s. */
void carbot_drive(struct CarbotRobot* robot, double forward, double turn_rate);
double carbot_top_speed(struct CarbotRobot* robot);

/* --- localisation (an overhead tracker: the true pose) ----------------------------------- */
typedef struct CarbotPose {
  double x, y;    /* chassis centre, m */
  double heading; /* rad, CCW from +x */
} CarbotPose;
CarbotPose carbot_pose(struct CarbotRobot* robot);
double carbot_speed(struct CarbotRobot* robot);    /* measured forward speed, m/s */
double carbot_odometer(struct CarbotRobot* robot); /* metres driven so far */

/* --- sensors ---------------------------------------------------------------------------- */
bool carbot_ir_black(struct CarbotRobot* robot, int side); /* infrared line sensor CARBOT_LEFT / CARBOT_RIGHT */
double carbot_sonar_range(struct CarbotRobot* robot);      /* ultrasonic range, m; carbot_sonar_max() when no echo */
double carbot_sonar_max(struct CarbotRobot* robot);
void carbot_sonar_aim(struct CarbotRobot* robot, double angle); /* turn the mount (rad, relative to the heading) */
double carbot_sonar_angle(struct CarbotRobot* robot);           /* where the mount points now */
bool carbot_bumper(struct CarbotRobot* robot);                  /* front bumper touched */
int carbot_bumps(struct CarbotRobot* robot);                    /* bumper presses so far */
bool carbot_escape(struct CarbotRobot* robot);                  /* escape button held down */

/* --- items and gripper (the world's items, seen by an overhead camera) --------------------- */
typedef struct CarbotItem {
  const char* name;
  double x, y;           /* where it is (in the gripper while held) */
  double dest_x, dest_y; /* where it belongs */
  bool held;
} CarbotItem;
int carbot_item_count(struct CarbotRobot* robot);
CarbotItem carbot_item(struct CarbotRobot* robot, int index);
void carbot_gripper_point(struct CarbotRobot* robot, double* x, double* y);
double carbot_grip_reach(struct CarbotRobot* robot);    /* an item this close to the gripper point can be gripped */
bool carbot_grip(struct CarbotRobot* robot, int index); /* true if now holding it */
void carbot_release(struct CarbotRobot* robot);         /* put the held item down under the gripper */
int carbot_held_item(struct CarbotRobot* robot);        /* index, or -1 */
int carbot_item_holder(struct CarbotRobot* robot, int index); /* the robot holding item `index`, or -1 */

/* --- signals for people around (not seen by other robots) -------------------------------- */
void carbot_lights(struct CarbotRobot* robot, bool on); /* the signal lights */
void carbot_beep(struct CarbotRobot* robot, int times); /* beeps `times` times */

#ifdef __cplusplus
}
#endif

#endif /* CARBOT_HAL_H */
