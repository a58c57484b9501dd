/* The Carbot's hardware as a robot library sees it: a C99 API, SI units.
 *
 * A robot library (sim/robots/) implements a chart interface (samples/NAME.iface) on top of
 * these calls, the way firmware sits on a board's HAL. In the simulator they act on the
 * simulation that carbot-sim bound with carbot::hal::bind(), on the robot of the last
 * carbot_act_on() or bind(); calling them with none bound
 * is a programming error and aborts with a message.
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
int carbot_robot(void);         /* this robot's number, 0 .. carbot_robot_count() - 1 */
int carbot_robot_count(void);   /* robots in the world */

/* A robot's handle: what carbot-sim gives each C engine as its instance context (gfec
 * --context-type='struct CarbotRobot *', docs/c-engine.md "Instance context"), so every
 * interface call names the robot it is for, as firmware passes a device. A robot library
 * starts each interface function with carbot_act_on(ctx): the HAL calls that follow act on
 * that robot, and carbot_robot() is its number (docs/sim.md "Several robots"). */
struct CarbotRobot;
struct CarbotRobot* carbot_robot_handle(int index);   /* robot `index`'s handle (0 .. CARBOT_MAX_ROBOTS - 1) */
int carbot_robot_of(const struct CarbotRobot* robot); /* the handle's robot number */
void carbot_act_on(struct CarbotRobot* robot);        /* the HAL acts on `robot` from here on */

/* --- time ------------------------------------------------------------------------------- */
double carbot_time(void);           /* simulated seconds since the start */
double carbot_control_period(void); /* seconds between two calls of the engine */

/* --- motion ----------------------------------------------------------------------------- */
/* Chassis motion: forward speed (m/s) and turn rate (rad/s, + = left). The wheels steer and
 * spin to match (inverse kinematics); (0, w) turns in place; top wheel speed 0.31 m/s. */
void carbot_drive(double forward, double turn_rate);
double carbot_top_speed(void);

/* --- localisation (an overhead tracker: the true pose) ----------------------------------- */
typedef struct CarbotPose {
  double x, y;    /* chassis centre, m */
  double heading; /* rad, CCW from +x */
} CarbotPose;
CarbotPose carbot_pose(void);
double carbot_speed(void);    /* measured forward speed, m/s */
double carbot_odometer(void); /* metres driven so far */

/* --- sensors ---------------------------------------------------------------------------- */
bool carbot_ir_black(int side);  /* infrared line sensor CARBOT_LEFT / CARBOT_RIGHT */
double carbot_sonar_range(void); /* ultrasonic range, m; carbot_sonar_max() when no echo */
double carbot_sonar_max(void);
void carbot_sonar_aim(double angle); /* turn the mount (rad, relative to the heading) */
double carbot_sonar_angle(void);     /* where the mount points now */
bool carbot_bumper(void);            /* front bumper touched */
int carbot_bumps(void);              /* bumper presses so far */
bool carbot_escape(void);            /* escape button held down */

/* --- items and gripper (the world's items, seen by an overhead camera) --------------------- */
typedef struct CarbotItem {
  const char* name;
  double x, y;           /* where it is (in the gripper while held) */
  double dest_x, dest_y; /* where it belongs */
  bool held;
} CarbotItem;
int carbot_item_count(void);
CarbotItem carbot_item(int index);
void carbot_gripper_point(double* x, double* y);
double carbot_grip_reach(void);    /* an item this close to the gripper point can be gripped */
bool carbot_grip(int index);       /* true if now holding it */
void carbot_release(void);         /* put the held item down under the gripper */
int carbot_held_item(void);        /* index, or -1 */
int carbot_item_holder(int index); /* the robot holding item `index`, or -1 */

/* --- signals for people around (not seen by other robots) -------------------------------- */
void carbot_lights(bool on); /* the signal lights */
void carbot_beep(int times); /* beeps `times` times */

#ifdef __cplusplus
}
#endif

#endif /* CARBOT_HAL_H */
