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

/// Follows a plan's actor starts and interruptions (its shim's events) to tell which actor of
/// the top-level plan runs and which supervisor fired. Actors of sub-plans are not rows yet.
class PlanFollower {
 public:
  explicit PlanFollower(const ChartInfo& chart) : chart_(chart) {}
  void take(const std::string& text, long frame, Recording& rec) {
    static const std::string kStart = "start ", kInterrupted = " interrupted by ";
    if (text.compare(0, kStart.size(), kStart) == 0) {
      current_ = row_of(text.substr(kStart.size()));
      return;
    }
    const std::size_t at = text.find(kInterrupted);
    if (at == std::string::npos) return;
    const std::string actor = actor_of(text.substr(0, at));
    const std::string supervisor = text.substr(at + kInterrupted.size());
    auto node = chart_.supervisor_nodes.find(actor + "/" + supervisor);
    if (node == chart_.supervisor_nodes.end()) node = chart_.supervisor_nodes.find(supervisor);
    rec.fired.push_back(
        {frame, node == chart_.supervisor_nodes.end() ? std::string() : node->second, supervisor + " (" + actor + ")"});
    current_ = -1;
  }
  int current() const { return current_; }

 private:
  /// "WallFollow.followWall" -> "followWall" when it is an actor of the chart itself.
  std::string actor_of(const std::string& qualified) const {
    const std::string prefix = chart_.name + ".";
    return qualified.compare(0, prefix.size(), prefix) == 0 ? qualified.substr(prefix.size()) : qualified;
  }
  int row_of(const std::string& qualified) const {
    const std::string actor = actor_of(qualified);
    for (std::size_t i = 0; i < chart_.rows.size(); ++i)
      if (chart_.rows[i].name == actor) return static_cast<int>(i);
    return -1;
  }
  const ChartInfo& chart_;
  int current_ = -1;
};

/// Takes what the engine's tick did into the recording: activation, calls, log entries.
/// Log entries made before the first tick (a plan's start) count for frame 0.
void record_tick(const Engine& engine, const ChartInfo& chart, long frame, PlanFollower& plan, Recording& rec) {
  std::vector<int> active;
  if (chart.kind == "plan") {
    for (std::size_t i = rec.log_frames.size(); i < engine_log().size(); ++i)
      plan.take(engine_log()[i].text, frame, rec);
    if (plan.current() >= 0) active.push_back(plan.current());
  } else {
    for (int p = 0; p < engine.places(); ++p)
      if (engine.activation(p) > 0) active.push_back(p);
  }
  // Sub-chart instances: depth first, so the place that runs one is decided before its rows.
  std::vector<int> nested;
  if (engine.has_instances()) {
    std::vector<bool> on(chart.rows.size(), false);
    for (int a : active) on[static_cast<std::size_t>(a)] = true;
    for (std::size_t i = 0; i < chart.instances.size(); ++i) {
      const ChartInfo::Instance& in = chart.instances[i];
      if (!on[in.parent_row]) continue;  // not running: its state is as its last tick left it
      for (std::size_t q = 0; q < in.count; ++q)
        if (engine.instance_activation(static_cast<int>(i), static_cast<int>(q)) > 0) {
          on[in.first + q] = true;
          nested.push_back(static_cast<int>(in.first + q));
        }
    }
  }
  rec.instances_active.push_back(std::move(nested));
  rec.active.push_back(std::move(active));
  rec.calls.push_back(std::move(call_log()));
  call_log().clear();
  while (rec.log_frames.size() < engine_log().size()) rec.log_frames.push_back(frame);
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
  Recording& rec = result.recording;
  PlanFollower plan(chart);
  call_log().clear();
  for (long tick = 0;; ++tick) {
    result.trace.push_back(row(sim));
    rec.items.push_back(sim.items());
    // A frame without an engine call (the last) keeps the activation it had.
    auto keep_activation = [&] {
      rec.active.push_back(rec.active.empty() ? std::vector<int>() : rec.active.back());
      rec.instances_active.push_back(rec.instances_active.empty() ? std::vector<int>()
                                                                  : rec.instances_active.back());
      rec.calls.emplace_back();
    };
    // The escape button is the robot's stop button: an sfc or fsm engine does not read it,
    // so the host stops the engine (a plan reads it through CheckEscape instead).
    if (chart.kind != "plan" && sim.escape()) {
      result.status = "terminated";
      keep_activation();
      break;
    }
    if (tick >= ticks) {
      keep_activation();
      break;
    }
    engine.run();
    log_state_change(engine, chart, sim.time(), last_state);
    record_tick(engine, chart, tick, plan, rec);
    if (const int status = engine.status(); status != 0) {
      result.status = status == 2 ? "terminated" : status > 0 ? "succeeded" : "failed";
      break;
    }
    sim.step_control();
    progress.update(sim.time());
  }
  engine.finish();
  // What stopping the engine logged belongs to the last frame.
  while (rec.log_frames.size() < engine_log().size())
    rec.log_frames.push_back(static_cast<long>(result.trace.size()) - 1);
  sim.stop();
  hal::bind(nullptr);
  result.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace carbot::driver
