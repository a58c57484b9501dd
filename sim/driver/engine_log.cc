#include "driver/engine_log.h"

namespace carbot::driver {

std::vector<EngineEvent>& engine_log() {
  static std::vector<EngineEvent> log;
  return log;
}

std::vector<std::string>& call_log() {
  static std::vector<std::string> log;
  return log;
}

}  // namespace carbot::driver

extern "C" void carbot_sim_call(const char* text) { carbot::driver::call_log().push_back(text ? text : ""); }

extern "C" void carbot_sim_plan_event(double t, const char* text) {
  carbot::driver::engine_log().push_back({t, text ? text : ""});
}
