// Runs one chart for a number of ticks and collects its log: the whole of `gfec run` apart
// from reading files and printing, and the reference side of differential testing.
#pragma once

#include "diagnostics.h"
#include "engine.h"
#include "event_log.h"

#include <cstdint>

namespace gfec::interp {

struct RunResult {
  EventLog log;
  bool completed = false;  ///< false: undefined behaviour stopped the run (reported to diag)
  std::uint64_t ticks = 0; ///< ticks run to the end
};

/// init, then `ticks` times run. Undefined behaviour is reported to `diag` as an error
/// [runtime] at the expression that would cause it, naming the tick, and ends the run.
RunResult run_chart(const model::Model &model, int chart, Environment &env, std::uint64_t ticks,
                    EngineOptions options, Diagnostics &diag);

} // namespace gfec::interp
