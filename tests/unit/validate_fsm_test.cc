// The validator: the rules and warnings of an fsm (docs/language.md §7).
// Each test validates chart text and compares every diagnostic as gfec prints it.
#include "validate_fixture.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec;
using test::all_warnings;
using test::kBot;
using test::Validated;

TEST_CASE("validate: terminal states have no body and no outgoing transitions", "[validate]") {
  Validated r({{"t.fsm", R"--(import "bot.iface";
fsm M {
  initial state A { Go(); }
  success state Done { Stop(); }
  failure state Failed;
  A -> Done when Black();
  A -> Failed when White();
  Done -> A;
}
)--"},
               {"bot.iface", kBot}});
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
  Validated r({{"t.fsm", R"--(import "bot.iface";
fsm M {
  initial state A post Black();
  success state Done post Distance();
  failure state Failed post !Black();
  A -> Done;
  A -> Failed;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.fsm:3:24: error: only a success or failure state can have a 'post' condition [terminal-state]
   initial state A post Black();
                        ^~~~~~~
t.fsm:4:27: error: postcondition must be bool, not 'float' [type-mismatch]
   success state Done post Distance();
                           ^~~~~~~~~~
)--");
}

TEST_CASE("validate: no transition from a state to itself, one per ordered pair", "[validate]") {
  Validated r({{"t.fsm", R"--(import "bot.iface";
fsm M {
  initial state A;
  state B;
  A -> A when Black();
  A -> B when Black();
  back: B -> A;
  A -> B when White();
  again: B -> A;
}
)--"},
               {"bot.iface", kBot}});
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
  Validated r({{"t.fsm", R"--(fsm M {
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

TEST_CASE("validate: sfc syntax in an fsm", "[validate]") {
  Validated r({{"t.fsm", R"--(import "bot.iface";
fsm M {
  initial state A { entry { Go(); } Go(); exit { Stop(); } }
  place B;
  A -> B;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.fsm:4:3: error: 'place' in an fsm: an fsm has states (write 'state B') [wrong-keyword]
   place B;
   ^~~~~~~~
)--");
}

TEST_CASE("validate: fsm states may have entry and exit blocks, terminal states still no body", "[validate]") {
  Validated r({{"t.fsm", R"--(import "bot.iface";
fsm M {
  initial state A { entry { Go(); } Go(); exit { Stop(); } }
  state B { exit { Stop(); } }
  success state Done { entry { Go(); } }
  failure state Lost { exit { Stop(); } }
  A -> B;
  B -> Done when Black();
  B -> Lost when White();
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.fsm:5:3: error: terminal state 'Done' cannot have a body [terminal-state]
   success state Done { entry { Go(); } }
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.fsm:6:3: error: terminal state 'Lost' cannot have a body [terminal-state]
   failure state Lost { exit { Stop(); } }
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
)--");
  Validated ok({{"t.fsm", R"--(import "bot.iface";
fsm M {
  initial state A { entry { Go(); } Go(); exit { Stop(); } }
  state B { exit { Stop(); } }
  success state Done;
  A -> B;
  B -> Done when Black();
}
)--"},
                {"bot.iface", kBot}});
  CHECK(ok.text().empty());
  REQUIRE(ok.model.charts.size() == 1);
  const auto &a = ok.model.charts[0].places[0];
  REQUIRE(a.entry);
  REQUIRE(a.exit);
  CHECK(a.entry->size() == 1);
  CHECK(a.exit->size() == 1);
  CHECK(a.action.size() == 1);
  CHECK(!ok.model.charts[0].places[1].entry);
  CHECK(ok.model.charts[0].places[1].exit);
}

TEST_CASE("validate: states no transition reaches and the transitions leaving them", "[validate]") {
  Validated r({{"t.fsm", R"--(import "bot.iface";
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
)--"},
               {"bot.iface", kBot}});
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
  Validated r({{"t.fsm", R"--(import "bot.iface";
fsm M {
  period 20ms;
  initial state A { Go(); }
  state B { Stop(); }
  success state Done;
  failure state Failed post Black();
  A -> B when elapsed(A) > 60ms;
  B -> A when White();
  B -> Done when Black();
  A -> Failed when elapsed(A) > 10s;
}
)--"},
               {"bot.iface", kBot}},
              all_warnings());
  CHECK(r.text() == R"--()--");
  const auto &c = r.model.charts.at(0);
  CHECK(c.kind == model::Chart::Kind::Fsm);
  CHECK(c.period_ms == 20);
  CHECK(c.places[2].terminal == model::Terminal::Success);
  CHECK(c.places[3].terminal == model::Terminal::Failure);
  CHECK(c.places[3].post.has_value());
  CHECK(c.places[0].timed);
  CHECK_FALSE(c.places[1].timed);
  CHECK(c.transitions[2].inputs == test::ids<model::PlaceId>({1}));
  CHECK(c.transitions[2].outputs == test::ids<model::PlaceId>({2}));
  REQUIRE(c.transitions[0].condition);
  CHECK(c.transitions[0].condition->args[1].kind == model::Expr::Kind::Ticks);
  CHECK(c.transitions[0].condition->args[1].ticks == 3);
  CHECK(c.transitions[0].condition->args[1].float_value == 60);
  CHECK(c.transitions[3].condition->args[1].ticks == 500);
}

TEST_CASE("validate: team machines: the declaration", "[validate][team]") {
  Validated r({{"t.fsm", R"--(import "bot.iface";
fsm M {
  team 1;
  initial state A;
}
fsm N {
  team 3;
  team 4;
  initial state A;
}
sfc S {
  team 2;
  initial place A;
}
fsm Big {
  team 5000;
  initial state A;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.fsm:3:3: error: a team has at least 2 agents, not 1 [team]
   team 1;
   ^~~~~~~
t.fsm:3:3: note: an fsm without 'team' is run by one agent
t.fsm:8:3: error: second 'team' declaration in fsm 'N' [team]
   team 4;
   ^~~~~~~
t.fsm:7:3: note: the first one is here
   team 3;
   ^~~~~~~
t.fsm:12:3: error: 'team' in sfc 'S': only an fsm can be a team machine [team]
   team 2;
   ^~~~~~~
t.fsm:16:3: error: a team has at most 1024 agents [team]
   team 5000;
   ^~~~~~~~~~
)--");
  REQUIRE(r.model.charts.size() == 4);
  CHECK(r.model.charts[0].team == 0);
  CHECK(r.model.charts[1].team == 3);
  CHECK(r.model.charts[2].team == 0);
}

TEST_CASE("validate: team machines: team(S) and agent()", "[validate][team]") {
  Validated r({{"t.fsm", R"--(import "bot.iface";
fsm Fetch {
  team 4;
  var int me = 0;
  initial state Go { me = agent(); if (team(Grab) == 0) { Stop(); } }
  state Grab;
  success state Got;
  Go -> Grab when Black() && team(Grab) == 0 && agent() >= 0;
  Grab -> Got when team(Got) + team(Go) > 1;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text().empty());
  REQUIRE(r.model.charts.size() == 1);
  const model::Chart &c = r.model.charts[0];
  CHECK(c.team == 4);
  const model::Expr &cond = *c.transitions[0].condition;  // (Black() && team(Grab) == 0) && agent() >= 0
  const model::Expr &team = cond.args.at(0).args.at(1).args.at(0);
  CHECK(team.kind == model::Expr::Kind::TeamCount);
  CHECK(team.type == model::Type::Int);
  CHECK(team.place() == model::PlaceId(1));
  const model::Expr &agent = cond.args.at(1).args.at(0);
  CHECK(agent.kind == model::Expr::Kind::Agent);
  CHECK(agent.type == model::Type::Int);
}

TEST_CASE("validate: team machines: team and agent where they cannot be", "[validate][team]") {
  Validated r({{"t.fsm", R"--(import "bot.iface";
const int K = agent();
fsm Solo {
  var int n = 0;
  initial state A { n = agent(); }
  state B;
  A -> B when team(B) > 0;
}
sfc S {
  initial place P { if (team(P) > 1) { Go(); } }
}
fsm T {
  team 2;
  var int n = agent();
  initial state Go { agent(); n = agent(1); }
  state Grab;
  Go -> Grab when team(Grap) == 0 || team(n) > 0;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.fsm:2:15: error: 'agent()' can only be used in a team machine [team]
 const int K = agent();
               ^~~~~~~
t.fsm:5:25: error: 'agent()' can only be used in a team machine [team]
   initial state A { n = agent(); }
                         ^~~~~~~
t.fsm:3:5: note: make fsm 'Solo' one by declaring its team size in it, e.g. 'team 2;'
 fsm Solo {
     ^~~~
t.fsm:7:15: error: 'team()' can only be used in a team machine [team]
   A -> B when team(B) > 0;
               ^~~~~~~
t.fsm:3:5: note: make fsm 'Solo' one by declaring its team size in it, e.g. 'team 2;'
 fsm Solo {
     ^~~~
t.fsm:10:25: error: 'team()' can only be used in a team machine [team]
   initial place P { if (team(P) > 1) { Go(); } }
                         ^~~~~~~
t.fsm:14:15: error: a constant expression cannot read 'agent()' [not-constant]
   var int n = agent();
               ^~~~~~~
t.fsm:15:22: error: 'agent()' as a statement has no effect [type-mismatch]
   initial state Go { agent(); n = agent(1); }
                      ^~~~~~~
t.fsm:15:35: error: 'agent' takes no arguments (have 1) [argument-count]
   initial state Go { agent(); n = agent(1); }
                                   ^~~~~~~~
t.fsm:17:24: error: unknown state 'Grap' [unknown-name]
   Go -> Grab when team(Grap) == 0 || team(n) > 0;
                        ^~~~
t.fsm:16:9: note: did you mean 'Grab'?
   state Grab;
         ^~~~
t.fsm:17:43: error: 'n' is a variable, not a state [type-mismatch]
   Go -> Grab when team(Grap) == 0 || team(n) > 0;
                                           ^
t.fsm:14:11: note: 'n' declared here
   var int n = agent();
           ^
)--");
}

TEST_CASE("validate: team machines: built-in and engine names", "[validate][team]") {
  Validated r({{"t.fsm", R"--(interface Bot { int agent(); bool elapsed(); }
fsm T {
  team 2;
  initial state report;
  state set_agent;
  state TEAM_SIZE;
  report -> set_agent;
  set_agent -> TEAM_SIZE;
}
fsm Solo {
  initial state report;
}
)--"}});
  CHECK(r.text() ==
        R"--(t.fsm:1:21: error: 'agent' is built into the chart language and cannot name a function [reserved-name]
 interface Bot { int agent(); bool elapsed(); }
                     ^~~~~
t.fsm:1:35: error: 'elapsed' is built into the chart language and cannot name a function [reserved-name]
 interface Bot { int agent(); bool elapsed(); }
                                   ^~~~~~~
t.fsm:4:17: error: state 'report' would generate 'T_report', which the engine of a team machine already defines [reserved-name]
   initial state report;
                 ^~~~~~
t.fsm:5:9: error: state 'set_agent' would generate 'T_set_agent', which the engine of a team machine already defines [reserved-name]
   state set_agent;
         ^~~~~~~~~
t.fsm:6:9: error: state 'TEAM_SIZE' would generate 'T_TEAM_SIZE', which the engine of a team machine already defines [reserved-name]
   state TEAM_SIZE;
         ^~~~~~~~~
)--");
}

TEST_CASE("validate: a team machine cannot run as a sub-chart", "[validate][team]") {
  test::Pipeline fe("t.fsm", test::files({{"t.fsm", R"--(fsm Fetch {
  team 3;
  initial state Go;
}
fsm Solo {
  initial state Go;
}
sfc Patrol {
  initial place Search runs Fetch;
  place Other runs Solo;
}
)--"}}));
  std::string text = fe.text();
  CHECK(
      text.find(
          R"--(t.fsm:9:29: error: fsm 'Fetch' is a team machine; it can only be compiled as the root, not run as a sub-chart [team-subchart]
   initial place Search runs Fetch;
                             ^~~~~
t.fsm:2:3: note: it is made a team machine here
   team 3;
   ^~~~~~~
)--") != std::string::npos);
  CHECK(text.find("'Solo'") == std::string::npos);
  CHECK(text.find("not run as a sub-chart") == text.rfind("not run as a sub-chart"));  // once: Fetch
}
