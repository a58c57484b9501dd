// Sub-plans: a plan used as an actor, with the fixed states OK, INTERRUPTED, ERROR.
#include <afp/afp.h>

#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>
#include <vector>

#include "fakes.h"

using namespace std::chrono_literals;
using afp::Status;
using afp::SubPlan;
using afp::Value;
using fakes::FakeActor;
using fakes::FakeSupervisor;
using fakes::fire_from;
using Lines = std::vector<std::string>;
using Times = std::vector<afp::Duration>;

namespace {

Status run(afp::SteppedExecutor& exec, int limit = 100) {
  for (int i = 0; i < limit && exec.status() == Status::Running; ++i) exec.step(10ms);
  return exec.status();
}

// Outer: nav (the sub-plan) then x on OK, y on INTERRUPTED, z on ERROR.
struct Outer {
  explicit Outer(std::unique_ptr<afp::Plan> inner) : plan("Outer") {
    nav = plan.add_actor("nav", std::make_unique<SubPlan>(std::move(inner)));
    x = plan.add_actor("x", std::make_unique<FakeActor>(1));
    y = plan.add_actor("y", std::make_unique<FakeActor>(1));
    z = plan.add_actor("z", std::make_unique<FakeActor>(1));
    plan.define_first_actor(nav);
    plan.define_subsequent(nav, SubPlan::OK, x);
    plan.define_subsequent(nav, SubPlan::INTERRUPTED, y);
    plan.define_subsequent(nav, SubPlan::ERROR, z);
    for (auto* actor : {x, y, z}) plan.define_subsequent(actor, FakeActor::DONE, afp::terminate);
  }
  afp::Plan plan;
  SubPlan* nav;
  FakeActor* x;
  FakeActor* y;
  FakeActor* z;
};

}  // namespace

TEST_CASE("a sub-plan that reaches terminate from a result state ends in OK", "[subplan]") {
  auto inner = std::make_unique<afp::Plan>("Inner");
  auto* a = inner->add_actor("a", std::make_unique<FakeActor>(1));
  inner->define_first_actor(a);
  inner->define_subsequent(a, FakeActor::DONE, afp::terminate);
  Outer outer(std::move(inner));
  afp::Configuration config;
  fakes::Recorder trace;
  afp::SteppedExecutor exec(outer.plan, config, &trace);
  exec.start();
  CHECK(run(exec) == Status::Succeeded);
  CHECK(trace.lines == Lines{"Outer: start nav", "Inner: start a", "Inner: a -> 0", "Inner: end succeeded",
                             "Outer: nav -> 0", "Outer: start x", "Outer: x -> 0", "Outer: end succeeded"});
  CHECK(outer.x->starts == 1);
}

TEST_CASE("a sub-plan that reaches terminate from an event ends in INTERRUPTED", "[subplan]") {
  auto inner = std::make_unique<afp::Plan>("Inner");
  auto* a = inner->add_actor("a", std::make_unique<FakeActor>(0));
  auto* s = inner->add_supervisor("s", std::make_unique<FakeSupervisor>(0ms, fire_from(20ms)));
  inner->define_first_actor(a);
  inner->define_supervision(a, s, FakeSupervisor::FIRED, afp::terminate);
  Outer outer(std::move(inner));
  afp::Configuration config;
  afp::SteppedExecutor exec(outer.plan, config);
  exec.start();
  CHECK(run(exec) == Status::Succeeded);
  CHECK(outer.y->starts == 1);
  CHECK(outer.x->starts + outer.z->starts == 0);
}

TEST_CASE("a sub-plan whose actor fails ends in ERROR - the plan above goes on", "[subplan]") {
  auto inner = std::make_unique<afp::Plan>("Inner");
  inner->declare("name", Value("abc"));
  auto* a = inner->add_actor("a", std::make_unique<FakeActor>(1));
  a->on_start = [](afp::Context& ctx) { afp::in<int>(afp::entry("name")).read(ctx); };
  inner->define_first_actor(a);
  inner->define_subsequent(a, FakeActor::DONE, afp::terminate);
  Outer outer(std::move(inner));
  afp::Configuration config;
  fakes::Recorder trace;
  afp::SteppedExecutor exec(outer.plan, config, &trace);
  exec.start();
  CHECK(run(exec) == Status::Succeeded);
  CHECK(outer.z->starts == 1);
  CHECK(exec.error().empty());
  CHECK(trace.lines == Lines{"Outer: start nav", "Inner: start a",
                             "Inner: a failed: cannot convert string \"abc\" to int: not a number", "Inner: end failed",
                             "Outer: nav -> 2", "Outer: start z", "Outer: z -> 0", "Outer: end succeeded"});
}

