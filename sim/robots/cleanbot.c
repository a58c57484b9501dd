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

/* One robot's memory; each robot in the world has its own: carbot_robot(), the robot of the
 * handle the interface call passed (carbot_act_on), picks it. */
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

/* Below, the fields of the robot whose engine is running go by their plain names, so the
 * behaviours read as they would in one robot's firmware. */
#define item robots[carbot_robot()].item
#define goal robots[carbot_robot()].goal
#define handle_since robots[carbot_robot()].handle_since
#define placed robots[carbot_robot()].placed
#define best_distance robots[carbot_robot()].best_distance
#define best_since robots[carbot_robot()].best_since

static double dist(double ax, double ay, double bx, double by) { return hypot(ax - bx, ay - by); }

static bool at_destination(CarbotItem it) {
  return !it.held && dist(it.x, it.y, it.dest_x, it.dest_y) < CLEANBOT_AT_DESTINATION;
}

/* The chosen item, choosing the first one not at its destination if none is chosen. */
static int current_item(void) {
  if (item >= 0) return item;
  for (int i = 0; i < carbot_item_count(); ++i) {
    if (!at_destination(carbot_item(i))) return item = i;
  }
  return -1;
}

/* Where the active goal is; false if there is none. */
static bool goal_point(double* x, double* y) {
  const int i = current_item();
  if (i < 0 || goal == GOAL_NONE) return false;
  const CarbotItem it = carbot_item(i);
  *x = goal == GOAL_ITEM ? it.x : it.dest_x;
  *y = goal == GOAL_ITEM ? it.y : it.dest_y;
  return true;
}

static double gripper_distance_to(double x, double y) {
  double gx, gy;
  carbot_gripper_point(&gx, &gy);
  return dist(gx, gy, x, y);
}

/* Sets the goal; a new goal restarts the progress watch. */
static void aim_at(enum Goal g) {
  if (g == goal) return;
  goal = g;
  best_distance = INFINITY;
  best_since = carbot_time();
}

static void watch_progress(double d) {
  if (d < best_distance - CLEANBOT_PROGRESS) {
    best_distance = d;
    best_since = carbot_time();
  }
}

/* Drives so that the gripper point comes to (x, y): turn towards it (on the spot when far
 * off), then run at a speed that falls with the remaining distance. A goal beside or behind
 * the gripper's reach (closer to the centre than the gripper) is backed away from first. */
static void go_to(double x, double y) {
  const CarbotPose p = carbot_pose();
  double gx, gy;
  carbot_gripper_point(&gx, &gy);
  const double reach = dist(p.x, p.y, gx, gy);
  const double centre_distance = dist(p.x, p.y, x, y);
  double error = atan2(y - p.y, x - p.x) - p.heading;
  error = atan2(sin(error), cos(error));
  watch_progress(dist(gx, gy, x, y));

  if (centre_distance < reach * 0.9) { /* too close to turn onto it: back off */
    carbot_drive(-0.10, 0);
    return;
  }
  double turn = CLEANBOT_TURN_GAIN * error;
  if (turn > CLEANBOT_MAX_TURN) turn = CLEANBOT_MAX_TURN;
  if (turn < -CLEANBOT_MAX_TURN) turn = -CLEANBOT_MAX_TURN;
  if (fabs(error) > CLEANBOT_TURN_IN_PLACE) {
    carbot_drive(0, turn);
    return;
  }
  const double remaining = centre_distance - reach;
  double speed = 0.8 * remaining;
  if (speed > CLEANBOT_CRUISE) speed = CLEANBOT_CRUISE;
  if (speed < CLEANBOT_SLOW) speed = CLEANBOT_SLOW;
  if (remaining < CLEANBOT_ARRIVED / 2) speed = 0;
  carbot_drive(speed * cos(error), turn);
}

/* Closing or opening the gripper takes a moment with the robot standing still; true once done. */
static bool handled(void) {
  carbot_drive(0, 0);
  if (handle_since < 0) handle_since = carbot_time();
  if (carbot_time() - handle_since < CLEANBOT_HANDLE_TIME) return false;
  handle_since = -1;
  return true;
}

/* --- actions ------------------------------------------------------------------------------ */

void DriveToItem(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);

  double x, y;
  aim_at(GOAL_ITEM);
  if (!goal_point(&x, &y)) {
    carbot_drive(0, 0);
    return;
  }
  if (Arrived(ctx)) carbot_drive(0, 0);
  else go_to(x, y);
}

void PickUp(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);

  double x, y;
  aim_at(GOAL_ITEM);
  if (Holding(ctx) || !goal_point(&x, &y)) {
    carbot_drive(0, 0);
    return;
  }
  if (!Arrived(ctx)) { /* the item is not (or no longer) in reach: fetch it first */
    handle_since = -1;
    go_to(x, y);
    return;
  }
  if (handled() && carbot_grip(item)) placed = false;
}

void Transport(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);

  double x, y;
  aim_at(GOAL_DESTINATION);
  if (!Holding(ctx) || !goal_point(&x, &y) || Arrived(ctx)) {
    carbot_drive(0, 0);
    return;
  }
  go_to(x, y);
}

void PlaceItem(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);

  aim_at(GOAL_DESTINATION);
  if (!Holding(ctx)) {
    carbot_drive(0, 0);
    return;
  }
  if (handled()) {
    carbot_release();
    placed = true;
  }
}

/* --- conditions --------------------------------------------------------------------------- */

bool Arrived(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);

  double x, y;
  return goal_point(&x, &y) && gripper_distance_to(x, y) < CLEANBOT_ARRIVED;
}

bool Holding(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);
  return current_item() >= 0 && carbot_held_item() == item;
}

bool FarFromDestination(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);

  const int i = current_item();
  if (i < 0) return false;
  const CarbotItem it = carbot_item(i);
  return dist(it.x, it.y, it.dest_x, it.dest_y) > CLEANBOT_FAR;
}

bool ItemPlaced(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);
  return placed && !Holding(ctx);
}

bool ItemAtDestination(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);

  const int i = current_item();
  return i >= 0 && at_destination(carbot_item(i));
}

/* No item to clean up, or no progress towards the goal for a while (pushing against a wall). */
bool Stuck(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);

  if (current_item() < 0) return true;
  return goal != GOAL_NONE && carbot_time() - best_since > CLEANBOT_STUCK_TIME;
}
