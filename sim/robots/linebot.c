/* LineBot (samples/linebot.iface) on the Carbot.
 *
 * The GFE line follower thinks of a differential-drive robot: a left and a right side, each
 * running forward or stopped. The Carbot has two steerable wheels instead, so this library
 * keeps a virtual differential drive: each call sets one side's speed, and the pair becomes a
 * chassis command (forward = mean of the sides, turn rate = difference / virtual track),
 * which the Carbot's inverse kinematics turns into wheel angles and speeds.
 *
 * Tuning (docs/sim.md, "LineBot"): the IR sensors sit 7 cm apart astride a 5 cm line. A
 * "stopped" side really stops; the turn that results is bounded by the virtual track and the
 * forward speed, both chosen gentle enough that the steering servo keeps up (a sharper turn
 * overshoots the line and oscillates against the steering lag).
 */
#include "robots/robots.h"

#include "hal/carbot_hal.h"

/* A side's speed when running, m/s. */
#define LINEBOT_SIDE_SPEED 0.20
/* A side's speed when "stopped", m/s. */
#define LINEBOT_STOP_SPEED 0.0
/* Virtual track width, m: turn rate = (right - left) / track. */
#define LINEBOT_TRACK 0.30

/* Each robot's side speeds (several line followers may share a world). */
static double left_speeds[CARBOT_MAX_ROBOTS];
static double right_speeds[CARBOT_MAX_ROBOTS];

void linebot_reset(void) {
  int i;
  for (i = 0; i < CARBOT_MAX_ROBOTS; ++i) {
    left_speeds[i] = 0;
    right_speeds[i] = 0;
  }
}

/* Sets one side of `robot` running at `speed`, and drives the chassis as the two sides ask. */
static void set_side(struct CarbotRobot* robot, double* side_speeds, double speed) {
  const int i = carbot_robot_of(robot);
  side_speeds[i] = speed;
  carbot_drive(robot, (left_speeds[i] + right_speeds[i]) / 2, (right_speeds[i] - left_speeds[i]) / LINEBOT_TRACK);
}

bool LineBot_Left_IR_Black(struct CarbotRobot* robot) { return carbot_ir_black(robot, CARBOT_LEFT); }
bool LineBot_Left_IR_White(struct CarbotRobot* robot) { return !carbot_ir_black(robot, CARBOT_LEFT); }
bool LineBot_Right_IR_Black(struct CarbotRobot* robot) { return carbot_ir_black(robot, CARBOT_RIGHT); }
bool LineBot_Right_IR_White(struct CarbotRobot* robot) { return !carbot_ir_black(robot, CARBOT_RIGHT); }

void LineBot_Left_FW(struct CarbotRobot* robot) { set_side(robot, left_speeds, LINEBOT_SIDE_SPEED); }

void LineBot_Left_Stop(struct CarbotRobot* robot) { set_side(robot, left_speeds, LINEBOT_STOP_SPEED); }

void LineBot_Right_FW(struct CarbotRobot* robot) { set_side(robot, right_speeds, LINEBOT_SIDE_SPEED); }

void LineBot_Right_Stop(struct CarbotRobot* robot) { set_side(robot, right_speeds, LINEBOT_STOP_SPEED); }
