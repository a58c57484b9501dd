// The validator: names across files, duplicates, unknown names, reserved words.
// Each test validates chart text and compares every diagnostic as gfec prints it.
#include "validate_fixture.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec;
using test::kBot;
using test::kToolbox;
using test::Validated;

TEST_CASE("validate: the same place name in two charts is fine", "[validate]") {
  Validated r({{"t.sfc", R"--(sfc S { initial place A; }
sfc R { initial place A; }
)--"}});
  CHECK(r.text() == R"--()--");
}

TEST_CASE("validate: a duplicate function within an interface", "[validate]") {
  Validated r({{"t.iface", R"--(interface Bot2 {
  void Go();
  bool Go();
}
)--"}});
  CHECK(r.text() == R"--(t.iface:3:8: error: redefinition of function 'Go' [duplicate-name]
   bool Go();
        ^~
t.iface:2:8: note: previous definition of 'Go' was here
   void Go();
        ^~
)--");
}

TEST_CASE("validate: a name clashing with an imported one is reported in the importing file", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
const int Go = 1;
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:2:11: error: constant 'Go' has the same name as a function [duplicate-name]
 const int Go = 1;
           ^~
bot.iface:4:8: note: function 'Go' declared here
   void Go();
        ^~
)--");
}

TEST_CASE("validate: a chart may not have the name of a function", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc Stop { initial place A; }
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:2:5: error: chart 'Stop' has the same name as a function [duplicate-name]
 sfc Stop { initial place A; }
     ^~~~
bot.iface:5:8: note: function 'Stop' declared here
   void Stop();
        ^~~~
)--");
}

TEST_CASE("validate: a chart constant hides a global constant of the same name", "[validate]") {
  Validated r({{"t.sfc", R"--(const float CRUISE = 0.5;
sfc S {
  const float CRUISE = 0.6;
  var float speed = CRUISE;
  initial place A;
}
)--"}});
  CHECK(r.text() == R"--()--");
  const auto &init = *r.model.charts.at(0).vars.at(0).init;
  CHECK(init.kind == model::Expr::Kind::Const);
  CHECK(r.model.consts.at(init.constant()).value.text == "0.6");
}

TEST_CASE("validate: an unknown function gets a did-you-mean at the declaration", "[validate]") {
  Validated r({{"t.sfc", R"--(interface LineBot {
  bool Left_IR_Black();
  void Left_FW();
}
sfc S {
  initial place A { Left_FW(); }
  place B;
  transition A -> B when Left_IR_Blak();
}
)--"}});
  CHECK(r.text() == R"--(t.sfc:8:26: error: unknown function 'Left_IR_Blak' [unknown-name]
   transition A -> B when Left_IR_Blak();
                          ^~~~~~~~~~~~
t.sfc:2:8: note: did you mean 'Left_IR_Black'?
   bool Left_IR_Black();
        ^~~~~~~~~~~~~
)--");
}

TEST_CASE("validate: an unknown name far from every declared one gets no suggestion", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  var int laps = 0;
  initial place A;
  A -> A when zzzzzz > 1;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:5:15: error: unknown name 'zzzzzz' [unknown-name]
   A -> A when zzzzzz > 1;
               ^~~~~~
)--");
}

TEST_CASE("validate: an unknown name is reported once per chart", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  var int laps = 0;
  initial place A { lap += 1; }
  place B { lap += 2; }
  transition A -> B when lap > 1;
  transition B -> A when lap > 2 && Whte() && Whte();
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:4:21: error: unknown variable 'lap' [unknown-name]
   initial place A { lap += 1; }
                     ^~~
t.sfc:3:11: note: did you mean 'laps'?
   var int laps = 0;
           ^~~~
t.sfc:6:26: error: unknown name 'lap' [unknown-name]
   transition A -> B when lap > 1;
                          ^~~
t.sfc:3:11: note: did you mean 'laps'?
   var int laps = 0;
           ^~~~
t.sfc:7:37: error: unknown function 'Whte' [unknown-name]
   transition B -> A when lap > 2 && Whte() && Whte();
                                     ^~~~
bot.iface:3:8: note: did you mean 'White'?
   bool White();
        ^~~~~
)--");
}

TEST_CASE("validate: names that are C or C++ keywords are rejected", "[validate]") {
  Validated r({{"t.sfc", R"--(interface Robot {
  void register();
  void Motor(int new, float speed);
}
sfc switch {
  var int class = 0;
  initial place int;
  place this;
}
toolbox Tools { actor Wait(in float goto) -> DONE | default; }
plan namespace {
  config { float double; }
  start private;
  actor private: Wait(1) { DONE -> terminate; default -> terminate; }
}
)--"}});
  CHECK(r.text() == R"--(t.sfc:3:18: error: 'new' is a keyword of C++ and cannot name a parameter [reserved-name]
   void Motor(int new, float speed);
                  ^~~
t.sfc:10:37: error: 'goto' is a keyword of C and cannot name a parameter [reserved-name]
 toolbox Tools { actor Wait(in float goto) -> DONE | default; }
                                     ^~~~
t.sfc:10:53: error: 'default' is a keyword of C and cannot name a result state [reserved-name]
 toolbox Tools { actor Wait(in float goto) -> DONE | default; }
                                                     ^~~~~~~
t.sfc:2:8: error: 'register' is a keyword of C and cannot name a function [reserved-name]
   void register();
        ^~~~~~~~
t.sfc:5:5: error: 'switch' is a keyword of C and cannot name a chart [reserved-name]
 sfc switch {
     ^~~~~~
t.sfc:11:6: error: 'namespace' is a keyword of C++ and cannot name a plan [reserved-name]
 plan namespace {
      ^~~~~~~~~
t.sfc:6:11: error: 'class' is a keyword of C++ and cannot name a variable [reserved-name]
   var int class = 0;
           ^~~~~
t.sfc:7:17: error: 'int' is a keyword of C and cannot name a place [reserved-name]
   initial place int;
                 ^~~
t.sfc:8:9: error: 'this' is a keyword of C++ and cannot name a place [reserved-name]
   place this;
         ^~~~
t.sfc:12:18: error: 'double' is a keyword of C and cannot name a config entry [reserved-name]
   config { float double; }
                  ^~~~~~
t.sfc:14:9: error: 'private' is a keyword of C++ and cannot name an actor [reserved-name]
   actor private: Wait(1) { DONE -> terminate; default -> terminate; }
         ^~~~~~~
)--");
}

TEST_CASE("validate: C++20's keywords and the C++ runtime's macros are reserved too (one list, compiler/naming/)",
          "[validate]") {
  Validated r({{"t.sfc", R"--(interface Robot { void requires(); }
sfc concept {
  var int co_await = 0;
  initial place stdout;
}
)--"}});
  CHECK(r.text() == R"--(t.sfc:1:24: error: 'requires' is a keyword of C++ and cannot name a function [reserved-name]
 interface Robot { void requires(); }
                        ^~~~~~~~
t.sfc:2:5: error: 'concept' is a keyword of C++ and cannot name a chart [reserved-name]
 sfc concept {
     ^~~~~~~
t.sfc:3:11: error: 'co_await' is a keyword of C++ and cannot name a variable [reserved-name]
   var int co_await = 0;
           ^~~~~~~~
t.sfc:4:17: error: 'stdout' is a macro of the C++ standard headers a plan includes and cannot name a place [reserved-name]
   initial place stdout;
                 ^~~~~~
)--");
}

TEST_CASE("validate: elapsed cannot name a function", "[validate]") {
  Validated r({{"t.sfc", R"--(interface Clock {
  int elapsed(int p);
}
)--"}});
  CHECK(r.text() ==
        R"--(t.sfc:2:7: error: 'elapsed' is built into the chart language and cannot name a function [reserved-name]
   int elapsed(int p);
       ^~~~~~~
)--");
}

TEST_CASE("validate: a place may not generate a name the engine or the interface already uses", "[validate]") {
  Validated r({{"t.sfc", R"--(interface LineBot {
  void Left_FW();
}
sfc Left {
  initial place FW;
  place init;
  place run;
  place PLACE_COUNT;
  place Stopped;
  enabled: FW -> Stopped;
}
)--"}});
  CHECK(r.text() == R"--(t.sfc:5:17: error: place 'FW' would generate 'Left_FW', the name of a function [reserved-name]
   initial place FW;
                 ^~
t.sfc:2:8: note: 'Left_FW' declared here
   void Left_FW();
        ^~~~~~~
t.sfc:6:9: error: place 'init' would generate 'Left_init', which the engine already defines [reserved-name]
   place init;
         ^~~~
t.sfc:7:9: error: place 'run' would generate 'Left_run', which the engine already defines [reserved-name]
   place run;
         ^~~
t.sfc:8:9: error: place 'PLACE_COUNT' would generate 'Left_PLACE_COUNT', which the engine already defines [reserved-name]
   place PLACE_COUNT;
         ^~~~~~~~~~~
t.sfc:10:3: error: transition 'enabled' would generate 'Left_enabled', which the engine already defines [reserved-name]
   enabled: FW -> Stopped;
   ^~~~~~~
)--");
}

TEST_CASE("validate: an unnamed transition's T<n> name may not be taken", "[validate]") {
  Validated r({{"t.sfc", R"--(sfc S {
  initial place A;
  place T1;
  transition A -> T1;
  transition T1 -> A;
  T0: A -> A;
}
)--"}});
  CHECK(
      r.text() ==
      R"--(t.sfc:4:3: error: this unnamed transition is named 'T0' by its position, which is already the name of a transition [duplicate-name]
   transition A -> T1;
   ^~~~~~~~~~~~~~~~~~~
t.sfc:6:3: note: 'T0' declared here; name the transition ('name: A -> B') or rename it
   T0: A -> A;
   ^~
t.sfc:5:3: error: this unnamed transition is named 'T1' by its position, which is already the name of a place [duplicate-name]
   transition T1 -> A;
   ^~~~~~~~~~~~~~~~~~~
t.sfc:3:9: note: 'T1' declared here; name the transition ('name: A -> B') or rename it
   place T1;
         ^~
)--");
}

TEST_CASE("validate: templates and plans share one namespace", "[validate]") {
  Validated r({{"t.plan", R"--(import "carbot.toolbox";
plan Turn { start t; actor t: Forward(1) { FORWARD_OK -> terminate; } }
toolbox Other { actor Forward(in float d) -> DONE; }
)--"},
               {"carbot.toolbox", kToolbox}});
  CHECK(r.text() == R"--(t.plan:2:6: error: plan 'Turn' has the same name as a template [duplicate-name]
 plan Turn { start t; actor t: Forward(1) { FORWARD_OK -> terminate; } }
      ^~~~
carbot.toolbox:3:9: note: template 'Turn' declared here
   actor Turn(in float angle) -> TURN_OK;
         ^~~~
t.plan:3:23: error: redefinition of template 'Forward' [duplicate-name]
 toolbox Other { actor Forward(in float d) -> DONE; }
                       ^~~~~~~
carbot.toolbox:2:9: note: previous definition of 'Forward' was here
   actor Forward(in float distance) -> FORWARD_OK;
         ^~~~~~~
)--");
}

TEST_CASE("validate: duplicate interfaces and toolboxes", "[validate]") {
  Validated r({{"t.iface", R"--(interface Bot { void A(); }
interface Bot { void B(); }
toolbox Box { actor X() -> OK; }
toolbox Box { actor Y() -> OK; }
)--"}});
  CHECK(r.text() == R"--(t.iface:2:11: error: redefinition of interface 'Bot' [duplicate-name]
 interface Bot { void B(); }
           ^~~
t.iface:1:11: note: previous definition of 'Bot' was here
 interface Bot { void A(); }
           ^~~
t.iface:4:9: error: redefinition of toolbox 'Box' [duplicate-name]
 toolbox Box { actor Y() -> OK; }
         ^~~
t.iface:3:9: note: previous definition of 'Box' was here
 toolbox Box { actor X() -> OK; }
         ^~~
)--");
}

TEST_CASE("validate: with --context a C library function's own prototype is no longer the library's",
          "[validate][names]") {
  // The context comes first in every prototype of the engine (docs/c-engine.md), so sqrt(void *,
  // double) is not the C library's sqrt, which gcc and clang know: a warning, for the functions
  // the chart and its sub-charts call only.
  Validated r(
      {{"t.sfc", R"--(interface Lib { double sqrt(double x); int abs(int v); void Motor(); double fabs(double x); }
sfc Q { initial place B { Motor(); } B -> B when abs(-1) == 1; }
sfc P { initial place A runs Q; A -> A when sqrt(2.0) > 1.0; }
)--"}});
  REQUIRE(r.text().empty());
  const model::ChartId p = r.model.charts.id_of(r.model.charts.back());
  check_context_prototypes(r.model, p, r.fe.diag);
  CHECK(
      r.text() ==
      R"--(t.sfc:1:17: warning: with --context 'sqrt' takes the context first, so it is no longer the C library's 'double sqrt(double)', which gcc or clang know: they warn about it in the engine's header [-Wlibrary-function]
 interface Lib { double sqrt(double x); int abs(int v); void Motor(); double fabs(double x); }
                 ^~~~~~~~~~~~~~~~~~~~~~
t.sfc:1:17: note: rename the function, or build the engine with -fno-builtin-sqrt
t.sfc:1:40: warning: with --context 'abs' takes the context first, so it is no longer the C library's 'int abs(int)', which gcc or clang know: they warn about it in the engine's header [-Wlibrary-function]
 interface Lib { double sqrt(double x); int abs(int v); void Motor(); double fabs(double x); }
                                        ^~~~~~~~~~~~~~~
t.sfc:1:40: note: rename the function, or build the engine with -fno-builtin-abs
)--");
}
