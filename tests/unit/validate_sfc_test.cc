// The validator: the rules and warnings of an sfc (docs/language.md §5).
// Each test validates chart text and compares every diagnostic as gfec prints it.
#include "validate_fixture.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec;
using test::all_warnings;
using test::kBot;
using test::Validated;

TEST_CASE("validate: fsm syntax in an sfc", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  initial place A;
  state B;
  success state Done;
  place C post Black();
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:4:3: error: 'state' in an sfc: an sfc has places (write 'place B') [wrong-keyword]
   state B;
   ^~~~~~~~
t.sfc:5:3: error: success and failure states belong to an fsm; an sfc has places [wrong-keyword]
   success state Done;
   ^~~~~~~~~~~~~~~~~~~
t.sfc:6:16: error: 'post' belongs to a terminal state of an fsm [wrong-keyword]
   place C post Black();
                ^~~~~~~
)--");
}

TEST_CASE("validate: transitions connect places of this chart", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  var int n = 0;
  initial place Wait;
  place Run;
  transition Wiat -> Run;
  transition Wait -> (Run, n);
  transition Wait -> Other;
}
sfc Other { initial place X; }
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:6:14: error: unknown place 'Wiat' [unknown-name]
   transition Wiat -> Run;
              ^~~~
t.sfc:4:17: note: did you mean 'Wait'?
   initial place Wait;
                 ^~~~
t.sfc:7:28: error: 'n' is a variable, not a place [type-mismatch]
   transition Wait -> (Run, n);
                            ^
t.sfc:3:11: note: 'n' declared here
   var int n = 0;
           ^
t.sfc:8:22: error: unknown place 'Other' [unknown-name]
   transition Wait -> Other;
                      ^~~~~
)--");
}

TEST_CASE("validate: the period is given at most once and is positive", "[validate]") {
  Validated r({{"t.sfc", R"--(sfc S {
  period 10ms;
  period 20ms;
  initial place A;
}
sfc R {
  period 0ms;
  initial place A;
  transition A -> A when elapsed(A) > 1s;
}
)--"}});
  CHECK(r.text() == R"--(t.sfc:3:3: error: second 'period' in sfc 'S' [period]
   period 20ms;
   ^~~~~~~~~~~~
t.sfc:2:3: note: the first one is here
   period 10ms;
   ^~~~~~~~~~~~
t.sfc:7:3: error: the period must be positive [period]
   period 0ms;
   ^~~~~~~~~~~
)--");
}

TEST_CASE("validate: unreachable places and dead transitions are warned about", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
const bool DEBUG = false;
sfc S {
  initial place A;
  place B;
  place C;
  place D;
  place E;
  transition A -> B when Black();
  transition B -> A when DEBUG && White();
  transition C -> D;
  transition (B, D) -> E;
  never: B -> A when false;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:6:9: warning: place 'C' can never become active [-Wunreachable-place]
   place C;
         ^
t.sfc:7:9: warning: place 'D' can never become active [-Wunreachable-place]
   place D;
         ^
t.sfc:8:9: warning: place 'E' can never become active [-Wunreachable-place]
   place E;
         ^
t.sfc:10:3: warning: transition 'T1' can never fire: its condition is always false [-Wdead-transition]
   transition B -> A when DEBUG && White();
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.sfc:11:3: warning: transition 'T2' can never fire: its input place 'C' never becomes active [-Wdead-transition]
   transition C -> D;
   ^~~~~~~~~~~~~~~~~~
t.sfc:12:3: warning: transition 'T3' can never fire: its input place 'D' never becomes active [-Wdead-transition]
   transition (B, D) -> E;
   ^~~~~~~~~~~~~~~~~~~~~~~
t.sfc:13:3: warning: transition 'never' can never fire: its condition is always false [-Wdead-transition]
   never: B -> A when false;
   ^~~~~
)--");
}

TEST_CASE("validate: reachability follows forks and joins", "[validate]") {
  Validated r({{"t.sfc", R"--(sfc S {
  initial place A;
  place B;
  place C;
  place D;
  transition A -> (B, C);
  transition (B, C) -> D;
  transition D -> A;
}
)--"}},
              all_warnings());
  CHECK(r.text() == R"--()--");
}

TEST_CASE("validate: no reachability warnings for a chart with errors", "[validate]") {
  Validated r({{"t.sfc", R"--(sfc S {
  initial place A;
  place B;
  place C;
  transition A -> Bee;
}
)--"}});
  CHECK(r.text() == R"--(t.sfc:5:19: error: unknown place 'Bee' [unknown-name]
   transition A -> Bee;
                   ^~~
)--");
}

TEST_CASE("validate: conflicts are off by default", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  initial place A;
  place B;
  place C;
  transition A -> B when Black();
  transition A -> C when White();
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--()--");
}

TEST_CASE("validate: conflicts: transitions sharing an input place, settled by declaration order", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  initial place A;
  place B;
  place C;
  left: A -> B when Black();
  right: A -> C when White();
  transition B -> A;
  transition (C, A) -> A when true;
  transition C -> B;
}
)--"},
               {"bot.iface", kBot}},
              all_warnings());
  CHECK(r.text() == R"--(t.sfc:7:3: warning: transition 'right' competes with 'left' for place 'A' [-Wconflict]
   right: A -> C when White();
   ^~~~~
t.sfc:6:3: note: 'left' is declared first: when both can fire, it takes the activation
   left: A -> B when Black();
   ^~~~
t.sfc:9:3: warning: transition 'T3' competes with 'left' for place 'A' [-Wconflict]
   transition (C, A) -> A when true;
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.sfc:6:3: note: 'left' is declared first: when both can fire, it takes the activation
   left: A -> B when Black();
   ^~~~
)--");
}

TEST_CASE("validate: verbatim code is noted only under -Wverbatim", "[validate]") {
  Validated r({{"t.sfc", R"--(%{ #include <stdio.h> %}
sfc S {
  initial place A { %{ puts("A"); %} }
}
)--"}},
              all_warnings());
  CHECK(r.text() == R"--(t.sfc:1:1: warning: verbatim code is copied unchecked: gfec cannot check it [-Wverbatim]
 %{ #include <stdio.h> %}
 ^~~~~~~~~~~~~~~~~~~~~~~~
t.sfc:3:21: warning: verbatim code is copied unchecked: gfec cannot check it [-Wverbatim]
   initial place A { %{ puts("A"); %} }
                     ^~~~~~~~~~~~~~~~
)--");
  CHECK(Validated({{"t.sfc", "%{ x %}\nsfc S { initial place A { %{ y; %} } }\n"}}).text() == "");
}

TEST_CASE("validate: -Werror on verbatim code does not hide a chart's other warnings", "[validate]") {
  WarningOptions w = all_warnings();
  w.as_errors = true;
  Validated r({{"t.sfc", "sfc S { initial place A { %{ x(); %} } place B; }\n"}}, w);
  CHECK(r.text() == R"--(t.sfc:1:27: error: verbatim code is copied unchecked: gfec cannot check it [-Werror=verbatim]
 sfc S { initial place A { %{ x(); %} } place B; }
                           ^~~~~~~~~~
t.sfc:1:46: error: place 'B' can never become active [-Werror=unreachable-place]
 sfc S { initial place A { %{ x(); %} } place B; }
                                              ^
)--");
}
