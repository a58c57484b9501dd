// The fixed entry points of a loadable engine (written by the shim, found by dlsym).
#pragma once

namespace carbot::driver {

/// The instance context type carbot-sim builds C engines with (gfec --context-type): a robot's
/// handle (sim/hal/carbot_hal.h), every interface call's first argument. It ends in `*`, so a
/// parameter's name can follow it directly.
constexpr const char* kContextType = "struct CarbotRobot *";

constexpr const char* kEngineSize = "carbot_engine_size";  ///< size_t (void): bytes of engine state
constexpr const char* kEngineInit = "carbot_engine_init";  ///< void (void*)
constexpr const char* kEngineRun = "carbot_engine_run";    ///< void (void*): one tick
constexpr const char* kEngineStatus =
    "carbot_engine_status";  ///< int (const void*): 0 running, 1 ok, -1 failed, 2 terminated
constexpr const char* kEngineState = "carbot_engine_state";    ///< int (const void*), optional (fsm): the state index
constexpr const char* kEnginePlaces = "carbot_engine_places";  ///< int (void), optional: places (states) of a C engine
constexpr const char* kEngineActivation =
    "carbot_engine_activation";  ///< unsigned (const void*, int), optional: X_activation
constexpr const char* kEngineSetAgent =
    "carbot_engine_set_agent";  ///< void (void*, int), a team machine only: X_set_agent
constexpr const char* kEngineReport =
    "carbot_engine_report";  ///< void (void*, int agent, int state), a team machine only: X_report
constexpr const char* kEngineInstanceActivation =
    "carbot_engine_instance_activation";  ///< unsigned (const void*, int, int), optional: a sub-chart instance's place
constexpr const char* kEngineSetContext =
    "carbot_engine_set_context";  ///< void (void*, struct CarbotRobot*): the robot (X_set_context, a plan's Env)
constexpr const char* kEngineFini = "carbot_engine_fini";  ///< void (void*), optional: destroys the state

}  // namespace carbot::driver
