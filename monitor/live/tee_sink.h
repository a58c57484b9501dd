// Hands a decoded run to two sinks at once: `gfec monitor --log --http` prints the log and
// feeds the live page from one reading of the stream.
#pragma once

#include "plan_sink.h"

namespace gfec::live {

class TeeSink final : public monitor::PlanSink {
public:
  TeeSink(monitor::RunSink &a, monitor::RunSink &b) : a_(a), b_(b) {}
  /// A plan's run: the events go to both too.
  TeeSink(monitor::PlanSink &a, monitor::PlanSink &b) : a_(a), b_(b), plan_a_(&a), plan_b_(&b) {}
  void started(std::size_t robot) override {
    a_.started(robot);
    b_.started(robot);
  }
  void tick(const monitor::DecodedTick &t) override {
    a_.tick(t);
    b_.tick(t);
  }
  void event(const monitor::DecodedPlanEvent &e) override {
    if (plan_a_) plan_a_->event(e);
    if (plan_b_) plan_b_->event(e);
  }
  void lost(std::size_t robot, std::uint64_t ticks_missing, const std::string &why) override {
    a_.lost(robot, ticks_missing, why);
    b_.lost(robot, ticks_missing, why);
  }
  void silent(double seconds) override {
    a_.silent(seconds);
    b_.silent(seconds);
  }
  void ended(const std::string &why) override {
    a_.ended(why);
    b_.ended(why);
  }

private:
  monitor::RunSink &a_, &b_;
  monitor::PlanSink *plan_a_ = nullptr, *plan_b_ = nullptr;
};

}  // namespace gfec::live
