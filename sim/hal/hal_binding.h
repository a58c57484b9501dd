// Which simulation the C HAL (carbot_hal.h) acts on. carbot-sim, the benchmark and the tests
// bind one before calling an engine or a toolbox, and unbind it after. Which of its robots a call
// is for, the call itself says: its first argument is the robot's handle (a C engine's instance
// context, a plan's toolbox environment; docs/sim.md "Several robots").
#pragma once

namespace carbot {
class Simulation;
}

namespace carbot::hal {

/// Makes the HAL act on `sim` (nullptr unbinds).
void bind(Simulation* sim);

}  // namespace carbot::hal
