#include "driver/run.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/geometry.h"
#include "hal/carbot_hal.h"
#include "hal/hal_binding.h"
#include "driver/engine_log.h"
#include "driver/trace_link.h"
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

/// Follows a plan's actor starts and interruptions (its shim's events) to tell which actor of
/// the top-level plan runs, which actor of its sub-plan runs inside it (one level: a sub-plan's
/// own sub-plans count as its actors' rows too), and which supervisor fired.
class PlanFollower {
 public:
  explicit PlanFollower(const ChartInfo& chart) : chart_(chart) {}
  void take(const std::string& text, long frame, Recording& rec) {
    static const std::string kStart = "start ", kInterrupted = " interrupted by ";
    if (text.compare(0, kStart.size(), kStart) == 0) {
      const std::string qualified = text.substr(kStart.size());
      const int row = row_of(qualified);
      if (row >= 0 || own(qualified)) {
        current_ = row;
        sub_ = -1;
      } else if (current_ >= 0) {
        // "Side.forward" inside the running actor `side`: the row "side/forward".
        const std::string& parent = chart_.rows[static_cast<std::size_t>(current_)].name;
        const std::string name = parent + "/" + qualified.substr(qualified.find('.') + 1);
        sub_ = -1;
        for (std::size_t i = 0; i < rec.sub_rows.size() && sub_ < 0; ++i)
          if (rec.sub_rows[i].name == name) sub_ = static_cast<int>(i);
        if (sub_ < 0) {
          rec.sub_rows.push_back({name, "", false, parent});
          rec.sub_plans.push_back(qualified.substr(0, qualified.find('.')));
          sub_ = static_cast<int>(rec.sub_rows.size()) - 1;
        }
      }
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
    // An actor of the plan itself stops; a sub-plan's actor stops inside the actor still running.
    if (own(text.substr(0, at))) current_ = -1;
    sub_ = -1;
  }
  int current() const { return current_; }
  /// The running sub-plan actor, an index into Recording::sub_rows, or -1.
  int sub() const { return sub_; }

 private:
  bool own(const std::string& qualified) const {
    return qualified.compare(0, chart_.name.size() + 1, chart_.name + ".") == 0;
  }
  /// "WallFollow.followWall" -> "followWall" when it is an actor of the chart itself.
  std::string actor_of(const std::string& qualified) const {
    return own(qualified) ? qualified.substr(chart_.name.size() + 1) : qualified;
  }
  int row_of(const std::string& qualified) const {
    if (!own(qualified)) return -1;
    const std::string actor = actor_of(qualified);
    for (std::size_t i = 0; i < chart_.rows.size(); ++i)
      if (chart_.rows[i].name == actor) return static_cast<int>(i);
    return -1;
  }
  const ChartInfo& chart_;
  int current_ = -1;
  int sub_ = -1;
};

/// Takes what the engine's tick did into the recording: activation, calls, log entries.
/// Log entries made before the first tick (a plan's start) count for frame 0.
void record_tick(const LoadedEngine& engine, const ChartInfo& chart, long frame, PlanFollower& plan, Recording& rec) {
  std::vector<int> active;
  if (chart.kind == "plan") {
    for (std::size_t i = rec.log_frames.size(); i < engine_log().size(); ++i)
      plan.take(engine_log()[i].text, frame, rec);
    if (plan.current() >= 0) active.push_back(plan.current());
    if (plan.current() >= 0 && plan.sub() >= 0)
      rec.instances_active.push_back({static_cast<int>(chart.rows.size()) + plan.sub()});
    else rec.instances_active.emplace_back();
  } else {
    active = active_places(engine);
  }
  // Sub-chart instances: depth first, so the place that runs one is decided before its rows.
  std::vector<int> nested;
  if (chart.kind != "plan" && engine.has_instances()) {
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
  if (chart.kind != "plan") rec.instances_active.push_back(std::move(nested));
  rec.active.push_back(std::move(active));
  rec.calls.push_back(std::move(call_log()));
  call_log().clear();
  while (rec.log_frames.size() < engine_log().size()) rec.log_frames.push_back(frame);
}

}  // namespace

TraceRow trace_row(const Simulation& sim) {
  const Pose p = sim.pose();
  return {sim.time(), p.x, p.y, deg(p.heading)};
}

std::vector<int> active_places(const LoadedEngine& engine) {
  std::vector<int> active;
  for (int p = 0; p < engine.places(); ++p)
    if (engine.activation(p) > 0) active.push_back(p);
  return active;
}

std::string status_text(int status) { return status == 2 ? "terminated" : status > 0 ? "succeeded" : "failed"; }

std::string state_change(const LoadedEngine& engine, const ChartInfo& chart, int& last) {
  const int now = engine.current_state();
  if (now < 0 || now == last) return "";
  last = now;
  return "state " + (now < static_cast<int>(chart.states.size()) ? chart.states[static_cast<std::size_t>(now)]
                                                                 : std::to_string(now));
}

void reset_robot_libraries() {
  linebot_reset();
  cleanbot_reset();
  fetchbot_reset();
}

RunResult run_engine(Simulation& sim, LoadedEngine& engine, const ChartInfo& chart, double seconds, bool quiet) {
  RunResult result;
  const auto start = Clock::now();
  hal::bind(&sim);
  reset_robot_libraries();
  engine_log().clear();
  engine.init();
  engine.set_context(carbot_robot_handle(0));  // every robot call of the engine names the robot
  Progress progress(!quiet, seconds);
  const long ticks = std::lround(seconds / sim.config().control_period);
  int last_state = -1;
  Recording& rec = result.recording;
  PlanFollower plan(chart);
  call_log().clear();
  for (long tick = 0;; ++tick) {
    result.trace.push_back(trace_row(sim));
    rec.items.push_back(sim.items());
    // A frame without an engine call (the last) keeps the activation it had.
    auto keep_activation = [&] {
      rec.active.push_back(rec.active.empty() ? std::vector<int>() : rec.active.back());
      rec.instances_active.push_back(rec.instances_active.empty() ? std::vector<int>() : rec.instances_active.back());
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
    trace_links().select(0);
    engine.run();
    // An fsm's state changes go to the engine log, as a plan's actor changes do, for result.json
    // and the picture.
    if (std::string change = state_change(engine, chart, last_state); !change.empty())
      engine_log().push_back({sim.time(), std::move(change)});
    record_tick(engine, chart, tick, plan, rec);
    if (const int status = engine.status(); status != 0) {
      result.status = status_text(status);
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
