// The reference interpreter on fsm machines: docs/language.md §7.
#include "../run/shared_charts.h"
#include "interpreter_support.h"

#include <fmt/format.h>

using namespace gfec;
using test::compile;
using test::run_log;
using test::ScriptedEnv;
using test::charts::kCensus;
using test::charts::kFsmEntryExit;

namespace {

const char *kCleanBot = R"(
interface CleanBot {
  void DriveToItem(); void PickUp(); void Transport(); void PlaceItem();
  bool Arrived(); bool Holding(); bool FarFromDestination(); bool ItemPlaced();
  bool ItemAtDestination(); bool Stuck();
}
)";

const char *kCleanUp = R"(
fsm CleanUp {
  initial state Z0 { DriveToItem(); }
  state Z1 { PickUp(); }
  state Z2 { Transport(); }
  state Z3 { PlaceItem(); }
  success state Done post ItemAtDestination();
  failure state Failed;

  Z0 -> Z1 when Arrived();
  Z1 -> Z2 when Holding() && FarFromDestination();
  Z1 -> Z3 when Holding() && !FarFromDestination();
  Z2 -> Z3 when Arrived();
  Z2 -> Z1 when !Holding();
  Z3 -> Done when ItemPlaced();
  Z3 -> Z1 when !Holding() && !ItemPlaced();
  Z0 -> Failed when Stuck();
}
)";

}  // namespace

TEST_CASE("interpreter fsm: one transition a tick, the first that holds, then the new state's action") {
  auto c = compile(kCleanUp, kCleanBot);
  ScriptedEnv env(*c);
  env.script("Arrived", {0, 1, 1, 1}).script("Holding", {0, 0, 1, 1}).script("FarFromDestination", {0, 0, 0, 0});
  env.script("ItemPlaced", {0, 0, 0, 1});
  CHECK(run_log(*c, env, 5) == "tick 1\n"
                               "call Arrived() = false\n"
                               "call Stuck() = false\n"
                               "call DriveToItem()\n"
                               "av 1 0 0 0 0 0\nstate Z0 running\n"
                               "tick 2\n"
                               "call Arrived() = true\n"  // Z0 -> Z1 fires; Z0 -> Failed is not tried
                               "call PickUp()\n"
                               "av 0 1 0 0 0 0\nstate Z1 running\n"
                               "tick 3\n"
                               "call Holding() = true\n"
                               "call FarFromDestination() = false\n"
                               "call Holding() = true\n"
                               "call FarFromDestination() = false\n"
                               "call PlaceItem()\n"
                               "av 0 0 0 1 0 0\nstate Z3 running\n"
                               "tick 4\n"
                               "call ItemPlaced() = true\n"
                               "av 0 0 0 0 1 0\nstate Done succeeded\n"
                               "tick 5\n"  // in a terminal state nothing happens
                               "av 0 0 0 0 1 0\nstate Done succeeded\n");
}

TEST_CASE("interpreter fsm: failure, hooks and the postcondition check") {
  auto c = compile(kCleanUp, kCleanBot);
  ScriptedEnv env(*c);
  env.script("Stuck", {1});
  CHECK(run_log(*c, env, 1, {true, false}) == "tick 1\ncall Arrived() = false\ncall Stuck() = true\nlost Z0\ngained "
                                              "Failed\nav 0 0 0 0 0 1\nstate Failed failed\n");

  ScriptedEnv done(*c);
  done.script("Arrived", {1}).script("Holding", {1}).script("ItemPlaced", {1});
  Diagnostics diag;
  interp::MachineOptions checks;
  checks.check_post = true;
  interp::RunResult r = interp::run_chart(c->model, model::ChartId(0), done, 3, checks, diag);
  std::string log = r.log.render({false, true});
  CHECK(log.find("fire T5: Z3 -> Done\nexit Z3\nentry Done\npost Done = false\ncall ItemAtDestination() = false\n") !=
        std::string::npos);
}

TEST_CASE("interpreter fsm: timers restart on entry, vars persist") {
  auto c = compile(R"(
fsm Blink {
  period 100ms;
  var int count = 0;
  initial state Off { count += 1; Show(count); }
  state On { Show(100); }
  success state Enough;
  Off -> Enough when count >= 3;
  Off -> On when elapsed(Off) >= 200ms;
  On -> Off;
}
)",
                   "interface Bot { void Show(int n); }");
  ScriptedEnv env(*c);
  CHECK(run_log(*c, env, 6) == "tick 1\ncall Show(1)\nav 1 0 0\nstate Off running\n"  // elapsed(Off) = 1 < 2
                               "tick 2\ncall Show(100)\nav 0 1 0\nstate On running\n"
                               "tick 3\ncall Show(2)\nav 1 0 0\nstate Off running\n"  // entered: its timer restarts
                               "tick 4\ncall Show(3)\nav 1 0 0\nstate Off running\n"  // elapsed 1
                               "tick 5\nav 0 0 1\nstate Enough succeeded\n"           // count >= 3 is tried first
                               "tick 6\nav 0 0 1\nstate Enough succeeded\n");
}

