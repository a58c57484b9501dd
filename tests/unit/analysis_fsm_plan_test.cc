// The fsm and plan analyses: states that never finish, shadowed transitions, config read before
// written, supervisors that can fire together.
#include "analysis_support.h"

using namespace gfec;
using test::analyze_text;
using test::compile;
using test::headlines;

namespace {
const char *kBot = "interface Bot { bool x(); bool y(); void Go(); }";
}  // namespace

TEST_CASE("analysis fsm: states that can never reach a terminal state") {
  auto c = compile(R"(
fsm Loop {
  initial state A { Go(); }
  state B;
  state C;
  success state Done;
  A -> Done when x();
  A -> B when y();
  B -> C;
  C -> B when x();
}
)",
                   kBot);
  CHECK(headlines(analyze_text(*c, false)) ==
        "t.sfc:5:9: warning: state 'B' can never reach a success or failure state: once there, fsm 'Loop' runs for "
        "ever [-Wtrap-state]\n"
        "t.sfc:6:9: warning: state 'C' can never reach a success or failure state: once there, fsm 'Loop' runs for "
        "ever [-Wtrap-state]\n");
  auto forever = compile("fsm Spin { initial state A; state B; A -> B; B -> A; }", kBot);
  CHECK(analyze_text(*forever) == "");  // no terminal state at all: meant to run for ever
}

TEST_CASE("analysis fsm: a transition shadowed by an earlier one with the same or a weaker precondition") {
  auto c = compile(R"(
fsm Pick {
  initial state A;
  state B;
  state C;
  state D;
  A -> B when x();
  A -> C when y() && x();
  B -> D;
  B -> A when y();
  C -> A when x() && y();
  C -> D when x() || (y() && !y());
  D -> A when !(x() || y());
  D -> B when !x() && !y();
}
)",
                   kBot);
  std::string all = analyze_text(*c, false);
  CHECK(headlines(all) ==
        "t.sfc:9:3: warning: transition 'T1' (A -> C) can never fire: 'T0' (A -> B) is tried first and holds whenever "
        "it does [-Wshadowed-transition]\n"
        "t.sfc:8:3: note: 'T0' has the same or a weaker precondition\n"
        "t.sfc:11:3: warning: transition 'T3' (B -> A) can never fire: 'T2' (B -> D) is tried first and holds "
        "whenever it does [-Wshadowed-transition]\n"
        "t.sfc:10:3: note: 'T2' has no precondition\n"
        "t.sfc:15:3: warning: transition 'T7' (D -> B) can never fire: 'T6' (D -> A) is tried first and holds "
        "whenever it does [-Wshadowed-transition]\n"
        "t.sfc:14:3: note: 'T6' has the same or a weaker precondition\n");
  // C -> D (x() || (y() && !y())) is x(): weaker than x() && y(), so it is not shadowed.
}

TEST_CASE("analysis fsm: shadowing compares a transition with the earlier ones of its own state only") {
  // The transitions of A and B interleaved, a never-firing one first: the warnings come in the
  // order of the shadowed transitions, each with the first earlier one of its state that holds.
  auto c = compile(R"(
fsm Mixed {
  initial state A;
  state B;
  state C;
  success state Done;
  A -> C when false;
  B -> C when y();
  A -> B when x();
  B -> A when y() && x();
  A -> Done when x() && y();
  C -> Done;
  B -> Done when y();
}
)",
                   kBot);
  CHECK(headlines(analyze_text(*c, false)) ==
        "t.sfc:11:3: warning: transition 'T3' (B -> A) can never fire: 'T1' (B -> C) is tried first and holds "
        "whenever it does [-Wshadowed-transition]\n"
        "t.sfc:9:3: note: 'T1' has the same or a weaker precondition\n"
        "t.sfc:12:3: warning: transition 'T4' (A -> Done) can never fire: 'T2' (A -> B) is tried first and holds "
        "whenever it does [-Wshadowed-transition]\n"
        "t.sfc:10:3: note: 'T2' has the same or a weaker precondition\n"
        "t.sfc:14:3: warning: transition 'T6' (B -> Done) can never fire: 'T1' (B -> C) is tried first and holds "
        "whenever it does [-Wshadowed-transition]\n"
        "t.sfc:9:3: note: 'T1' has the same or a weaker precondition\n");
}

TEST_CASE("analysis fsm: a long chain is checked in linear time") {
  // 50,000 states in a chain to Done, and a trap beside its end: quadratic checks took minutes.
  const int n = 50000;
  std::string text = "fsm Chain {\n  initial state S0;\n";
  for (int i = 1; i < n; ++i) text += "  state S" + std::to_string(i) + ";\n";
  text += "  state Trap;\n  success state Done;\n";
  for (int i = 0; i + 1 < n; ++i) text += "  S" + std::to_string(i) + " -> S" + std::to_string(i + 1) + " when x();\n";
  text += "  S" + std::to_string(n - 1) + " -> Done when x();\n  S" + std::to_string(n - 1) + " -> Trap when y();\n}\n";
  auto c = compile(text, kBot);
  std::string report;
  std::string all = analyze_text(*c, false, {}, &report);
  CHECK(headlines(all) == "t.sfc:50003:9: warning: state 'Trap' can never reach a success or failure state: once "
                          "there, fsm 'Chain' runs for ever [-Wtrap-state]\n");
  CHECK(report.find("reachable states: 50002 of 50002") != std::string::npos);
  CHECK(report.find("states that can never finish: 1\n") != std::string::npos);
}

