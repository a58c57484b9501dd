#include "run_chart.h"

#include <fmt/format.h>

namespace gfec::interp {

RunResult run_chart(const model::Model &model, model::ChartId chart, Environment &env, std::uint64_t ticks,
                    MachineOptions options, Diagnostics &diag, const AfterTick &after_tick) {
  RunResult result;
  bool started = false;  // a tick began (the log may have been emptied since)
  try {
    Machine engine(model, chart, options);
    for (std::uint64_t t = 0; t < ticks; ++t) {
      started = true;
      engine.run(env, &result.log);
      result.ticks = engine.ticks();
      if (after_tick) after_tick(result.log);
    }
    result.completed = true;
  } catch (const RuntimeError &e) {
    std::string when = result.ticks < ticks ? fmt::format("during tick {}", result.ticks + 1) : "";
    if (!started && result.log.events().empty()) when = "in init";
    diag.error(e.range, ErrorKind::Runtime, fmt::format("{} {}", e.what(), when));
  }
  return result;
}

RunResult run_team(const model::Model &model, model::ChartId chart, const std::vector<Environment *> &envs,
                   std::uint64_t ticks, MachineOptions options, Diagnostics &diag, const AfterTick &after_tick) {
  RunResult result;
  std::size_t agent = 0;
  std::uint64_t tick = 0;
  try {
    std::vector<Machine> engines;
    engines.reserve(envs.size());
    for (std::size_t k = 0; k < envs.size(); ++k) {
      engines.emplace_back(model, chart, options);
      engines.back().set_agent(static_cast<int>(k));
    }
    for (tick = 1; tick <= ticks; ++tick) {
      result.log.add(EventKind::Tick, 0, fmt::format("tick {}", tick));
      for (agent = 0; agent < engines.size(); ++agent) {
        EventLog own;
        engines[agent].run(*envs[agent], &own);
        result.log.add(EventKind::Agent, 1, fmt::format("agent {}", agent));
        for (const Event &e : own.events())
          if (e.kind != EventKind::Tick) result.log.add(e.kind, e.depth + 1, e.text);
      }
      // The reference exchange: every agent's state to every other, after all have ticked.
      std::string states = "team";
      for (std::size_t from = 0; from < engines.size(); ++from) {
        const model::PlaceId state = engines[from].state();
        states += " " + engines[from].chart().places.at(state).name;
        for (std::size_t to = 0; to < engines.size(); ++to) engines[to].report(static_cast<int>(from), state);
      }
      result.log.add(EventKind::Exchange, 1, std::move(states));
      result.ticks = tick;
      if (after_tick) after_tick(result.log);
    }
    result.completed = true;
  } catch (const RuntimeError &e) {
    std::string when = tick == 0 ? "in init" : fmt::format("during tick {} (agent {})", tick, agent);
    diag.error(e.range, ErrorKind::Runtime, fmt::format("{} {}", e.what(), when));
  }
  return result;
}

}  // namespace gfec::interp
