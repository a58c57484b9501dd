// The reference interpreter on sfc charts: each test pins one rule of docs/language.md §5.1.
#include "../run/shared_charts.h"
#include "interpreter_support.h"

#include <fmt/format.h>

#include <algorithm>

using namespace gfec;
using test::compile;
using test::kLineFollowerLeftSeesLine;
using test::run_log;
using test::ScriptedEnv;
using test::charts::kIfElse;

namespace {

const char *kLineBot = R"(
interface LineBot {
  bool Left_IR_Black(); bool Left_IR_White(); bool Right_IR_Black(); bool Right_IR_White();
  void Left_FW(); void Left_Stop(); void Right_FW(); void Right_Stop();
}
)";

const char *kLineFollower = R"(
sfc LineFollower {
  initial place LeftFw    { Left_FW(); }
  place        LeftStop   { Left_Stop(); }
  initial place RightFw   { Right_FW(); }
  place        RightStop  { Right_Stop(); }
  transition LeftFw   -> LeftStop  when Left_IR_Black();
  transition LeftStop -> LeftFw    when Left_IR_White();
  transition RightFw  -> RightStop when Right_IR_Black();
  transition RightStop -> RightFw  when Right_IR_White();
}
)";

}  // namespace

TEST_CASE("interpreter sfc: the line follower, observable log") {
  auto c = compile(kLineFollower, kLineBot);
  ScriptedEnv env(*c);
  env.script("Left_IR_Black", {0, 1, 0}).script("Left_IR_White", {0, 0, 1});
  CHECK(run_log(*c, env, 3) == "tick 1\n"
                               "call Left_IR_Black() = false\n"
                               "call Right_IR_Black() = false\n"
                               "call Left_FW()\n"
                               "call Right_FW()\n"
                               "av 1 0 1 0\n"
                               "tick 2\n"
                               "call Left_IR_Black() = true\n"
                               "call Right_IR_Black() = false\n"
                               "call Left_Stop()\n"
                               "call Right_FW()\n"
                               "av 0 1 1 0\n"
                               "tick 3\n"
                               "call Left_IR_White() = true\n"  // LeftFw -> LeftStop is closed: its sensor is not read
                               "call Right_IR_Black() = false\n"
                               "call Left_FW()\n"
                               "call Right_FW()\n"
                               "av 1 0 1 0\n");
}

TEST_CASE("interpreter sfc: every layer, indented, as gfec run prints it") {
  auto c = compile(kLineFollower, kLineBot);
  ScriptedEnv env(*c);
  env.script("Left_IR_Black", {1});
  CHECK(run_log(*c, env, 1, {true, true, true}) == std::string("tick 1\n"
                                                               "  entry LeftFw\n"
                                                               "  entry RightFw\n") +
                                                       kLineFollowerLeftSeesLine);
}

TEST_CASE("interpreter sfc: activation produced in a tick is consumed only in the next") {
  auto c = compile(R"(
sfc Chain {
  initial place A;
  place B;
  place C;
  A -> B;
  B -> C;
}
)");
  ScriptedEnv env(*c);
  CHECK(run_log(*c, env, 3) == "tick 1\nav 0 1 0\ntick 2\nav 0 0 1\ntick 3\nav 0 0 1\n");
}

TEST_CASE("interpreter sfc: conflicts go to the first open transition whose condition holds") {
  auto c = compile(R"(
sfc Pick {
  initial place A;
  place B;
  place C;
  transition First: A -> B when Go(1);
  transition Second: A -> C when Go(2);
  transition Third: A -> C;
}
)",
                   "interface Bot { bool Go(int which); }");
  ScriptedEnv env(*c);
  env.script("Go", {1});
  // First takes A's only activation: Second is no longer open, so Go(2) is never called.
  CHECK(run_log(*c, env, 1) == "tick 1\ncall Go(1) = true\nav 0 1 0\n");
  ScriptedEnv no(*c);
  CHECK(run_log(*c, no, 1) == "tick 1\ncall Go(1) = false\ncall Go(2) = false\nav 0 0 1\n");
}

