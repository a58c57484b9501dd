// The stepped executor: every rule of the plan model, deterministically, in plan time.
#include <afp/afp.h>

#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>
#include <vector>

#include "fakes.h"

using namespace std::chrono_literals;
using afp::Status;
using afp::Value;
using fakes::CountDown;
using fakes::FakeActor;
using fakes::FakeSupervisor;
using fakes::fire_from;
using fakes::hand_over;
using fakes::never;
using Lines = std::vector<std::string>;
using Times = std::vector<afp::Duration>;

namespace {

// Runs steps of `dt` until the plan ends or `limit` steps.
Status run(afp::SteppedExecutor& exec, afp::Duration dt = 10ms, int limit = 100) {
  for (int i = 0; i < limit && exec.status() == Status::Running; ++i) exec.step(dt);
  return exec.status();
}

FakeSupervisor* add_supervisor(afp::Plan& plan, const std::string& name, afp::Duration period,
                               FakeSupervisor::Rule rule) {
  return plan.add_supervisor(name, std::make_unique<FakeSupervisor>(period, std::move(rule)));
}

}  // namespace

TEST_CASE("an actor's result state selects the next actor - terminate ends in Succeeded", "[stepped]") {
  afp::Plan plan("P");
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(2, FakeActor::DONE));
  auto* b = plan.add_actor("b", std::make_unique<FakeActor>(1, FakeActor::OTHER));
  auto* c = plan.add_actor("c", std::make_unique<FakeActor>(1));
  plan.define_first_actor(a);
  plan.define_subsequent(a, FakeActor::DONE, b);
  plan.define_subsequent(a, FakeActor::OTHER, c);
  plan.define_subsequent(b, FakeActor::DONE, c);
  plan.define_subsequent(b, FakeActor::OTHER, afp::terminate);
  plan.define_subsequent(c, FakeActor::DONE, afp::terminate);
  afp::Configuration config;
  fakes::Recorder trace;
  afp::SteppedExecutor exec(plan, config, &trace);

  CHECK(exec.status() == Status::NotStarted);
  exec.start();
  CHECK(exec.status() == Status::Running);
  CHECK(exec.step(10ms) == Status::Running);
  CHECK(exec.step(10ms) == Status::Running);
  CHECK(exec.step(10ms) == Status::Succeeded);
  CHECK(trace.lines == Lines{"P: start a", "P: a -> 0", "P: start b", "P: b -> 1", "P: end succeeded"});
  CHECK(trace.times == Times{0ms, 20ms, 20ms, 30ms, 30ms});
  CHECK(a->stops == 1);
  CHECK(b->stops == 1);
  CHECK(c->starts == 0);
  CHECK(exec.error().empty());
}

TEST_CASE("a computation loop reads its input at start and commits its output when it finishes", "[stepped]") {
  afp::Plan plan("Loop");
  plan.declare("n", Value(3));
  auto* count = plan.add_actor("count", std::make_unique<CountDown>(afp::in<int>(afp::entry("n")), afp::out<int>("n")));
  plan.define_first_actor(count);
  plan.define_subsequent(count, CountDown::AGAIN, count);
  plan.define_subsequent(count, CountDown::DONE, afp::terminate);
  afp::Configuration config;
  afp::SteppedExecutor exec(plan, config);  // no trace observer
  exec.start();
  CHECK(config.get<int>("n") == 3);  // computed at start, not yet committed
  CHECK(run(exec) == Status::Succeeded);
  CHECK(exec.now() == 30ms);
  CHECK(config.get<int>("n") == 0);
}

