// The threaded executor: supervisors in their own threads, one winner per
// actor run, external configuration access while running, clean shutdown.
// tsan.sh runs these under ThreadSanitizer.
#include <afp/afp.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "fakes.h"

using namespace std::chrono_literals;
using afp::Status;
using afp::Value;
using fakes::FakeActor;
using fakes::FakeSupervisor;
using fakes::hand_over;
using Lines = std::vector<std::string>;

namespace {

const afp::ThreadedOptions fast{1ms, 1ms};

// Waits for a start()ed run to end; after `limit` it stops the run, so a hang
// shows up as a failed status check instead of a stuck test.
Status await(afp::ThreadedExecutor& exec, std::chrono::seconds limit = 10s) {
  auto deadline = std::chrono::steady_clock::now() + limit;
  while (!afp::is_finished(exec.status()) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(1ms);
  if (!afp::is_finished(exec.status())) exec.request_stop();
  return exec.wait();
}

FakeSupervisor::Rule when_set(const char* flag) {
  return [flag](afp::Context& ctx) {
    return ctx.config().get<bool>(flag) ? afp::CheckResult(FakeSupervisor::FIRED) : afp::no_event;
  };
}

}  // namespace

TEST_CASE("threaded: result states select the next actors up to terminate", "[threaded]") {
  afp::Plan plan("P");
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(3));
  auto* b = plan.add_actor("b", std::make_unique<FakeActor>(2, FakeActor::OTHER));
  plan.define_first_actor(a);
  plan.define_subsequent(a, FakeActor::DONE, b);
  plan.define_subsequent(b, FakeActor::OTHER, afp::terminate);
  afp::Configuration config;
  fakes::Recorder trace;
  afp::ThreadedExecutor exec(plan, config, &trace, fast);
  CHECK(exec.run() == Status::Succeeded);
  CHECK(exec.status() == Status::Succeeded);
  CHECK(trace.lines == Lines{"P: start a", "P: a -> 0", "P: start b", "P: b -> 1", "P: end succeeded"});
  CHECK(a->steps_total == 3);
  CHECK(b->stops == 1);
}

TEST_CASE("threaded: an external write makes a supervisor interrupt - its output is committed", "[threaded]") {
  afp::Plan plan("P");
  plan.declare("go", Value(false));
  plan.declare("reason", Value(""));
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(0));
  auto* b = plan.add_actor("b", std::make_unique<FakeActor>(1));
  auto* s = plan.add_supervisor("s", std::make_unique<FakeSupervisor>(2ms, [](afp::Context& ctx) {
                                  if (!ctx.config().get<bool>("go")) return afp::no_event;
                                  afp::out<std::string>("reason").write(ctx, "go seen");
                                  return afp::CheckResult(FakeSupervisor::FIRED);
                                }));
  hand_over(plan, a, s, b);
  afp::Configuration config;
  fakes::Recorder trace;
  afp::ThreadedExecutor exec(plan, config, &trace, fast);
  exec.start();
  std::this_thread::sleep_for(20ms);
  CHECK(exec.status() == Status::Running);
  config.set("go", true);
  CHECK(await(exec) == Status::Succeeded);
  CHECK(config.get<std::string>("reason") == "go seen");
  CHECK(trace.lines == Lines{"P: start a", "P: a interrupted by s.0", "P: start b", "P: b -> 0", "P: end succeeded"});
  CHECK(a->stops == 1);
  CHECK(s->starts == 1);
  CHECK(s->stops == 1);
}