TEST_CASE("a sub-plan's global supervisor acts only inside the sub-plan", "[subplan]") {
  auto inner = std::make_unique<afp::Plan>("Inner");
  auto* a = inner->add_actor("a", std::make_unique<FakeActor>(0));
  auto* ig = inner->add_supervisor("ig", std::make_unique<FakeSupervisor>(0ms, fire_from(30ms)));
  inner->define_first_actor(a);
  inner->define_global_supervision(ig, FakeSupervisor::FIRED, afp::terminate);

  afp::Plan plan("Outer");
  auto* p1 = plan.add_actor("p1", std::make_unique<FakeActor>(2));
  auto* nav = plan.add_actor("nav", std::make_unique<SubPlan>(std::move(inner)));
  auto* p2 = plan.add_actor("p2", std::make_unique<FakeActor>(3));
  plan.define_first_actor(p1);
  plan.define_subsequent(p1, FakeActor::DONE, nav);
  plan.define_subsequent(nav, SubPlan::INTERRUPTED, p2);
  plan.define_subsequent(p2, FakeActor::DONE, afp::terminate);
  afp::Configuration config;
  fakes::Recorder trace;
  afp::SteppedExecutor exec(plan, config, &trace);
  exec.start();

  CHECK(run(exec) == Status::Succeeded);  // the inner `terminate` did not end the outer plan
  CHECK(trace.lines == Lines{"Outer: start p1", "Outer: p1 -> 0", "Outer: start nav", "Inner: start a",
                             "Inner: a interrupted by ig.0", "Inner: end interrupted", "Outer: nav -> 1",
                             "Outer: start p2", "Outer: p2 -> 0", "Outer: end succeeded"});
  CHECK(ig->check_times() == Times{30ms});  // only while the sub-plan ran (20ms..30ms)
  CHECK(ig->starts == 1);
  CHECK(ig->stops == 1);
  CHECK(p2->steps_total == 3);
}

TEST_CASE("a supervisor of the plan above interrupts the whole sub-plan, before the sub-plan's own", "[subplan]") {
  auto inner = std::make_unique<afp::Plan>("Inner");
  inner->declare("x", Value(0));
  inner->declare("y", Value(0));
  auto* a = inner->add_actor("a", std::make_unique<FakeActor>(1));
  auto* b = inner->add_actor("b", std::make_unique<FakeActor>(0));
  a->on_start = [](afp::Context& ctx) { afp::out<int>("x").write(ctx, 1); };
  b->on_start = [](afp::Context& ctx) { afp::out<int>("y").write(ctx, 1); };
  auto* ig = inner->add_supervisor("ig", std::make_unique<FakeSupervisor>(0ms, fire_from(30ms)));
  inner->define_first_actor(a);
  inner->define_subsequent(a, FakeActor::DONE, b);
  inner->define_global_supervision(ig, FakeSupervisor::FIRED, afp::terminate);

  afp::Plan plan("Outer");
  auto* nav = plan.add_actor("nav", std::make_unique<SubPlan>(std::move(inner)));
  auto* p2 = plan.add_actor("p2", std::make_unique<FakeActor>(1));
  auto* s = plan.add_supervisor("s", std::make_unique<FakeSupervisor>(0ms, fire_from(30ms)));
  plan.define_first_actor(nav);
  plan.define_supervision(nav, s, FakeSupervisor::FIRED, p2);
  plan.define_subsequent(nav, SubPlan::INTERRUPTED, afp::terminate);
  plan.define_subsequent(p2, FakeActor::DONE, afp::terminate);
  afp::Configuration config;
  fakes::Recorder trace;
  afp::SteppedExecutor exec(plan, config, &trace);
  exec.start();

  CHECK(run(exec) == Status::Succeeded);
  CHECK(trace.lines == Lines{"Outer: start nav", "Inner: start a", "Inner: a -> 0", "Inner: start b",
                             "Inner: end stopped", "Outer: nav interrupted by s.0", "Outer: start p2", "Outer: p2 -> 0",
                             "Outer: end succeeded"});
  CHECK(ig->check_times() == Times{10ms, 20ms});  // at 30ms the outer supervisor came first
  CHECK(b->stops == 1);
  CHECK(ig->stops == 1);
  // Inner actors commit as they finish; the interrupted inner actor's output is dropped.
  CHECK(config.get<int>("x") == 1);
  CHECK(config.get<int>("y") == 0);
}