TEST_CASE("an actor's supervisor interrupts it and its event selects the next actor", "[stepped]") {
  afp::Plan plan("P");
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(0));  // never finishes
  auto* b = plan.add_actor("b", std::make_unique<FakeActor>(1));
  auto* s = add_supervisor(plan, "s", 0ms, fire_from(30ms));
  hand_over(plan, a, s, b);
  afp::Configuration config;
  fakes::Recorder trace;
  afp::SteppedExecutor exec(plan, config, &trace);
  exec.start();

  CHECK(run(exec) == Status::Succeeded);
  CHECK(trace.lines == Lines{"P: start a", "P: a interrupted by s.0", "P: start b", "P: b -> 0", "P: end succeeded"});
  CHECK(trace.times == Times{0ms, 30ms, 30ms, 40ms, 40ms});
  CHECK(s->check_times() == Times{10ms, 20ms, 30ms});  // not while b runs
  CHECK(a->steps_total == 2);                          // the step at 30ms was preempted
  CHECK(a->stops == 1);
  CHECK(s->starts == 1);
  CHECK(s->stops == 1);
}

TEST_CASE("a global supervisor watches every actor and may terminate the plan: Interrupted", "[stepped]") {
  afp::Plan plan("P");
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(3));
  auto* b = plan.add_actor("b", std::make_unique<FakeActor>(0));
  auto* g = add_supervisor(plan, "escape", 0ms, fire_from(50ms));
  plan.define_global_supervision(g, FakeSupervisor::FIRED, afp::terminate);
  plan.define_first_actor(a);
  plan.define_subsequent(a, FakeActor::DONE, b);
  plan.define_subsequent(b, FakeActor::DONE, afp::terminate);
  afp::Configuration config;
  fakes::Recorder trace;
  afp::SteppedExecutor exec(plan, config, &trace);
  exec.start();

  CHECK(run(exec) == Status::Interrupted);
  CHECK(trace.lines ==
        Lines{"P: start a", "P: a -> 0", "P: start b", "P: b interrupted by escape.0", "P: end interrupted"});
  CHECK(trace.times.back() == 50ms);
  CHECK(g->starts == 1);  // started once for the whole plan, not per actor
  CHECK(g->stops == 1);
  CHECK(b->stops == 1);
}

TEST_CASE("when several supervisors fire in one step, exactly one interrupts, by a fixed order", "[stepped]") {
  // Order: global supervisors, then the actor's own, each in declaration order.
  // The first that raises a non-ignored event wins; the others are not checked.
  afp::Plan plan("P");
  plan.declare("who", afp::Type::String);
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(0));
  auto* x = plan.add_actor("x", std::make_unique<FakeActor>(1));
  auto* y = plan.add_actor("y", std::make_unique<FakeActor>(1));
  auto writes_name = [](std::string name) {
    return [name](afp::Context& ctx) {
      afp::out<std::string>("who").write(ctx, name);
      return ctx.now() >= 20ms ? afp::CheckResult(FakeSupervisor::FIRED) : afp::no_event;
    };
  };
  auto* l1 = add_supervisor(plan, "l1", 0ms, writes_name("l1"));
  auto* l2 = add_supervisor(plan, "l2", 0ms, writes_name("l2"));
  plan.define_first_actor(a);
  for (auto* actor : {x, y}) plan.define_subsequent(actor, FakeActor::DONE, afp::terminate);
  plan.define_subsequent(a, FakeActor::DONE, afp::terminate);
  std::string winner;
  afp::Configuration config;

  SECTION("the actor's own supervisors in declaration order, not creation order") {
    plan.define_supervision(a, l2, FakeSupervisor::FIRED, y);
    plan.define_supervision(a, l1, FakeSupervisor::FIRED, x);
    winner = "l2";
    afp::SteppedExecutor exec(plan, config);
    exec.start();
    CHECK(run(exec) == Status::Succeeded);
    CHECK(y->starts == 1);
    CHECK(x->starts == 0);
    CHECK(l1->check_times() == Times{10ms});  // not checked once l2 had interrupted at 20ms
  }
  SECTION("global supervisors before the actor's own") {
    auto* g = add_supervisor(plan, "g", 0ms, writes_name("g"));
    plan.define_supervision(a, l1, FakeSupervisor::FIRED, x);
    plan.define_supervision(a, l2, FakeSupervisor::FIRED, y);
    plan.define_global_supervision(g, FakeSupervisor::FIRED, afp::terminate);
    winner = "g";
    afp::SteppedExecutor exec(plan, config);
    exec.start();
    CHECK(run(exec) == Status::Interrupted);
    CHECK(exec.now() == 20ms);
    CHECK(x->starts + y->starts == 0);
  }
  CHECK(config.get<std::string>("who") == winner);  // only the winner's output is committed
}

