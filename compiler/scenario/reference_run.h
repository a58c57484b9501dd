// A test's ticks and sets on the reference interpreter (compiler/interpreter): the snapshot
// after each tick, as the generated engine's harness reports its own.
#pragma once

#include "model.h"
#include "scenario/scenario.h"
#include "scenario/snapshot.h"

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gfec::scenario {

/// The ticks of a run whose records are kept in full; null keeps every tick.
using KeptTicks = const std::set<std::uint64_t> *;

/// What a run left, tick by tick (tick 0: after _init). A test of a million ticks keeps a
/// digest per tick, not a million records: the records are kept only for the ticks asked for
/// (those an expectation reads), and the digests say at which tick two runs first differ.
struct Run {
  /// By tick: the digest of every agent's record (digest(), which reads what compare() reads).
  std::vector<std::uint64_t> digests;
  /// By tick: every agent's record (one agent unless the chart is a team machine).
  std::map<std::uint64_t, std::vector<Snapshot>> kept;
  std::string error;        ///< not empty: the run stopped (undefined behaviour, a crash)
  SourceRange error_range;  ///< where, when the reference interpreter knows
  bool error_located = false;

  std::uint64_t recorded() const { return digests.size(); }
  /// Tick `tick`'s records, or null when the run did not keep (or reach) it.
  const std::vector<Snapshot> *at(std::uint64_t tick) const {
    auto it = kept.find(tick);
    return it == kept.end() ? nullptr : &it->second;
  }
  /// Records the next tick: its digest, and its records if `keep` asks for them.
  void record(std::vector<Snapshot> &&agents, KeptTicks keep, const model::Model &model, model::ChartId chart);
};

/// The number of ticks the test runs in all.
std::uint64_t total_ticks(const Test &test);
/// The ticks after which the test's expectations are evaluated.
std::set<std::uint64_t> expectation_ticks(const Test &test);

Run run_reference(const model::Model &model, const Test &test, KeptTicks keep = nullptr);

/// The last tick, at most `up_to`, in which agent `agent` called `function` (with `args`, when
/// given) on the reference run, with that call; none when it was not called in the `window` ticks up to `up_to`. For the
/// note of a failed expectation about a call: it runs the test again, keeping only those ticks.
struct LastCall {
  std::uint64_t tick = 0;
  std::string text;  ///< `Led(true)`
};
std::optional<LastCall> last_call(const model::Model &model, const Test &test, model::FunctionId function,
                                  const std::optional<std::vector<std::string>> &args, std::size_t agent,
                                  std::uint64_t up_to, std::uint64_t window);

/// What both runs leave alike after they recorded a tick: the instances that are not running
/// zeroed (settle_instances), and every agent's reports as the reference exchange left them —
/// after tick k (k >= 1) each agent holds every other agent's state of tick k.
void settle_tick(std::vector<Snapshot> &agents, const std::vector<Instance> &instances, const model::Chart &chart);

}  // namespace gfec::scenario
