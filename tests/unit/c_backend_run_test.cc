// Compile-and-run tests of the C engine: each chart's engine is compiled with gcc and clang at
// -std=c99 -Wall -Wextra -Wpedantic -Werror, linked with a harness that scripts the sensing
// functions tick by tick and logs every call, and run. The expected logs are written by hand
// from docs/language.md §5.1 and §7, never produced by the engine.
#include "../run/c_backend_support.h"
#include "../run/shared_charts.h"

#include <catch2/catch.hpp>

using namespace cbt;
using gfec::test::charts::kFsmEntryExit;
using gfec::test::charts::kIfElse;

namespace {

/// Compiles chart text (with every file it imports) through the real front end and the C back
/// end, then compiles and runs the engine on `script`: the log (see cbt::harness_source()). Every
/// chart runs in both engine forms (c_layout.h), which must write the same log.
std::string run_files(const std::string &test, const std::map<std::string, std::string> &files, const std::string &main,
                      const std::string &script, const std::string &defines = "") {
  std::string logs[2];
  const EngineForm forms[2] = {EngineForm::Readable, EngineForm::Scalable};
  for (int f = 0; f < 2; ++f) {
    auto compiled = compile_chart(files, main, "engine.c", true, forms[f]);
    INFO(compiled->errors);
    REQUIRE(!compiled->diag.has_errors());
    logs[f] = compile_and_run(test + (f == 0 ? "" : "_scalable"), compiled->files, compiled->model,
                              compiled->the_chart(), script, defines);
  }
  INFO("the scalable engine's log differs from the readable one's");
  CHECK(logs[1] == logs[0]);
  return logs[0];
}

std::string run(const std::string &test, const std::string &chart, const std::string &script,
                const std::string &defines = "") {
  return run_files(test, {{"chart.sfc", chart}}, "chart.sfc", script, defines);
}

/// A sample chart and the interface it imports, as users have them.
std::string run_sample(const std::string &test, const std::string &chart, const std::string &iface,
                       const std::string &script, const std::string &defines = "") {
  fs::path samples = fs::path(GFEC_SOURCE_DIR) / "samples";
  return run_files(test, {{chart, read_file(samples / chart)}, {iface, read_file(samples / iface)}}, chart, script,
                   defines);
}

}  // namespace

TEST_CASE("c engine run: line follower, activation produced in a tick waits for the next", "[c_backend][run]") {
  std::string log = run_sample("line_follower", "line_follower.sfc", "linebot.iface",
                               "\n"
                               "Left_IR_Black\n"
                               "Left_IR_Black Right_IR_Black Left_IR_White\n"
                               "Left_IR_White\n");
  CHECK(log == "tick 1\n"
               "cond Left_IR_Black -> 0\n"  // T0 open; T1 not (LeftStop empty), so no call
               "cond Right_IR_Black -> 0\n"
               "act Left_FW\n"
               "act Right_FW\n"
               "av LeftFw RightFw\n"
               "tick 2\n"
               "cond Left_IR_Black -> 1\n"   // T0 fires; LeftStop's new activation is not
               "cond Right_IR_Black -> 0\n"  // available to T1 in this tick: no Left_IR_White
               "act Left_Stop\n"             // actions after the update
               "act Right_FW\n"
               "av LeftStop RightFw\n"
               "tick 3\n"
               "cond Left_IR_White -> 1\n"  // T0 closed: no Left_IR_Black
               "cond Right_IR_Black -> 1\n"
               "act Left_FW\n"
               "act Right_Stop\n"
               "av LeftFw RightStop\n"
               "tick 4\n"
               "cond Left_IR_Black -> 0\n"
               "cond Right_IR_White -> 0\n"
               "act Left_FW\n"
               "act Right_Stop\n"
               "av LeftFw RightStop\n");
}

TEST_CASE("c engine run: conflicts go to the first open transition whose condition holds", "[c_backend][run]") {
  std::string log = run("conflict", R"(
interface Bot { bool X(); bool Y(); bool Z(); void DoA(); void DoB(); void DoC(); }
sfc Conflict {
  initial place A { DoA(); }
  place B { DoB(); }
  place C { DoC(); }
  transition A -> B when X() && Y();
  transition A -> C when Z();
  transition B -> A;
  transition C -> A;
})",
                        "Y Z\n"
                        "X Y Z\n"
                        "X Y Z\n"
                        "\n");
  CHECK(log == "tick 1\n"
               "cond X -> 0\n"  // && short-circuits: Y is not asked
               "cond Z -> 1\n"  // the second transition takes A
               "act DoC\n"
               "av C\n"
               "tick 2\n"  // A is empty at the start: neither condition is asked; C -> A fires
               "act DoA\n"
               "av A\n"
               "tick 3\n"
               "cond X -> 1\n"
               "cond Y -> 1\n"  // the first transition takes A; the second is closed: no Z
               "act DoB\n"
               "av B\n"
               "tick 4\n"
               "act DoA\n"
               "av A\n");
}