TEST_CASE("an interrupted actor's outputs are discarded", "[stepped]") {
  afp::Plan plan("P");
  plan.declare("x", Value(0));
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(0));
  auto* b = plan.add_actor("b", std::make_unique<FakeActor>(1));
  a->on_start = [](afp::Context& ctx) { afp::out<int>("x").write(ctx, 5); };
  a->on_step = [](afp::Context& ctx) { afp::out<int>("x").write(ctx, 6); };
  auto* s = add_supervisor(plan, "s", 0ms, fire_from(20ms));
  hand_over(plan, a, s, b);
  afp::Configuration config;
  afp::SteppedExecutor exec(plan, config);
  exec.start();
  CHECK(run(exec) == Status::Succeeded);
  CHECK(a->steps_total == 1);
  CHECK(config.get<int>("x") == 0);
}

TEST_CASE("the interrupting supervisor's outputs are committed - other checks' outputs are not", "[stepped]") {
  afp::Plan plan("P");
  plan.declare("seen", Value(0));
  plan.declare("ignored", Value(0));
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(0));
  auto* b = plan.add_actor("b", std::make_unique<FakeActor>(0));
  auto* s = add_supervisor(plan, "s", 0ms, [](afp::Context& ctx) {
    afp::out<int>("seen").write(ctx, int(ctx.now() / 1ms));
    return ctx.now() >= 30ms ? afp::CheckResult(FakeSupervisor::FIRED) : afp::no_event;
  });
  auto* noisy = add_supervisor(plan, "noisy", 0ms, [](afp::Context& ctx) {
    afp::out<int>("ignored").write(ctx, 1);
    return afp::CheckResult(FakeSupervisor::OTHER_EVENT);
  });
  auto* stop = add_supervisor(plan, "stop", 0ms, fire_from(60ms));
  plan.define_global_supervision(noisy, FakeSupervisor::OTHER_EVENT, afp::ignore);
  plan.define_global_supervision(stop, FakeSupervisor::FIRED, afp::terminate);
  hand_over(plan, a, s, b);
  afp::Configuration config;
  fakes::Recorder trace;
  afp::SteppedExecutor exec(plan, config, &trace);
  exec.start();

  CHECK(run(exec) == Status::Interrupted);
  CHECK(config.get<int>("seen") == 30);    // the interrupting check's write
  CHECK(config.get<int>("ignored") == 0);  // an ignored event interrupts nothing and commits nothing
  CHECK(noisy->checks == 6);
  CHECK(trace.lines == Lines{"P: start a", "P: a interrupted by s.0", "P: start b", "P: b interrupted by stop.0",
                             "P: end interrupted"});
}

TEST_CASE("a supervisor's ignored event leaves the actor running - another event of it interrupts", "[stepped]") {
  afp::Plan plan("P");
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(0));
  auto* s = add_supervisor(plan, "s", 0ms, [](afp::Context& ctx) {
    return ctx.now() < 40ms ? afp::CheckResult(FakeSupervisor::OTHER_EVENT) : afp::CheckResult(FakeSupervisor::FIRED);
  });
  plan.define_first_actor(a);
  plan.define_subsequent(a, FakeActor::DONE, afp::terminate);
  plan.define_supervision(a, s, FakeSupervisor::OTHER_EVENT, afp::ignore);
  plan.define_supervision(a, s, FakeSupervisor::FIRED, afp::terminate);
  afp::Configuration config;
  afp::SteppedExecutor exec(plan, config);
  exec.start();
  CHECK(run(exec) == Status::Interrupted);
  CHECK(exec.now() == 40ms);
  CHECK(a->steps_total == 3);
}

