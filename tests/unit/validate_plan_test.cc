// The validator: toolboxes and plans (docs/language.md §8).
// Each test validates chart text and compares every diagnostic as gfec prints it.
#include "validate_fixture.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec;
using test::all_warnings;
using test::kToolbox;
using test::Validated;

TEST_CASE("validate: toolbox templates: parameter types, duplicates, outcomes, periods", "[validate]") {
  Validated r({{"t.toolbox", R"--(toolbox Box {
  actor A(in integer x, in void y, out float x) -> DONE | DONE;
  supervisor S(in float d) events HIT period 0ms;
  computation C(in int n) -> OK;
  actor D(in object o, in string s, out bool b, out double d) -> OK;
}
)--"}});
  CHECK(r.text() == R"--(t.toolbox:2:14: error: unknown type name 'integer' [unknown-type]
   actor A(in integer x, in void y, out float x) -> DONE | DONE;
              ^~~~~~~
t.toolbox:2:28: error: type 'void' is not allowed for a template parameter [bad-type]
   actor A(in integer x, in void y, out float x) -> DONE | DONE;
                            ^~~~
t.toolbox:2:46: error: redefinition of parameter 'x' [duplicate-name]
   actor A(in integer x, in void y, out float x) -> DONE | DONE;
                                              ^
t.toolbox:2:22: note: previous definition of 'x' was here
   actor A(in integer x, in void y, out float x) -> DONE | DONE;
                      ^
t.toolbox:2:59: error: redefinition of result state 'DONE' [duplicate-name]
   actor A(in integer x, in void y, out float x) -> DONE | DONE;
                                                           ^~~~
t.toolbox:2:52: note: previous definition of 'DONE' was here
   actor A(in integer x, in void y, out float x) -> DONE | DONE;
                                                    ^~~~
t.toolbox:3:39: error: the period must be positive [period]
   supervisor S(in float d) events HIT period 0ms;
                                       ^~~~~~~~~~
)--");
}

TEST_CASE("validate: a plan has exactly one start", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
plan P {
  config { float dist = 30; float angle; int count = 3; bool loud = true; string label = "x"; }
  start go;
  start go2;
  actor go: Forward(1) { FORWARD_OK -> terminate; }
  actor go2: Forward(2) { FORWARD_OK -> terminate; }
}
plan Q {
  actor x: Forward(1) { FORWARD_OK -> terminate; }
}
plan R {
  start xx;
  actor x: Forward(1) { FORWARD_OK -> terminate; }
}
)--"},
               {"carbot.toolbox", kToolbox}});
  CHECK(r.text() == R"--(t.plan:5:9: error: plan 'P' has more than one start actor [start]
   start go2;
         ^~~
t.plan:4:9: note: the first 'start' is here
   start go;
         ^~
t.plan:9:6: error: plan 'Q' has no start actor [start]
 plan Q {
      ^
t.plan:9:6: note: name the actor that runs first with 'start NAME;'
t.plan:13:9: error: unknown actor 'xx' [unknown-name]
   start xx;
         ^~
)--");
}

TEST_CASE("validate: unknown templates get a did-you-mean among the right kind", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
plan P {
  config { float dist = 30; float angle; int count = 3; bool loud = true; string label = "x"; }
  start a;
  actor a: Foward(1) { FORWARD_OK -> terminate; }
  actor b: CheckTuch() { TOUCHED -> terminate; }
  supervise s: CheckTuch() { TOUCHED -> terminate; }
}
)--"},
               {"carbot.toolbox", kToolbox}});
  CHECK(r.text() == R"--(t.plan:5:12: error: unknown template 'Foward' [unknown-name]
   actor a: Foward(1) { FORWARD_OK -> terminate; }
            ^~~~~~
carbot.toolbox:2:9: note: did you mean 'Forward'?
   actor Forward(in float distance) -> FORWARD_OK;
         ^~~~~~~
t.plan:6:12: error: unknown template 'CheckTuch' [unknown-name]
   actor b: CheckTuch() { TOUCHED -> terminate; }
            ^~~~~~~~~
t.plan:7:16: error: unknown supervisor template 'CheckTuch' [unknown-name]
   supervise s: CheckTuch() { TOUCHED -> terminate; }
                ^~~~~~~~~
carbot.toolbox:7:14: note: did you mean 'CheckTouch'?
   supervisor CheckTouch() events TOUCHED;
              ^~~~~~~~~~
)--");
}

