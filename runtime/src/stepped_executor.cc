#include "afp/stepped_executor.h"

#include <stdexcept>

#include "level.h"
#include "step_watchers.h"

namespace afp {

// The executor is the services of every level it runs: plan time is its clock.
struct SteppedExecutor::Impl final : detail::Services {
  Impl(Plan& to_run, Configuration& config, TraceObserver* trace) : Services(config, trace), plan(to_run) {}

  Duration now() const override { return time; }
  std::unique_ptr<detail::Watchers> make_watchers() override { return std::make_unique<detail::StepWatchers>(*this); }

  Plan& plan;
  Duration time{0};
  std::unique_ptr<detail::Level> level;  // made by start()
};

SteppedExecutor::SteppedExecutor(Plan& plan, Configuration& config, TraceObserver* trace)
    : impl_(std::make_unique<Impl>(plan, config, trace)) {
  plan.declare_into(config);
}

SteppedExecutor::~SteppedExecutor() = default;

void SteppedExecutor::start() {
  if (impl_->level) throw std::logic_error("a SteppedExecutor runs its plan once");
  impl_->plan.validate();
  impl_->level = std::make_unique<detail::Level>(impl_->plan, *impl_);
  impl_->level->begin();
}

Status SteppedExecutor::step(Duration dt) { return advance_to(impl_->time + dt); }

Status SteppedExecutor::advance_to(Duration t) {
  if (!impl_->level) throw std::logic_error("SteppedExecutor::start() not called");
  if (t < impl_->time) throw std::invalid_argument("SteppedExecutor: plan time cannot go back");
  impl_->time = t;
  impl_->level->advance();
  return status();
}

void SteppedExecutor::stop() {
  if (impl_->level) impl_->level->abort();
}

Duration SteppedExecutor::now() const { return impl_->time; }

Status SteppedExecutor::status() const { return impl_->level ? impl_->level->status() : Status::NotStarted; }

const std::string& SteppedExecutor::error() const {
  static const std::string none;
  return impl_->level ? impl_->level->error() : none;
}

}  // namespace afp
