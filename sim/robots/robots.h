/* The robot libraries carbot-sim links and exports to generated engines, plus their reset
 * hooks. Each implements an interface (samples/linebot.iface, cleanbot.iface, fetchbot.iface),
 * and each of its functions carries the interface's name (CleanBot_PickUp implements CleanBot's
 * PickUp): carbot-sim links every library into one program, and two interfaces may share a
 * function's name (CleanBot and FetchBot both have PickUp). carbot-sim compiles each engine
 * with a header renaming its calls to these names (sim/driver/chart_build.cc, robot_names).
 * carbot-sim builds engines with the instance context `struct CarbotRobot *`
 * (sim/hal/carbot_hal.h), so each function's first argument is the robot the call is for. */
#ifndef CARBOT_ROBOTS_H
#define CARBOT_ROBOTS_H

#include <stdbool.h>

struct CarbotRobot;

#ifdef __cplusplus
extern "C" {
#endif

/* samples/linebot.iface */
bool LineBot_Left_IR_Black(struct CarbotRobot* ctx);
bool LineBot_Left_IR_White(struct CarbotRobot* ctx);
bool LineBot_Right_IR_Black(struct CarbotRobot* ctx);
bool LineBot_Right_IR_White(struct CarbotRobot* ctx);
void LineBot_Left_FW(struct CarbotRobot* ctx);
void LineBot_Left_Stop(struct CarbotRobot* ctx);
void LineBot_Right_FW(struct CarbotRobot* ctx);
void LineBot_Right_Stop(struct CarbotRobot* ctx);

/* samples/cleanbot.iface */
void CleanBot_DriveToItem(struct CarbotRobot* ctx);
void CleanBot_PickUp(struct CarbotRobot* ctx);
void CleanBot_Transport(struct CarbotRobot* ctx);
void CleanBot_PlaceItem(struct CarbotRobot* ctx);
bool CleanBot_Arrived(struct CarbotRobot* ctx);
bool CleanBot_Holding(struct CarbotRobot* ctx);
bool CleanBot_FarFromDestination(struct CarbotRobot* ctx);
bool CleanBot_ItemPlaced(struct CarbotRobot* ctx);
bool CleanBot_ItemAtDestination(struct CarbotRobot* ctx);
bool CleanBot_Stuck(struct CarbotRobot* ctx);

/* samples/fetchbot.iface */
void FetchBot_DriveToItem(struct CarbotRobot* ctx);
void FetchBot_PickUp(struct CarbotRobot* ctx);
void FetchBot_Carry(struct CarbotRobot* ctx);
void FetchBot_Park(struct CarbotRobot* ctx);
void FetchBot_Beep(struct CarbotRobot* ctx, int times);
void FetchBot_Lights(struct CarbotRobot* ctx, bool on);
bool FetchBot_Arrived(struct CarbotRobot* ctx);
bool FetchBot_Holding(struct CarbotRobot* ctx);
bool FetchBot_Parked(struct CarbotRobot* ctx);
bool FetchBot_Delivered(struct CarbotRobot* ctx);

/* Forget all state of a library (every robot's); carbot-sim calls these before a run. */
void linebot_reset(void);
void cleanbot_reset(void);
void fetchbot_reset(void);

#ifdef __cplusplus
}
#endif

#endif /* CARBOT_ROBOTS_H */