TEST_CASE("interpreter sfc: fork, join and counters above one") {
  auto c = compile(R"(
sfc Par {
  initial place S;
  place L;
  place R;
  place J;
  transition Fork: S -> (L, R);
  transition Join: (L, R) -> J;
  transition Again: J -> S;
  transition Extra: J -> L;
}
)");
  ScriptedEnv env(*c);
  // Tick 1 forks; tick 2 joins; tick 3 J goes back to S (Again wins the conflict); tick 4
  // forks again.
  CHECK(run_log(*c, env, 4) == "tick 1\nav 0 1 1 0\ntick 2\nav 0 0 0 1\ntick 3\nav 1 0 0 0\ntick 4\nav 0 1 1 0\n");

  auto u = compile(R"(
sfc Pump {
  initial place S;
  place P;
  transition S -> (S, P);
}
)");
  ScriptedEnv none(*u);
  // S loses and regains its activation each tick (no exit, no entry); P counts up.
  CHECK(run_log(*u, none, 3, {true, true}) == "tick 1\nentry S\nfire T0: S -> (S, P)\nentry P\ngained P\nav 1 1\n"
                                              "tick 2\nfire T0: S -> (S, P)\nav 1 2\n"
                                              "tick 3\nfire T0: S -> (S, P)\nav 1 3\n");
}

TEST_CASE("interpreter sfc: all exits before all entries, a place that loses and regains stays") {
  auto c = compile(R"(
sfc Blocks {
  initial place A { entry { Log(1); } Log(2); exit { Log(3); } }
  initial place B { exit { Log(4); } }
  place C { entry { Log(5); } }
  transition A -> A;
  transition B -> C;
}
)",
                   "interface Bot { void Log(int what); }");
  ScriptedEnv env(*c);
  CHECK(run_log(*c, env, 2) == "tick 1\n"
                               "call Log(1)\n"  // the first tick begins with the initial places' entry blocks
                               "call Log(4)\n"  // B exits, then C enters; A lost and regained: nothing
                               "call Log(5)\n"
                               "call Log(2)\n"
                               "av 1 0 1\n"
                               "tick 2\n"
                               "call Log(2)\n"
                               "av 1 0 1\n");
}

TEST_CASE("interpreter sfc: timers count whole ticks and restart on entry") {
  auto c = compile(R"(
sfc Timed {
  period 10ms;
  initial place A { Tick(); }
  place B;
  transition A -> B when elapsed(A) >= 25ms;
  transition B -> A;
}
)",
                   "interface Bot { void Tick(); }");
  ScriptedEnv env(*c);
  // 25ms is 3 ticks (rounded up). elapsed(A) is 1 in tick 1 (step 1 counts before the
  // transitions), so A -> B fires in tick 3; A is back in tick 4 with its timer at 0.
  CHECK(run_log(*c, env, 8) == "tick 1\ncall Tick()\nav 1 0\ntick 2\ncall Tick()\nav 1 0\ntick 3\nav 0 1\n"
                               "tick 4\ncall Tick()\nav 1 0\ntick 5\ncall Tick()\nav 1 0\ntick 6\ncall Tick()\nav 1 0\n"
                               "tick 7\nav 0 1\ntick 8\ncall Tick()\nav 1 0\n");
}

TEST_CASE("interpreter sfc: the engine API mirrors the C engine's") {
  auto c = compile(R"(
sfc Api {
  var int n = 2;
  initial place A { n += 1; }
  place B;
  A -> B when n >= 4;
}
)");
  ScriptedEnv env(*c);
  interp::Machine e(c->model, model::ChartId(0));
  const model::PlaceId a(0), b(1);
  const model::VarId n(0);
  CHECK(e.activation(a) == 1);
  CHECK(e.activation(b) == 0);
  CHECK(e.activation(model::PlaceId(7)) == 0);
  CHECK(e.vars().at(n).i == 2);
  e.run(env, nullptr);
  CHECK(e.vars().at(n).i == 3);
  e.run(env, nullptr);
  e.run(env, nullptr);
  CHECK(e.activation(a) == 0);
  CHECK(e.activation(b) == 1);
  CHECK(e.ticks() == 3);
  e.init();
  CHECK(e.activation(a) == 1);
  CHECK(e.vars().at(n).i == 2);
  CHECK(e.ticks() == 0);
}