TEST_CASE("c engine run: counters above one", "[c_backend][run]") {
  std::string log = run("count", R"(
interface Bot { bool More(); bool Take(); void DoA(); void DoB(); }
sfc Count {
  initial place A { DoA(); }
  place B { DoB(); }
  place C;
  place D;
  transition Grow: A -> (A, B) when More();
  transition B -> C when Take();
  transition Again: C -> (B, D);
})",
                        "More\n"
                        "More\n"
                        "Take\n"
                        "\n");
  CHECK(log == "tick 1\n"
               "cond More -> 1\n"  // A -> (A, B): B's token is new, T1 stays closed
               "act DoA\n"
               "act DoB\n"
               "av A B\n"
               "tick 2\n"
               "cond More -> 1\n"
               "cond Take -> 0\n"
               "act DoA\n"
               "act DoB\n"  // once, whatever the count
               "av A B:2\n"
               "tick 3\n"
               "cond More -> 0\n"
               "cond Take -> 1\n"  // a transition fires at most once per tick
               "act DoA\n"
               "act DoB\n"
               "av A B C\n"
               "tick 4\n"
               "cond More -> 0\n"
               "cond Take -> 0\n"  // C -> (B, D): B back to two
               "act DoA\n"
               "act DoB\n"
               "av A B:2 D\n");
}

namespace {

const char *kJoin = R"(
interface Bot {
  bool Again(); bool Go(); bool BackAgain();
  void EnterA(); void ExitA(); void DoA(); void ExitB(); void EnterC(); void ExitC(); void DoC();
}
sfc Join {
  initial place A { entry { EnterA(); } exit { ExitA(); } DoA(); }
  initial place B { exit { ExitB(); } }
  place C { entry { EnterC(); } exit { ExitC(); } DoC(); }
  transition Loop: A -> A when Again();
  transition Sync: (A, B) -> C when Go();
  transition Back: C -> (A, B) when BackAgain();
})";

const char *kJoinScript = "\n"
                          "Again Go\n"
                          "Go\n"
                          "BackAgain\n";

}  // namespace

TEST_CASE("c engine run: join, entry and exit, lost and regained in one tick", "[c_backend][run]") {
  std::string log = run("join", kJoin, kJoinScript);
  CHECK(log == "tick 1\n"
               "act EnterA\n"  // the first tick: entries of the initial places
               "cond Again -> 0\n"
               "cond Go -> 0\n"
               "act DoA\n"
               "av A B\n"
               "tick 2\n"
               "cond Again -> 1\n"  // Loop takes A: Sync is closed (no Go); A lost and regained
               "act DoA\n"          // its activation: no exit, no entry
               "av A B\n"
               "tick 3\n"
               "cond Again -> 0\n"
               "cond Go -> 1\n"
               "act ExitA\n"  // all exits in declaration order, then the entries
               "act ExitB\n"
               "act EnterC\n"
               "act DoC\n"
               "av C\n"
               "tick 4\n"
               "cond BackAgain -> 1\n"
               "act ExitC\n"
               "act EnterA\n"
               "act DoA\n"
               "av A B\n");
}

TEST_CASE("c engine run: observation hooks with -DX_HOOKS", "[c_backend][run]") {
  std::string log = run("join_hooks", kJoin, kJoinScript, "-DJoin_HOOKS");
  CHECK(log == "tick 1\n"
               "act EnterA\n"
               "cond Again -> 0\n"
               "cond Go -> 0\n"
               "act DoA\n"
               "av A B\n"
               "tick 2\n"
               "cond Again -> 1\n"  // A active at both ends of the tick: no hook
               "act DoA\n"
               "av A B\n"
               "tick 3\n"
               "cond Again -> 0\n"
               "cond Go -> 1\n"
               "act ExitA\n"
               "act ExitB\n"
               "act EnterC\n"
               "hook lost A\n"  // after exits and entries, before the actions
               "hook lost B\n"
               "hook gained C\n"
               "hook enabled Back\n"
               "act DoC\n"
               "av C\n"
               "tick 4\n"
               "cond BackAgain -> 1\n"
               "act ExitC\n"
               "act EnterA\n"
               "hook lost C\n"
               "hook gained A\n"
               "hook gained B\n"
               "hook enabled Loop\n"
               "hook enabled Sync\n"
               "act DoA\n"
               "av A B\n");
}