TEST_CASE("interpreter fsm: entry and exit blocks") {
  // The machine of c_backend_run_test.cc "fsm entry and exit".
  auto c = compile(kFsmEntryExit);
  ScriptedEnv env(*c);
  env.script("Go", {0, 1, 0, 0, 1, 0, 1}).script("Back", {0, 0, 0, 1, 0, 0, 1}).script("Fin", {0, 0, 0, 0, 0, 1, 1});
  CHECK(run_log(*c, env, 7) ==
        "tick 1\ncall EnterA()\ncall Go() = false\ncall DoA()\nav 1 0 0\nstate A running\n"
        "tick 2\ncall Go() = true\ncall ExitA()\ncall EnterB()\ncall DoB()\nav 0 1 0\nstate B running\n"
        "tick 3\ncall Back() = false\ncall Fin() = false\ncall DoB()\ncall Late()\nav 0 1 0\nstate B running\n"
        "tick 4\ncall Back() = true\ncall ExitB()\ncall EnterA()\ncall DoA()\nav 1 0 0\nstate A running\n"
        "tick 5\ncall Go() = true\ncall ExitA()\ncall EnterB()\ncall DoB()\nav 0 1 0\nstate B running\n"
        "tick 6\ncall Back() = false\ncall Fin() = true\ncall ExitB()\nav 0 0 1\nstate Done succeeded\n"
        "tick 7\nav 0 0 1\nstate Done succeeded\n");
  // Explained: the exit, then the entry, then the action.
  ScriptedEnv go(*c);
  go.script("Go", {0, 1});
  std::string explained = run_log(*c, go, 2, {false, true, true});
  CHECK(explained.find("tick 2\n"
                       "  cond T0 = true\n"
                       "    call Go() = true\n"
                       "  fire T0: A -> B\n"
                       "  exit A\n"
                       "    call ExitA()\n"
                       "  entry B\n"
                       "    call EnterB()\n") != std::string::npos);
}

TEST_CASE("interpreter fsm: a team of four under the reference exchange") {
  // The census of c_backend_team_test.cc: the same calls, in the interpreter's words.
  auto c = compile(kCensus);
  std::vector<std::unique_ptr<ScriptedEnv>> envs;
  std::vector<interp::Environment *> agents;
  const std::vector<std::vector<double>> moves = {{0, 0, 1, 0}, {1, 0, 0, 0}, {0}, {1, 0}};
  for (const auto &m : moves) {
    envs.push_back(std::make_unique<ScriptedEnv>(*c));
    envs.back()->script("Move", m);
    agents.push_back(envs.back().get());
  }
  Diagnostics diag;
  interp::RunResult r = interp::run_team(c->model, model::ChartId(0), agents, 4, {}, diag);
  REQUIRE(r.completed);
  auto agent = [](int k, bool move, const char *count, const char *state) {
    return fmt::format("agent {}\ncall Move() = {}\ncall Count({})\nav {}\nstate {} running\n", k,
                       move ? "true" : "false", count, std::string(state) == "Go" ? "1 0" : "0 1", state);
  };
  CHECK(r.log.render({}) == "tick 1\n" + agent(0, false, "0, 0, 0", "Go") + agent(1, true, "1, 0, 0", "Wait") +
                                agent(2, false, "2, 0, 0", "Go") + agent(3, true, "3, 0, 0", "Wait") + "tick 2\n" +
                                agent(0, false, "0, 1, 2", "Go") + agent(1, false, "1, 2, 1", "Wait") +
                                agent(2, false, "2, 1, 2", "Go") + agent(3, false, "3, 2, 1", "Wait") + "tick 3\n" +
                                agent(0, true, "0, 1, 2", "Wait") + agent(1, false, "1, 2, 1", "Wait") +
                                agent(2, false, "2, 1, 2", "Go") + agent(3, false, "3, 2, 1", "Wait") + "tick 4\n" +
                                agent(0, false, "0, 1, 2", "Wait") + agent(1, false, "1, 1, 2", "Wait") +
                                agent(2, false, "2, 0, 3", "Go") + agent(3, false, "3, 1, 2", "Wait"));
  // Explained: each agent's part one level deeper, and the exchange after the tick.
  std::string explained = r.log.render({false, true, true});
  CHECK(explained.find("tick 3\n  agent 0\n    cond T0 = true\n      call Move() = true\n") != std::string::npos);
  CHECK(explained.find("  team Wait Wait Go Wait\ntick 4\n") != std::string::npos);
}

TEST_CASE("interpreter fsm: the engine's team API") {
  auto c = compile(R"(
fsm Census {
  team 4;
  initial state Go;
  state Wait;
  Go -> Wait when team(Wait) > 1;
})");
  interp::Machine e(c->model, model::ChartId(0));
  CHECK(e.team_size() == 4);
  e.set_agent(2);
  const model::PlaceId wait(1);
  e.report(2, wait);  // its own number
  e.report(4, wait);  // no such agent
  e.report(-1, wait);
  e.report(0, model::PlaceId(2));  // no such state
  const std::vector<model::PlaceId> none(4, model::PlaceId::none());
  CHECK(e.reports() == none);
  e.report(0, wait);
  e.report(3, wait);
  e.set_agent(9);  // ignored
  CHECK(e.agent() == 2);
  ScriptedEnv env(*c);
  e.run(env, nullptr);
  CHECK(e.state() == wait);  // two others in Wait
  e.init();
  CHECK(e.agent() == 0);
  CHECK(e.reports() == none);
}