TEST_CASE("interpreter sfc: if, else if and else in actions, entry and exit") {
  // The chart of c_backend_run_test.cc "if, else if and else": the same calls, in the
  // interpreter's words.
  auto c = compile(kIfElse);
  ScriptedEnv env(*c);
  env.script("X", {1, 0, 0, 1, 0, 1}).script("Y", {0, 0, 1, 1, 0, 1}).script("N", {2, 0}).script("M", {1, 0});
  CHECK(run_log(*c, env, 6) == "tick 1\n"
                               "call X() = true\ncall A()\n"  // P's entry on the first tick
                               "call N() = 2\ncall M() = 1\ncall N() = 2\ncall B(2)\n"
                               "av 1 0\n"
                               "tick 2\n"
                               "call N() = 0\ncall M() = 0\ncall Y() = false\ncall D()\n"
                               "call B(0)\n"  // elapsed(P) is 20ms
                               "av 1 0\n"
                               "tick 3\n"
                               "call N() = 0\ncall M() = 0\ncall Y() = true\ncall X() = false\n"
                               "call B(1)\n"
                               "av 1 0\n"
                               "tick 4\n"
                               "call N() = 0\ncall M() = 0\ncall Y() = true\ncall X() = true\ncall C()\n"
                               "call B(2)\n"
                               "av 1 0\n"
                               "tick 5\n"  // k is 2: P -> Q
                               "call D()\n"
                               "av 0 1\n"
                               "tick 6\n"
                               "call X() = true\n"             // Q -> P
                               "call Y() = true\ncall B(2)\n"  // Q's exit
                               "call X() = true\ncall A()\n"   // P's entry
                               "call N() = 0\ncall M() = 0\ncall Y() = true\ncall X() = true\ncall C()\n"
                               "av 1 0\n");
}

namespace {

/// A chart with named actions (docs/language.md §14); it must compile without an error.
std::unique_ptr<test::Compiled> compile_actions(const std::string &text) {
  auto c = std::make_unique<test::Compiled>(text);
  INFO(c->diagnostics());
  REQUIRE(!c->diag.has_errors());
  return c;
}

}  // namespace

TEST_CASE("interpreter sfc: action control, N held by two places, P and P1 on the initial place, P0, final runs",
          "[iec]") {
  // By hand from docs/iec.md "Action control". Tick 1: A is initial and rises: Hold (N), Pulse
  // (P) and Edge (P1) run. Tick 2: A -> (B, C): Hold runs (B, C hold it); Pulse's Q falls: its
  // final run. Tick 3: B is left: Hold still runs (C holds it), Edge runs (P0 of B). Tick 4: C
  // is left: Hold's Q falls, its final run. Tick 5: nothing runs.
  auto c = compile_actions(R"(
sfc Acts {
  var int k = 0;
  out int hold = 0;
  out int pulse = 0;
  out int edge = 0;
  action Hold { hold += 1; }
  action Pulse { pulse += 1; }
  action Edge { edge += 1; }
  initial place Clock { k += 1; }
  initial place A { P Pulse; P1 Edge; N Hold; }
  place B { N Hold; P0 Edge; }
  place C { N Hold; }
  place E;
  place F;
  A -> (B, C) when k >= 1;
  B -> E when k >= 2;
  C -> F when k >= 3;
}
)");
  ScriptedEnv env(*c);
  CHECK(run_log(*c, env, 5) == "tick 1\nav 1 1 0 0 0 0\nout hold = 1\nout pulse = 1\nout edge = 1\n"
                               "tick 2\nav 1 0 1 1 0 0\nout hold = 2\nout pulse = 2\nout edge = 1\n"
                               "tick 3\nav 1 0 0 1 1 0\nout hold = 3\nout pulse = 2\nout edge = 2\n"
                               "tick 4\nav 1 0 0 0 1 1\nout hold = 4\nout pulse = 2\nout edge = 2\n"
                               "tick 5\nav 1 0 0 0 1 1\nout hold = 4\nout pulse = 2\nout edge = 2\n");
}

