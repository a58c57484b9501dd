// The Counter toolbox, filled in from gfec's skeleton (gfec --emit=toolbox-skeleton
// charts/counter.toolbox): what charts/count.plan runs.
#ifndef COUNTER_TOOLBOX_H
#define COUNTER_TOOLBOX_H

#include <afp/afp.h>

#include <utility>

/// The environment: nothing to share here.
class Counter {};

/// actor CountTo(in int limit, out int reached) -> DONE: one count per step up to the limit.
class CountTo : public afp::Actor {
public:
  enum State { DONE };

  CountTo(Counter &ee, afp::In<int> limit, afp::Out<int> reached)
      : ee_(ee), limit_(std::move(limit)), reached_(std::move(reached)) {}

  void start(afp::Context &ctx) override {
    limit_value_ = limit_.read(ctx);
    count_ = 0;
  }
  afp::StepResult step(afp::Context &ctx) override {
    (void)ee_;
    if (++count_ < limit_value_) return afp::running;
    reached_.write(ctx, count_);
    return DONE;
  }

private:
  Counter &ee_;
  afp::In<int> limit_;
  afp::Out<int> reached_;
  int limit_value_ = 0;
  int count_ = 0;
};

#endif  // COUNTER_TOOLBOX_H