TEST_CASE("c engine run: timers count whole ticks from the tick a place became active", "[c_backend][run]") {
  std::string log = run("timer", R"(
interface Bot { bool Start(); void Waiting(); void Finished(); }
sfc Timer {
  period 30ms;
  initial place Idle;
  place Wait { Waiting(); }
  place Done { Finished(); }
  transition Idle -> Wait when Start();
  transition Wait -> Done when elapsed(Wait) >= 100ms;   // 100 / 30 rounded up: 4 ticks
  transition Done -> Wait when Start();
})",
                        "Start\n\n\n\n\nStart\n\n\n\n\n");
  std::string wait = "act Waiting\nav Wait\n";
  CHECK(log == "tick 1\ncond Start -> 1\n" + wait +   // Wait's timer is 0 at the end of tick 1
                   "tick 2\n" + wait +                // 1
                   "tick 3\n" + wait +                // 2
                   "tick 4\n" + wait +                // 3
                   "tick 5\nact Finished\nav Done\n"  // 4 >= 4
                   "tick 6\ncond Start -> 1\n" +
                   wait +  // back to Wait: the timer starts again at 0
                   "tick 7\n" + wait + "tick 8\n" + wait + "tick 9\n" + wait + "tick 10\nact Finished\nav Done\n");
}

TEST_CASE("c engine run: a duration shorter than the period is one tick, not none", "[c_backend][run]") {
  // 1e-9ms rounds up to one tick of 10 ms (docs/language.md "Time"): false in the tick Wait is
  // entered (its timer is 0), true from the next; as 0 ticks it was true at once.
  std::string log = run("tiny_duration", R"(
interface Bot { void Waiting(); void Late(); }
sfc Tiny {
  period 10ms;
  initial place Idle;
  place Wait { if (elapsed(Wait) >= 1e-9ms) { Late(); } Waiting(); }
  transition Idle -> Wait;
})",
                        "\n\n\n");
  CHECK(log == "tick 1\nact Waiting\nav Wait\n"
               "tick 2\nact Late\nact Waiting\nav Wait\n"
               "tick 3\nact Late\nact Waiting\nav Wait\n");
}

TEST_CASE("c engine run: an initial place's timer counts from the first tick", "[c_backend][run]") {
  std::string log = run("warm", R"(
interface Bot { void Heating(); void Serve(); }
sfc Warm {
  period 10ms;
  initial place Heat { Heating(); }
  place Ready { Serve(); }
  transition Heat -> Ready when elapsed(Heat) >= 20ms;
})",
                        "\n\n\n");
  CHECK(log == "tick 1\nact Heating\nav Heat\n"  // active since _init: 1 tick at step 1
               "tick 2\nact Serve\nav Ready\n"   // 2 ticks = 20ms
               "tick 3\nact Serve\nav Ready\n");
}

TEST_CASE("c engine run: variables and constants", "[c_backend][run]") {
  std::string log = run("laps", R"(
interface Bot { void Report(int n); void Halt(); void Speed(float s); }
const float HALF = 0.5;
sfc Laps {
  var int laps = 0;
  var float speed = HALF;
  const int LAPS = 3;
  initial place Run { laps += 1; speed -= 0.125; Report(laps); Speed(speed * 2.0 - -HALF); }
  place Stop { Halt(); }
  transition Run -> Stop when laps >= LAPS;
})",
                        "\n\n\n\n\n");
  CHECK(log == "tick 1\nact Report(1)\nact Speed(1.25)\nav Run\n"
               "tick 2\nact Report(2)\nact Speed(1)\nav Run\n"
               "tick 3\nact Report(3)\nact Speed(0.75)\nav Run\n"
               "tick 4\nact Halt\nav Stop\n"
               "tick 5\nact Halt\nav Stop\n");
}

namespace {

const char *kCleanUpScript = "\n"
                             "Arrived Holding\n"
                             "Holding FarFromDestination\n"
                             "\n"
                             "Holding\n"
                             "ItemPlaced ItemAtDestination\n"
                             "Arrived\n";

std::string cleanup_log(bool checks) {
  return std::string("tick 1\n"
                     "cond Arrived -> 0\n"
                     "cond Stuck -> 0\n"  // only the transitions leaving Z0 are asked
                     "act DriveToItem\n"
                     "state Z0 status 0\n"
                     "tick 2\n"
                     "cond Arrived -> 1\n"  // one transition per tick: Z1's are not tried
                     "act PickUp\n"         // the action of the new state
                     "state Z1 status 0\n"
                     "tick 3\n"
                     "cond Holding -> 1\n"
                     "cond FarFromDestination -> 1\n"
                     "act Transport\n"
                     "state Z2 status 0\n"
                     "tick 4\n"
                     "cond Arrived -> 0\n"
                     "cond Holding -> 0\n"  // dropped: back to Z1
                     "act PickUp\n"
                     "state Z1 status 0\n"
                     "tick 5\n"
                     "cond Holding -> 1\n"
                     "cond FarFromDestination -> 0\n"
                     "cond Holding -> 1\n"
                     "cond FarFromDestination -> 0\n"
                     "act PlaceItem\n"
                     "state Z3 status 0\n"
                     "tick 6\n"
                     "cond ItemPlaced -> 1\n") +
         (checks ? "cond ItemAtDestination -> 1\n" : "") +
         "state Done status 1\n"
         "tick 7\n"  // terminal: nothing happens
         "state Done status 1\n";
}

std::string run_cleanup(const std::string &test, const std::string &script, const std::string &defines = "") {
  return run_sample(test, "cleanup.fsm", "cleanbot.iface", script, defines);
}

}  // namespace

