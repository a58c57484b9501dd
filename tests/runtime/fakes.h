// Test doubles for the runtime: scriptable actors and supervisors that count
// what the executor does to them, and a trace observer that records events as
// text so that a test can assert a whole run at once.
#pragma once

#include <afp/afp.h>

#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace fakes {

using namespace std::chrono_literals;

/// Finishes in `state` at its `steps`-th step of each run (never if steps <= 0).
/// Optional hooks run at start, at each step and at stop (read inputs, write outputs, throw).
class FakeActor : public afp::Actor {
 public:
  enum State { DONE, OTHER, THIRD };

  explicit FakeActor(int steps = 1, int state = DONE) : steps_(steps), state_(state) {}

  void start(afp::Context& ctx) override {
    ++starts;
    taken_ = 0;
    if (on_start) on_start(ctx);
  }

  afp::StepResult step(afp::Context& ctx) override {
    ++steps_total;
    if (on_step) on_step(ctx);
    return ++taken_ == steps_ ? afp::StepResult(state_) : afp::running;
  }

  void stop() override {
    ++stops;
    if (on_stop) on_stop();
  }

  std::function<void(afp::Context&)> on_start;
  std::function<void(afp::Context&)> on_step;
  std::function<void()> on_stop;
  std::atomic<int> starts{0};
  std::atomic<int> steps_total{0};
  std::atomic<int> stops{0};

 private:
  int steps_;
  int state_;
  int taken_ = 0;
};

/// Calls `rule` at each check (and `on_start`, if set, at start); counts its
/// life and records check times.
class FakeSupervisor : public afp::Supervisor {
 public:
  enum Event { FIRED, OTHER_EVENT };
  using Rule = std::function<afp::CheckResult(afp::Context&)>;

  FakeSupervisor(afp::Duration period, Rule rule) : afp::Supervisor(period), rule_(std::move(rule)) {}

  void start(afp::Context& ctx) override {
    ++starts;
    if (on_start) on_start(ctx);
  }

  afp::CheckResult check(afp::Context& ctx) override {
    ++checks;
    {
      std::lock_guard lock(mutex_);
      check_times_.push_back(ctx.now());
    }
    return rule_(ctx);
  }

  void stop() override { ++stops; }

  std::function<void(afp::Context&)> on_start;

  /// The plan times of every check so far.
  std::vector<afp::Duration> check_times() const {
    std::lock_guard lock(mutex_);
    return check_times_;
  }

  std::atomic<int> starts{0};
  std::atomic<int> checks{0};
  std::atomic<int> stops{0};

 private:
  Rule rule_;
  mutable std::mutex mutex_;
  std::vector<afp::Duration> check_times_;
};

/// A rule that raises `event` from plan time `at` on.
inline FakeSupervisor::Rule fire_from(afp::Duration at, int event = FakeSupervisor::FIRED) {
  return [at, event](afp::Context& ctx) { return ctx.now() >= at ? afp::CheckResult(event) : afp::no_event; };
}

/// A rule that never raises an event.
inline FakeSupervisor::Rule never() {
  return [](afp::Context&) { return afp::no_event; };
}

/// The hand-over several tests build: `a` runs first and `s`, supervising it, hands over to `b`
/// when it fires; `a` or `b` finishing (DONE) ends the plan.
inline void hand_over(afp::Plan& plan, const afp::Actor* a, const afp::Supervisor* s, const afp::Actor* b) {
  plan.define_first_actor(a);
  plan.define_subsequent(a, FakeActor::DONE, afp::terminate);
  plan.define_supervision(a, s, FakeSupervisor::FIRED, b);
  plan.define_subsequent(b, FakeActor::DONE, afp::terminate);
}

/// The example computation of the toolbox: rest = n - 1; AGAIN while rest > 0.
class CountDown : public afp::Computation {
 public:
  enum State { AGAIN, DONE };

  CountDown(afp::In<int> n, afp::Out<int> rest) : n_(std::move(n)), rest_(std::move(rest)) {}

  int compute(afp::Context& ctx) override {
    int rest = n_.read(ctx) - 1;
    rest_.write(ctx, rest);
    return rest > 0 ? AGAIN : DONE;
  }

 private:
  afp::In<int> n_;
  afp::Out<int> rest_;
};

/// Records the trace as lines "Plan: what", with the plan time of each.
class Recorder : public afp::TraceObserver {
 public:
  void actor_started(const afp::Plan& plan, std::string_view actor, afp::Duration now) override {
    add(plan, "start " + std::string(actor), now);
  }
  void actor_finished(const afp::Plan& plan, std::string_view actor, int state, afp::Duration now) override {
    add(plan, std::string(actor) + " -> " + std::to_string(state), now);
  }
  void actor_interrupted(const afp::Plan& plan, std::string_view actor, std::string_view supervisor, int event,
                         afp::Duration now) override {
    add(plan, std::string(actor) + " interrupted by " + std::string(supervisor) + "." + std::to_string(event), now);
  }
  void component_failed(const afp::Plan& plan, std::string_view component, std::string_view what,
                        afp::Duration now) override {
    add(plan, std::string(component) + " failed: " + std::string(what), now);
  }
  void plan_finished(const afp::Plan& plan, afp::Status status, afp::Duration now) override {
    add(plan, std::string("end ") + afp::to_string(status), now);
  }

  std::vector<std::string> lines;
  std::vector<afp::Duration> times;

 private:
  void add(const afp::Plan& plan, std::string what, afp::Duration now) {
    lines.push_back(plan.name() + ": " + what);
    times.push_back(now);
  }
};

}  // namespace fakes