TEST_CASE("supervisors are checked at their period in plan time", "[stepped]") {
  afp::Plan plan("P");
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(2));
  auto* b = plan.add_actor("b", std::make_unique<FakeActor>(0));
  auto* every_step = add_supervisor(plan, "every_step", 0ms, never());
  auto* slow = add_supervisor(plan, "slow", 30ms, never());
  auto* local = add_supervisor(plan, "local", 30ms, never());
  plan.define_global_supervision(every_step, FakeSupervisor::FIRED, afp::terminate);
  plan.define_global_supervision(slow, FakeSupervisor::FIRED, afp::terminate);
  plan.define_first_actor(a);
  plan.define_subsequent(a, FakeActor::DONE, b);
  plan.define_supervision(b, local, FakeSupervisor::FIRED, afp::terminate);
  plan.define_subsequent(b, FakeActor::DONE, afp::terminate);
  afp::Configuration config;
  afp::SteppedExecutor exec(plan, config);
  exec.start();

  SECTION("steps shorter than the period") {
    run(exec, 10ms, 10);
    CHECK(every_step->check_times() == Times{10ms, 20ms, 30ms, 40ms, 50ms, 60ms, 70ms, 80ms, 90ms, 100ms});
    CHECK(slow->check_times() == Times{30ms, 60ms, 90ms});
    CHECK(local->check_times() == Times{50ms, 80ms});  // from b's start at 20ms
  }
  SECTION("steps longer than the period: one check per step, on the period's grid") {
    run(exec, 35ms, 4);
    CHECK(slow->check_times() == Times{35ms, 70ms, 105ms, 140ms});
    exec.advance_to(150ms);
    CHECK(slow->check_times().size() == 5);  // 150 >= 150: the grid slot after 140
    exec.advance_to(170ms);
    CHECK(slow->check_times().size() == 5);
  }
}

TEST_CASE("time only moves forward and the executor runs once", "[stepped]") {
  afp::Plan plan("P");
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(0));
  plan.define_first_actor(a);
  afp::Configuration config;
  afp::SteppedExecutor exec(plan, config);
  CHECK_THROWS_AS(exec.step(10ms), std::logic_error);
  exec.start();
  CHECK_THROWS_AS(exec.start(), std::logic_error);
  exec.advance_to(15ms);
  exec.advance_to(15ms);
  CHECK(a->steps_total == 2);
  CHECK_THROWS_AS(exec.advance_to(5ms), std::invalid_argument);
  CHECK(exec.now() == 15ms);
}

TEST_CASE("the application's writes between steps are read by the next actor start", "[stepped]") {
  afp::Plan plan("P");
  plan.declare("walldist", Value(30.0f));
  std::vector<float> seen;
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(1));
  auto dist = afp::in<float>([](const afp::ConfigView& c) { return c.get<float>("walldist") - 5; });
  a->on_start = [&](afp::Context& ctx) { seen.push_back(dist.read(ctx)); };
  plan.define_first_actor(a);
  plan.define_subsequent(a, FakeActor::DONE, a);
  afp::Configuration config;
  afp::SteppedExecutor exec(plan, config);
  config.set("walldist", 20);  // before the start, after the executor declared it
  exec.start();
  exec.step(10ms);
  config.set("walldist", "40");
  exec.step(10ms);
  CHECK(seen == std::vector<float>{15.0f, 15.0f, 35.0f});
  CHECK(config.get<float>("walldist") == 40.0f);
}

TEST_CASE("stop() ends a running plan with Stopped and stops everything once", "[stepped]") {
  afp::Plan plan("P");
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(0));
  auto* s = add_supervisor(plan, "s", 0ms, never());
  auto* g = add_supervisor(plan, "g", 0ms, never());
  plan.define_first_actor(a);
  plan.define_supervision(a, s, FakeSupervisor::FIRED, afp::terminate);
  plan.define_global_supervision(g, FakeSupervisor::FIRED, afp::terminate);
  afp::Configuration config;
  fakes::Recorder trace;
  afp::SteppedExecutor exec(plan, config, &trace);
  exec.start();
  exec.step(10ms);
  exec.stop();
  CHECK(exec.status() == Status::Stopped);
  CHECK(exec.step(10ms) == Status::Stopped);
  CHECK(a->stops == 1);
  CHECK(a->steps_total == 1);
  CHECK(s->stops == 1);
  CHECK(g->stops == 1);
  CHECK(trace.lines == Lines{"P: start a", "P: end stopped"});
}