TEST_CASE("validate: templates of the wrong kind", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
plan P {
  config { float dist = 30; float angle; int count = 3; bool loud = true; string label = "x"; }
  start a;
  actor a: CheckTouch() { TOUCHED -> terminate; }
  supervise s: Forward(1) { FORWARD_OK -> terminate; }
  supervise t: Q() { OK -> terminate; }
  computation c: Turn(1) { TURN_OK -> terminate; }
}
plan Q { start q; actor q: Turn(1) { TURN_OK -> terminate; } }
)--"},
               {"carbot.toolbox", kToolbox}});
  CHECK(
      r.text() ==
      R"--(t.plan:5:12: error: 'CheckTouch' is a supervisor template; an actor needs an actor or computation [template-kind]
   actor a: CheckTouch() { TOUCHED -> terminate; }
            ^~~~~~~~~~
carbot.toolbox:7:3: note: 'CheckTouch' declared here
   supervisor CheckTouch() events TOUCHED;
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.plan:6:16: error: 'Forward' is an actor template; 'supervise' needs a supervisor template [template-kind]
   supervise s: Forward(1) { FORWARD_OK -> terminate; }
                ^~~~~~~
carbot.toolbox:2:3: note: 'Forward' declared here
   actor Forward(in float distance) -> FORWARD_OK;
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.plan:7:16: error: 'Q' is a plan; 'supervise' needs a supervisor template [template-kind]
   supervise t: Q() { OK -> terminate; }
                ^
t.plan:10:1: note: 'Q' declared here
 plan Q { start q; actor q: Turn(1) { TURN_OK -> terminate; } }
 ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.plan:8:18: error: 'Turn' is not a computation [template-kind]
   computation c: Turn(1) { TURN_OK -> terminate; }
                  ^~~~
carbot.toolbox:3:3: note: 'Turn' declared here
   actor Turn(in float angle) -> TURN_OK;
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
)--");
}

TEST_CASE("validate: every result state and event is connected, once, to something that exists", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
plan P {
  config { float dist = 30; float angle; int count = 3; bool loud = true; string label = "x"; }
  start a;
  actor a: SearchWall(angle) { WALL_FOUND -> b; NO_WALL_FUND -> b; }
  actor b: Turn(angle) {
    TURN_OK -> a;
    TURN_OK -> terminate;
    supervise touch: CheckTouch() { TOUCH -> a; }
  }
  actor c: Forward(dist) { FORWARD_OK -> bb; supervise lane: CheckLane(dist) { } }
}
)--"},
               {"carbot.toolbox", kToolbox}},
              all_warnings());
  CHECK(r.text() == R"--(t.plan:5:49: error: unknown result state 'NO_WALL_FUND' of 'SearchWall' [unknown-name]
   actor a: SearchWall(angle) { WALL_FOUND -> b; NO_WALL_FUND -> b; }
                                                 ^~~~~~~~~~~~
carbot.toolbox:4:53: note: did you mean 'NO_WALL_FOUND'?
   actor SearchWall(out float angle) -> WALL_FOUND | NO_WALL_FOUND;
                                                     ^~~~~~~~~~~~~
t.plan:8:5: error: result state 'TURN_OK' is connected twice [duplicate-rule]
     TURN_OK -> terminate;
     ^~~~~~~
t.plan:7:5: note: first connected here
     TURN_OK -> a;
     ^~~~~~~~~~~~~
t.plan:9:37: error: unknown event 'TOUCH' of 'CheckTouch' [unknown-name]
     supervise touch: CheckTouch() { TOUCH -> a; }
                                     ^~~~~
carbot.toolbox:7:34: note: did you mean 'TOUCHED'?
   supervisor CheckTouch() events TOUCHED;
                                  ^~~~~~~
t.plan:11:42: error: unknown actor 'bb' [unknown-name]
   actor c: Forward(dist) { FORWARD_OK -> bb; supervise lane: CheckLane(dist) { } }
                                          ^~
t.plan:11:56: error: event 'LANE_NOT_FREE' of 'CheckLane' is not connected [not-connected]
   actor c: Forward(dist) { FORWARD_OK -> bb; supervise lane: CheckLane(dist) { } }
                                                        ^~~~
carbot.toolbox:8:3: note: 'CheckLane' has the events LANE_NOT_FREE
   supervisor CheckLane(in float dist) events LANE_NOT_FREE period 10ms;
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
)--");
}

