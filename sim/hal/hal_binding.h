// Which simulation the C HAL (carbot_hal.h) acts on. carbot-sim, the benchmark and the tests
// bind one before calling an engine or a toolbox, and unbind it after.
#pragma once

namespace carbot {
class Simulation;
}

namespace carbot::hal {

/// Makes the HAL act on `sim` (nullptr unbinds).
void bind(Simulation* sim);

/// The bound simulation; aborts with a message if there is none.
Simulation& bound();

}  // namespace carbot::hal
