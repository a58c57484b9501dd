// Runs one chart for a number of ticks and collects its log: the whole of `gfec run` apart
// from reading files and printing, and the reference side of differential testing.
#pragma once

#include "diagnostics.h"
#include "machine.h"
#include "event_log.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace gfec::interp {

struct RunResult {
  EventLog log;
  bool completed = false;   ///< false: undefined behaviour stopped the run (reported to diag)
  std::uint64_t ticks = 0;  ///< ticks run to the end
};

/// Called after every tick with the log so far; it may take the events and clear the log, so
/// that a long run is printed as it goes and never held whole (gfec run).
using AfterTick = std::function<void(EventLog &log)>;

/// init, then `ticks` times run. Undefined behaviour is reported to `diag` as an error
/// [runtime] at the expression that would cause it, naming the tick, and ends the run.
RunResult run_chart(const model::Model &model, model::ChartId chart, Environment &env, std::uint64_t ticks,
                    MachineOptions options, Diagnostics &diag, const AfterTick &after_tick = {});

/// A team machine run by `envs.size()` agents (at most its team size), one engine each, under
/// the reference exchange (docs/language.md "Teams"): init every engine and give engine k agent
/// number k; then each tick, every agent ticks in agent order (`envs[k]` answers agent k's
/// calls), then every agent's state is reported to every other. Each agent's part of the tick
/// is logged after `agent k`, one level deeper; the exchange as `team S0 S1 ...`.
RunResult run_team(const model::Model &model, model::ChartId chart, const std::vector<Environment *> &envs,
                   std::uint64_t ticks, MachineOptions options, Diagnostics &diag, const AfterTick &after_tick = {});

}  // namespace gfec::interp
