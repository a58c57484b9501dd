// `gfec monitor PLAN.plan --log`: the decoded events, one line each, as an afp::TraceObserver
// that logs them writes them (docs/live.md "Plans"): the plan time in ms, then `start`, `finish`,
// `interrupt`, `fail` or `end`. The monitor's own lines begin with `#`.
#pragma once

#include "model.h"
#include "plan_sink.h"

#include <ostream>
#include <string>

namespace gfec::monitor {

class PlanLogSink : public PlanSink {
public:
  PlanLogSink(const model::Model &model, const trace::PlanLayout &layout, std::ostream &out)
      : model_(model), layout_(layout), out_(out) {}
  void started(std::size_t) override {}
  void event(const DecodedPlanEvent &e) override;
  void lost(std::size_t robot, std::uint64_t events_missing, const std::string &why) override;
  void silent(double seconds) override;
  void ended(const std::string &) override {}

private:
  const model::Model &model_;
  const trace::PlanLayout &layout_;
  std::ostream &out_;
  bool say_state_ = false;  ///< after a loss: say what runs at the next frame
};

}  // namespace gfec::monitor
