// The Carbot's supervisors and its one computation.
#include "carbot_toolbox.h"

namespace carbot::toolbox {

using namespace std::chrono_literals;

CheckTouch::CheckTouch(Environment& ee) : ee_(ee) {}
afp::CheckResult CheckTouch::check(afp::Context&) { return ee_.bumper() ? afp::CheckResult(TOUCHED) : afp::no_event; }

CheckLane::CheckLane(Environment& ee, afp::In<float> dist) : afp::Supervisor(10ms), ee_(ee), dist_(std::move(dist)) {}

void CheckLane::start(afp::Context& ctx) {
  limit_ = dist_.read(ctx) / 100.0;
  ee_.aim_sonar(0);  // look where the robot goes
}

afp::CheckResult CheckLane::check(afp::Context&) {
  if (!ee_.sonar_at(0)) return afp::no_event;
  return ee_.sonar_range() < limit_ ? afp::CheckResult(LANE_NOT_FREE) : afp::no_event;
}

CheckEscape::CheckEscape(Environment& ee) : ee_(ee) {}
afp::CheckResult CheckEscape::check(afp::Context&) { return ee_.escape() ? afp::CheckResult(ESCAPE) : afp::no_event; }

CountDown::CountDown(Environment&, afp::In<int> n, afp::Out<int> rest) : n_(std::move(n)), rest_(std::move(rest)) {}

int CountDown::compute(afp::Context& ctx) {
  const int rest = n_.read(ctx) - 1;
  rest_.write(ctx, rest);
  return rest > 0 ? AGAIN : DONE;
}

}  // namespace carbot::toolbox
