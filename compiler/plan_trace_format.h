// The live trace of a plan (docs/live.md "Plans"): what the afp runtime's LinkTrace writes for
// every event of a plan and its sub-plans, and what `gfec monitor PLAN.plan` reads. The frame is
// a C engine's (trace_format.h) with kind bit kFlagPlan; the payload is one event record and the
// active actor of every level. gfec computes the fingerprint from the model as the runtime does
// from the wired afp::Plan, so the two agree whenever the wiring was generated from this plan.
#pragma once

#include "model.h"
#include "trace_format.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gfec::trace {

constexpr std::uint8_t kFlagPlan = 0x08;      ///< a plan's frame (always also kFlagFull)
constexpr std::size_t kMaxPlanMessage = 200;  ///< a failure's message is cut to this many bytes

/// The record kinds of a plan frame, as numbered on the wire.
enum class PlanRecord : std::uint32_t { Started, Finished, Interrupted, Failed, Ended, State };

/// One level of a plan's tree: the plan itself or the plan a sub-plan actor runs.
struct PlanLevel {
  std::string path;  ///< "" for the plan, "nav", "nav.side" for a sub-plan actor's plan
  model::PlanId plan;
  std::vector<std::string> actors;       ///< in declaration order (the runtime's add_actor order)
  std::vector<std::string> supervisors;  ///< the globals, then each actor's, in declaration order
  std::vector<std::size_t> children;     ///< by actor: the level its sub-plan runs, or npos
};

struct PlanLayout {
  model::PlanId plan;
  std::vector<PlanLevel> levels;  ///< depth first in declaration order, levels[0] the plan
  /// FNV-1a of "gfec plan trace 1", each level's plan, actor and supervisor names (afp::LinkTrace
  /// hashes the same text from the wired plan).
  std::uint32_t fingerprint = 0;
  /// The longest payload: the time, the record, its level and numbers, a cut message, and the
  /// active actor of every level (each number at most 5 bytes).
  std::size_t max_payload() const { return 6 * 5 + 5 + kMaxPlanMessage + levels.size() * 5; }
};

PlanLayout plan_layout_of(const model::Model &model, model::PlanId plan);

}  // namespace gfec::trace