namespace {
const char *kToolbox = R"(
toolbox Bot {
  actor Forward(in float distance) -> FORWARD_OK;
  actor Turn(in float angle) -> TURN_OK;
  actor SearchWall(out float angle) -> WALL_FOUND | NO_WALL_FOUND;
  supervisor CheckTouch() events TOUCHED;
  supervisor CheckLane(in float dist) events LANE_NOT_FREE;
  supervisor CheckEscape() events ESCAPE;
}
)";
}  // namespace

TEST_CASE("analysis plan: a config entry read before anything writes it") {
  auto c = compile(R"(
plan Walls {
  config { float walldist = 30; float angle; }
  start search;
  actor search: SearchWall(angle) { WALL_FOUND -> turn; NO_WALL_FOUND -> guess; }
  actor turn: Turn(angle) { TURN_OK -> search; }
  actor guess: Turn(angle) { TURN_OK -> ahead; }
  actor ahead: Forward(walldist) { FORWARD_OK -> search; }
}
)",
                   kToolbox);
  // turn follows SearchWall's write on every way in; guess is reached after NO_WALL_FOUND too,
  // which also commits the out argument, so neither reads too early. Forward reads walldist,
  // which has a value.
  CHECK(analyze_text(*c, false) == "");

  auto early = compile(R"(
plan Early {
  config { float angle; float dist; }
  supervise lane: CheckLane(dist) { LANE_NOT_FREE -> terminate; }
  start turn;
  actor turn: Turn(angle) { TURN_OK -> search; }
  actor search: SearchWall(angle) { WALL_FOUND -> turn; NO_WALL_FOUND -> terminate; }
}
)",
                       kToolbox);
  CHECK(headlines(analyze_text(*early, false)) ==
        "t.sfc:5:29: warning: supervisor 'lane' may read config entry 'dist' before anything has written it "
        "[-Wuninitialized-config]\n"
        "t.sfc:4:31: note: 'dist' has no initial value, and not every way to supervisor 'lane' passes an actor or "
        "supervisor that writes it; give it a value here, or set it from the application before the plan starts\n"
        "t.sfc:7:20: warning: actor 'turn' may read config entry 'angle' before anything has written it "
        "[-Wuninitialized-config]\n"
        "t.sfc:4:18: note: 'angle' has no initial value, and not every way to actor 'turn' passes an actor or "
        "supervisor that writes it; give it a value here, or set it from the application before the plan starts\n");
}

TEST_CASE("analysis plan: supervisors that can interrupt one actor in the same step, and the winner") {
  auto c = compile(R"(
plan Guarded {
  config { float dist = 10; }
  supervise escape: CheckEscape() { ESCAPE -> terminate; }
  start ahead;
  actor ahead: Forward(dist) {
    FORWARD_OK -> ahead;
    supervise touch: CheckTouch() { TOUCHED -> back; }
    supervise lane: CheckLane(dist) { LANE_NOT_FREE -> ignore; }
  }
  actor back: Forward(-dist) { FORWARD_OK -> ahead; }
}
)",
                   kToolbox);
  std::string all = analyze_text(*c);
  CHECK(headlines(all) == "t.sfc:7:9: warning: 2 supervisors watch actor 'ahead' and can raise events in the same "
                          "step; 'escape' (global) wins [-Wsupervisor-race]\n"
                          "t.sfc:7:9: note: they are checked in this order, and the first to raise an event "
                          "interrupts: 'escape' (global), then 'touch'\n");
  CHECK(analyze_text(*c, false) == "");  // off by default
}

TEST_CASE("analysis: the samples are clean with the default warnings") {
  for (const char *sample : {"line_follower.sfc", "cleanup.fsm", "wall_follow.plan"}) {
    INFO(sample);
    test::Pipeline p(std::string(GFEC_SOURCE_DIR) + "/samples/" + sample, RealFileSystem());
    REQUIRE_FALSE(p.diag.has_errors());
    std::size_t before = p.diag.all().size();
    analysis::analyze(p.model, p.diag);
    CHECK(p.diag.all().size() == before);
  }
}

TEST_CASE("analysis: sub-charts' states are free inputs: different paths are different conditions", "[subcharts]") {
  // active(Work.Slow) and active(Work.Fast) are two facts about the sub-chart; the analyses
  // cannot follow it, so neither transition may be called shadowed or dead.
  auto c = compile(R"(
sfc Job { initial place Slow; place Fast; Slow -> Fast when x(); }
fsm Boss {
  initial state Work runs Job;
  state Quick;
  state Calm;
  success state Done;
  Work -> Quick when active(Work.Fast);
  Work -> Calm when active(Work.Slow);
  state Sub runs Fetch;
  Work -> Sub when y();
  Quick -> Done;
  Calm -> Done;
  Sub -> Done when succeeded(Sub);
  Sub -> Work when failed(Sub);
}
fsm Fetch { initial state F; success state Ok; failure state No; F -> Ok when x(); F -> No when y(); }
)",
                   kBot);
  CHECK(analyze_text(*c) == "");
  // The same path twice is the same fact: the second transition is shadowed.
  auto same = compile(R"(
sfc Job { initial place Slow; place Fast; Slow -> Fast when x(); }
fsm Boss {
  initial state Work runs Job;
  state Quick;
  state Calm;
  success state Done;
  Work -> Quick when active(Work.Fast);
  Work -> Calm when active(Work.Fast) && y();
  Quick -> Done;
  Calm -> Done;
}
)",
                      kBot);
  CHECK(headlines(analyze_text(*same, false)) ==
        "t.sfc:10:3: warning: transition 'T1' (Work -> Calm) can never fire: 'T0' (Work -> Quick) is tried first and "
        "holds whenever it does [-Wshadowed-transition]\n"
        "t.sfc:9:3: note: 'T0' has the same or a weaker precondition\n");
}
