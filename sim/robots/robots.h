/* The robot libraries carbot-sim links and exports to generated engines, plus their reset
 * hooks. The interface functions themselves are declared by each generated engine.h
 * (from samples/linebot.iface, samples/cleanbot.iface and samples/fetchbot.iface); they are repeated here so the
 * libraries are compiled against the exact C prototypes an engine expects. carbot-sim builds
 * engines with the instance context `struct CarbotRobot *` (sim/hal/carbot_hal.h), so each
 * function's first argument is the robot the call is for. */
#ifndef CARBOT_ROBOTS_H
#define CARBOT_ROBOTS_H

#include <stdbool.h>

struct CarbotRobot;

#ifdef __cplusplus
extern "C" {
#endif

/* samples/linebot.iface */
bool Left_IR_Black(struct CarbotRobot* ctx);
bool Left_IR_White(struct CarbotRobot* ctx);
bool Right_IR_Black(struct CarbotRobot* ctx);
bool Right_IR_White(struct CarbotRobot* ctx);
void Left_FW(struct CarbotRobot* ctx);
void Left_Stop(struct CarbotRobot* ctx);
void Right_FW(struct CarbotRobot* ctx);
void Right_Stop(struct CarbotRobot* ctx);

/* samples/cleanbot.iface */
void DriveToItem(struct CarbotRobot* ctx);
void PickUp(struct CarbotRobot* ctx);
void Transport(struct CarbotRobot* ctx);
void PlaceItem(struct CarbotRobot* ctx);
bool Arrived(struct CarbotRobot* ctx);
bool Holding(struct CarbotRobot* ctx);
bool FarFromDestination(struct CarbotRobot* ctx);
bool ItemPlaced(struct CarbotRobot* ctx);
bool ItemAtDestination(struct CarbotRobot* ctx);
bool Stuck(struct CarbotRobot* ctx);

/* samples/fetchbot.iface, prefixed: its names clash with CleanBot's, so a FetchBot engine is
 * compiled with its calls renamed to these (sim/driver/chart_build.cc) */
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
