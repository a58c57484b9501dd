#include "driver/run.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/geometry.h"
#include "hal/hal_binding.h"
#include "driver/engine_log.h"
#include "robots/robots.h"

namespace carbot::driver {
namespace {

using Clock = std::chrono::steady_clock;

/// A one-line progress display, redrawn a few times a second, only on a terminal.
class Progress {
 public:
  Progress(bool enabled, double limit) : enabled_(enabled && isatty(STDERR_FILENO)), limit_(limit) {}
  ~Progress() {
    if (shown_) std::fprintf(stderr, "\r\033[K");
  }
  void update(double sim_t) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (now - last_ < std::chrono::milliseconds(200)) return;
    last_ = now;
    const double wall = std::chrono::duration<double>(now - start_).count();
    std::fprintf(stderr, "\r\033[Kcarbot-sim: %6.1f / %.1f s simulated (%.0fx real time)", sim_t, limit_,
                 wall > 0 ? sim_t / wall : 0.0);
    shown_ = true;
  }

 private:
  bool enabled_;
  double limit_;
  bool shown_ = false;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_ = Clock::now();
};

TraceRow row(const Simulation& sim) {
  const Pose p = sim.pose();
  return {sim.time(), p.x, p.y, deg(p.heading)};
}

/// An fsm's state changes go to the engine log as "state Z1 PickUp()", as a plan's actor
/// changes do, for result.json and the picture.
void log_state_change(const Engine& engine, const ChartInfo& chart, double t, int& last) {
  const int now = engine.current_state();
  if (now < 0 || now == last) return;
  last = now;
  const std::string label = now < static_cast<int>(chart.states.size()) ? chart.states[now] : std::to_string(now);
  engine_log().push_back({t, "state " + label});
}

}  // namespace

RunResult run_engine(Simulation& sim, Engine& engine, const ChartInfo& chart, double seconds, bool quiet) {
  RunResult result;
  const auto start = Clock::now();
  hal::bind(&sim);
  linebot_reset();
  cleanbot_reset();
  engine_log().clear();
  engine.init();
  Progress progress(!quiet, seconds);
  const long ticks = std::lround(seconds / sim.config().control_period);
  int last_state = -1;
  for (long tick = 0;; ++tick) {
    result.trace.push_back(row(sim));
    // The escape button is the robot's stop button: an sfc or fsm engine does not read it,
    // so the host stops the engine (a plan reads it through CheckEscape instead).
    if (chart.kind != "plan" && sim.escape()) {
      result.status = "terminated";
      break;
    }
    if (tick >= ticks) break;
    engine.run();
    log_state_change(engine, chart, sim.time(), last_state);
    if (const int status = engine.status(); status != 0) {
      result.status = status == 2 ? "terminated" : status > 0 ? "succeeded" : "failed";
      break;
    }
    sim.step_control();
    progress.update(sim.time());
  }
  engine.finish();
  sim.stop();
  hal::bind(nullptr);
  result.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace carbot::driver
