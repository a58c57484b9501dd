// Runs a generated plan on the stepped executor over a script and logs what happens: the
// compile-and-run tests of the cpp back end (tests/unit/cpp_backend_run_test.cc). Built with
//   -DPLAN_HEADER='"wall_follow.hpp"' -DPLAN_FACTORY=make_WallFollow -DPLAN_ENV=Carbot
// and a scripted toolbox from this folder. The script comes on stdin (scripted_env.h): the
// first line is read before the start (its `set:` writes configure the plan), each further
// line is one step of 10 ms. The log: what the trace observer hears, with the plan time in ms,
// what the toolbox's components print (indented), then the status and every config entry.
// With the argument `threaded` the plan runs on the threaded executor instead, to its end:
// the script's first line is applied, the others are not read, and plan times are left out
// of the log (they are real time there). With `link=FILE` an afp::LinkTrace beside the log
// writes the plan's frames to FILE (docs/live.md "Plans"), with a heartbeat after each step,
// for `gfec monitor PLAN --log` to decode (tests/cli/monitor_plan.sh).
#include PLAN_HEADER

#include <afp/afp.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <map>
#include <string>

using namespace std::chrono_literals;

namespace {

long ms(afp::Duration d) { return static_cast<long>(std::chrono::duration_cast<std::chrono::milliseconds>(d).count()); }

struct Log : afp::TraceObserver {
  bool timed = true;

  /// The plan time, or nothing when it is real time.
  std::string at(afp::Duration now) const { return timed ? std::to_string(ms(now)) + " " : ""; }

  void actor_started(const afp::Plan &plan, std::string_view actor, afp::Duration now) override {
    std::cout << at(now) << "start " << plan.name() << "." << actor << "\n";
  }
  void actor_finished(const afp::Plan &plan, std::string_view actor, int state, afp::Duration now) override {
    std::cout << at(now) << "finish " << plan.name() << "." << actor << " state " << state << "\n";
  }
  void actor_interrupted(const afp::Plan &plan, std::string_view actor, std::string_view supervisor, int event,
                         afp::Duration now) override {
    std::cout << at(now) << "interrupt " << plan.name() << "." << actor << " by " << supervisor << " event " << event
              << "\n";
  }
  void component_failed(const afp::Plan &plan, std::string_view component, std::string_view what,
                        afp::Duration now) override {
    std::cout << at(now) << "fail " << plan.name() << "." << component << ": " << what << "\n";
  }
  void plan_finished(const afp::Plan &plan, afp::Status status, afp::Duration now) override {
    std::cout << at(now) << "end " << plan.name() << " " << afp::to_string(status) << "\n";
  }
};

std::string shown(const afp::Value &v) {
  if (const auto *object = v.get_if<afp::Object>()) {
    const int *i = object->get<int>();
    return i ? "object " + std::to_string(*i) : "null";
  }
  if (const auto *s = v.get_if<std::string>()) return "\"" + *s + "\"";
  return afp::convert<std::string>(v);
}

void apply_writes(afp::Configuration &config, const std::map<std::string, std::string> &writes) {
  for (const auto &[name, value] : writes) {
    config.set(name, afp::Value(value));
    std::cout << "set " << name << "=" << shown(config.value(name)) << "\n";
  }
}

}  // namespace

template <class Executor> void report(const Executor &exec) {
  std::cout << "status " << afp::to_string(exec.status());
  if (!exec.error().empty()) std::cout << ": " << exec.error();
  std::cout << "\n";
}

int main(int argc, char **argv) {
  PLAN_ENV ee;
  afp::Configuration config;
  Log log;
  auto plan = PLAN_FACTORY(ee);
  std::string line;
  bool threaded = false;
  std::ofstream frames;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "threaded") threaded = true;
    else if (arg.rfind("link=", 0) == 0) frames.open(arg.substr(5), std::ios::binary);
  }
  afp::LinkTrace link(*plan, [&](const unsigned char *data, std::size_t n) {
    frames.write(reinterpret_cast<const char *>(data), static_cast<std::streamsize>(n));
  });
  afp::TraceTee both(&log, frames.is_open() ? &link : nullptr);
  if (threaded) {
    log.timed = false;
    afp::ThreadedExecutor exec(*plan, config, &both);
    if (std::getline(std::cin, line)) apply_writes(config, ee.next(line));
    exec.run();
    report(exec);
  } else {
    afp::SteppedExecutor exec(*plan, config, &both);
    if (std::getline(std::cin, line)) apply_writes(config, ee.next(line));
    exec.start();
    while (exec.status() == afp::Status::Running && std::getline(std::cin, line)) {
      apply_writes(config, ee.next(line));
      exec.step(10ms);
      link.heartbeat(exec.now());
    }
    report(exec);
  }
  for (const auto &name : config.names()) std::cout << "config " << name << "=" << shown(config.value(name)) << "\n";
  return 0;
}
