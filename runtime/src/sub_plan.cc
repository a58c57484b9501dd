#include "afp/sub_plan.h"

#include "level.h"

namespace afp {

SubPlan::SubPlan(std::unique_ptr<Plan> plan) : plan_(std::move(plan)) {
  if (!plan_) throw PlanError("null sub-plan");
}

SubPlan::~SubPlan() = default;

void SubPlan::start(Context& ctx) {
  // The inner plan runs on the services of the executor running the outer one.
  level_ = std::make_unique<detail::Level>(*plan_, ctx.services());
  level_->begin();
}

StepResult SubPlan::step(Context&) {
  level_->advance();
  switch (level_->status()) {
    case Status::Succeeded: return OK;
    case Status::Interrupted: return INTERRUPTED;
    case Status::Failed: return ERROR;
    default: return running;
  }
}

void SubPlan::stop() { level_.reset(); }  // ~Level stops an inner plan still running

}  // namespace afp