TEST_CASE("interpreter sfc: action control, an initial place left in tick 1 falls in tick 1", "[iec]") {
  // By hand from docs/iec.md "Action control", "The initial step". Tick 1: A, active from
  // initialisation, is left: Fall (P0) runs; Hold (N), Rise (P1) and Pulse (P) do not, as A is
  // not active at the action control (no Q, so no final run either). S stays: Keep (N) and Up
  // (P1) run, Down (P0) does not. Tick 2: S is left: Down runs, Keep's final run. Tick 3: A is
  // entered again: Hold, Rise and Pulse run. Tick 4: Hold, Pulse's final run. Tick 5: Hold.
  auto c = compile_actions(R"(
sfc InitialLeft {
  var int k = 0;
  out int hold = 0;
  out int rise = 0;
  out int fall = 0;
  out int pulse = 0;
  out int keep = 0;
  out int up = 0;
  out int down = 0;
  action Hold { hold += 1; }
  action Rise { rise += 1; }
  action Fall { fall += 1; }
  action Pulse { pulse += 1; }
  action Keep { keep += 1; }
  action Up { up += 1; }
  action Down { down += 1; }
  initial place Clock { k += 1; }
  initial place A { N Hold; P1 Rise; P0 Fall; P Pulse; }
  initial place S { N Keep; P1 Up; P0 Down; }
  place B;
  place T;
  A -> B when k == 0;
  S -> T when k == 1;
  B -> A when k >= 2;
}
)");
  ScriptedEnv env(*c);
  const std::string outs[] = {
      "out hold = 0\nout rise = 0\nout fall = 1\nout pulse = 0\nout keep = 1\nout up = 1\nout down = 0\n",
      "out hold = 0\nout rise = 0\nout fall = 1\nout pulse = 0\nout keep = 2\nout up = 1\nout down = 1\n",
      "out hold = 1\nout rise = 1\nout fall = 1\nout pulse = 1\nout keep = 2\nout up = 1\nout down = 1\n",
      "out hold = 2\nout rise = 1\nout fall = 1\nout pulse = 2\nout keep = 2\nout up = 1\nout down = 1\n",
      "out hold = 3\nout rise = 1\nout fall = 1\nout pulse = 2\nout keep = 2\nout up = 1\nout down = 1\n"};
  CHECK(run_log(*c, env, 5) == "tick 1\nav 1 0 1 1 0\n" + outs[0] + "tick 2\nav 1 0 0 1 1\n" + outs[1] +
                                   "tick 3\nav 1 1 0 0 1\n" + outs[2] + "tick 4\nav 1 1 0 0 1\n" + outs[3] +
                                   "tick 5\nav 1 1 0 0 1\n" + outs[4]);
}

TEST_CASE("interpreter sfc: action control, S stored across places, R wins over S in one tick", "[iec]") {
  // Tick 1: A sets Lamp. Tick 2: B holds nothing, Lamp stays set. Tick 3: C sets and resets it:
  // the reset wins, Q falls, the final run. Tick 4: nothing (had S won, Lamp would still run).
  auto c = compile_actions(R"(
sfc Store {
  var int k = 0;
  out int lamp = 0;
  action Lamp { lamp += 1; }
  initial place Clock { k += 1; }
  initial place A { S Lamp; }
  place B;
  place C { S Lamp; R Lamp; }
  place D;
  A -> B when k >= 1;
  B -> C when k >= 2;
  C -> D when k >= 3;
}
)");
  ScriptedEnv env(*c);
  CHECK(run_log(*c, env, 5) == "tick 1\nav 1 1 0 0 0\nout lamp = 1\n"
                               "tick 2\nav 1 0 1 0 0\nout lamp = 2\n"
                               "tick 3\nav 1 0 0 1 0\nout lamp = 3\n"
                               "tick 4\nav 1 0 0 0 1\nout lamp = 3\n"
                               "tick 5\nav 1 0 0 0 1\nout lamp = 3\n");
}

