/* CleanBot (samples/cleanbot.iface) on the Carbot.
 *
 * Behaviours (actions, called every control period while their state is active) and world
 * facts (conditions). The library perceives the world through the HAL: the overhead tracker
 * gives the robot's pose, the overhead camera the items and where each belongs. The chart
 * carries no world knowledge: the item to clean up is the first one in the world file that
 * is not at its destination, and it stays the chosen one until it is put down there.
 *
 * Units: metres, seconds, radians. Details and numbers: docs/sim.md, "CleanBot".
 */
#include "robots/robots.h"

#include <math.h>

#include "hal/carbot_hal.h"

#define CLEANBOT_CRUISE 0.25         /* m/s when far from the goal */
#define CLEANBOT_SLOW 0.05           /* m/s creeping in on the goal */
#define CLEANBOT_TURN_GAIN 2.0       /* turn rate per radian of heading error */
#define CLEANBOT_MAX_TURN 1.5        /* rad/s */
#define CLEANBOT_TURN_IN_PLACE 0.6   /* rad: a larger heading error turns on the spot */
#define CLEANBOT_ARRIVED 0.05        /* m: gripper point this close to the goal */
#define CLEANBOT_AT_DESTINATION 0.10 /* m: an item this close to its destination is there */
#define CLEANBOT_FAR 0.25            /* m: FarFromDestination beyond this */
#define CLEANBOT_HANDLE_TIME 0.5     /* s to close or open the gripper */
#define CLEANBOT_STUCK_TIME 8.0      /* s without 2 cm of progress towards the goal */
#define CLEANBOT_PROGRESS 0.02       /* m */

enum Goal { GOAL_NONE, GOAL_ITEM, GOAL_DESTINATION };

/* One robot's memory; each robot in the world has its own, picked by the robot a call is for. */
struct CleanBot {
  int item;             /* the item being cleaned up, -1 none chosen */
  enum Goal goal;       /* what it drives to */
  double handle_since;  /* when the gripper started closing/opening, -1 idle */
  bool placed;          /* the last PlaceItem put the item down */
  double best_distance; /* progress watch: nearest the goal so far ... */
  double best_since;    /* ... and since when */
};
static struct CleanBot robots[CARBOT_MAX_ROBOTS];
void cleanbot_reset(void) {
  int i;
  for (i = 0; i < CARBOT_MAX_ROBOTS; ++i) {
    robots[i].item = -1;
    robots[i].goal = GOAL_NONE;
    robots[i].handle_since = -1;
    robots[i].placed = false;
    robots[i].best_distance = INFINITY;
    robots[i].best_since = 0;
  }
}

/* The memory of the robot a call is for. */
static struct CleanBot* me(struct CarbotRobot* robot) { return &robots[carbot_robot_of(robot)]; }

static double dist(double ax, double ay, double bx, double by) { return hypot(ax - bx, ay - by); }

static bool at_destination(CarbotItem it) {
  return !it.held && dist(it.x, it.y, it.dest_x, it.dest_y) < CLEANBOT_AT_DESTINATION;
}

/* The chosen item, choosing the first one not at its destination if none is chosen. */
static int current_item(struct CarbotRobot* robot) {
  if (me(robot)->item >= 0) return me(robot)->item;
  for (int i = 0; i < carbot_item_count(robot); ++i) {
    if (!at_destination(carbot_item(robot, i))) return me(robot)->item = i;
  }
  return -1;
}

/* Where the active goal is; false if there is none. */
static bool goal_point(struct CarbotRobot* robot, double* x, double* y) {
  const int i = current_item(robot);
  if (i < 0 || me(robot)->goal == GOAL_NONE) return false;
  const CarbotItem it = carbot_item(robot, i);
  *x = me(robot)->goal == GOAL_ITEM ? it.x : it.dest_x;
  *y = me(robot)->goal == GOAL_ITEM ? it.y : it.dest_y;
  return true;
}

static double gripper_distance_to(struct CarbotRobot* robot, double x, double y) {
  double gx, gy;
  carbot_gripper_point(robot, &gx, &gy);
  return dist(gx, gy, x, y);
}

/* Sets the goal; a new goal restarts the progress watch. */
static void aim_at(struct CarbotRobot* robot, enum Goal g) {
  if (g == me(robot)->goal) return;
  me(robot)->goal = g;
  me(robot)->best_distance = INFINITY;
  me(robot)->best_since = carbot_time(robot);
}

static void watch_progress(struct CarbotRobot* robot, double d) {
  if (d < me(robot)->best_distance - CLEANBOT_PROGRESS) {
    me(robot)->best_distance = d;
    me(robot)->best_since = carbot_time(robot);
  }
}

/* Drives so that the gripper point comes to (x, y): turn towards it (on the spot when far
 * off), then run at a speed that falls with the remaining distance. A goal beside or behind
 * the gripper's reach (closer to the centre than the gripper) is backed away from first. */