TEST_CASE("validate: ignore is for events only", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
plan P {
  config { float dist = 30; float angle; int count = 3; bool loud = true; string label = "x"; }
  start a;
  supervise s: CheckTouch() { TOUCHED -> ignore; }
  actor a: Forward(1) { FORWARD_OK -> ignore; }
}
)--"},
               {"carbot.toolbox", kToolbox}});
  CHECK(r.text() ==
        R"--(t.plan:6:39: error: result state 'FORWARD_OK' cannot be ignored: only supervisor events can [ignore-state]
   actor a: Forward(1) { FORWARD_OK -> ignore; }
                                       ^~~~~~
t.plan:6:39: note: a result state leads to an actor or to 'terminate'
)--");
}

TEST_CASE("validate: argument count and types", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
plan P {
  config { float dist = 30; float angle; int count = 3; bool loud = true; string label = "x"; }
  start a;
  actor a: Forward() { FORWARD_OK -> b; }
  actor b: Forward(1, 2) { FORWARD_OK -> c; }
  actor c: Forward(loud) { FORWARD_OK -> d; }
  actor d: Say(dist, count) { SAID -> e; }
  actor e: Say(label + " " + dist, loud) { SAID -> f; }
  actor f: Forward(label) { FORWARD_OK -> terminate; }
}
)--"},
               {"carbot.toolbox", kToolbox}});
  CHECK(r.text() == R"--(t.plan:5:3: error: too few arguments to 'Forward' (expected 1, have 0) [argument-count]
   actor a: Forward() { FORWARD_OK -> b; }
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
carbot.toolbox:2:3: note: 'Forward' declared here
   actor Forward(in float distance) -> FORWARD_OK;
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.plan:6:3: error: too many arguments to 'Forward' (expected 1, have 2) [argument-count]
   actor b: Forward(1, 2) { FORWARD_OK -> c; }
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
carbot.toolbox:2:3: note: 'Forward' declared here
   actor Forward(in float distance) -> FORWARD_OK;
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.plan:7:20: error: incompatible type for argument 1 ('distance') of 'Forward': expected 'float', have 'bool' [type-mismatch]
   actor c: Forward(loud) { FORWARD_OK -> d; }
                    ^~~~
carbot.toolbox:2:3: note: 'Forward' declared here
   actor Forward(in float distance) -> FORWARD_OK;
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.plan:8:22: error: incompatible type for argument 2 ('loud') of 'Say': expected 'bool', have 'int' [type-mismatch]
   actor d: Say(dist, count) { SAID -> e; }
                      ^~~~~
carbot.toolbox:5:3: note: 'Say' declared here
   actor Say(in string text, in bool loud) -> SAID;
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
)--");
}