TEST_CASE("c engine run: fsm clean-up, one transition per tick, terminal state stops", "[c_backend][run]") {
  CHECK(run_cleanup("cleanup", kCleanUpScript) == cleanup_log(false));
}

TEST_CASE("c engine run: fsm postconditions are asserted with -DX_CHECKS", "[c_backend][run]") {
  CHECK(run_cleanup("cleanup_checks", kCleanUpScript, "-DCleanUp_CHECKS") == cleanup_log(true));
  // ItemAtDestination() false on entering Done: the assertion stops the program.
  fs::path samples = fs::path(GFEC_SOURCE_DIR) / "samples";
  auto compiled = compile_chart(
      {{"cleanup.fsm", read_file(samples / "cleanup.fsm")}, {"cleanbot.iface", read_file(samples / "cleanbot.iface")}},
      "cleanup.fsm", "engine.c");
  REQUIRE(!compiled->diag.has_errors());
  std::string log = compile_and_run("cleanup_checks_fail", compiled->files, compiled->model, compiled->the_chart(),
                                    "\nArrived\nHolding\nItemPlaced\n", "-DCleanUp_CHECKS", false);
  CHECK(log.find("cond ItemPlaced -> 1\ncond ItemAtDestination -> 0\n") != std::string::npos);
  CHECK(log.find("cleanup.fsm:12") != std::string::npos);  // the assertion names the chart's line
  CHECK(log.find("state Done") == std::string::npos);
}

TEST_CASE("c engine run: fsm failure state", "[c_backend][run]") {
  CHECK(run_cleanup("cleanup_failed", "Stuck\nArrived\n") == "tick 1\n"
                                                             "cond Arrived -> 0\n"
                                                             "cond Stuck -> 1\n"
                                                             "state Failed status -1\n"
                                                             "tick 2\n"
                                                             "state Failed status -1\n");
}

namespace {

const char *kBlink = R"(
interface Bot { bool Stop(); void LedOn(); void LedOff(); }
fsm Blink {
  period 10ms;
  initial state On { LedOn(); }
  state Off { LedOff(); }
  success state Done;
  On -> Off when elapsed(On) >= 20ms;
  Off -> Done when Stop();
  Off -> On when elapsed(Off) >= 10ms;
})";

}  // namespace

TEST_CASE("c engine run: fsm timers", "[c_backend][run]") {
  std::string log = run("blink", kBlink, "\n\n\n\n\nStop\n\n");
  CHECK(log == "tick 1\nact LedOn\nstate On status 0\n"                  // On's timer: 1
               "tick 2\nact LedOff\nstate Off status 0\n"                // 2 >= 2: to Off, whose timer starts at 0
               "tick 3\ncond Stop -> 0\nact LedOn\nstate On status 0\n"  // Off's timer 1 >= 1
               "tick 4\nact LedOn\nstate On status 0\n"
               "tick 5\nact LedOff\nstate Off status 0\n"
               "tick 6\ncond Stop -> 1\nstate Done status 1\n"
               "tick 7\nstate Done status 1\n");
}

TEST_CASE("c engine run: fsm hooks", "[c_backend][run]") {
  std::string log = run("blink_hooks", kBlink, "\n\n\nStop\n", "-DBlink_HOOKS");
  CHECK(log == "tick 1\nact LedOn\nstate On status 0\n"
               "tick 2\n"
               "hook lost On\nhook gained Off\nhook enabled T1\nhook enabled T2\n"  // before the action
               "act LedOff\nstate Off status 0\n"
               "tick 3\ncond Stop -> 0\n"
               "hook lost Off\nhook gained On\nhook enabled T0\n"
               "act LedOn\nstate On status 0\n"
               "tick 4\nact LedOn\nstate On status 0\n");
}

