// The validator: the rules and warnings of an fsm (LANGUAGE.md section 7).
// Each test validates chart text and compares every diagnostic as gfec prints it.
#include "support.h"
#include "validate.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec;

namespace {

[[maybe_unused]] const char *const kBot = R"--(interface Bot {
  bool Black();
  bool White();
  void Go();
  void Stop();
  void Motor(int side, float speed);
  void Lamp(bool on);
  float Distance();
  int Count();
}
)--";

[[maybe_unused]] const char *const kToolbox = R"--(toolbox Carbot {
  actor Forward(in float distance) -> FORWARD_OK;
  actor Turn(in float angle) -> TURN_OK;
  actor SearchWall(out float angle) -> WALL_FOUND | NO_WALL_FOUND;
  actor Say(in string text, in bool loud) -> SAID;
  computation CountDown(in int n, out int rest) -> AGAIN | DONE;
  supervisor CheckTouch() events TOUCHED;
  supervisor CheckLane(in float dist) events LANE_NOT_FREE period 10ms;
}
)--";

/// Loads in-memory files (the first is the main file) and validates them.
struct Run {
  test::FrontEnd fe;
  model::Model model;

  Run(std::initializer_list<std::pair<std::string, std::string>> files, WarningOptions w = {}) : fe(files, w) {
    model = validate(fe.loaded.program, fe.sources, fe.diag);
  }
  std::string text() const { return fe.text(); }
};

[[maybe_unused]] WarningOptions all_warnings() {
  WarningOptions w;
  for (int i = 0; i < static_cast<int>(Warning::Count_); ++i) w.set(static_cast<Warning>(i), true);
  return w;
}

} // namespace

