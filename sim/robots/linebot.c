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
#define left_speed left_speeds[carbot_robot()]
#define right_speed right_speeds[carbot_robot()]

void linebot_reset(void) {
  int i;
  for (i = 0; i < CARBOT_MAX_ROBOTS; ++i) {
    left_speeds[i] = 0;
    right_speeds[i] = 0;
  }
}

static void apply(void) { carbot_drive((left_speed + right_speed) / 2, (right_speed - left_speed) / LINEBOT_TRACK); }

bool Left_IR_Black(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);
  return carbot_ir_black(CARBOT_LEFT);
}
bool Left_IR_White(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);
  return !carbot_ir_black(CARBOT_LEFT);
}
bool Right_IR_Black(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);
  return carbot_ir_black(CARBOT_RIGHT);
}
bool Right_IR_White(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);
  return !carbot_ir_black(CARBOT_RIGHT);
}

void Left_FW(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);

  left_speed = LINEBOT_SIDE_SPEED;
  apply();
}

void Left_Stop(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);

  left_speed = LINEBOT_STOP_SPEED;
  apply();
}

void Right_FW(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);

  right_speed = LINEBOT_SIDE_SPEED;
  apply();
}

void Right_Stop(struct CarbotRobot* ctx) {
  carbot_act_on(ctx);

  right_speed = LINEBOT_STOP_SPEED;
  apply();
}