TEST_CASE("c engine run: several engines side by side share nothing", "[c_backend][run]") {
  fs::path samples = fs::path(GFEC_SOURCE_DIR) / "samples";
  for (auto form : {EngineForm::Readable, EngineForm::Scalable}) {
    auto compiled = compile_chart({{"line_follower.sfc", read_file(samples / "line_follower.sfc")},
                                   {"linebot.iface", read_file(samples / "linebot.iface")}},
                                  "line_follower.sfc", "engine.c", true, form);
    REQUIRE(!compiled->diag.has_errors());
    fs::path dir = scratch_dir(form == EngineForm::Readable ? "side_by_side" : "side_by_side_scalable");
    for (const auto &f : compiled->files) write_file(dir / f.path, f.contents);
    write_file(dir / "main.c", R"(#include "engine.h"
#include <stdio.h>
static bool black = false;
bool Left_IR_Black(void) { return black; }
bool Left_IR_White(void) { return !black; }
bool Right_IR_Black(void) { return false; }
bool Right_IR_White(void) { return true; }
void Left_FW(void) {}
void Left_Stop(void) {}
void Right_FW(void) {}
void Right_Stop(void) {}
int main(void)
{
    LineFollower a, b;
    LineFollower_init(&a);
    LineFollower_init(&b);
    black = true;
    LineFollower_run(&a);
    printf("a %u %u b %u %u\n", LineFollower_activation(&a, LineFollower_LeftFw),
           LineFollower_activation(&a, LineFollower_LeftStop), LineFollower_activation(&b, LineFollower_LeftFw),
           LineFollower_activation(&b, LineFollower_LeftStop));
    printf("out of range %u %u\n", LineFollower_activation(&a, -1), LineFollower_activation(&a, LineFollower_PLACE_COUNT));
    return 0;
}
)");
    for (const auto &cc : c_compilers()) {
      auto build =
          run_command(fmt::format("cd '{}' && {} {} main.c engine.c -o run-{}", dir.string(), cc, kStrictFlags, cc),
                      dir / "build.log");
      INFO(build.output);
      REQUIRE(build.status == 0);
      auto out = run_command(fmt::format("'{}/run-{}'", dir.string(), cc), dir / "run.log");
      CHECK(out.output == "a 0 1 b 1 0\nout of range 0 0\n");
    }
  }
}

// ------------------------------------------------------------------ where C reads a chart differently
// Found by the differential tests (docs/verification.md): each chart below failed there before
// the back end wrote what the chart means rather than what C would make of its spelling.

TEST_CASE("c engine run: int literals are decimal, a leading zero is not octal", "[c_backend][run]") {
  // C reads 010 as 8; docs/language.md says 10. Floats with leading zeros are
  // decimal in C too.
  std::string log = run("octal", R"(
interface Bot { void A(int n); void B(double x); }
const int K = 010 + 1;
sfc Octal {
  var int v = 010;
  initial place P { A(010); A(00); A(v + 007); A(K); v += 010; A(v); A(-010 * 2); B(010.5); B(0010e-1); }
  place Q;
  transition P -> Q when v == 030;
})",
                        "\n\n\n");
  const std::string actions =
      "act A(10)\nact A(0)\nact A({})\nact A(11)\nact A({})\nact A(-20)\nact B(10.5)\nact B(1)\n";
  CHECK(log == "tick 1\n" + fmt::format(actions, 17, 20) +
                   "av P\n"  // v: 10, then 20
                   "tick 2\n" +
                   fmt::format(actions, 27, 30) +
                   "av P\n"    // v: 20, then 30
                   "tick 3\n"  // v == 30 (octal 030 would be 24)
                   "av Q\n");
}

TEST_CASE("c engine run: a floating value becomes an int by truncation, written as a cast", "[c_backend][run]") {
  // Without the casts clang rejects the engine (-Wliteral-conversion, and
  // -Wimplicit-const-int-float-conversion for 16777217, which a float cannot hold).
  std::string log = run("float_into_int", R"(
interface Bot { void I(int n); void J(int a, float b); void E(bool b); float F(); double D(); int H(int n); }
sfc Trunc {
  var int v = 2.75;
  var int w = -1.5 * 3;
  var float g = 16777217;
  var float f = 0.5;
  initial place P {
    I(v); I(w);
    I(0.25); I(-1.75); I(F());
    J(D() * 2, 1);
    v = 0.5; I(v);
    v += 2.5; I(v);
    v -= f; I(v);
    v = -3; v += f; I(v);
    E(g == 16777216);
  }
  place Q;
  transition P -> Q when H(2.5) == 3;
})",
                        "F=3.9 D=1.3\n"
                        "F=-2.5 D=-0.7\n");
  CHECK(log == "tick 1\n"
               "call H(2)\n"  // 2.5 -> 2
               "cond H -> 0\n"
               "act I(2)\n"   // v = 2.75 -> 2
               "act I(-4)\n"  // w = -4.5 -> -4: toward zero
               "act I(0)\n"
               "act I(-1)\n"
               "cond F -> 3.9\n"
               "act I(3)\n"
               "cond D -> 1.3\n"
               "act J(2, 1)\n"  // 2.6 -> 2
               "act I(0)\n"     // v = 0.5
               "act I(2)\n"     // v = (int)(0 + 2.5)
               "act I(1)\n"     // v = (int)(2 - 0.5f)
               "act I(-2)\n"    // v = (int)(-3 + 0.5f): -2.5 -> -2, not -3 + (int)0.5
               "act E(1)\n"     // g holds 16777216
               "av P\n"
               "tick 2\n"
               "call H(2)\n"
               "cond H -> 0\n"
               "act I(-2)\n"
               "act I(-4)\n"
               "act I(0)\n"
               "act I(-1)\n"
               "cond F -> -2.5\n"
               "act I(-2)\n"
               "cond D -> -0.7\n"
               "act J(-1, 1)\n"  // -1.4 -> -1
               "act I(0)\n"
               "act I(2)\n"
               "act I(1)\n"
               "act I(-2)\n"
               "act E(1)\n"
               "av P\n");
}