TEST_CASE("validate: an fsm has exactly one initial state", "[validate]") {
  Run r({{"t.fsm", R"--(fsm M {
  state A;
  state B;
  A -> B;
}
fsm N {
  initial state A;
  initial state B;
  A -> B;
}
)--"}});
  CHECK(r.text() == R"--(t.fsm:1:5: error: fsm 'M' has no initial state [initial-state]
 fsm M {
     ^
t.fsm:1:5: note: mark the state it starts in with 'initial state'
t.fsm:8:17: error: fsm 'N' has more than one initial state [initial-state]
   initial state B;
                 ^
t.fsm:7:17: note: 'A' is already its initial state
   initial state A;
                 ^
)--");
}

TEST_CASE("validate: terminal states have no body and no outgoing transitions", "[validate]") {
  Run r({{"t.fsm", R"--(import "bot.iface";
fsm M {
  initial state A { Go(); }
  success state Done { Stop(); }
  failure state Failed;
  A -> Done when Black();
  A -> Failed when White();
  Done -> A;
}
)--"}, {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.fsm:4:3: error: terminal state 'Done' cannot have a body [terminal-state]
   success state Done { Stop(); }
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.fsm:8:3: error: transition leaves terminal state 'Done' [terminal-state]
   Done -> A;
   ^~~~~~~~~~
t.fsm:4:17: note: 'Done' ends the machine
   success state Done { Stop(); }
                 ^~~~
)--");
}

TEST_CASE("validate: post is for terminal states and must be bool", "[validate]") {
  Run r({{"t.fsm", R"--(import "bot.iface";
fsm M {
  initial state A post Black();
  success state Done post Distance();
  failure state Failed post !Black();
  A -> Done;
  A -> Failed;
}
)--"}, {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.fsm:3:24: error: only a success or failure state can have a 'post' condition [terminal-state]
   initial state A post Black();
                        ^~~~~~~
t.fsm:4:27: error: postcondition must be bool, not 'float' [type-mismatch]
   success state Done post Distance();
                           ^~~~~~~~~~
)--");
}

TEST_CASE("validate: no transition from a state to itself, one per ordered pair", "[validate]") {
  Run r({{"t.fsm", R"--(import "bot.iface";
fsm M {
  initial state A;
  state B;
  A -> A when Black();
  A -> B when Black();
  back: B -> A;
  A -> B when White();
  again: B -> A;
}
)--"}, {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.fsm:5:3: error: transition from state 'A' to itself [self-transition]
   A -> A when Black();
   ^~~~~~~~~~~~~~~~~~~~
t.fsm:8:3: error: second transition from 'A' to 'B' [duplicate-transition]
   A -> B when White();
   ^~~~~~~~~~~~~~~~~~~~
t.fsm:6:3: note: the first one is here
   A -> B when Black();
   ^~~~~~~~~~~~~~~~~~~~
t.fsm:9:3: error: second transition from 'B' to 'A' [duplicate-transition]
   again: B -> A;
   ^~~~~
t.fsm:7:3: note: the first one is here
   back: B -> A;
   ^~~~
)--");
}

TEST_CASE("validate: an fsm transition has one source and one target state", "[validate]") {
  Run r({{"t.fsm", R"--(fsm M {
  initial state A;
  state B;
  state C;
  (A, B) -> C;
  A -> (B, C);
  A -> Z;
}
)--"}});
  CHECK(r.text() == R"--(t.fsm:5:3: error: an fsm transition has exactly one source state [fsm-transition]
   (A, B) -> C;
   ^~~~~~~~~~~~
t.fsm:6:3: error: an fsm transition has exactly one target state [fsm-transition]
   A -> (B, C);
   ^~~~~~~~~~~~
t.fsm:7:8: error: unknown state 'Z' [unknown-name]
   A -> Z;
        ^
)--");
}

TEST_CASE("validate: every state is connected to the initial state", "[validate]") {
  Run r({{"t.fsm", R"--(fsm M {
  initial state A;
  state B;
  state C;
  state D;
  state E;
  A -> B;
  C -> D;
}
)--"}});
  CHECK(r.text() == R"--(t.fsm:4:9: error: state 'C' is not connected to the initial state 'A' [not-connected]
   state C;
         ^
t.fsm:5:9: error: state 'D' is not connected to the initial state 'A' [not-connected]
   state D;
         ^
t.fsm:6:9: error: state 'E' is not connected to the initial state 'A' [not-connected]
   state E;
         ^
)--");
}

TEST_CASE("validate: sfc syntax in an fsm", "[validate]") {
  Run r({{"t.fsm", R"--(import "bot.iface";
fsm M {
  initial state A { entry { Go(); } Go(); exit { Stop(); } }
  place B;
  A -> B;
}
)--"}, {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.fsm:3:21: error: 'entry' blocks belong to sfc places; an fsm state has only its action [wrong-keyword]
   initial state A { entry { Go(); } Go(); exit { Stop(); } }
                     ^~~~~~~~~~~~~~~
t.fsm:3:43: error: 'exit' blocks belong to sfc places; an fsm state has only its action [wrong-keyword]
   initial state A { entry { Go(); } Go(); exit { Stop(); } }
                                           ^~~~~~~~~~~~~~~~
t.fsm:4:3: error: 'place' in an fsm: an fsm has states (write 'state B') [wrong-keyword]
   place B;
   ^~~~~~~~
)--");
}

TEST_CASE("validate: states no transition reaches and the transitions leaving them", "[validate]") {
  Run r({{"t.fsm", R"--(import "bot.iface";
fsm M {
  initial state A;
  state B;
  state C;
  success state Done;
  A -> B when false;
  B -> Done;
  C -> A when Black();
  A -> Done;
}
)--"}, {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.fsm:4:9: warning: state 'B' can never become active [-Wunreachable-place]
   state B;
         ^
t.fsm:5:9: warning: state 'C' can never become active [-Wunreachable-place]
   state C;
         ^
t.fsm:7:3: warning: transition 'T0' can never fire: its condition is always false [-Wdead-transition]
   A -> B when false;
   ^~~~~~~~~~~~~~~~~~
t.fsm:8:3: warning: transition 'T1' can never fire: state 'B' never becomes active [-Wdead-transition]
   B -> Done;
   ^~~~~~~~~~
t.fsm:9:3: warning: transition 'T2' can never fire: state 'C' never becomes active [-Wdead-transition]
   C -> A when Black();
   ^~~~~~~~~~~~~~~~~~~~
)--");
}

TEST_CASE("validate: the sample's shape: one transition per pair, terminal states", "[validate]") {
  Run r({{"t.fsm", R"--(import "bot.iface";
fsm M {
  period 20ms;
  initial state A { Go(); }
  state B { Stop(); }
  success state Done;
  failure state Failed post Black();
  A -> B when elapsed(A) > 50ms;
  B -> A when White();
  B -> Done when Black();
  A -> Failed when elapsed(A) > 10s;
}
)--"}, {"bot.iface", kBot}}, all_warnings());
  CHECK(r.text() == R"--()--");
  const auto &c = r.model.charts.at(0);
  CHECK(c.kind == model::Chart::Kind::Fsm);
  CHECK(c.period_ms == 20);
  CHECK(c.places[2].terminal == model::Terminal::Success);
  CHECK(c.places[3].terminal == model::Terminal::Failure);
  CHECK(c.places[3].post.has_value());
  CHECK(c.places[0].timed);
  CHECK_FALSE(c.places[1].timed);
  CHECK(c.transitions[2].inputs == std::vector<int>{1});
  CHECK(c.transitions[2].outputs == std::vector<int>{2});
  REQUIRE(c.transitions[0].condition);
  CHECK(c.transitions[0].condition->args[1].kind == model::Expr::Kind::Ticks);
  CHECK(c.transitions[0].condition->args[1].ticks == 3);
  CHECK(c.transitions[0].condition->args[1].ms == 50);
  CHECK(c.transitions[3].condition->args[1].ticks == 500);
}

