// Which simulation, and which of its robots, the C HAL (carbot_hal.h) acts on. carbot-sim, the
// benchmark and the tests bind one before calling an engine or a toolbox, and unbind it after.
//
// Several robots in one world: carbot-sim is single-threaded, so before it ticks robot i's
// engine it binds robot i, and every interface call that engine makes (and every HAL call of
// the robot library under it) acts on robot i. This is the simulator's stand-in for an
// instance context: on firmware each robot runs its own engine on its own board, so the
// board's HAL is "bound" by construction (docs/sim.md, "Several robots").
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