namespace {

const char *kOrder = R"(
interface Bot {
  int S0(); int S1(); int S2(); bool B(); bool C();
  int Twice(int a, int b);
  void A(int x, bool y); void Three(int a, int b, int c); void Stop();
}
sfc Order {
  period 10ms;
  var int v = 0;
  initial place P {
    entry { Three(S0(), S1(), S2()); }
    A(S2(), S0() < 2);
    Three(S0(), S1() + S2(), -S0());
    v = S1() - S2() * S0();
    A(v, B() && C() == B());
    A(Twice(S1(), S2()), B() || C() != (S0() > S1()));
  }
  place Q { entry { A(S1(), S0() > 0); } Stop(); }
  transition P -> Q when S0() + S1() > S2() && (B() || S2() < S1() - S0());
  transition Q -> P when elapsed(Q) >= 1s && B();
})";

}  // namespace

TEST_CASE("c engine run: calls are made left to right, in arguments and operands alike", "[c_backend][run]") {
  // gcc evaluates arguments right to left; C leaves the order open. docs/language.md §4, §5.1: left
  // to right, && and || short-circuiting. Both engine forms (the scalable one is a switch).
  std::string log = run("call_order", kOrder,
                        "S0=1 S1=2 S2=3 Twice=7\n"
                        "S0=2 S1=2 S2=3 C Twice=5\n"
                        "S0=1 S1=1 S2=3 B C Twice=4\n"
                        "S0=1 S1=3 S2=3 B\n"
                        "\n");
  CHECK(log == "tick 1\n"
               "cond S0 -> 1\n"  // entry P: Three(S0(), S1(), S2())
               "cond S1 -> 2\n"
               "cond S2 -> 3\n"
               "act Three(1, 2, 3)\n"
               "cond S0 -> 1\n"  // T0: S0() + S1() > S2() is false; && stops there
               "cond S1 -> 2\n"
               "cond S2 -> 3\n"
               "cond S2 -> 3\n"  // A(S2(), S0() < 2)
               "cond S0 -> 1\n"
               "act A(3, 1)\n"
               "cond S0 -> 1\n"  // Three(S0(), S1() + S2(), -S0())
               "cond S1 -> 2\n"
               "cond S2 -> 3\n"
               "cond S0 -> 1\n"
               "act Three(1, 5, -1)\n"
               "cond S1 -> 2\n"  // v = S1() - S2() * S0() = -1
               "cond S2 -> 3\n"
               "cond S0 -> 1\n"
               "cond B -> 0\n"  // B() && ...: false, C() == B() is not evaluated
               "act A(-1, 0)\n"
               "cond S1 -> 2\n"  // Twice(S1(), S2()) before B() || ...
               "cond S2 -> 3\n"
               "call Twice(2, 3)\n"
               "cond Twice -> 7\n"
               "cond B -> 0\n"
               "cond C -> 0\n"  // C() != (S0() > S1())
               "cond S0 -> 1\n"
               "cond S1 -> 2\n"
               "act A(7, 0)\n"
               "av P\n"
               "tick 2\n"
               "cond S0 -> 2\n"  // T0: 4 > 3, then B() || S2() < S1() - S0()
               "cond S1 -> 2\n"
               "cond S2 -> 3\n"
               "cond B -> 0\n"
               "cond S2 -> 3\n"
               "cond S1 -> 2\n"
               "cond S0 -> 2\n"  // 3 < 0: T0 does not fire
               "cond S2 -> 3\n"
               "cond S0 -> 2\n"
               "act A(3, 0)\n"
               "cond S0 -> 2\n"
               "cond S1 -> 2\n"
               "cond S2 -> 3\n"
               "cond S0 -> 2\n"
               "act Three(2, 5, -2)\n"
               "cond S1 -> 2\n"  // v = 2 - 3 * 2
               "cond S2 -> 3\n"
               "cond S0 -> 2\n"
               "cond B -> 0\n"
               "act A(-4, 0)\n"
               "cond S1 -> 2\n"
               "cond S2 -> 3\n"
               "call Twice(2, 3)\n"
               "cond Twice -> 5\n"
               "cond B -> 0\n"
               "cond C -> 1\n"  // 1 != (2 > 2)
               "cond S0 -> 2\n"
               "cond S1 -> 2\n"
               "act A(5, 1)\n"
               "av P\n"
               "tick 3\n"
               "cond S0 -> 1\n"  // T0: 2 > 3 is false
               "cond S1 -> 1\n"
               "cond S2 -> 3\n"
               "cond S2 -> 3\n"
               "cond S0 -> 1\n"
               "act A(3, 1)\n"
               "cond S0 -> 1\n"
               "cond S1 -> 1\n"
               "cond S2 -> 3\n"
               "cond S0 -> 1\n"
               "act Three(1, 4, -1)\n"
               "cond S1 -> 1\n"  // v = 1 - 3 * 1
               "cond S2 -> 3\n"
               "cond S0 -> 1\n"
               "cond B -> 1\n"  // B() && C() == B(): C() before the second B()
               "cond C -> 1\n"
               "cond B -> 1\n"
               "act A(-2, 1)\n"
               "cond S1 -> 1\n"
               "cond S2 -> 3\n"
               "call Twice(1, 3)\n"
               "cond Twice -> 4\n"
               "cond B -> 1\n"  // || decided: nothing more
               "act A(4, 1)\n"
               "av P\n"
               "tick 4\n"
               "cond S0 -> 1\n"  // T0: 4 > 3 and B(): P -> Q
               "cond S1 -> 3\n"
               "cond S2 -> 3\n"
               "cond B -> 1\n"
               "cond S1 -> 3\n"  // entry Q: A(S1(), S0() > 0)
               "cond S0 -> 1\n"
               "act A(3, 1)\n"
               "act Stop\n"
               "av Q\n"
               "tick 5\n"  // T1: elapsed(Q) is 1 tick of 100: && stops before B()
               "act Stop\n"
               "av Q\n");
}

