// Compile-and-run tests of the C engine: each chart's engine is compiled with gcc and clang at
// -std=c99 -Wall -Wextra -Wpedantic -Werror, linked with a harness that scripts the sensing
// functions tick by tick and logs every call, and run. The expected logs are written by hand
// from LANGUAGE.md §5.1 and §7, never produced by the engine.
#include "../run/c_backend_support.h"

#include <catch2/catch.hpp>

using namespace cbt;
using Kind = model::Chart::Kind;
using B = ChartBuilder;

namespace {

std::string run(const std::string &test, const ChartBuilder &b, const std::string &script,
                const std::string &defines = "") {
  auto files = emit_c(b.model(), "engine.c", true, "chart.sfc");
  return compile_and_run(test, files, b.model(), b.model().charts.front(), script, defines);
}

/* sfc LineFollower {
     initial place LeftFw { Left_FW(); }     place LeftStop  { Left_Stop(); }
     initial place RightFw { Right_FW(); }   place RightStop { Right_Stop(); }
     transition LeftFw -> LeftStop when Left_IR_Black();    transition LeftStop -> LeftFw when Left_IR_White();
     transition RightFw -> RightStop when Right_IR_Black(); transition RightStop -> RightFw when Right_IR_White(); } */
ChartBuilder line_follower() {
  ChartBuilder b("LineFollower", Kind::Sfc);
  for (const char *f : {"Left_IR_Black", "Left_IR_White", "Right_IR_Black", "Right_IR_White"}) b.fn(f, Type::Bool);
  for (const char *f : {"Left_FW", "Left_Stop", "Right_FW", "Right_Stop"}) b.fn(f);
  b.place("LeftFw", true, {b.act("Left_FW")});
  b.place("LeftStop", false, {b.act("Left_Stop")});
  b.place("RightFw", true, {b.act("Right_FW")});
  b.place("RightStop", false, {b.act("Right_Stop")});
  b.transition({"LeftFw"}, {"LeftStop"}, b.call("Left_IR_Black"));
  b.transition({"LeftStop"}, {"LeftFw"}, b.call("Left_IR_White"));
  b.transition({"RightFw"}, {"RightStop"}, b.call("Right_IR_Black"));
  b.transition({"RightStop"}, {"RightFw"}, b.call("Right_IR_White"));
  return b;
}

} // namespace

