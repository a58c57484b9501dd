#include "level.h"

namespace afp::detail {

Level::Level(Plan& plan, Services& services) : plan_(plan), services_(services) {}

Level::~Level() { abort(); }

void Level::begin() {
  plan_.validate();
  watchers_ = services_.make_watchers();
  status_ = Status::Running;
  watchers_->start_global(watches(plan_.global_));
  start_actor(plan_.first_);
}

void Level::advance() {
  if (status_ != Status::Running) return;
  if (auto claim = watchers_->poll()) return interrupt(std::move(*claim));
  StepResult result = running;
  Context ctx(services_, shadow_);
  if (auto error = capture([&] { result = plan_.actors_[current_].actor->step(ctx); }))
    return fail(actor_name(), *error);
  if (result.is_running()) return;
  // The critical section (docs/runtime.md 2.2): a supervisor that claimed before the actor
  // finished wins; from here on none can interrupt.
  if (auto claim = watchers_->close()) return interrupt(std::move(*claim));
  finish_actor(result.state());
}

void Level::abort() {
  if (status_ != Status::Running) return;
  watchers_->stop_local();
  (void)stop_actor();  // the run ends Stopped whatever the actor's stop() does
  end(Status::Stopped);
}

void Level::start_actor(std::size_t index) {
  current_ = index;
  shadow_.clear();
  trace([&](TraceObserver& t) { t.actor_started(plan_, actor_name(), services_.now()); });
  Context ctx(services_, shadow_);
  actor_active_ = true;
  if (auto error = capture([&] { plan_.actors_[current_].actor->start(ctx); })) return fail(actor_name(), *error);
  watchers_->start_local(watches(plan_.actors_[current_].supervised));
}

void Level::finish_actor(int state) {
  watchers_->stop_local();
  if (auto error = stop_actor()) return fail(actor_name(), *error);
  const auto& rules = plan_.actors_[current_].next;
  auto rule = rules.find(state);
  if (rule == rules.end()) return fail(actor_name(), "no rule for result state " + std::to_string(state));
  services_.config().commit(shadow_);
  trace([&](TraceObserver& t) { t.actor_finished(plan_, actor_name(), state, services_.now()); });
  if (rule->second.kind == Target::Kind::Terminate) return end(Status::Succeeded);
  start_actor(rule->second.actor);
}

void Level::interrupt(Claim claim) {
  watchers_->stop_local();
  const std::string& supervisor = plan_.supervisors_[claim.supervisor].name;
  if (claim.failed) return fail(supervisor, claim.error);
  if (auto error = stop_actor()) return fail(actor_name(), *error);
  services_.config().commit(claim.outputs);  // the actor's shadow is dropped by the next start
  trace([&](TraceObserver& t) { t.actor_interrupted(plan_, actor_name(), supervisor, claim.event, services_.now()); });
  if (claim.target.kind == Target::Kind::Terminate) return end(Status::Interrupted);
  start_actor(claim.target.actor);
}

void Level::fail(const std::string& component, const std::string& what) {
  error_ = component + ": " + what;
  trace([&](TraceObserver& t) { t.component_failed(plan_, component, what, services_.now()); });
  watchers_->stop_local();
  (void)stop_actor();  // a second failure while stopping adds nothing
  end(Status::Failed);
}

void Level::end(Status status) {
  watchers_->stop_local();
  watchers_->stop_global();
  status_ = status;
  trace([&](TraceObserver& t) { t.plan_finished(plan_, status, services_.now()); });
}

std::optional<std::string> Level::stop_actor() {
  if (!actor_active_) return std::nullopt;
  actor_active_ = false;
  return capture([&] { plan_.actors_[current_].actor->stop(); });
}

std::vector<Watch> Level::watches(const std::vector<Supervision>& list) const {
  std::vector<Watch> out;
  for (const auto& rules : list) out.push_back(Watch{plan_.supervisors_[rules.supervisor].supervisor.get(), &rules});
  return out;
}

const std::string& Level::actor_name() const { return plan_.actors_[current_].name; }

}  // namespace afp::detail
