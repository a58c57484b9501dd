#include "driver/plan_log.h"

namespace carbot::driver {

std::vector<PlanEvent>& plan_log() {
  static std::vector<PlanEvent> log;
  return log;
}

}  // namespace carbot::driver

extern "C" void carbot_sim_plan_event(double t, const char* text) {
  carbot::driver::plan_log().push_back({t, text ? text : ""});
}