TEST_CASE("validate: out parameters are bound to plain config entries", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
const float K = 1;
plan P {
  config { float dist = 30; float angle; int count = 3; bool loud = true; string label = "x"; }
  start a;
  actor a: SearchWall(angle + 1) { WALL_FOUND -> b; NO_WALL_FOUND -> b; }
  actor b: SearchWall(K) { WALL_FOUND -> c; NO_WALL_FOUND -> c; }
  actor c: SearchWall(3) { WALL_FOUND -> d; NO_WALL_FOUND -> d; }
  actor d: SearchWall((angle)) { WALL_FOUND -> e; NO_WALL_FOUND -> e; }
  actor e: SearchWall(angel) { WALL_FOUND -> f; NO_WALL_FOUND -> f; }
  actor f: SearchWall(loud) { WALL_FOUND -> g; NO_WALL_FOUND -> g; }
  computation g: CountDown(count, label) { AGAIN -> g; DONE -> terminate; }
}
)--"},
               {"carbot.toolbox", kToolbox}});
  CHECK(r.text() ==
        R"--(t.plan:6:23: error: out parameter 'angle' of 'SearchWall' must be bound to a config entry [out-argument]
   actor a: SearchWall(angle + 1) { WALL_FOUND -> b; NO_WALL_FOUND -> b; }
                       ^~~~~~~~~
carbot.toolbox:4:3: note: 'SearchWall' declared here
   actor SearchWall(out float angle) -> WALL_FOUND | NO_WALL_FOUND;
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.plan:7:23: error: out parameter 'angle' of 'SearchWall' must be bound to a config entry [out-argument]
   actor b: SearchWall(K) { WALL_FOUND -> c; NO_WALL_FOUND -> c; }
                       ^
carbot.toolbox:4:3: note: 'SearchWall' declared here
   actor SearchWall(out float angle) -> WALL_FOUND | NO_WALL_FOUND;
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.plan:8:23: error: out parameter 'angle' of 'SearchWall' must be bound to a config entry [out-argument]
   actor c: SearchWall(3) { WALL_FOUND -> d; NO_WALL_FOUND -> d; }
                       ^
carbot.toolbox:4:3: note: 'SearchWall' declared here
   actor SearchWall(out float angle) -> WALL_FOUND | NO_WALL_FOUND;
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.plan:9:23: error: out parameter 'angle' of 'SearchWall' must be bound to a config entry [out-argument]
   actor d: SearchWall((angle)) { WALL_FOUND -> e; NO_WALL_FOUND -> e; }
                       ^~~~~~~
carbot.toolbox:4:3: note: 'SearchWall' declared here
   actor SearchWall(out float angle) -> WALL_FOUND | NO_WALL_FOUND;
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.plan:10:23: error: unknown config entry 'angel' [unknown-name]
   actor e: SearchWall(angel) { WALL_FOUND -> f; NO_WALL_FOUND -> f; }
                       ^~~~~
t.plan:4:35: note: did you mean 'angle'?
   config { float dist = 30; float angle; int count = 3; bool loud = true; string label = "x"; }
                                   ^~~~~
t.plan:11:23: error: out parameter 'angle' of 'SearchWall' has type 'float', which config entry 'loud' of type 'bool' cannot hold [type-mismatch]
   actor f: SearchWall(loud) { WALL_FOUND -> g; NO_WALL_FOUND -> g; }
                       ^~~~
carbot.toolbox:4:3: note: 'SearchWall' declared here
   actor SearchWall(out float angle) -> WALL_FOUND | NO_WALL_FOUND;
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
)--");
}

TEST_CASE("validate: a computation cannot be supervised", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
plan P {
  config { float dist = 30; float angle; int count = 3; bool loud = true; string label = "x"; }
  start c;
  computation c: CountDown(count, count) {
    AGAIN -> c;
    DONE -> terminate;
    supervise touch: CheckTouch() { TOUCHED -> terminate; }
  }
}
)--"},
               {"carbot.toolbox", kToolbox}});
  CHECK(r.text() == R"--(t.plan:8:15: error: computation 'c' cannot be supervised [computation-supervisor]
     supervise touch: CheckTouch() { TOUCHED -> terminate; }
               ^~~~~
t.plan:8:15: note: a computation runs to its result without interruption
)--");
}

