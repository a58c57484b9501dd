// The validator: sub-charts (docs/language.md "Sub-charts"): `runs`, cycles, periods, and the
// built-ins that read sub-charts. Each test compares every diagnostic as gfec prints it.
#include "validate_fixture.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec;
using test::Validated;

namespace {

const char *const kBot = R"--(interface Bot {
  bool Arrived();
  bool Holding();
  bool Stuck();
  bool Late();
  void DriveToItem();
  void PickUp();
  void Beep();
  void Park();
}
)--";

}  // namespace

TEST_CASE("validate: sub-charts lower to place indices, paths and outcomes", "[validate][subcharts]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
fsm Fetch {
  initial state Go { DriveToItem(); }
  state Grab { PickUp(); }
  success state Got;
  failure state Lost;
  Go -> Grab when Arrived();
  Grab -> Got when Holding() && elapsed(Grab) >= 30ms;
  Go -> Lost when Stuck();
}
sfc Patrol {
  period 10ms;
  initial place Search runs Fetch { Beep(); }
  place Home  { Park(); }
  place Retry runs Fetch;
  transition Search -> Home  when succeeded(Search);
  transition Search -> Retry when failed(Search) || elapsed(Search) >= 30s;
  transition Retry -> Home   when succeeded(Retry) || active(Retry.Grab) && Late();
  transition Home -> Search  when active(Home);
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == "");
  REQUIRE(r.model.charts.size() == 2);
  const model::Chart &fetch = r.model.charts[0];
  const model::Chart &patrol = r.model.charts[1];
  // Fetch declares no period: it runs at Patrol's, and its durations count Patrol's ticks.
  CHECK(fetch.period_ms == 10);
  CHECK(fetch.transitions[1].condition->args[1].args[1].ticks == 3);
  CHECK(patrol.places[0].runs == model::ChartId(0));
  CHECK_FALSE(patrol.places[1].runs);
  CHECK(patrol.places[2].runs == model::ChartId(0));
  CHECK_FALSE(fetch.places[0].runs);
  using K = model::Expr::Kind;
  const model::Expr &succeeded = *patrol.transitions[0].condition;
  CHECK(succeeded.kind == K::Succeeded);
  CHECK(succeeded.type == model::Type::Bool);
  CHECK(succeeded.place() == model::PlaceId(0));
  const model::Expr &failed = patrol.transitions[1].condition->args[0];
  CHECK(failed.kind == K::Failed);
  CHECK(failed.place() == model::PlaceId(0));
  const model::Expr &path = patrol.transitions[2].condition->args[1].args[0];
  CHECK(path.kind == K::Active);
  CHECK(path.path == test::ids<model::PlaceId>({2, 1}));
  const model::Expr &one = *patrol.transitions[3].condition;
  CHECK(one.kind == K::Active);
  CHECK(one.path == test::ids<model::PlaceId>({1}));
}

TEST_CASE("validate: sub-charts: three levels, the same chart under two parents of one period",
          "[validate][subcharts]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc Leaf { initial place L { Beep(); } }
fsm Mid { initial state M runs Leaf; success state Done; M -> Done when elapsed(M) >= 20ms; }
sfc Top { period 5ms; initial place A runs Mid; initial place B runs Leaf; A -> A2 when active(A.M.L); place A2; }
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == "");
  REQUIRE(r.model.charts.size() == 3);
  CHECK(r.model.charts[0].period_ms == 5);
  CHECK(r.model.charts[1].period_ms == 5);
  CHECK(r.model.charts[1].transitions[0].condition->args[1].ticks == 4);
  CHECK(r.model.charts[2].transitions[0].condition->path == test::ids<model::PlaceId>({0, 0, 0}));
}

TEST_CASE("validate: sub-charts: an unknown chart after 'runs' gets a did-you-mean, a function is no chart",
          "[validate][subcharts]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
fsm Fetch { initial state Go; success state Got; Go -> Got when Arrived(); }
sfc Top {
  initial place A runs Fech;
  place B runs Beep;
  place C runs Top2;
  transition A -> B;
}
sfc Top2 { initial place X; }
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:4:24: error: unknown chart 'Fech' [unknown-name]
   initial place A runs Fech;
                        ^~~~
t.sfc:2:5: note: did you mean 'Fetch'?
 fsm Fetch { initial state Go; success state Got; Go -> Got when Arrived(); }
     ^~~~~
t.sfc:5:16: error: 'Beep' is a function; a place or state runs an sfc or an fsm [type-mismatch]
   place B runs Beep;
                ^~~~
bot.iface:8:8: note: 'Beep' declared here
   void Beep();
        ^~~~
t.sfc:6:9: warning: place 'C' can never become active [-Wunreachable-place]
   place C runs Top2;
         ^
)--");
}

