/* FetchBot (samples/fetchbot.iface) on the Carbot: a team of robots fetching one item.
 *
 * Every robot of the team links this library; each keeps its own memory (the robot a call
 * is for picks it), as each real robot would in its own firmware. The item to fetch is the first
 * one in the world file. Nothing here knows about the team: whether a robot picks the item
 * up or stands back is the chart's decision (samples/fetch_team.fsm). Obstacles and other
 * robots are not avoided: a robot that drives at an item another robot is holding runs into
 * that robot, which is what the contrast run shows.
 *
 * As every robot library's, its functions carry the interface's name (FetchBot_PickUp:
 * CleanBot has a PickUp too); carbot-sim renames an engine's calls to them (sim/robots/robots.h).
 *
 * Units: metres, seconds, radians. Details and numbers: docs/sim.md, "FetchBot".
 */
#include "robots/robots.h"

#include <math.h>

#include "hal/carbot_hal.h"

#define FETCHBOT_CRUISE 0.25       /* m/s when far from the item */
#define FETCHBOT_SLOW 0.05         /* m/s creeping in on it */
#define FETCHBOT_TURN_GAIN 2.0     /* turn rate per radian of heading error */
#define FETCHBOT_MAX_TURN 1.5      /* rad/s */
#define FETCHBOT_TURN_IN_PLACE 0.6 /* rad: a larger heading error turns on the spot */
#define FETCHBOT_ARRIVED 0.05      /* m: gripper point this close to the item */
#define FETCHBOT_HANDLE_TIME 0.5   /* s to close the gripper */
#define FETCHBOT_PARK_DISTANCE 0.9 /* m: a parked robot's centre is this far from the item */
#define FETCHBOT_BACK_SPEED 0.20   /* m/s backing away to park */
#define FETCHBOT_STILL 0.02        /* m/s: slower than this is standing */
#define FETCHBOT_DELIVERED 0.10    /* m: an item this close to its destination is there */

/* One robot's memory. */
struct FetchBot {
  double handle_since; /* when the gripper started closing or opening, -1 idle */
};
static struct FetchBot robots[CARBOT_MAX_ROBOTS];

void fetchbot_reset(void) {
  int i;
  for (i = 0; i < CARBOT_MAX_ROBOTS; ++i) robots[i].handle_since = -1;
}

static struct FetchBot* me(struct CarbotRobot* robot) { return &robots[carbot_robot_of(robot)]; }

static double dist(double ax, double ay, double bx, double by) { return hypot(ax - bx, ay - by); }

static bool item_at(struct CarbotRobot* robot, double* x, double* y) {
  CarbotItem it;
  if (carbot_item_count(robot) < 1) return false;
  it = carbot_item(robot, 0);
  *x = it.x;
  *y = it.y;
  return true;
}

/* Heading error towards (x, y) from the robot's centre, in (-pi, pi]. */
static double bearing_error(CarbotPose p, double x, double y) {
  const double e = atan2(y - p.y, x - p.x) - p.heading;
  return atan2(sin(e), cos(e));
}

static double clamp_turn(double turn) {
  if (turn > FETCHBOT_MAX_TURN) return FETCHBOT_MAX_TURN;
  if (turn < -FETCHBOT_MAX_TURN) return -FETCHBOT_MAX_TURN;
  return turn;
}

/* Drives so that the gripper point comes to (x, y), as the CleanBot does: turn on the spot
 * when far off, else run at a speed that falls with the remaining distance. */
static void go_to(struct CarbotRobot* robot, double x, double y) {
  const CarbotPose p = carbot_pose(robot);
  double gx, gy, speed, remaining, reach, error, turn;
  carbot_gripper_point(robot, &gx, &gy);
  reach = dist(p.x, p.y, gx, gy);
  error = bearing_error(p, x, y);
  if (dist(p.x, p.y, x, y) < reach * 0.9) { /* too close to turn onto it: back off */
    carbot_drive(robot, -0.10, 0);
    return;
  }
  turn = clamp_turn(FETCHBOT_TURN_GAIN * error);
  if (fabs(error) > FETCHBOT_TURN_IN_PLACE) {
    carbot_drive(robot, 0, turn);
    return;
  }
  remaining = dist(p.x, p.y, x, y) - reach;
  speed = 0.8 * remaining;
  if (speed > FETCHBOT_CRUISE) speed = FETCHBOT_CRUISE;
  if (speed < FETCHBOT_SLOW) speed = FETCHBOT_SLOW;
  if (remaining < FETCHBOT_ARRIVED / 2) speed = 0;
  carbot_drive(robot, speed * cos(error), turn);
}