TEST_CASE("interpreter sfc: action control, L and D against the place's timer", "[iec]") {
  // 20ms at 10ms is 2 ticks; the initial place's timer is 1 in tick 1. L: tick 1 only, then
  // its final run in tick 2. D: from tick 2 on.
  auto c = compile_actions(R"(
sfc Timed {
  period 10ms;
  out int brief = 0;
  out int late = 0;
  action Short { brief += 1; }
  action Late { late += 1; }
  initial place A { L Short 20ms; D Late 20ms; }
}
)");
  ScriptedEnv env(*c);
  CHECK(run_log(*c, env, 4) == "tick 1\nav 1\nout brief = 1\nout late = 0\n"
                               "tick 2\nav 1\nout brief = 2\nout late = 1\n"
                               "tick 3\nav 1\nout brief = 2\nout late = 2\n"
                               "tick 4\nav 1\nout brief = 2\nout late = 3\n");
}

TEST_CASE("interpreter sfc: action control, SD set and its place left before the delay", "[iec]") {
  // docs/iec.md "Action control": SD's timer counts from the tick of the set (0 then), 30ms at
  // 10ms is 3 ticks. Tick 1: A sets Late (timer 0). Tick 2: A is left; the flag stays (timer 1).
  // Tick 4: timer 3, Late runs, and every tick after. Tick 7: C resets it: its final run.
  auto c = compile_actions(R"(
sfc SdLeft {
  period 10ms;
  var int k = 0;
  out int on = 0;
  action Late { on += 1; }
  initial place Clock { k += 1; }
  initial place A { SD Late 30ms; }
  place B;
  place C { R Late; }
  place D;
  A -> B when k >= 1;
  B -> C when k >= 6;
  C -> D when k >= 7;
}
)");
  ScriptedEnv env(*c);
  CHECK(run_log(*c, env, 8) == "tick 1\nav 1 1 0 0 0\nout on = 0\n"
                               "tick 2\nav 1 0 1 0 0\nout on = 0\n"
                               "tick 3\nav 1 0 1 0 0\nout on = 0\n"
                               "tick 4\nav 1 0 1 0 0\nout on = 1\n"
                               "tick 5\nav 1 0 1 0 0\nout on = 2\n"
                               "tick 6\nav 1 0 1 0 0\nout on = 3\n"
                               "tick 7\nav 1 0 0 1 0\nout on = 4\n"
                               "tick 8\nav 1 0 0 0 1\nout on = 4\n");
}

TEST_CASE("interpreter sfc: action control, R before the SD delay, R in the tick of a set", "[iec]") {
  // Tick 1: A sets Late. Tick 2: B resets it before its 3 ticks: Late never runs. Tick 3: C sets
  // Late and Lamp (SL, which would run at once) and resets both: the reset wins, neither runs,
  // and no SD timer is left counting (had the set won, Late would run from tick 6).
  auto c = compile_actions(R"(
sfc SdReset {
  period 10ms;
  var int k = 0;
  out int late = 0;
  out int lamp = 0;
  action Late { late += 1; }
  action Lamp { lamp += 1; }
  initial place Clock { k += 1; }
  initial place A { SD Late 30ms; }
  place B { R Late; }
  place C { SD Late 30ms; R Late; SL Lamp 20ms; R Lamp; }
  place D;
  A -> B when k >= 1;
  B -> C when k >= 2;
  C -> D when k >= 3;
}
)");
  ScriptedEnv env(*c);
  std::string expected;
  const char *av[] = {"1 1 0 0 0", "1 0 1 0 0", "1 0 0 1 0", "1 0 0 0 1"};
  for (int tick = 1; tick <= 8; ++tick)
    expected += fmt::format("tick {}\nav {}\nout late = 0\nout lamp = 0\n", tick, av[std::min(tick, 4) - 1]);
  CHECK(run_log(*c, env, 8) == expected);
}

