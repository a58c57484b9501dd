// In and Out parameters: formulas over the configuration, converted to the
// parameter's type; outputs converted to the entry's type.
#include <afp/afp.h>

#include <catch2/catch.hpp>

#include <string>

#include "fakes.h"

using namespace std::chrono_literals;
using afp::ConfigView;
using afp::Value;

namespace {

afp::Configuration& wall_config(afp::Configuration& config) {
  config.declare("walldist", Value(30.0f));
  config.declare("label", Value("12.5"));
  config.declare("name", Value("abc"));
  config.declare("n", Value(3));
  return config;
}

}  // namespace

TEST_CASE("an In reads a constant, an entry or a formula, converted to its type", "[params]") {
  afp::Configuration config;
  ConfigView view(wall_config(config));
  CHECK(afp::in<float>(100000).evaluate(view) == 100000.0f);
  CHECK(afp::in<std::string>("text").evaluate(view) == "text");
  CHECK(afp::in<int>(afp::entry("walldist")).evaluate(view) == 30);
  CHECK(afp::in<float>(afp::entry("label")).evaluate(view) == 12.5f);
  auto formula = afp::in<float>([](const ConfigView& c) { return c.get<float>("walldist") - 5; });
  CHECK(formula.evaluate(view) == 25.0f);
  auto text = afp::in<std::string>([](const ConfigView& c) { return "n=" + c.get<std::string>("n"); });
  CHECK(text.evaluate(view) == "n=3");
}

TEST_CASE("an In sees the configuration as it is when read", "[params]") {
  afp::Configuration config;
  ConfigView view(wall_config(config));
  auto dist = afp::in<double>(afp::entry("walldist"));
  config.set("walldist", 40);
  CHECK(dist.evaluate(view) == 40.0);
}

TEST_CASE("an In whose text is not a number fails to convert", "[params]") {
  afp::Configuration config;
  ConfigView view(wall_config(config));
  CHECK_THROWS_AS(afp::in<float>(afp::entry("name")).evaluate(view), afp::ConversionError);
  CHECK_THROWS_AS(afp::in<float>(afp::entry("missing")).evaluate(view), afp::ConfigError);
}

TEST_CASE("an Out writes to the shadow, converted to the entry's type, committed at the end", "[params]") {
  using fakes::FakeActor;
  afp::Plan plan("P");
  plan.declare("n", Value(0));
  plan.declare("s", Value(""));
  auto* a = plan.add_actor("a", std::make_unique<FakeActor>(2));
  a->on_start = [](afp::Context& ctx) {
    afp::out<float>("n").write(ctx, 7.9f);
    afp::out<float>("s").write(ctx, 0.5f);
    CHECK(ctx.config().get<int>("n") == 0);  // not visible before the commit
  };
  plan.define_first_actor(a);
  plan.define_subsequent(a, FakeActor::DONE, afp::terminate);
  afp::Configuration config;
  afp::SteppedExecutor exec(plan, config);
  exec.start();
  exec.step(10ms);
  CHECK(config.value("n") == Value(0));
  CHECK(exec.step(10ms) == afp::Status::Succeeded);
  CHECK(config.value("n") == Value(7));
  CHECK(config.value("s") == Value("0.5"));
}