TEST_CASE(
    "validate: sub-charts: succeeded/failed need a place that runs an fsm, active paths resolve in the right chart",
    "[validate][subcharts]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
fsm Fetch { initial state Go; state Grab; success state Got; failure state Lost; Go -> Grab; Grab -> Got; Go -> Lost; }
sfc Line { initial place Left; place Right; Left -> Right; }
sfc Top {
  initial place Search runs Fetch;
  place Follow runs Line;
  place Idle;
  Search -> Follow when succeeded(Follow) || failed(Idle) || succeeded(Search);
  Follow -> Idle when active(Follow.Rigth) || active(Search.Grab.Hand) || active(Serch.Go);
  Idle -> Search when active(Search.Gone) || active(Search, Idle) || active();
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() ==
        R"--(t.sfc:8:25: error: 'succeeded(Follow)': place 'Follow' runs sfc 'Line', which never succeeds [subchart]
   Search -> Follow when succeeded(Follow) || failed(Idle) || succeeded(Search);
                         ^~~~~~~~~~~~~~~~~
t.sfc:6:21: note: only an fsm succeeds or fails; 'active(Follow.P)' reads the places of an sfc
   place Follow runs Line;
                     ^~~~
t.sfc:8:46: error: 'failed(Idle)': place 'Idle' runs no sub-chart [subchart]
   Search -> Follow when succeeded(Follow) || failed(Idle) || succeeded(Search);
                                              ^~~~~~~~~~~~
t.sfc:7:9: note: only a place or state that runs an fsm succeeds or fails ('place Idle runs FSM')
   place Idle;
         ^~~~
t.sfc:9:37: error: unknown place 'Rigth' in sfc 'Line', which 'Follow' runs [unknown-name]
   Follow -> Idle when active(Follow.Rigth) || active(Search.Grab.Hand) || active(Serch.Go);
                                     ^~~~~
t.sfc:3:38: note: did you mean 'Right'?
 sfc Line { initial place Left; place Right; Left -> Right; }
                                      ^~~~~
t.sfc:9:66: error: 'Grab' runs no sub-chart, so 'Hand' names nothing in it [unknown-name]
   Follow -> Idle when active(Follow.Rigth) || active(Search.Grab.Hand) || active(Serch.Go);
                                                                  ^~~~
t.sfc:2:37: note: 'Grab' declared here
 fsm Fetch { initial state Go; state Grab; success state Got; failure state Lost; Go -> Grab; Grab -> Got; Go -> Lost; }
                                     ^~~~
t.sfc:9:82: error: unknown place 'Serch' [unknown-name]
   Follow -> Idle when active(Follow.Rigth) || active(Search.Grab.Hand) || active(Serch.Go);
                                                                                  ^~~~~
t.sfc:5:17: note: did you mean 'Search'?
   initial place Search runs Fetch;
                 ^~~~~~
t.sfc:10:37: error: unknown state 'Gone' in fsm 'Fetch', which 'Search' runs [unknown-name]
   Idle -> Search when active(Search.Gone) || active(Search, Idle) || active();
                                     ^~~~
t.sfc:10:46: error: 'active' takes one argument: a place or state, or a path 'P.Q' into its sub-chart [active]
   Idle -> Search when active(Search.Gone) || active(Search, Idle) || active();
                                              ^~~~~~~~~~~~~~~~~~~~
t.sfc:10:70: error: 'active' takes one argument: a place or state, or a path 'P.Q' into its sub-chart [active]
   Idle -> Search when active(Search.Gone) || active(Search, Idle) || active();
                                                                      ^~~~~~~~
)--");
}

TEST_CASE("validate: sub-charts: a terminal state runs nothing", "[validate][subcharts]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
fsm Fetch {
  initial state Go { DriveToItem(); }
  success state Got runs Line;
  Go -> Got when Arrived();
}
sfc Line { initial place Left; }
)--"},
               {"bot.iface", kBot}});
  CHECK(
      r.text() ==
      R"--(t.sfc:4:26: error: terminal state 'Got' cannot run a sub-chart: the machine has stopped there [terminal-runs]
   success state Got runs Line;
                          ^~~~
)--");
}

TEST_CASE("validate: sub-charts: a sub-chart without a period of its own takes its parent's, and says so",
          "[validate][subcharts]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc Sub { initial place A { Beep(); } place B; transition A -> B when elapsed(A) >= 1s; }
sfc Top { initial place P runs Sub; }
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:2:71: error: 'elapsed(A)' needs a period, but sfc 'Sub' declares none [missing-period]
 sfc Sub { initial place A { Beep(); } place B; transition A -> B when elapsed(A) >= 1s; }
                                                                       ^~~~~~~~~~
t.sfc:2:5: note: a sub-chart takes the period of the chart that runs it; declare one there, e.g. 'period 10ms;'
 sfc Sub { initial place A { Beep(); } place B; transition A -> B when elapsed(A) >= 1s; }
     ^~~
)--");
}

