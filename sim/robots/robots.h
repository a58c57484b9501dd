/* The robot libraries carbot-sim links and exports to generated engines, plus their reset
 * hooks. The interface functions themselves are declared by each generated engine.h
 * (from samples/linebot.iface, samples/cleanbot.iface and samples/fetchbot.iface); they are repeated here so the
 * libraries are compiled against the exact C prototypes an engine expects. */
#ifndef CARBOT_ROBOTS_H
#define CARBOT_ROBOTS_H

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

/* samples/linebot.iface */
bool Left_IR_Black(void);
bool Left_IR_White(void);
bool Right_IR_Black(void);
bool Right_IR_White(void);
void Left_FW(void);
void Left_Stop(void);
void Right_FW(void);
void Right_Stop(void);

/* samples/cleanbot.iface */
void DriveToItem(void);
void PickUp(void);
void Transport(void);
void PlaceItem(void);
bool Arrived(void);
bool Holding(void);
bool FarFromDestination(void);
bool ItemPlaced(void);
bool ItemAtDestination(void);
bool Stuck(void);

/* samples/fetchbot.iface, prefixed: its names clash with CleanBot's, so a FetchBot engine is
 * compiled with its calls renamed to these (sim/driver/chart_build.cc) */
void FetchBot_DriveToItem(void);
void FetchBot_PickUp(void);
void FetchBot_Carry(void);
void FetchBot_Park(void);
void FetchBot_Beep(int times);
void FetchBot_Lights(bool on);
bool FetchBot_Arrived(void);
bool FetchBot_Holding(void);
bool FetchBot_Parked(void);
bool FetchBot_Delivered(void);

/* Forget all state of a library (every robot's); carbot-sim calls these before a run. */
void linebot_reset(void);
void cleanbot_reset(void);
void fetchbot_reset(void);

#ifdef __cplusplus
}
#endif

#endif /* CARBOT_ROBOTS_H */