TEST_CASE("threaded: of many supervisors firing together exactly one interrupts", "[threaded]") {
  constexpr int watchers = 6;
  for (int run = 0; run < 20; ++run) {
    afp::Plan plan("P");
    plan.declare("who", Value(-1));
    auto* a = plan.add_actor("a", std::make_unique<FakeActor>(0));
    plan.define_first_actor(a);
    std::vector<FakeActor*> targets;
    for (int i = 0; i < watchers; ++i) {
      auto* target = plan.add_actor("t" + std::to_string(i), std::make_unique<FakeActor>(1));
      auto* s =
          plan.add_supervisor("s" + std::to_string(i), std::make_unique<FakeSupervisor>(1ms, [i](afp::Context& ctx) {
                                afp::out<int>("who").write(ctx, i);
                                return afp::CheckResult(FakeSupervisor::FIRED);
                              }));
      plan.define_supervision(a, s, FakeSupervisor::FIRED, target);
      plan.define_subsequent(target, FakeActor::DONE, afp::terminate);
      targets.push_back(target);
    }
    afp::Configuration config;
    fakes::Recorder trace;
    afp::ThreadedExecutor exec(plan, config, &trace, fast);
    REQUIRE(exec.run() == Status::Succeeded);

    int started = 0;
    for (auto* target : targets) started += target->starts;
    REQUIRE(started == 1);
    int who = config.get<int>("who");
    REQUIRE(who >= 0);
    CHECK(targets[who]->starts == 1);  // the winner's output and the winner's target
    auto interruptions = std::count_if(trace.lines.begin(), trace.lines.end(), [](const std::string& l) {
      return l.find("interrupted by") != std::string::npos;
    });
    CHECK(interruptions == 1);
    CHECK(trace.lines[1] == "P: a interrupted by s" + std::to_string(who) + ".0");
  }
}

TEST_CASE("threaded: an actor finishing and a supervisor firing never both end the actor", "[threaded]") {
  for (int run = 0; run < 30; ++run) {
    afp::Plan plan("P");
    plan.declare("x", Value(0));
    auto* a = plan.add_actor("a", std::make_unique<FakeActor>(1));
    auto* by_state = plan.add_actor("by_state", std::make_unique<FakeActor>(1));
    auto* by_event = plan.add_actor("by_event", std::make_unique<FakeActor>(1));
    a->on_start = [](afp::Context& ctx) { afp::out<int>("x").write(ctx, 1); };
    auto* s = plan.add_supervisor("s", std::make_unique<FakeSupervisor>(1ms, [](afp::Context& ctx) {
                                    afp::out<int>("x").write(ctx, 2);
                                    return afp::CheckResult(FakeSupervisor::FIRED);
                                  }));
    plan.define_first_actor(a);
    plan.define_subsequent(a, FakeActor::DONE, by_state);
    plan.define_supervision(a, s, FakeSupervisor::FIRED, by_event);
    plan.define_subsequent(by_state, FakeActor::DONE, afp::terminate);
    plan.define_subsequent(by_event, FakeActor::DONE, afp::terminate);
    afp::Configuration config;
    afp::ThreadedExecutor exec(plan, config, nullptr, fast);
    REQUIRE(exec.run() == Status::Succeeded);
    REQUIRE(by_state->starts + by_event->starts == 1);
    CHECK(config.get<int>("x") == (by_state->starts == 1 ? 1 : 2));
    CHECK(a->stops == 1);
  }
}

TEST_CASE("threaded: the application reads and writes the configuration while the plan runs", "[threaded]") {
  afp::Plan plan("P");
  plan.declare("step", Value(1));
  plan.declare("count", Value(0));
  plan.declare("stop", Value(false));
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(1));
  auto step = afp::in<int>(afp::entry("step"));
  auto count = afp::in<int>(afp::entry("count"));
  a->on_start = [=](afp::Context& ctx) { afp::out<int>("count").write(ctx, count.read(ctx) + step.read(ctx)); };
  auto* escape = plan.add_supervisor("escape", std::make_unique<FakeSupervisor>(1ms, when_set("stop")));
  plan.define_global_supervision(escape, FakeSupervisor::FIRED, afp::terminate);
  plan.define_first_actor(a);
  plan.define_subsequent(a, FakeActor::DONE, a);
  afp::Configuration config;
  afp::ThreadedExecutor exec(plan, config, nullptr, fast);
  exec.start();
  int last = 0;
  bool monotonic = true;
  for (int i = 0; i < 200; ++i) {
    config.set("step", 1 + i % 3);
    int now = config.get<int>("count");
    monotonic = monotonic && now >= last;
    last = now;
    std::this_thread::sleep_for(100us);
  }
  config.set("stop", true);
  CHECK(await(exec) == Status::Interrupted);
  CHECK(monotonic);
  CHECK(config.get<int>("count") > 0);
  CHECK(escape->stops == 1);
}

