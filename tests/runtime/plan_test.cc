// Wiring a plan: what the generated code calls, and the mistakes it rejects.
#include <afp/afp.h>

#include <catch2/catch.hpp>

#include "fakes.h"

using namespace std::chrono_literals;
using fakes::CountDown;
using fakes::FakeActor;
using fakes::FakeSupervisor;

TEST_CASE("instances are owned by the plan and known by name", "[plan]") {
  afp::Plan plan("WallFollow");
  auto* a = plan.add_actor("searchFirstWall", std::make_unique<FakeActor>());
  auto* s = plan.add_supervisor("touch", std::make_unique<FakeSupervisor>(10ms, fakes::never()));
  CHECK(plan.name() == "WallFollow");
  CHECK(plan.name_of(a) == "searchFirstWall");
  CHECK(plan.name_of(s) == "touch");
  CHECK(s->period() == 10ms);
}

TEST_CASE("a plan without a first actor cannot run", "[plan]") {
  afp::Plan plan("P");
  plan.add_actor("a", std::make_unique<FakeActor>());
  CHECK_THROWS_WITH(plan.validate(), "plan 'P' has no first actor");
  afp::Configuration config;
  afp::SteppedExecutor exec(plan, config);
  CHECK_THROWS_AS(exec.start(), afp::PlanError);
  CHECK(exec.status() == afp::Status::NotStarted);
}

TEST_CASE("wiring mistakes are reported when the rule is defined", "[plan]") {
  afp::Plan plan("P");
  afp::Plan other("Q");
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>());
  auto* c = plan.add_actor("c", std::make_unique<CountDown>(afp::in<int>(3), afp::out<int>("n")));
  auto* s = plan.add_supervisor("s", std::make_unique<FakeSupervisor>(0ms, fakes::never()));
  auto* g = plan.add_supervisor("g", std::make_unique<FakeSupervisor>(0ms, fakes::never()));
  auto* foreign = other.add_actor("x", std::make_unique<FakeActor>());

  CHECK_THROWS_WITH(plan.add_actor("a", std::make_unique<FakeActor>()), "two instances named 'a' in plan 'P'");
  CHECK_THROWS_WITH(plan.add_supervisor("a", std::make_unique<FakeSupervisor>(0ms, fakes::never())),
                    "two instances named 'a' in plan 'P'");
  CHECK_THROWS_WITH(plan.define_first_actor(foreign), "an actor that is not part of plan 'P'");
  CHECK_THROWS_AS(plan.define_subsequent(a, FakeActor::DONE, foreign), afp::PlanError);

  plan.define_subsequent(a, FakeActor::DONE, afp::terminate);
  CHECK_THROWS_WITH(plan.define_subsequent(a, FakeActor::DONE, a), "two rules for state 0 of actor 'a'");
  CHECK_THROWS_WITH(plan.define_supervision(c, s, FakeSupervisor::FIRED, a), "computation 'c' cannot have supervisors");

  plan.define_supervision(a, s, FakeSupervisor::FIRED, afp::ignore);
  CHECK_THROWS_WITH(plan.define_supervision(a, s, FakeSupervisor::FIRED, a), "two rules for event 0 of supervisor 's'");
  CHECK_THROWS_WITH(plan.define_global_supervision(s, FakeSupervisor::OTHER_EVENT, afp::terminate),
                    "supervisor 's' already watches actor 'a'");

  plan.define_global_supervision(g, FakeSupervisor::FIRED, afp::terminate);
  CHECK_THROWS_WITH(plan.define_supervision(a, g, FakeSupervisor::OTHER_EVENT, a), "supervisor 'g' is already global");

  plan.define_first_actor(a);
  CHECK_THROWS_WITH(plan.define_first_actor(c), "plan 'P' has two first actors");
  CHECK_NOTHROW(plan.validate());
}

TEST_CASE("a plan declares its entries and its sub-plans' in the configuration", "[plan]") {
  auto inner = std::make_unique<afp::Plan>("Inner");
  inner->declare("count", afp::Value(5));
  afp::Plan plan("Outer");
  plan.declare("walldist", afp::Value(30.0f));
  plan.declare("wallangle", afp::Type::Float);
  CHECK_THROWS_WITH(plan.declare("wallangle", afp::Type::Int),
                    "configuration entry 'wallangle' declared twice in plan 'Outer'");
  plan.add_actor("nav", std::make_unique<afp::SubPlan>(std::move(inner)));
  afp::Configuration config;
  config.declare("walldist", afp::Value(12.0f));
  plan.declare_into(config);
  CHECK(config.names() == std::vector<std::string>{"count", "wallangle", "walldist"});
  CHECK(config.get<float>("walldist") == 12.0f);  // set before: kept
  CHECK(config.get<int>("count") == 5);
}
