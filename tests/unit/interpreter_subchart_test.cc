// The reference interpreter on sub-charts (docs/language.md "Sub-charts"): instances started
// before their place's entry block, ticked right after its action block, stopped innermost
// first before its exit block; succeeded/failed/active read at the start of the tick in
// conditions and as things are now in actions. Every expected log is written by hand from those
// rules, tick by tick (the comments say why each call comes where it does).
#include "interpreter_support.h"

using namespace gfec;
using test::compile;
using test::run_log;
using test::ScriptedEnv;

namespace {

const char *kThreeLevelsBot = R"(
interface Bot {
  bool TopGo(); bool TopBack(); bool MidGo(); bool MidDone(); bool LeafGo();
  void TopIn(); void TopAct(); void TopOut(); void TopB();
  void MidAct(); void Mid2();
  void LeafIn(); void LeafAct(); void LeafOut(); void Leaf2();
}
)";

const char *kThreeLevels = R"(
sfc Leaf {
  initial place L1 { entry { LeafIn(); } LeafAct(); exit { LeafOut(); } }
  place L2 { Leaf2(); }
  L1 -> L2 when LeafGo();
}
fsm Mid {
  initial state M1 runs Leaf { MidAct(); }
  state M2 { Mid2(); }
  success state Ok;
  M1 -> M2 when MidGo();
  M2 -> Ok when MidDone();
}
sfc Top {
  initial place A runs Mid { entry { TopIn(); } TopAct(); exit { TopOut(); } }
  place B { TopB(); }
  A -> B when TopGo();
  B -> A when TopBack();
}
)";

}  // namespace

TEST_CASE("interpreter sub-charts: an sfc in an fsm in an sfc, started, ticked and stopped",
          "[interpreter][subcharts]") {
  auto c = compile(kThreeLevels, kThreeLevelsBot);
  ScriptedEnv env(*c);
  env.script("LeafGo", {0, 1, 0})
      .script("TopGo", {0, 0, 1, 0})
      .script("TopBack", {0, 0, 0, 1, 0})
      .script("MidGo", {0, 0, 0, 0, 1, 0})
      .script("MidDone", {0, 0, 0, 0, 0, 1});
  CHECK(run_log(*c, env, 7, {}, "Top") ==
        // Top's first tick: A's entry; A's action, then Mid's first tick (its instance was
        // started by _init), whose state M1 acts and then ticks Leaf for the first time.
        "tick 1\n"
        "call TopIn()\n"
        "call TopGo() = false\n"
        "call TopAct()\n"
        "call MidGo() = false\n"
        "call MidAct()\n"
        "call LeafIn()\n"
        "call LeafGo() = false\n"
        "call LeafAct()\n"
        "av 1 0\n"
        // Leaf moves to L2 inside Mid inside Top.
        "tick 2\n"
        "call TopGo() = false\n"
        "call TopAct()\n"
        "call MidGo() = false\n"
        "call MidAct()\n"
        "call LeafGo() = true\n"
        "call LeafOut()\n"
        "call Leaf2()\n"
        "av 1 0\n"
        // A loses its activation: Mid stops (M1 stops Leaf: L2 has no exit code), then A's exit.
        "tick 3\n"
        "call TopGo() = true\n"
        "call TopOut()\n"
        "call TopB()\n"
        "av 0 1\n"
        // A again: Mid and Leaf start afresh, so Leaf's initial entry runs once more.
        "tick 4\n"
        "call TopBack() = true\n"
        "call TopIn()\n"
        "call TopAct()\n"
        "call MidGo() = false\n"
        "call MidAct()\n"
        "call LeafIn()\n"
        "call LeafGo() = false\n"
        "call LeafAct()\n"
        "av 1 0\n"
        // Mid leaves M1: M1's instance stops first (L1's exit), then M2 acts and runs nothing.
        "tick 5\n"
        "call TopGo() = false\n"
        "call TopAct()\n"
        "call MidGo() = true\n"
        "call LeafOut()\n"
        "call Mid2()\n"
        "av 1 0\n"
        // Mid succeeds: a terminal state acts and runs nothing.
        "tick 6\n"
        "call TopGo() = false\n"
        "call TopAct()\n"
        "call MidDone() = true\n"
        "av 1 0\n"
        // A finished machine does nothing at all.
        "tick 7\n"
        "call TopGo() = false\n"
        "call TopAct()\n"
        "av 1 0\n");
}

