// Runs charts/count.plan, compiled by gfec_add_chart(), on the stepped executor.
#include "count.hpp"

#include <chrono>
#include <cstdio>

int main() {
  Counter ee;
  auto plan = make_Count(ee);
  afp::Configuration config;
  afp::SteppedExecutor exec(*plan, config);
  exec.start();
  int steps = 0;
  while (exec.status() == afp::Status::Running && steps < 100) {
    exec.step(std::chrono::milliseconds(10));
    ++steps;
  }
  std::printf("reached=%d succeeded=%d\n", config.get<int>("reached"), exec.status() == afp::Status::Succeeded);
  return 0;
}
