// afp_step_bench: what the Action Flow Plan runtime costs per step of the stepped executor
// (runtime/, docs/runtime.md), beside the actor's own work. It measures; it never fails on time.
//
//   afp_step_bench [STEPS]
//
// Cases: one actor that never finishes (the executor's fixed cost per step); the same actor
// watched by 1 and 8 supervisors checked every step; two actors that hand over to each other at
// every step (a transition per step: stop, next actor, start); the same with an afp::LinkTrace
// whose frames go to a function that only counts their bytes (two events, two frames a step:
// what the plan's live trace adds, docs/live.md "Plans"). The actors and supervisors do nothing,
// so the figures are the runtime's own overhead per step.
#include <afp/afp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

namespace {

using namespace std::chrono_literals;

/// Runs forever, or finishes in state 0 at every step (`finish`).
class Idle : public afp::Actor {
public:
  explicit Idle(bool finish) : finish_(finish) {}
  afp::StepResult step(afp::Context &) override {
    ++steps;
    return finish_ ? afp::StepResult(0) : afp::running;
  }
  long steps = 0;

private:
  bool finish_;
};

/// Never raises its event.
class Quiet : public afp::Supervisor {
public:
  Quiet() : afp::Supervisor(afp::Duration::zero()) {}
  afp::CheckResult check(afp::Context &) override { return afp::no_event; }
};

double link_bytes_per_frame = 0;  ///< of the last run with a LinkTrace

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// ns per executor step for a plan of one actor with `supervisors` global supervisors, or of two
/// actors that hand over at each step (`handover`), with a LinkTrace as its observer (`link`).
double executor_ns(long steps, int supervisors, bool handover, bool link = false) {
  afp::Plan plan("Bench");
  auto *a = plan.add_actor("a", std::make_unique<Idle>(handover));
  plan.define_first_actor(a);
  if (handover) {
    auto *b = plan.add_actor("b", std::make_unique<Idle>(true));
    plan.define_subsequent(a, 0, b);
    plan.define_subsequent(b, 0, a);
  }
  for (int i = 0; i < supervisors; ++i) {
    auto *s = plan.add_supervisor("s" + std::to_string(i), std::make_unique<Quiet>());
    plan.define_global_supervision(s, 0, afp::terminate);
  }
  afp::Configuration config;
  unsigned long bytes = 0, frames = 0;
  afp::LinkTrace trace(plan, [&](const unsigned char *, std::size_t n) {
    bytes += n;
    ++frames;
  });
  afp::SteppedExecutor exec(plan, config, link ? &trace : nullptr);
  exec.start();
  auto start = std::chrono::steady_clock::now();
  for (long i = 0; i < steps; ++i) exec.step(10ms);
  double s = seconds_since(start);
  if (exec.status() != afp::Status::Running) std::fprintf(stderr, "afp_step_bench: the plan stopped early\n");
  if (link && frames > 0) link_bytes_per_frame = static_cast<double>(bytes) / static_cast<double>(frames);
  return s * 1e9 / static_cast<double>(steps);
}

}  // namespace

int main(int argc, char **argv) {
  long steps = argc > 1 ? std::atol(argv[1]) : 2000000;
  std::printf("afp_step_bench: stepped executor, %ld steps of 10 ms plan time per case\n", steps);
  std::printf("%-44s %12s\n", "plan", "ns per step");
  std::printf("%-44s %12.1f\n", "1 actor, running", executor_ns(steps, 0, false));
  std::printf("%-44s %12.1f\n", "1 actor + 1 global supervisor", executor_ns(steps, 1, false));
  std::printf("%-44s %12.1f\n", "1 actor + 8 global supervisors", executor_ns(steps, 8, false));
  std::printf("%-44s %12.1f\n", "2 actors handing over at every step", executor_ns(steps, 0, true));
  std::printf("%-44s %12.1f\n", "the same with an afp::LinkTrace (2 frames)", executor_ns(steps, 0, true, true));
  std::printf("%-44s %12.1f\n", "  its bytes per frame", link_bytes_per_frame);
  return 0;
}