static void go_to(struct CarbotRobot* robot, double x, double y) {
  const CarbotPose p = carbot_pose(robot);
  double gx, gy;
  carbot_gripper_point(robot, &gx, &gy);
  const double reach = dist(p.x, p.y, gx, gy);
  const double centre_distance = dist(p.x, p.y, x, y);
  double error = atan2(y - p.y, x - p.x) - p.heading;
  error = atan2(sin(error), cos(error));
  watch_progress(robot, dist(gx, gy, x, y));

  if (centre_distance < reach * 0.9) { /* too close to turn onto it: back off */
    carbot_drive(robot, -0.10, 0);
    return;
  }
  double turn = CLEANBOT_TURN_GAIN * error;
  if (turn > CLEANBOT_MAX_TURN) turn = CLEANBOT_MAX_TURN;
  if (turn < -CLEANBOT_MAX_TURN) turn = -CLEANBOT_MAX_TURN;
  if (fabs(error) > CLEANBOT_TURN_IN_PLACE) {
    carbot_drive(robot, 0, turn);
    return;
  }
  const double remaining = centre_distance - reach;
  double speed = 0.8 * remaining;
  if (speed > CLEANBOT_CRUISE) speed = CLEANBOT_CRUISE;
  if (speed < CLEANBOT_SLOW) speed = CLEANBOT_SLOW;
  if (remaining < CLEANBOT_ARRIVED / 2) speed = 0;
  carbot_drive(robot, speed * cos(error), turn);
}

/* Closing or opening the gripper takes a moment with the robot standing still; true once done. */
static bool handled(struct CarbotRobot* robot) {
  carbot_drive(robot, 0, 0);
  if (me(robot)->handle_since < 0) me(robot)->handle_since = carbot_time(robot);
  if (carbot_time(robot) - me(robot)->handle_since < CLEANBOT_HANDLE_TIME) return false;
  me(robot)->handle_since = -1;
  return true;
}

/* --- actions ------------------------------------------------------------------------------ */

void CleanBot_DriveToItem(struct CarbotRobot* robot) {
  double x, y;
  aim_at(robot, GOAL_ITEM);
  if (!goal_point(robot, &x, &y)) {
    carbot_drive(robot, 0, 0);
    return;
  }
  if (CleanBot_Arrived(robot)) carbot_drive(robot, 0, 0);
  else go_to(robot, x, y);
}

void CleanBot_PickUp(struct CarbotRobot* robot) {
  double x, y;
  aim_at(robot, GOAL_ITEM);
  if (CleanBot_Holding(robot) || !goal_point(robot, &x, &y)) {
    carbot_drive(robot, 0, 0);
    return;
  }
  if (!CleanBot_Arrived(robot)) { /* the item is not (or no longer) in reach: fetch it first */
    me(robot)->handle_since = -1;
    go_to(robot, x, y);
    return;
  }
  if (handled(robot) && carbot_grip(robot, me(robot)->item)) me(robot)->placed = false;
}

void CleanBot_Transport(struct CarbotRobot* robot) {
  double x, y;
  aim_at(robot, GOAL_DESTINATION);
  if (!CleanBot_Holding(robot) || !goal_point(robot, &x, &y) || CleanBot_Arrived(robot)) {
    carbot_drive(robot, 0, 0);
    return;
  }
  go_to(robot, x, y);
}

void CleanBot_PlaceItem(struct CarbotRobot* robot) {
  aim_at(robot, GOAL_DESTINATION);
  if (!CleanBot_Holding(robot)) {
    carbot_drive(robot, 0, 0);
    return;
  }
  if (handled(robot)) {
    carbot_release(robot);
    me(robot)->placed = true;
  }
}

/* --- conditions --------------------------------------------------------------------------- */

bool CleanBot_Arrived(struct CarbotRobot* robot) {
  double x, y;
  return goal_point(robot, &x, &y) && gripper_distance_to(robot, x, y) < CLEANBOT_ARRIVED;
}

bool CleanBot_Holding(struct CarbotRobot* robot) {
  return current_item(robot) >= 0 && carbot_held_item(robot) == me(robot)->item;
}

bool CleanBot_FarFromDestination(struct CarbotRobot* robot) {
  const int i = current_item(robot);
  if (i < 0) return false;
  const CarbotItem it = carbot_item(robot, i);
  return dist(it.x, it.y, it.dest_x, it.dest_y) > CLEANBOT_FAR;
}

bool CleanBot_ItemPlaced(struct CarbotRobot* robot) { return me(robot)->placed && !CleanBot_Holding(robot); }

bool CleanBot_ItemAtDestination(struct CarbotRobot* robot) {
  const int i = current_item(robot);
  return i >= 0 && at_destination(carbot_item(robot, i));
}

/* No item to clean up, or no progress towards the goal for a while (pushing against a wall). */
bool CleanBot_Stuck(struct CarbotRobot* robot) {
  if (current_item(robot) < 0) return true;
  return me(robot)->goal != GOAL_NONE && carbot_time(robot) - me(robot)->best_since > CLEANBOT_STUCK_TIME;
}