/* --- actions ------------------------------------------------------------------------------ */

void FetchBot_DriveToItem(struct CarbotRobot* robot) {
  double x, y;
  if (!item_at(robot, &x, &y) || FetchBot_Arrived(robot)) {
    carbot_drive(robot, 0, 0);
    return;
  }
  go_to(robot, x, y);
}

void FetchBot_PickUp(struct CarbotRobot* robot) {
  double x, y;
  if (FetchBot_Holding(robot) || !item_at(robot, &x, &y)) {
    carbot_drive(robot, 0, 0);
    return;
  }
  if (!FetchBot_Arrived(robot)) { /* not in reach (yet, or any more): go for it */
    me(robot)->handle_since = -1;
    go_to(robot, x, y);
    return;
  }
  carbot_drive(robot, 0, 0);
  if (me(robot)->handle_since < 0) me(robot)->handle_since = carbot_time(robot);
  if (carbot_time(robot) - me(robot)->handle_since < FETCHBOT_HANDLE_TIME) return;
  me(robot)->handle_since = -1;
  (void)carbot_grip(robot, 0); /* fails if another robot holds it: PickUp goes on trying */
}

/* Drives the held item to its destination, then stands still while the gripper opens and
 * puts it down. */
void FetchBot_Carry(struct CarbotRobot* robot) {
  CarbotItem it;
  double gx, gy;
  if (!FetchBot_Holding(robot)) {
    carbot_drive(robot, 0, 0);
    return;
  }
  it = carbot_item(robot, 0);
  carbot_gripper_point(robot, &gx, &gy);
  if (dist(gx, gy, it.dest_x, it.dest_y) >= FETCHBOT_ARRIVED) {
    me(robot)->handle_since = -1;
    go_to(robot, it.dest_x, it.dest_y);
    return;
  }
  carbot_drive(robot, 0, 0);
  if (me(robot)->handle_since < 0) me(robot)->handle_since = carbot_time(robot);
  if (carbot_time(robot) - me(robot)->handle_since < FETCHBOT_HANDLE_TIME) return;
  me(robot)->handle_since = -1;
  carbot_release(robot);
}

/* Backs away from the item, still facing it, until FETCHBOT_PARK_DISTANCE from it; then stands. */
void FetchBot_Park(struct CarbotRobot* robot) {
  double x, y;
  CarbotPose p;
  if (!item_at(robot, &x, &y)) {
    carbot_drive(robot, 0, 0);
    return;
  }
  p = carbot_pose(robot);
  if (dist(p.x, p.y, x, y) >= FETCHBOT_PARK_DISTANCE) {
    carbot_drive(robot, 0, 0);
    return;
  }
  carbot_drive(robot, -FETCHBOT_BACK_SPEED, clamp_turn(FETCHBOT_TURN_GAIN * bearing_error(p, x, y)));
}

void FetchBot_Beep(struct CarbotRobot* robot, int times) { carbot_beep(robot, times); }

void FetchBot_Lights(struct CarbotRobot* robot, bool on) { carbot_lights(robot, on); }

/* --- conditions --------------------------------------------------------------------------- */

bool FetchBot_Arrived(struct CarbotRobot* robot) {
  double x, y, gx, gy;
  if (!item_at(robot, &x, &y)) return false;
  carbot_gripper_point(robot, &gx, &gy);
  return dist(gx, gy, x, y) < FETCHBOT_ARRIVED;
}

bool FetchBot_Holding(struct CarbotRobot* robot) {
  return carbot_item_count(robot) > 0 && carbot_held_item(robot) == 0;
}

bool FetchBot_Delivered(struct CarbotRobot* robot) {
  CarbotItem it;
  if (carbot_item_count(robot) < 1) return false;
  it = carbot_item(robot, 0);
  return !it.held && dist(it.x, it.y, it.dest_x, it.dest_y) < FETCHBOT_DELIVERED;
}

bool FetchBot_Parked(struct CarbotRobot* robot) {
  double x, y;
  CarbotPose p;
  if (!item_at(robot, &x, &y)) return true;
  p = carbot_pose(robot);
  return dist(p.x, p.y, x, y) >= FETCHBOT_PARK_DISTANCE - 0.05 && fabs(carbot_speed(robot)) < FETCHBOT_STILL;
}