namespace {

const char *kOrderFsm = R"(
interface Bot { int S0(); int S1(); void Log(int a, int b); }
fsm Machine {
  initial state Z0 { Log(S0(), S1()); }
  success state Done post S0() < S1();
  Z0 -> Done when S1() > S0();
})";

std::string order_fsm_log(bool checks) {
  return std::string("tick 1\n"
                     "cond S1 -> 1\n"  // S1() > S0(): 1 > 2 is false
                     "cond S0 -> 2\n"
                     "cond S0 -> 2\n"  // Log(S0(), S1())
                     "cond S1 -> 1\n"
                     "act Log(2, 1)\n"
                     "state Z0 status 0\n"
                     "tick 2\n"
                     "cond S1 -> 2\n"  // 2 > 1: to Done
                     "cond S0 -> 1\n") +
         (checks ? "cond S0 -> 1\ncond S1 -> 2\n" : "") +  // the postcondition, left to right
         "state Done status 1\n";
}

}  // namespace

TEST_CASE("c engine run: fsm calls left to right in conditions, actions and postconditions", "[c_backend][run]") {
  const char *script = "S0=2 S1=1\nS0=1 S1=2\n";
  CHECK(run("call_order_fsm", kOrderFsm, script) == order_fsm_log(false));
  CHECK(run("call_order_fsm_checks", kOrderFsm, script, "-DMachine_CHECKS") == order_fsm_log(true));
  // With NDEBUG assert() reads nothing: the temporaries it would use are left out too (else unused).
  CHECK(run("call_order_fsm_ndebug", kOrderFsm, script, "-DMachine_CHECKS -DNDEBUG") == order_fsm_log(false));
}

TEST_CASE("c engine run: if, else if and else", "[c_backend][run]") {
  std::string log = run("if_else", kIfElse,
                        "X N=2 M=1\n"
                        "\n"
                        "Y\n"
                        "Y X\n"
                        "\n"
                        "X Y\n");
  CHECK(log == "tick 1\n"
               "cond X -> 1\n"  // the first tick: P's entry, the then-branch
               "act A\n"
               "cond N -> 2\n"  // k < 2: the transition asks nothing; N() before M()
               "cond M -> 1\n"
               "cond N -> 2\n"  // 3 > 2: the first branch
               "act B(2)\n"
               "av P\n"  // elapsed(P) is 1 tick, below 2: no B(k)
               "tick 2\n"
               "cond N -> 0\n"
               "cond M -> 0\n"
               "cond Y -> 0\n"  // else if fails: else
               "act D\n"
               "act B(0)\n"  // 2 ticks: 20ms
               "av P\n"
               "tick 3\n"
               "cond N -> 0\n"
               "cond M -> 0\n"
               "cond Y -> 1\n"
               "cond X -> 0\n"  // the nested if without else does nothing; k becomes 1
               "act B(1)\n"
               "av P\n"
               "tick 4\n"
               "cond N -> 0\n"
               "cond M -> 0\n"
               "cond Y -> 1\n"
               "cond X -> 1\n"
               "act C\n"  // k becomes 2
               "act B(2)\n"
               "av P\n"
               "tick 5\n"  // k >= 2: P -> Q
               "act D\n"
               "av Q\n"
               "tick 6\n"
               "cond X -> 1\n"  // Q -> P
               "cond Y -> 1\n"  // Q's exit
               "act B(2)\n"
               "cond X -> 1\n"  // P's entry
               "act A\n"
               "cond N -> 0\n"
               "cond M -> 0\n"
               "cond Y -> 1\n"
               "cond X -> 1\n"
               "act C\n"  // k becomes 3; P's timer was reset: no B(k)
               "av P\n");
}