TEST_CASE("an actor that throws or whose parameter does not convert ends the plan in Failed", "[stepped]") {
  afp::Plan plan("P");
  plan.declare("name", Value("abc"));
  plan.declare("f", Value(1.0f));
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(2));
  std::string what;  // the failure message after "a: "
  SECTION("throws in start") {
    a->on_start = [](afp::Context&) { throw std::runtime_error("boom"); };
    what = "boom";
  }
  SECTION("throws in step") {
    a->on_step = [](afp::Context&) { throw 42; };
    what = "unknown exception";
  }
  SECTION("an In whose text is not a number") {
    a->on_start = [](afp::Context& ctx) { afp::in<float>(afp::entry("name")).read(ctx); };
    what = "cannot convert string \"abc\" to float: not a number";
  }
  SECTION("an Out whose value does not convert to the entry") {
    a->on_step = [](afp::Context& ctx) { afp::out<std::string>("f").write(ctx, "wide"); };
    what = "cannot convert string \"wide\" to float: not a number";
  }
  SECTION("an Out to an unknown entry") {
    a->on_start = [](afp::Context& ctx) { afp::out<int>("nope").write(ctx, 1); };
    what = "unknown configuration entry 'nope'";
  }
  SECTION("throws in stop after finishing") {
    plan.define_subsequent(a, FakeActor::DONE, afp::terminate);
    a->on_stop = [] { throw std::runtime_error("motor jammed"); };
    what = "motor jammed";
  }
  SECTION("a result state without a rule") { what = "no rule for result state 0"; }
  plan.define_first_actor(a);
  afp::Configuration config;
  fakes::Recorder trace;
  afp::SteppedExecutor exec(plan, config, &trace);
  exec.start();
  CHECK(run(exec) == Status::Failed);
  CHECK(exec.error() == "a: " + what);
  REQUIRE(trace.lines.size() >= 2);
  CHECK(trace.lines[trace.lines.size() - 2] == "P: a failed: " + what);
  CHECK(trace.lines.back() == "P: end failed");
  CHECK(a->stops == 1);  // stop() follows start() whatever happened
  CHECK(config.get<float>("f") == 1.0f);
}

TEST_CASE("a supervisor that throws, or raises an event without a rule, fails the plan", "[stepped]") {
  afp::Plan plan("P");
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(0));
  plan.define_first_actor(a);
  std::string expected;
  SECTION("throws in check") {
    auto* s =
        add_supervisor(plan, "s", 0ms, [](afp::Context&) -> afp::CheckResult { throw std::runtime_error("bad"); });
    plan.define_supervision(a, s, FakeSupervisor::FIRED, afp::terminate);
    expected = "s: bad";
  }
  SECTION("throws in start") {
    auto* s = add_supervisor(plan, "s", 0ms, never());
    s->on_start = [](afp::Context&) { throw std::runtime_error("no sensor"); };
    plan.define_supervision(a, s, FakeSupervisor::FIRED, afp::terminate);
    expected = "s: no sensor";
  }
  SECTION("an event without a rule") {
    auto* g = add_supervisor(plan, "g", 0ms, fire_from(0ms, FakeSupervisor::OTHER_EVENT));
    plan.define_global_supervision(g, FakeSupervisor::FIRED, afp::terminate);
    expected = "g: no rule for event 1";
  }
  afp::Configuration config;
  afp::SteppedExecutor exec(plan, config);
  exec.start();
  CHECK(exec.step(10ms) == Status::Failed);
  CHECK(exec.error() == expected);
  CHECK(a->stops == 1);
}
