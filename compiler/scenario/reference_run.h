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
  std::vector<Snapshot> ticks;  ///< ticks[k]: after k ticks (ticks[0]: after _init)
  std::string error;            ///< not empty: the run stopped (undefined behaviour, a crash)
  SourceRange error_range;      ///< where, when the reference interpreter knows
  bool error_located = false;
};

/// The number of ticks the test runs in all.
std::uint64_t total_ticks(const Test &test);

Run run_reference(const model::Model &model, const Test &test);

}  // namespace gfec::scenario