TEST_CASE("c engine run: if in an fsm, and the if/else chain in the generated C", "[c_backend][run]") {
  const char *chart = R"(
interface Bot { bool X(); bool Y(); void A(); void B(); void C(); }
fsm Choice {
  var int n = 0;
  initial state S {
    if (X()) { A(); } else if (Y()) { B(); } else { C(); }
    n += 1;
  }
  success state Done;
  S -> Done when n >= 3;
})";
  std::string log = run("if_fsm", chart, "X\nY\n\nX Y\n");
  CHECK(log == "tick 1\ncond X -> 1\nact A\nstate S status 0\n"
               "tick 2\ncond X -> 0\ncond Y -> 1\nact B\nstate S status 0\n"
               "tick 3\ncond X -> 0\ncond Y -> 0\nact C\nstate S status 0\n"
               "tick 4\nstate Done status 1\n");  // n is 3: the machine ends, no action
  auto compiled = compile_chart({{"chart.sfc", chart}}, "chart.sfc", "engine.c", false);
  REQUIRE(!compiled->diag.has_errors());
  const std::string &c = compiled->files.at(0).contents;
  // Inside the tick's `if (m->status == 0)` (one exit: docs/misra.md).
  CHECK(c.find("            if (X()) {\n"
               "                A();\n"
               "            } else if (Y()) {\n"
               "                B();\n"
               "            } else {\n"
               "                C();\n"
               "            }\n"
               "            m->n += 1;\n") != std::string::npos);
}

namespace {

const char *kFsmEntryExitScript = "\nGo\n\nBack\nGo\nFin\nGo Back Fin\n";

}  // namespace

TEST_CASE("c engine run: fsm entry and exit", "[c_backend][run]") {
  std::string log = run("fsm_entry_exit_text", kFsmEntryExit, kFsmEntryExitScript);
  CHECK(log == "tick 1\n"
               "act EnterA\n"  // the first tick begins with the initial state's entry
               "cond Go -> 0\n"
               "act DoA\n"
               "state A status 0\n"
               "tick 2\n"
               "cond Go -> 1\n"
               "act ExitA\n"   // the old state's exit, then the new state's entry: its
               "act EnterB\n"  // timer is 0, so no Late()
               "act DoB\n"
               "state B status 0\n"
               "tick 3\n"
               "cond Back -> 0\n"
               "cond Fin -> 0\n"
               "act DoB\n"
               "act Late\n"  // one tick in B
               "state B status 0\n"
               "tick 4\n"
               "cond Back -> 1\n"
               "act ExitB\n"
               "act EnterA\n"
               "act DoA\n"
               "state A status 0\n"
               "tick 5\n"
               "cond Go -> 1\n"
               "act ExitA\n"
               "act EnterB\n"  // B's timer starts again from 0
               "act DoB\n"
               "state B status 0\n"
               "tick 6\n"
               "cond Back -> 0\n"
               "cond Fin -> 1\n"
               "act ExitB\n"  // a terminal state has no entry and no action
               "state Done status 1\n"
               "tick 7\n"  // nothing happens any more
               "state Done status 1\n");
  std::string hooks = run("fsm_entry_exit_hooks", kFsmEntryExit, "\nGo\n", "-DDoors_HOOKS");
  CHECK(hooks == "tick 1\nact EnterA\ncond Go -> 0\nact DoA\nstate A status 0\n"
                 "tick 2\ncond Go -> 1\nact ExitA\nact EnterB\n"
                 "hook lost A\nhook gained B\nhook enabled T1\nhook enabled T2\n"  // after exit and entry
                 "act DoB\nstate B status 0\n");
}

TEST_CASE("c engine run: an fsm's if (active(S)) tests the state without extra brackets", "[c_backend][run]") {
  // `if ((m->state == X))` is clang's -Wparentheses-equality (an error under -Werror): found by
  // gfec_differential --subcharts 2 --seed 11, case 8.
  const char *chart = R"(
interface Bot { bool X(); void A(); void B(); }
fsm Where {
  initial state S { if (active(S)) { A(); } else { B(); } }
  state T { if (active(S)) { A(); } else if (active(T)) { B(); } }
  S -> T when X();
})";
  // Tick 1: X() false, S stays and its action takes the then branch; tick 2: X() true, T is
  // entered and its action runs the else-if branch; tick 3: T stays (no transition leaves it).
  std::string log = run("if_active_fsm", chart, "\nX\n\n");
  CHECK(log == "tick 1\ncond X -> 0\nact A\nstate S status 0\n"
               "tick 2\ncond X -> 1\nact B\nstate T status 0\n"
               "tick 3\nact B\nstate T status 0\n");
  auto compiled = compile_chart({{"chart.sfc", chart}}, "chart.sfc", "engine.c", false);
  REQUIRE(!compiled->diag.has_errors());
  const std::string &c = compiled->files.at(0).contents;
  CHECK(c.find("if (m->state == Where_S) {") != std::string::npos);
  CHECK(c.find("} else if (m->state == Where_T) {") != std::string::npos);
}