TEST_CASE("validate: sub-charts: active() only inside a chart, never constant, never a statement",
          "[validate][subcharts]") {
  Validated r({{"t.sfc", R"--(const bool K = active(X);
sfc S { var bool v = active(A); initial place A { active(A); } }
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:1:16: error: 'active' can only be used inside an sfc or fsm [active]
 const bool K = active(X);
                ^~~~~~~~~
t.sfc:2:22: error: a constant expression cannot read 'active()' [not-constant]
 sfc S { var bool v = active(A); initial place A { active(A); } }
                      ^~~~~~~~~
t.sfc:2:51: error: 'active()' as a statement has no effect [type-mismatch]
 sfc S { var bool v = active(A); initial place A { active(A); } }
                                                   ^~~~~~~~~
)--");
}

TEST_CASE("validate: sub-charts: a sub-chart's period must be its parent's, two parents must agree",
          "[validate][subcharts]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
fsm Fast { period 20ms; initial state Go { DriveToItem(); } success state Got; Go -> Got when elapsed(Go) >= 100ms; }
sfc Sub { initial place A { Beep(); } place B; transition A -> B when elapsed(A) >= 1s; }
sfc Top {
  period 10ms;
  initial place P runs Fast;
  initial place Q runs Sub;
}
sfc Other {
  period 50ms;
  initial place R runs Sub;
}
sfc NoPeriod {
  initial place S runs Fast;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() ==
        R"--(t.sfc:6:24: error: sub-chart 'Fast' declares period 20ms but 'Top', which runs it, has period 10ms [period]
   initial place P runs Fast;
                        ^~~~
t.sfc:2:12: note: a sub-chart runs at the period of the chart that runs it; remove this period or make the two equal
 fsm Fast { period 20ms; initial state Go { DriveToItem(); } success state Got; Go -> Got when elapsed(Go) >= 100ms; }
            ^~~~~~~~~~~~
t.sfc:14:24: error: sub-chart 'Fast' declares period 20ms but 'NoPeriod', which runs it, has no period [period]
   initial place S runs Fast;
                        ^~~~
t.sfc:2:12: note: a sub-chart runs at the period of the chart that runs it; remove this period or make the two equal
 fsm Fast { period 20ms; initial state Go { DriveToItem(); } success state Got; Go -> Got when elapsed(Go) >= 100ms; }
            ^~~~~~~~~~~~
t.sfc:11:24: error: sub-chart 'Sub' would run at period 50ms here but at period 10ms in 'Top'; it declares no period of its own [period]
   initial place R runs Sub;
                        ^~~
t.sfc:7:24: note: 'Sub' is also run here
   initial place Q runs Sub;
                        ^~~
)--");
}

TEST_CASE("validate: sub-charts: the built-ins that read sub-charts cannot name a function", "[validate][subcharts]") {
  Validated r({{"t.sfc", R"--(interface Bot {
  bool active();
  bool succeeded(int x);
  void failed();
}
)--"}});
  CHECK(r.text() ==
        R"--(t.sfc:2:8: error: 'active' is built into the chart language and cannot name a function [reserved-name]
   bool active();
        ^~~~~~
t.sfc:3:8: error: 'succeeded' is built into the chart language and cannot name a function [reserved-name]
   bool succeeded(int x);
        ^~~~~~~~~
t.sfc:4:8: error: 'failed' is built into the chart language and cannot name a function [reserved-name]
   void failed();
        ^~~~~~
)--");
}

TEST_CASE("validate: sub-charts: a team machine is never run as a sub-chart", "[validate][subcharts]") {
  // `team N;` is parsed by the team machines' front end; the AST field is set by hand here so
  // that this check is tested on its own.
  test::FrontEnd fe({{"t.sfc", R"--(fsm Crew { initial state Go; success state Done; Go -> Done; }
sfc Top { initial place A runs Crew; }
)--"}});
  REQUIRE(fe.text() == "");
  ast::Chart &crew = fe.loaded.program.files.at(0)->charts.at(0);
  crew.teams.push_back({4, crew.name.range});
  model::Model m = validate(fe.loaded.program, fe.sources, fe.diag);
  std::string text = fe.text();
  CHECK(text.find("t.sfc:2:32: error: fsm 'Crew' is a team machine; it can only be compiled as the root, not run as a "
                  "sub-chart [team-subchart]\n") == 0);
  CHECK(text.find("t.sfc:1:5: note: it is made a team machine here\n") != std::string::npos);
}
