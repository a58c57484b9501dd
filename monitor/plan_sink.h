// What a live monitor hands on from a plan's decoded trace stream (docs/live.md "Plans"): one
// event of the plan or a sub-plan at a time, each decoded exactly.
#pragma once

#include "plan_trace_format.h"
#include "run_sink.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gfec::monitor {

struct DecodedPlanEvent {
  std::uint32_t sequence = 0;  ///< the frame's number, from 1
  std::uint32_t ms = 0;        ///< plan time in milliseconds
  trace::PlanRecord record = trace::PlanRecord::State;
  std::size_t level = 0;  ///< which plan of the tree (PlanLayout::levels)
  /// The event as an afp::TraceObserver's log writes it ("start WallFollow.followWall"); empty
  /// for a frame of the state alone (LinkTrace::heartbeat).
  std::string text;
  /// After the event, by level: the running actor's number + 1, 0 for none.
  std::vector<std::uint32_t> active;
};

/// Receives a plan's decoded run; a RunSink for what plans and charts share (losses, silence,
/// the end). Its tick() is never called.
class PlanSink : public RunSink {
public:
  virtual void event(const DecodedPlanEvent &e) = 0;
  void tick(const DecodedTick &) override {}
};

}  // namespace gfec::monitor