TEST_CASE("threaded: request_stop ends the run and joins every supervisor thread", "[threaded]") {
  afp::Plan plan("P");
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(0));
  auto* s = plan.add_supervisor("s", std::make_unique<FakeSupervisor>(1ms, fakes::never()));
  auto* g = plan.add_supervisor("g", std::make_unique<FakeSupervisor>(0ms, fakes::never()));
  plan.define_first_actor(a);
  plan.define_supervision(a, s, FakeSupervisor::FIRED, afp::terminate);
  plan.define_global_supervision(g, FakeSupervisor::FIRED, afp::terminate);
  afp::Configuration config;
  fakes::Recorder trace;
  afp::ThreadedExecutor exec(plan, config, &trace, fast);
  std::thread runner([&] { exec.run(); });  // run() in a thread of the application's
  while (s->checks < 3 || g->checks < 3) std::this_thread::sleep_for(1ms);
  exec.request_stop();
  runner.join();
  CHECK(exec.status() == Status::Stopped);
  CHECK(trace.lines == Lines{"P: start a", "P: end stopped"});
  CHECK(a->stops == 1);
  CHECK(s->stops == 1);
  CHECK(g->stops == 1);
}

TEST_CASE("threaded: destroying the executor stops a running plan", "[threaded]") {
  afp::Plan plan("P");
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(0));
  auto* g = plan.add_supervisor("g", std::make_unique<FakeSupervisor>(1ms, fakes::never()));
  plan.define_first_actor(a);
  plan.define_global_supervision(g, FakeSupervisor::FIRED, afp::terminate);
  afp::Configuration config;
  {
    afp::ThreadedExecutor exec(plan, config, nullptr, fast);
    exec.start();
    CHECK_THROWS_AS(exec.start(), std::logic_error);
    while (a->steps_total < 2) std::this_thread::sleep_for(1ms);
  }
  CHECK(a->stops == 1);
  CHECK(g->stops == 1);
}

TEST_CASE("threaded: a sub-plan's supervisors run in threads and stay inside the sub-plan", "[threaded]") {
  auto inner = std::make_unique<afp::Plan>("Inner");
  auto* a = inner->add_actor("a", std::make_unique<FakeActor>(0));
  auto* ig = inner->add_supervisor("ig", std::make_unique<FakeSupervisor>(1ms, fakes::fire_from(5ms)));
  inner->define_first_actor(a);
  inner->define_global_supervision(ig, FakeSupervisor::FIRED, afp::terminate);
  afp::Plan plan("Outer");
  auto* nav = plan.add_actor("nav", std::make_unique<afp::SubPlan>(std::move(inner)));
  auto* next = plan.add_actor("next", std::make_unique<FakeActor>(2));
  plan.define_first_actor(nav);
  plan.define_subsequent(nav, afp::SubPlan::INTERRUPTED, next);
  plan.define_subsequent(next, FakeActor::DONE, afp::terminate);
  afp::Configuration config;
  fakes::Recorder trace;
  afp::ThreadedExecutor exec(plan, config, &trace, fast);
  CHECK(exec.run() == Status::Succeeded);
  CHECK(trace.lines == Lines{"Outer: start nav", "Inner: start a", "Inner: a interrupted by ig.0",
                             "Inner: end interrupted", "Outer: nav -> 1", "Outer: start next", "Outer: next -> 0",
                             "Outer: end succeeded"});
  CHECK(ig->stops == 1);
  CHECK(a->stops == 1);
}

