// A test's ticks and sets on the reference interpreter (compiler/interpreter): the snapshot
// after each tick, as the generated engine's harness reports its own.
#pragma once

#include "model.h"
#include "scenario/scenario.h"
#include "scenario/snapshot.h"

#include <string>
#include <vector>

namespace gfec::scenario {

struct Run {
  /// ticks[k][a]: agent a after k ticks (ticks[0]: after _init); one agent unless the chart
  /// is a team machine.
  std::vector<std::vector<Snapshot>> ticks;
  std::string error;        ///< not empty: the run stopped (undefined behaviour, a crash)
  SourceRange error_range;  ///< where, when the reference interpreter knows
  bool error_located = false;
};

/// The number of ticks the test runs in all.
std::uint64_t total_ticks(const Test &test);

Run run_reference(const model::Model &model, const Test &test);

/// What both runs leave alike after they recorded a tick: the instances that are not running
/// zeroed (settle_instances), and every agent's reports as the reference exchange left them —
/// after tick k (k >= 1) each agent holds every other agent's state of tick k.
void settle_tick(std::vector<Snapshot> &agents, const std::vector<Instance> &instances, const model::Chart &chart);

}  // namespace gfec::scenario