TEST_CASE("interpreter sub-charts: one chart run by two places, and a place that loses and regains "
          "activation in one tick",
          "[interpreter][subcharts]") {
  auto c = compile(R"(
sfc Counter { var int n = 0; initial place C { n += 1; Count(n); } }
sfc Two {
  initial place P runs Counter { Mark(1); }
  place Q runs Counter { Mark(2); }
  transition Go: P -> (P, Q) when Start();
}
)",
                   "interface Bot { bool Start(); void Mark(int m); void Count(int n); }");
  ScriptedEnv env(*c);
  env.script("Start", {0, 1, 0});
  // P's instance counts on through tick 2 (P lost and regained its activation: no stop, no
  // start); Q's is a separate instance that starts from n = 0.
  CHECK(run_log(*c, env, 3, {}, "Two") == "tick 1\n"
                                          "call Start() = false\n"
                                          "call Mark(1)\n"
                                          "call Count(1)\n"
                                          "av 1 0\n"
                                          "tick 2\n"
                                          "call Start() = true\n"
                                          "call Mark(1)\n"
                                          "call Count(2)\n"
                                          "call Mark(2)\n"
                                          "call Count(1)\n"
                                          "av 1 1\n"
                                          "tick 3\n"
                                          "call Start() = false\n"
                                          "call Mark(1)\n"
                                          "call Count(3)\n"
                                          "call Mark(2)\n"
                                          "call Count(2)\n"
                                          "av 1 1\n");
  // What gfec run prints: starts, runs and stops by instance path, then each running instance's
  // activation after the root's.
  ScriptedEnv again(*c);
  again.script("Start", {0, 1, 0});
  std::string log = run_log(*c, again, 2, {false, true, true}, "Two");
  CHECK(log.substr(log.find("tick 2")) == "tick 2\n"
                                          "  cond Go = true\n"
                                          "    call Start() = true\n"
                                          "  fire Go: P -> (P, Q)\n"
                                          "  start Q: Counter\n"
                                          "  entry Q\n"
                                          "  action P\n"
                                          "    call Mark(1)\n"
                                          "  run P: Counter\n"
                                          "    action P.C\n"
                                          "      set n = 2\n"
                                          "      call Count(2)\n"
                                          "  action Q\n"
                                          "    call Mark(2)\n"
                                          "  run Q: Counter\n"
                                          "    entry Q.C\n"
                                          "    action Q.C\n"
                                          "      set n = 1\n"
                                          "      call Count(1)\n"
                                          "  av 1 1\n"
                                          "  av P: 1\n"
                                          "  av Q: 1\n");
}

namespace {

const char *kBoss = R"(
fsm Job {
  initial state Work { Working(); }
  state Check;
  success state Done;
  failure state Broken;
  Work -> Check when Finish();
  Check -> Done when Good();
  Check -> Broken when !Good();
}
sfc Boss {
  initial place J runs Job { Report(active(J.Work), active(J.Check), succeeded(J), failed(J)); }
  initial place Watch { Seen(active(J.Check), succeeded(J)); }
  place Happy { Yay(); }
  place Sad;
  transition J -> Happy when succeeded(J);
  transition J -> Sad when failed(J);
}
)";

const char *kBossBot = R"(interface Bot {
  bool Finish(); bool Good();
  void Working(); void Yay();
  void Report(bool work, bool check, bool ok, bool failed);
  void Seen(bool check, bool ok);
})";

}  // namespace