TEST_CASE("threaded: a supervisor that throws fails the plan", "[threaded]") {
  afp::Plan plan("P");
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(0));
  auto* s = plan.add_supervisor("s", std::make_unique<FakeSupervisor>(1ms, [](afp::Context&) -> afp::CheckResult {
                                  throw std::runtime_error("sensor lost");
                                }));
  plan.define_first_actor(a);
  plan.define_supervision(a, s, FakeSupervisor::FIRED, afp::terminate);
  afp::Configuration config;
  afp::ThreadedExecutor exec(plan, config, nullptr, fast);
  exec.start();
  CHECK(await(exec) == Status::Failed);
  CHECK(exec.error() == "s: sensor lost");
  CHECK(a->stops == 1);
  CHECK(s->stops == 1);
}

namespace {

// A trace hook that throws on the n-th call of actor_started.
struct ThrowingTrace : afp::TraceObserver {
  explicit ThrowingTrace(int at) : throw_at(at) {}
  void actor_started(const afp::Plan&, std::string_view, afp::Duration) override {
    if (++calls == throw_at) throw std::runtime_error("trace disk full");
  }
  int throw_at;
  int calls = 0;
};

}  // namespace

TEST_CASE("threaded: a trace hook that throws fails the run, under start() and run() alike", "[threaded]") {
  for (int at : {1, 2}) {
    for (bool background : {true, false}) {
      INFO("throws at call " << at << (background ? " under start()" : " under run()"));
      afp::Plan plan("P");
      auto* a = plan.add_actor("a", std::make_unique<FakeActor>(2));
      auto* b = plan.add_actor("b", std::make_unique<FakeActor>(1000000));
      plan.define_first_actor(a);
      plan.define_subsequent(a, FakeActor::DONE, b);
      plan.define_subsequent(b, FakeActor::DONE, afp::terminate);
      afp::Configuration config;
      ThrowingTrace trace(at);
      afp::ThreadedExecutor exec(plan, config, &trace, fast);
      Status end;
      if (background) {
        exec.start();  // once called std::terminate
        end = await(exec);
      } else {
        end = exec.run();  // once let the exception escape, leaving the status NotStarted
      }
      CHECK(end == Status::Failed);
      CHECK(exec.status() == Status::Failed);
      CHECK(exec.error() == "trace observer: trace disk full");
      CHECK(trace.calls == at);  // not called again after it threw
      CHECK(a->stops == 1);      // the actor it interrupted was stopped
    }
  }
}

TEST_CASE("threaded: an actor that throws in its step fails the run in the executor's thread", "[threaded]") {
  afp::Plan plan("P");
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(5));
  a->on_step = [](afp::Context&) { throw std::runtime_error("motor stalled"); };
  plan.define_first_actor(a);
  plan.define_subsequent(a, FakeActor::DONE, afp::terminate);
  afp::Configuration config;
  fakes::Recorder trace;
  afp::ThreadedExecutor exec(plan, config, &trace, fast);
  exec.start();
  CHECK(await(exec) == Status::Failed);
  CHECK(exec.error() == "a: motor stalled");
  CHECK(a->stops == 1);
  REQUIRE(!trace.lines.empty());
  CHECK(trace.lines.back() == "P: end failed");
}

TEST_CASE("threaded: start, stop and destroy in quick succession, many times, end cleanly", "[threaded]") {
  const auto begin = std::chrono::steady_clock::now();
  for (int i = 0; i < 300; ++i) {
    afp::Plan plan("P");
    auto* a = plan.add_actor("a", std::make_unique<FakeActor>(1000000));
    plan.define_first_actor(a);
    plan.define_subsequent(a, FakeActor::DONE, afp::terminate);
    afp::Configuration config;
    auto exec = std::make_unique<afp::ThreadedExecutor>(plan, config, nullptr, fast);
    exec->start();
    if (i % 3 == 1) exec->request_stop();
    if (i % 3 == 2) std::this_thread::sleep_for(std::chrono::microseconds(200 * (i % 7)));
    if (i % 5 == 0) {
      exec->request_stop();
      CHECK(exec->wait() == Status::Stopped);
    }
    exec.reset();  // the destructor stops a run still going and joins every thread
    CHECK(a->starts == a->stops);
  }
  CHECK(std::chrono::steady_clock::now() - begin < 60s);
}
