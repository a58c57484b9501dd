// Which simulation, and which of its robots, the C HAL (carbot_hal.h) acts on. carbot-sim, the
// benchmark and the tests bind one before calling an engine or a toolbox, and unbind it after.
//
// Several robots in one world: a C engine's interface calls carry their robot (the engine's
// instance context, a CarbotRobot handle) and the robot library switches the HAL to it with
// carbot_act_on(), which re-binds the bound simulation's robot. A plan has no context: before
// its engine runs, carbot-sim binds the plan's robot (docs/sim.md "Several robots").
#pragma once

namespace carbot {
class Simulation;
}

namespace carbot::hal {

/// Makes the HAL act on robot `robot` of `sim` (nullptr unbinds).
void bind(Simulation* sim, int robot = 0);

/// The robot the HAL is bound to.
int bound_robot();

/// The bound simulation, its bound robot selected; aborts with a message if there is none.
Simulation& bound();

}  // namespace carbot::hal