TEST_CASE("interpreter sub-charts: succeeded, failed and active(P.Q) in conditions and actions",
          "[interpreter][subcharts]") {
  auto c = compile(kBoss, kBossBot);
  // Both runs alike until Check reads Good(): J works, and Finish() takes it to Check in tick 2.
  // J's action reads its instance before it ticks; Watch's, after (J comes first).
  const std::string first_two_ticks = "tick 1\n"
                                      "call Report(true, false, false, false)\n"
                                      "call Finish() = false\n"
                                      "call Working()\n"
                                      "call Seen(false, false)\n"
                                      "av 1 1 0 0\n"
                                      "tick 2\n"
                                      "call Report(true, false, false, false)\n"
                                      "call Finish() = true\n"
                                      "call Seen(true, false)\n"
                                      "av 1 1 0 0\n";
  SECTION("success") {
    ScriptedEnv env(*c);
    env.script("Finish", {0, 1, 0}).script("Good", {1});
    CHECK(run_log(*c, env, 4, {}, "Boss") ==
          first_two_ticks + "tick 3\n"
                            "call Report(false, true, false, false)\n"
                            "call Good() = true\n"
                            "call Seen(false, true)\n"
                            "av 1 1 0 0\n"
                            // The condition sees the success tick 3 left; J is then inactive, so Watch reads false.
                            "tick 4\n"
                            "call Seen(false, false)\n"
                            "call Yay()\n"
                            "av 0 1 1 0\n");
  }
  SECTION("failure") {
    ScriptedEnv env(*c);
    env.script("Finish", {0, 1, 0}).script("Good", {0});
    CHECK(run_log(*c, env, 4, {}, "Boss") == first_two_ticks + "tick 3\n"
                                                               "call Report(false, true, false, false)\n"
                                                               "call Good() = false\n"
                                                               "call Good() = false\n"
                                                               "call Seen(false, false)\n"
                                                               "av 1 1 0 0\n"
                                                               "tick 4\n"
                                                               "call Seen(false, false)\n"
                                                               "av 0 1 0 1\n");
  }
}

TEST_CASE("interpreter sub-charts: stopping runs the exits innermost first, in declaration order",
          "[interpreter][subcharts]") {
  auto c = compile(R"(
sfc Inner {
  initial place I1 { exit { Out(11); } }
  initial place I2 { exit { Out(12); } }
}
sfc Middle {
  initial place M1 runs Inner { exit { Out(21); } }
  initial place M2 { exit { Out(22); } }
  initial place M3 runs Inner { exit { Out(23); } }
}
sfc Outer {
  initial place A runs Middle { exit { Out(1); } }
  initial place B runs Inner { exit { Out(2); } }
  place C;
  transition (A, B) -> C when Leave();
}
)",
                   "interface Bot { bool Leave(); void Out(int n); }");
  ScriptedEnv env(*c);
  env.script("Leave", {0, 1});
  CHECK(run_log(*c, env, 2, {}, "Outer") ==
        "tick 1\n"
        "call Leave() = false\n"
        "av 1 1 0\n"
        "tick 2\n"
        "call Leave() = true\n"
        "call Out(11)\n"  // A stops Middle: M1 stops its Inner (I1, I2), then M1's exit
        "call Out(12)\n"
        "call Out(21)\n"
        "call Out(22)\n"  // M2 runs nothing
        "call Out(11)\n"  // M3's Inner, then M3
        "call Out(12)\n"
        "call Out(23)\n"
        "call Out(1)\n"   // then A's own exit
        "call Out(11)\n"  // B: its Inner, then B
        "call Out(12)\n"
        "call Out(2)\n"
        "av 0 0 1\n");
}

TEST_CASE("interpreter sub-charts: a sub-chart's timers count its own ticks at its parent's period",
          "[interpreter][subcharts]") {
  auto c = compile(R"(
sfc Blink { initial place On { Lamp(1); } place Off { Lamp(0); } On -> Off when elapsed(On) >= 20ms; }
sfc Top { period 10ms; initial place Idle; place Busy runs Blink; Idle -> Busy when Go(); }
)",
                   "interface Bot { bool Go(); void Lamp(int on); }");
  ScriptedEnv env(*c);
  env.script("Go", {0, 1});
  // Blink is started in tick 2 and ticks in that same tick, its first: as for a compiled chart's
  // first tick after _init, step 1 counts it, so On's timer is 1 then and 2 (20ms) at Blink's
  // second tick, tick 3, when it moves to Off.
  CHECK(run_log(*c, env, 5, {}, "Top") == "tick 1\n"
                                          "call Go() = false\n"
                                          "av 1 0\n"
                                          "tick 2\n"
                                          "call Go() = true\n"
                                          "call Lamp(1)\n"
                                          "av 0 1\n"
                                          "tick 3\n"
                                          "call Lamp(0)\n"
                                          "av 0 1\n"
                                          "tick 4\n"
                                          "call Lamp(0)\n"
                                          "av 0 1\n"
                                          "tick 5\n"
                                          "call Lamp(0)\n"
                                          "av 0 1\n");
}