TEST_CASE("validate: formulas: + - * / and brackets over entries and constants", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
plan P {
  config { float dist = 30; float angle; int count = 3; bool loud = true; string label = "x"; }
  start a;
  actor a: Forward(dist % 2) { FORWARD_OK -> b; }
  actor b: Forward(Distance()) { FORWARD_OK -> c; }
  actor c: Forward(!loud) { FORWARD_OK -> d; }
  actor d: Forward(1s) { FORWARD_OK -> e; }
  actor e: Forward(dist > 1) { FORWARD_OK -> f; }
  actor f: Forward(loud + 1) { FORWARD_OK -> g; }
  actor g: Forward(-label) { FORWARD_OK -> h; }
  actor h: Forward(nope * 2) { FORWARD_OK -> terminate; }
}
)--"},
               {"carbot.toolbox", kToolbox}});
  CHECK(r.text() == R"--(t.plan:5:20: error: operator '%' cannot be used in a plan argument [formula]
   actor a: Forward(dist % 2) { FORWARD_OK -> b; }
                    ^~~~~~~~
t.plan:5:20: note: a plan argument is a formula over config entries and constants: + - * / and brackets
t.plan:6:20: error: a function call cannot be used in a plan argument [formula]
   actor b: Forward(Distance()) { FORWARD_OK -> c; }
                    ^~~~~~~~~~
t.plan:6:20: note: a plan argument is a formula over config entries and constants: + - * / and brackets
t.plan:7:20: error: operator '!' cannot be used in a plan argument [formula]
   actor c: Forward(!loud) { FORWARD_OK -> d; }
                    ^~~~~
t.plan:7:20: note: a plan argument is a formula over config entries and constants: + - * / and brackets
t.plan:8:20: error: a duration cannot be used in a plan argument [formula]
   actor d: Forward(1s) { FORWARD_OK -> e; }
                    ^~
t.plan:8:20: note: a plan argument is a formula over config entries and constants: + - * / and brackets
t.plan:9:20: error: operator '>' cannot be used in a plan argument [formula]
   actor e: Forward(dist > 1) { FORWARD_OK -> f; }
                    ^~~~~~~~
t.plan:9:20: note: a plan argument is a formula over config entries and constants: + - * / and brackets
t.plan:10:20: error: invalid operands to binary '+' (have 'bool' and 'int') [type-mismatch]
   actor f: Forward(loud + 1) { FORWARD_OK -> g; }
                    ^~~~~~~~
t.plan:11:20: error: invalid operand to unary '-' (have 'string') [type-mismatch]
   actor g: Forward(-label) { FORWARD_OK -> h; }
                    ^~~~~~
t.plan:12:20: error: unknown config entry 'nope' [unknown-name]
   actor h: Forward(nope * 2) { FORWARD_OK -> terminate; }
                    ^~~~
)--");
}

TEST_CASE("validate: config entries: types, duplicates, constant initializers", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
const int BASE = 10;
plan P {
  config {
    float dist = BASE * 3;
    flaot speed;
    bool loud = 1;
    object thing = 1;
    string label = "n" + BASE;
    float twice = dist * 2;
  }
  config { float dist; }
  start a;
  actor a: Forward(dist) { FORWARD_OK -> terminate; }
}
)--"},
               {"carbot.toolbox", kToolbox}});
  CHECK(r.text() == R"--(t.plan:6:5: error: unknown type name 'flaot' [unknown-type]
     flaot speed;
     ^~~~~
t.plan:6:5: note: did you mean 'float'?
t.plan:12:18: error: redefinition of config entry 'dist' [duplicate-name]
   config { float dist; }
                  ^~~~
t.plan:5:11: note: previous definition of 'dist' was here
     float dist = BASE * 3;
           ^~~~
t.plan:7:17: error: cannot initialize 'loud' of type 'bool' with a value of type 'int' [type-mismatch]
     bool loud = 1;
                 ^
t.plan:8:20: error: cannot initialize 'thing' of type 'object' with a value of type 'int' [type-mismatch]
     object thing = 1;
                    ^
t.plan:10:19: error: a config initializer cannot read config entry 'dist' [not-constant]
     float twice = dist * 2;
                   ^~~~
)--");
}

TEST_CASE("validate: config entries, actors and supervisors share the plan's namespace", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
plan P {
  config { float dist = 30; float angle; int count = 3; bool loud = true; string label = "x"; }
  start dist;
  actor dist: Forward(1) { FORWARD_OK -> a; supervise a: CheckTouch() { TOUCHED -> terminate; } }
  actor a: Forward(1) { FORWARD_OK -> terminate; }
}
)--"},
               {"carbot.toolbox", kToolbox}});
  CHECK(r.text() == R"--(t.plan:5:9: error: actor 'dist' has the same name as a config entry [duplicate-name]
   actor dist: Forward(1) { FORWARD_OK -> a; supervise a: CheckTouch() { TOUCHED -> terminate; } }
         ^~~~
t.plan:3:18: note: config entry 'dist' declared here
   config { float dist = 30; float angle; int count = 3; bool loud = true; string label = "x"; }
                  ^~~~
t.plan:6:9: error: actor 'a' has the same name as a supervisor [duplicate-name]
   actor a: Forward(1) { FORWARD_OK -> terminate; }
         ^
t.plan:5:55: note: supervisor 'a' declared here
   actor dist: Forward(1) { FORWARD_OK -> a; supervise a: CheckTouch() { TOUCHED -> terminate; } }
                                                       ^
)--");
}