TEST_CASE("interpreter sfc: action control, DS set only if its place is still active at the delay", "[iec]") {
  // A is initial: its timer is 1 in tick 1. Kept (DS 20ms): A's timer reaches 2 in tick 2, Kept
  // is set and runs until C resets it in tick 6 (its final run). Early (DS 30ms): A is left in
  // tick 3, the tick its timer would reach 3: never set, never runs.
  auto c = compile_actions(R"(
sfc Ds {
  period 10ms;
  var int k = 0;
  out int a = 0;
  out int b = 0;
  action Early { a += 1; }
  action Kept { b += 1; }
  initial place Clock { k += 1; }
  initial place A { DS Early 30ms; DS Kept 20ms; }
  place B;
  place C { R Kept; }
  A -> B when k >= 2;
  B -> C when k >= 5;
}
)");
  ScriptedEnv env(*c);
  CHECK(run_log(*c, env, 7) == "tick 1\nav 1 1 0 0\nout a = 0\nout b = 0\n"
                               "tick 2\nav 1 1 0 0\nout a = 0\nout b = 1\n"
                               "tick 3\nav 1 0 1 0\nout a = 0\nout b = 2\n"
                               "tick 4\nav 1 0 1 0\nout a = 0\nout b = 3\n"
                               "tick 5\nav 1 0 1 0\nout a = 0\nout b = 4\n"
                               "tick 6\nav 1 0 0 1\nout a = 0\nout b = 5\n"
                               "tick 7\nav 1 0 0 1\nout a = 0\nout b = 5\n");
}

TEST_CASE("interpreter sfc: action control, SL runs out, SD 0 / DS 0 as S, SL 0 never", "[iec]") {
  // Lim (SL 30ms, 3 ticks): ticks 1-3, its final run in tick 4; A still holds it in tick 5 but
  // the flag is still set, so the limit does not start again. C resets it in tick 7, D sets it
  // again in tick 8: ticks 8-10 and the final run in 11. B (entered in tick 6, timer 0) holds
  // Zsd under SD 0 and Zds under DS 0: both run at once, as under S, until C resets them (their
  // final runs in tick 7); Zsl under SL 0 never runs.
  auto c = compile_actions(R"(
sfc Sl {
  period 10ms;
  var int k = 0;
  out int l = 0;
  out int z = 0;
  out int y = 0;
  out int w = 0;
  action Lim { l += 1; }
  action Zsd { z += 1; }
  action Zds { y += 1; }
  action Zsl { w += 1; }
  initial place Clock { k += 1; }
  initial place A { SL Lim 30ms; }
  place B { SD Zsd 0ms; DS Zds 0ms; SL Zsl 0ms; }
  place C { R Zsd; R Zds; R Lim; }
  place D { SL Lim 30ms; }
  A -> B when k >= 5;
  B -> C when k >= 6;
  C -> D when k >= 7;
}
)");
  ScriptedEnv env(*c);
  CHECK(run_log(*c, env, 12) == "tick 1\nav 1 1 0 0 0\nout l = 1\nout z = 0\nout y = 0\nout w = 0\n"
                                "tick 2\nav 1 1 0 0 0\nout l = 2\nout z = 0\nout y = 0\nout w = 0\n"
                                "tick 3\nav 1 1 0 0 0\nout l = 3\nout z = 0\nout y = 0\nout w = 0\n"
                                "tick 4\nav 1 1 0 0 0\nout l = 4\nout z = 0\nout y = 0\nout w = 0\n"
                                "tick 5\nav 1 1 0 0 0\nout l = 4\nout z = 0\nout y = 0\nout w = 0\n"
                                "tick 6\nav 1 0 1 0 0\nout l = 4\nout z = 1\nout y = 1\nout w = 0\n"
                                "tick 7\nav 1 0 0 1 0\nout l = 4\nout z = 2\nout y = 2\nout w = 0\n"
                                "tick 8\nav 1 0 0 0 1\nout l = 5\nout z = 2\nout y = 2\nout w = 0\n"
                                "tick 9\nav 1 0 0 0 1\nout l = 6\nout z = 2\nout y = 2\nout w = 0\n"
                                "tick 10\nav 1 0 0 0 1\nout l = 7\nout z = 2\nout y = 2\nout w = 0\n"
                                "tick 11\nav 1 0 0 0 1\nout l = 8\nout z = 2\nout y = 2\nout w = 0\n"
                                "tick 12\nav 1 0 0 0 1\nout l = 8\nout z = 2\nout y = 2\nout w = 0\n");
}
