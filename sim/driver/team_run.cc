// The run loop for several robots in one world: one engine per robot, each with its robot as
// instance context, ticked in robot order, and for a team machine the exchange of states after
// every tick (docs/sim.md, "Several robots"; docs/language.md "Teams").
#include <chrono>
#include <cmath>
#include <cstdint>
#include <deque>

#include "driver/engine_log.h"
#include "driver/trace_link.h"
#include "driver/run.h"
#include "hal/carbot_hal.h"
#include "hal/hal_binding.h"

namespace carbot::driver {
namespace {

/// splitmix64: a tiny generator whose sequence is fixed by its seed on every platform (the
/// standard library's distributions are not), so a lossy run repeats exactly.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  double uniform() {  // [0, 1)
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t state_;
};

/// A report on its way: agent `from` is in `state`, for agent `to`, arriving after tick `due`.
struct Message {
  long due;
  int from, to, state;
};

}  // namespace

RunResult run_team(Simulation& sim, std::vector<LoadedEngine*> engines, const ChartInfo& chart, double seconds,
                   Exchange exchange) {
  RunResult result;
  const auto start = std::chrono::steady_clock::now();
  const int n = sim.robot_count();
  result.robots.resize(static_cast<std::size_t>(n));
  result.team_machine = chart.team > 0;
  reset_robot_libraries();
  // Each engine gets its robot as context: every interface call it makes names the robot it is
  // for, and the robot library passes it on to the HAL (docs/sim.md "Several robots"). The HAL
  // is bound to the simulation only.
  hal::bind(&sim);
  for (int i = 0; i < n; ++i) {
    engines[static_cast<std::size_t>(i)]->init();
    engines[static_cast<std::size_t>(i)]->set_context(carbot_robot_handle(i));
    engines[static_cast<std::size_t>(i)]->set_agent(i);
  }
  Random random(exchange.seed);
  std::deque<Message> on_the_way;  // in order of arrival: the delay is the same for all
  std::vector<bool> running(static_cast<std::size_t>(n), true);
  std::vector<int> last_state(static_cast<std::size_t>(n), -1);
  const long ticks = std::lround(seconds / sim.config().control_period);

  auto robot = [&](int i) -> RobotRun& { return result.robots[static_cast<std::size_t>(i)]; };
  auto engine = [&](int i) -> LoadedEngine& { return *engines[static_cast<std::size_t>(i)]; };
  // A row without an engine call (the robot's engine ended, or the run did) keeps the activation
  // it had, and has no calls.
  auto keep_activation = [&](int i) {
    RobotRun& r = robot(i);
    r.active.push_back(r.active.empty() ? std::vector<int>() : r.active.back());
    r.calls.emplace_back();
  };
  // The run viewer's recording (docs/viewer.md): where each item is, and who holds it, per row;
  // each engine's calls of a tick (a recording build reports them through call_log()).
  Recording& rec = result.recording;
  call_log().clear();

  for (long tick = 0;; ++tick) {
    for (int i = 0; i < n; ++i) {
      sim.select(i);
      robot(i).trace.push_back(trace_row(sim));
    }
    rec.items.push_back(sim.items());
    std::vector<int> holders;
    for (std::size_t k = 0; k < sim.items().size(); ++k) holders.push_back(sim.holder(static_cast<int>(k)));
    rec.holders.push_back(std::move(holders));
    // The escape button stops every robot still running (see run_engine).
    if (sim.escape() || tick >= ticks) {
      for (int i = 0; i < n; ++i) {
        if (sim.escape() && running[static_cast<std::size_t>(i)]) {
          robot(i).status = "terminated";
          robot(i).ended = tick;
        }
        keep_activation(i);
      }
      break;
    }
    bool any_running = false;
    for (int i = 0; i < n; ++i) {
      if (!running[static_cast<std::size_t>(i)]) {
        keep_activation(i);
        continue;
      }
      sim.select(i);            // this robot's row below; its engine's calls reach it through their context
      trace_links().select(i);  // its engine's trace frame goes down its own link
      engine(i).run();
      RobotRun& r = robot(i);
      if (std::string change = state_change(engine(i), chart, last_state[static_cast<std::size_t>(i)]); !change.empty())
        r.state_log.push_back({sim.time(), std::move(change)});
      r.active.push_back(active_places(engine(i)));
      r.calls.push_back(std::move(call_log()));
      call_log().clear();
      if (const int status = engine(i).status(); status != 0) {
        r.status = status_text(status);
        r.ended = tick;
        running[static_cast<std::size_t>(i)] = false;
        sim.stop();  // an engine that ended drives its robot no more
      } else {
        any_running = true;
      }
    }
    if (!any_running) break;
    // The exchange: every agent's state to every other (an ended engine still reports its
    // final state, as a robot standing in "Got" would), possibly late or lost.
    if (result.team_machine && exchange.enabled) {
      for (int from = 0; from < n; ++from) {
        const int state = engine(from).current_state();
        for (int to = 0; to < n; ++to) {
          if (to == from) continue;
          ++exchange.sent;
          if (exchange.loss > 0 && random.uniform() < exchange.loss) {
            ++exchange.lost;
            continue;
          }
          on_the_way.push_back({tick + exchange.delay_ticks, from, to, state});
        }
      }
      while (!on_the_way.empty() && on_the_way.front().due <= tick) {
        const Message& m = on_the_way.front();
        engine(m.to).report(m.from, m.state);
        on_the_way.pop_front();
      }
    }
    sim.step_control();
  }
  for (int i = 0; i < n; ++i) {
    sim.select(i);
    engine(i).finish();
    sim.stop();
    RobotRun& r = robot(i);
    r.state = engine(i).current_state();
    r.final_pose = sim.pose();
    r.distance_m = sim.odometer();
    r.bumps = sim.bumps();
    r.bump_log = sim.bump_log();
    r.left_floor = sim.left_floor();
    r.held = sim.held_item();
    r.lights = sim.lights();
    r.beeps = sim.beeps();
  }
  hal::bind(nullptr);
  sim.select(0);
  // The run's status: running while any robot runs, else the worst of theirs.
  auto any = [&](const char* s) {
    for (const RobotRun& r : result.robots)
      if (r.status == s) return true;
    return false;
  };
  result.status = any("running")      ? "running"
                  : any("terminated") ? "terminated"
                  : any("failed")     ? "failed"
                                      : "succeeded";
  result.exchange = exchange;
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace carbot::driver
