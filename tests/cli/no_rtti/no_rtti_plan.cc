// The runtime built and used with -fno-rtti (tests/cli/runtime_no_rtti.sh): a sub-plan whose
// configuration entry reaches the executor's configuration, a computation refused a supervisor
// (an exception, which -fno-rtti keeps), and an Object handed out by type.
#include <afp/afp.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

using namespace std::chrono_literals;

namespace {

struct Done : afp::Actor {
  afp::StepResult step(afp::Context &) override { return 0; }
};
struct Sum : afp::Computation {
  int compute(afp::Context &) override { return 0; }
};
struct Never : afp::Supervisor {
  Never() : afp::Supervisor(10ms) {}
  afp::CheckResult check(afp::Context &) override { return afp::no_event; }
};
struct Box {
  int n;
};

int failures = 0;
void expect(bool ok, const char *what) {
  if (!ok) {
    std::printf("FAIL: %s\n", what);
    ++failures;
  }
}

}  // namespace

int main() {
  auto inner = std::make_unique<afp::Plan>("Inner");
  inner->declare("speed", afp::Value(3));
  auto *a = inner->add_actor("a", std::make_unique<Done>());
  inner->define_first_actor(a);
  inner->define_subsequent(a, 0, afp::terminate);

  afp::Plan outer("Outer");
  auto *nav = outer.add_actor("nav", std::make_unique<afp::SubPlan>(std::move(inner)));
  auto *sum = outer.add_actor("sum", std::make_unique<Sum>());
  auto *never = outer.add_supervisor("never", std::make_unique<Never>());
  outer.define_first_actor(nav);
  outer.define_subsequent(nav, afp::SubPlan::OK, sum);
  outer.define_subsequent(sum, 0, afp::terminate);
  bool refused = false;
  try {
    outer.define_supervision(sum, never, 0, afp::terminate);
  } catch (const afp::PlanError &) { refused = true; }
  expect(refused, "a computation took a supervisor");

  afp::Configuration config;
  afp::SteppedExecutor exec(outer, config);
  exec.start();
  for (int i = 0; i < 20 && exec.status() == afp::Status::Running; ++i) exec.step(10ms);
  expect(exec.status() == afp::Status::Succeeded, "the plan did not succeed");
  expect(config.get<int>("speed") == 3, "the sub-plan's entry was not declared");

  afp::Object box = afp::make_object<Box>(Box{7});
  expect(box.get<Box>() && box.get<Box>()->n == 7, "Object::get<Box>");
  expect(box.get<const Box>() != nullptr, "Object::get<const Box>");
  expect(box.get<int>() == nullptr, "Object::get<int> of a Box");
  if (failures == 0) std::printf("no-rtti plan: ok\n");
  return failures == 0 ? 0 : 1;
}