TEST_CASE("validate: sub-plans: fixed states, no arguments", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
plan Main {
  start nav;
  actor nav: Navigate(1) { OK -> nav; INTERUPTED -> terminate; }
}
plan Navigate {
  start f;
  actor f: Forward(1) { FORWARD_OK -> terminate; }
}
)--"},
               {"carbot.toolbox", kToolbox}});
  CHECK(r.text() == R"--(t.plan:4:3: error: sub-plan 'Navigate' takes no arguments [argument-count]
   actor nav: Navigate(1) { OK -> nav; INTERUPTED -> terminate; }
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.plan:4:39: error: unknown result state 'INTERUPTED' of 'Navigate' [unknown-name]
   actor nav: Navigate(1) { OK -> nav; INTERUPTED -> terminate; }
                                       ^~~~~~~~~~
t.plan:4:39: note: did you mean 'INTERRUPTED'?
t.plan:4:9: error: result state 'ERROR' of 'Navigate' is not connected [not-connected]
   actor nav: Navigate(1) { OK -> nav; INTERUPTED -> terminate; }
         ^~~
t.plan:4:9: note: a sub-plan's result states are OK, INTERRUPTED, ERROR
)--");
}

TEST_CASE("validate: a plan that contains itself", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
plan A {
  start x;
  actor x: B() { OK -> terminate; INTERRUPTED -> terminate; ERROR -> terminate; }
}
plan B {
  start y;
  actor y: C() { OK -> terminate; INTERRUPTED -> terminate; ERROR -> terminate; }
}
plan C {
  start z;
  actor z: A() { OK -> terminate; INTERRUPTED -> terminate; ERROR -> terminate; }
}
plan Self {
  start s;
  actor s: Self() { OK -> terminate; INTERRUPTED -> terminate; ERROR -> terminate; }
}
)--"},
               {"carbot.toolbox", kToolbox}});
  CHECK(r.text() == R"--(t.plan:2:6: error: plan 'A' contains itself [recursive-plan]
 plan A {
      ^
t.plan:4:9: note: 'A' uses 'B' as actor 'x'
   actor x: B() { OK -> terminate; INTERRUPTED -> terminate; ERROR -> terminate; }
         ^
t.plan:8:9: note: 'B' uses 'C' as actor 'y'
   actor y: C() { OK -> terminate; INTERRUPTED -> terminate; ERROR -> terminate; }
         ^
t.plan:12:9: note: 'C' uses 'A' as actor 'z'
   actor z: A() { OK -> terminate; INTERRUPTED -> terminate; ERROR -> terminate; }
         ^
t.plan:14:6: error: plan 'Self' contains itself [recursive-plan]
 plan Self {
      ^~~~
t.plan:16:9: note: 'Self' uses 'Self' as actor 's'
   actor s: Self() { OK -> terminate; INTERRUPTED -> terminate; ERROR -> terminate; }
         ^
)--");
}

TEST_CASE("validate: actors no path reaches from start", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
plan P {
  config { float dist = 30; float angle; int count = 3; bool loud = true; string label = "x"; }
  supervise esc: CheckTouch() { TOUCHED -> rescue; }
  start a;
  actor a: Forward(1) { FORWARD_OK -> b; supervise lane: CheckLane(dist) { LANE_NOT_FREE -> c; } }
  actor b: Forward(1) { FORWARD_OK -> terminate; }
  actor c: Forward(1) { FORWARD_OK -> terminate; }
  actor rescue: Forward(1) { FORWARD_OK -> terminate; }
  actor lost: Forward(1) { FORWARD_OK -> lost2; }
  actor lost2: Forward(1) { FORWARD_OK -> lost; }
}
)--"},
               {"carbot.toolbox", kToolbox}});
  CHECK(r.text() ==
        R"--(t.plan:10:9: warning: actor 'lost' is never reached from the start actor 'a' [-Wunreachable-actor]
   actor lost: Forward(1) { FORWARD_OK -> lost2; }
         ^~~~
t.plan:11:9: warning: actor 'lost2' is never reached from the start actor 'a' [-Wunreachable-actor]
   actor lost2: Forward(1) { FORWARD_OK -> lost; }
         ^~~~~
)--");
}