TEST_CASE("c engine run: line follower, activation produced in a tick waits for the next", "[c_backend][run]") {
  std::string log = run("line_follower", line_follower(),
                        "\n"
                        "Left_IR_Black\n"
                        "Left_IR_Black Right_IR_Black Left_IR_White\n"
                        "Left_IR_White\n");
  CHECK(log == "tick 1\n"
               "cond Left_IR_Black -> 0\n"   // T0 open; T1 not (LeftStop empty), so no call
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
               "cond Left_IR_White -> 1\n"   // T0 closed: no Left_IR_Black
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

/* sfc Conflict {
     initial place A { DoA(); }  place B { DoB(); }  place C { DoC(); }
     transition A -> B when X() && Y();
     transition A -> C when Z();
     transition B -> A;
     transition C -> A; } */
TEST_CASE("c engine run: conflicts go to the first open transition whose condition holds", "[c_backend][run]") {
  ChartBuilder b("Conflict", Kind::Sfc);
  for (const char *f : {"X", "Y", "Z"}) b.fn(f, Type::Bool);
  for (const char *f : {"DoA", "DoB", "DoC"}) b.fn(f);
  b.place("A", true, {b.act("DoA")});
  b.place("B", false, {b.act("DoB")});
  b.place("C", false, {b.act("DoC")});
  b.transition({"A"}, {"B"}, B::bin(BinaryOp::And, b.call("X"), b.call("Y")));
  b.transition({"A"}, {"C"}, b.call("Z"));
  b.transition({"B"}, {"A"});
  b.transition({"C"}, {"A"});
  std::string log = run("conflict", b,
                        "Y Z\n"
                        "X Y Z\n"
                        "X Y Z\n"
                        "\n");
  CHECK(log == "tick 1\n"
               "cond X -> 0\n"  // && short-circuits: Y is not asked
               "cond Z -> 1\n"  // the second transition takes A
               "act DoC\n"
               "av C\n"
               "tick 2\n"       // A is empty at the start: neither condition is asked; C -> A fires
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

/* sfc Count {
     initial place A { DoA(); }  place B { DoB(); }  place C;
     transition Grow: A -> (A, B) when More();
     transition B -> C when Take();
     transition Twice: C -> (B, B); } */
TEST_CASE("c engine run: counters above one", "[c_backend][run]") {
  ChartBuilder b("Count", Kind::Sfc);
  for (const char *f : {"More", "Take"}) b.fn(f, Type::Bool);
  for (const char *f : {"DoA", "DoB"}) b.fn(f);
  b.place("A", true, {b.act("DoA")});
  b.place("B", false, {b.act("DoB")});
  b.place("C");
  b.transition({"A"}, {"A", "B"}, b.call("More"), "Grow");
  b.transition({"B"}, {"C"}, b.call("Take"));
  b.transition({"C"}, {"B", "B"}, std::nullopt, "Twice");
  std::string log = run("count", b,
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
               "act DoB\n"         // once, whatever the count
               "av A B:2\n"
               "tick 3\n"
               "cond More -> 0\n"
               "cond Take -> 1\n"  // a transition fires at most once per tick
               "act DoA\n"
               "act DoB\n"
               "av A B C\n"
               "tick 4\n"
               "cond More -> 0\n"
               "cond Take -> 0\n"  // C -> (B, B) adds two
               "act DoA\n"
               "act DoB\n"
               "av A B:3\n");
}

namespace {

/* sfc Join {
     initial place A { entry { EnterA(); } exit { ExitA(); } DoA(); }
     initial place B { exit { ExitB(); } }
     place C { entry { EnterC(); } exit { ExitC(); } DoC(); }
     transition Loop: A -> A when Again();
     transition Sync: (A, B) -> C when Go();
     transition Back: C -> (A, B) when BackAgain(); } */
ChartBuilder join_chart() {
  ChartBuilder b("Join", Kind::Sfc);
  for (const char *f : {"Again", "Go", "BackAgain"}) b.fn(f, Type::Bool);
  for (const char *f : {"EnterA", "ExitA", "DoA", "ExitB", "EnterC", "ExitC", "DoC"}) b.fn(f);
  auto enter_a = b.act("EnterA"), exit_a = b.act("ExitA"), do_a = b.act("DoA");
  auto &a = b.place("A", true, {do_a});
  a.entry = std::vector<Stmt>{enter_a};
  a.exit = std::vector<Stmt>{exit_a};
  auto exit_b = b.act("ExitB");
  b.place("B", true).exit = std::vector<Stmt>{exit_b};
  auto enter_c = b.act("EnterC"), exit_c = b.act("ExitC"), do_c = b.act("DoC");
  auto &c = b.place("C", false, {do_c});
  c.entry = std::vector<Stmt>{enter_c};
  c.exit = std::vector<Stmt>{exit_c};
  b.transition({"A"}, {"A"}, b.call("Again"), "Loop");
  b.transition({"A", "B"}, {"C"}, b.call("Go"), "Sync");
  b.transition({"C"}, {"A", "B"}, b.call("BackAgain"), "Back");
  return b;
}

const char *kJoinScript = "\n"
                          "Again Go\n"
                          "Go\n"
                          "BackAgain\n";

} // namespace

TEST_CASE("c engine run: join, entry and exit, lost and regained in one tick", "[c_backend][run]") {
  std::string log = run("join", join_chart(), kJoinScript);
  CHECK(log == "tick 1\n"
               "act EnterA\n"       // the first tick: entries of the initial places
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
               "act ExitA\n"        // all exits in declaration order, then the entries
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
  std::string log = run("join_hooks", join_chart(), kJoinScript, "-DJoin_HOOKS");
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
               "hook lost A\n"      // after exits and entries, before the actions
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

/* sfc Timer {
     period 30ms;
     initial place Idle;  place Wait { Waiting(); }  place Done { Finished(); }
     transition Idle -> Wait when Start();
     transition Wait -> Done when elapsed(Wait) >= 100ms;   // 100 / 30 rounded up: 4 ticks
     transition Done -> Wait when Start(); } */
TEST_CASE("c engine run: timers count whole ticks from the tick a place became active", "[c_backend][run]") {
  ChartBuilder b("Timer", Kind::Sfc);
  b.fn("Start", Type::Bool).fn("Waiting").fn("Finished");
  b.chart().period_ms = 30;
  b.place("Idle", true);
  b.place("Wait", false, {b.act("Waiting")});
  b.place("Done", false, {b.act("Finished")});
  b.transition({"Idle"}, {"Wait"}, b.call("Start"));
  b.transition({"Wait"}, {"Done"}, B::bin(BinaryOp::Ge, b.elapsed("Wait"), B::ticks(4, 100)));
  b.transition({"Done"}, {"Wait"}, b.call("Start"));
  std::string log = run("timer", b, "Start\n\n\n\n\nStart\n\n\n\n\n");
  std::string wait = "act Waiting\nav Wait\n";
  CHECK(log == "tick 1\ncond Start -> 1\n" + wait +  // Wait's timer is 0 at the end of tick 1
                   "tick 2\n" + wait +               // 1
                   "tick 3\n" + wait +               // 2
                   "tick 4\n" + wait +               // 3
                   "tick 5\nact Finished\nav Done\n" // 4 >= 4
                   "tick 6\ncond Start -> 1\n" + wait +  // back to Wait: the timer starts again at 0
                   "tick 7\n" + wait + "tick 8\n" + wait + "tick 9\n" + wait +
                   "tick 10\nact Finished\nav Done\n");
}

/* sfc Warm {
     period 10ms;
     initial place Heat { Heating(); }  place Ready { Serve(); }
     transition Heat -> Ready when elapsed(Heat) >= 20ms; } */
TEST_CASE("c engine run: an initial place's timer counts from the first tick", "[c_backend][run]") {
  ChartBuilder b("Warm", Kind::Sfc);
  b.fn("Heating").fn("Serve");
  b.chart().period_ms = 10;
  b.place("Heat", true, {b.act("Heating")});
  b.place("Ready", false, {b.act("Serve")});
  b.transition({"Heat"}, {"Ready"}, B::bin(BinaryOp::Ge, b.elapsed("Heat"), B::ticks(2, 20)));
  std::string log = run("warm", b, "\n\n\n");
  CHECK(log == "tick 1\nact Heating\nav Heat\n"  // active since _init: 1 tick at step 1
               "tick 2\nact Serve\nav Ready\n"   // 2 ticks = 20ms
               "tick 3\nact Serve\nav Ready\n");
}

/* sfc Laps {
     var int laps = 0;
     const int LAPS = 3;
     initial place Run { laps += 1; Report(laps); }  place Stop { Halt(); }
     transition Run -> Stop when laps >= LAPS; } */
TEST_CASE("c engine run: variables and constants", "[c_backend][run]") {
  ChartBuilder b("Laps", Kind::Sfc);
  b.fn("Report", Type::Void, {{Type::Int, "n"}}).fn("Halt");
  b.var("laps", Type::Int, B::int_lit("0"));
  int laps_max = b.constant("LAPS", B::int_lit("3"));
  b.place("Run", true, {b.assign("laps", AssignOp::Add, B::int_lit("1")), b.act("Report", {b.var_ref("laps")})});
  b.place("Stop", false, {b.act("Halt")});
  b.transition({"Run"}, {"Stop"}, B::bin(BinaryOp::Ge, b.var_ref("laps"), b.const_ref(laps_max)));
  std::string log = run("laps", b, "\n\n\n\n\n");
  CHECK(log == "tick 1\nact Report(1)\nav Run\n"
               "tick 2\nact Report(2)\nav Run\n"
               "tick 3\nact Report(3)\nav Run\n"
               "tick 4\nact Halt\nav Stop\n"
               "tick 5\nact Halt\nav Stop\n");
}

namespace {

/* fsm CleanUp (samples/cleanup.fsm, LANGUAGE.md §7) */
ChartBuilder cleanup() {
  ChartBuilder b("CleanUp", Kind::Fsm);
  for (const char *f : {"DriveToItem", "PickUp", "Transport", "PlaceItem"}) b.fn(f);
  for (const char *f : {"Arrived", "Holding", "FarFromDestination", "ItemPlaced", "ItemAtDestination", "Stuck"})
    b.fn(f, Type::Bool);
  b.chart().period_ms = 10;
  b.place("Z0", true, {b.act("DriveToItem")});
  b.place("Z1", false, {b.act("PickUp")});
  b.place("Z2", false, {b.act("Transport")});
  b.place("Z3", false, {b.act("PlaceItem")});
  auto post = b.call("ItemAtDestination");
  auto &done = b.place("Done");
  done.terminal = model::Terminal::Success;
  done.post = post;
  b.place("Failed").terminal = model::Terminal::Failure;
  auto holding = [&] { return b.call("Holding"); };
  auto not_ = [](Expr e) { return B::un(UnaryOp::Not, std::move(e)); };
  b.transition({"Z0"}, {"Z1"}, b.call("Arrived"));
  b.transition({"Z1"}, {"Z2"}, B::bin(BinaryOp::And, holding(), b.call("FarFromDestination")));
  b.transition({"Z1"}, {"Z3"}, B::bin(BinaryOp::And, holding(), not_(b.call("FarFromDestination"))));
  b.transition({"Z2"}, {"Z3"}, b.call("Arrived"));
  b.transition({"Z2"}, {"Z1"}, not_(holding()));
  b.transition({"Z3"}, {"Done"}, b.call("ItemPlaced"));
  b.transition({"Z3"}, {"Z1"}, B::bin(BinaryOp::And, not_(holding()), not_(b.call("ItemPlaced"))));
  b.transition({"Z0"}, {"Failed"}, b.call("Stuck"));
  return b;
}

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

} // namespace

TEST_CASE("c engine run: fsm clean-up, one transition per tick, terminal state stops", "[c_backend][run]") {
  CHECK(run("cleanup", cleanup(), kCleanUpScript) == cleanup_log(false));
}

TEST_CASE("c engine run: fsm postconditions are asserted with -DX_CHECKS", "[c_backend][run]") {
  CHECK(run("cleanup_checks", cleanup(), kCleanUpScript, "-DCleanUp_CHECKS") == cleanup_log(true));
  // ItemAtDestination() false on entering Done: the assertion stops the program.
  auto b = cleanup();
  auto files = emit_c(b.model(), "engine.c", true, "chart.sfc");
  std::string log = compile_and_run("cleanup_checks_fail", files, b.model(), b.model().charts.front(),
                                    "\nArrived\nHolding\nItemPlaced\n", "-DCleanUp_CHECKS", false);
  CHECK(log.find("cond ItemAtDestination -> 0\n") != std::string::npos);
  CHECK(log.find("state Done") == std::string::npos);
}

TEST_CASE("c engine run: fsm failure state", "[c_backend][run]") {
  CHECK(run("cleanup_failed", cleanup(), "Stuck\nArrived\n") == "tick 1\n"
                                                                "cond Arrived -> 0\n"
                                                                "cond Stuck -> 1\n"
                                                                "state Failed status -1\n"
                                                                "tick 2\n"
                                                                "state Failed status -1\n");
}

namespace {

/* fsm Blink {
     period 10ms;
     initial state On { entry { LedOn(); } exit { LedOff(); } Shine(); }
     state Off { entry { Dark(); } }
     success state Done;
     On -> Off when elapsed(On) >= 20ms;
     Off -> Done when Stop();
     Off -> On when elapsed(Off) >= 10ms; } */
ChartBuilder blink() {
  ChartBuilder b("Blink", Kind::Fsm);
  b.fn("Stop", Type::Bool).fn("LedOn").fn("LedOff").fn("Shine").fn("Dark");
  b.chart().period_ms = 10;
  auto led_on = b.act("LedOn"), led_off = b.act("LedOff"), shine = b.act("Shine");
  auto &on = b.place("On", true, {shine});
  on.entry = std::vector<Stmt>{led_on};
  on.exit = std::vector<Stmt>{led_off};
  auto dark = b.act("Dark");
  b.place("Off").entry = std::vector<Stmt>{dark};
  b.place("Done").terminal = model::Terminal::Success;
  b.transition({"On"}, {"Off"}, B::bin(BinaryOp::Ge, b.elapsed("On"), B::ticks(2, 20)));
  b.transition({"Off"}, {"Done"}, b.call("Stop"));
  b.transition({"Off"}, {"On"}, B::bin(BinaryOp::Ge, b.elapsed("Off"), B::ticks(1, 10)));
  return b;
}

} // namespace

TEST_CASE("c engine run: fsm entry, exit and timers", "[c_backend][run]") {
  std::string log = run("blink", blink(), "\n\n\n\n\nStop\n\n");
  CHECK(log == "tick 1\nact LedOn\nact Shine\nstate On status 0\n"  // entry of the initial state; timer 1
               "tick 2\nact LedOff\nact Dark\nstate Off status 0\n"  // timer 2: exit On, enter Off
               "tick 3\ncond Stop -> 0\nact LedOn\nact Shine\nstate On status 0\n"
               "tick 4\nact Shine\nstate On status 0\n"
               "tick 5\nact LedOff\nact Dark\nstate Off status 0\n"
               "tick 6\ncond Stop -> 1\nstate Done status 1\n"
               "tick 7\nstate Done status 1\n");
}

TEST_CASE("c engine run: fsm hooks", "[c_backend][run]") {
  std::string log = run("blink_hooks", blink(), "\n\n\nStop\n", "-DBlink_HOOKS");
  CHECK(log == "tick 1\nact LedOn\nact Shine\nstate On status 0\n"
               "tick 2\nact LedOff\nact Dark\n"
               "hook lost On\nhook gained Off\nhook enabled T1\nhook enabled T2\n"
               "state Off status 0\n"
               "tick 3\ncond Stop -> 0\nact LedOn\n"
               "hook lost Off\nhook gained On\nhook enabled T0\n"
               "act Shine\nstate On status 0\n"
               "tick 4\nact Shine\nstate On status 0\n");
}

TEST_CASE("c engine run: several engines side by side share nothing", "[c_backend][run]") {
  auto b = line_follower();
  auto files = emit_c(b.model(), "engine.c", true, "chart.sfc");
  fs::path dir = scratch_dir("side_by_side");
  for (const auto &f : files) write_file(dir / f.path, f.contents);
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
    auto build = run_command(fmt::format("cd '{}' && {} {} main.c engine.c -o run-{}", dir.string(), cc, kStrictFlags, cc),
                             dir / "build.log");
    INFO(build.output);
    REQUIRE(build.status == 0);
    auto out = run_command(fmt::format("'{}/run-{}'", dir.string(), cc), dir / "run.log");
    CHECK(out.output == "a 0 1 b 1 0\nout of range 0 0\n");
  }
}
