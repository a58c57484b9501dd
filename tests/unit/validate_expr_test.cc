// The validator: expressions, statements, constants and types (docs/language.md §3 and 4).
// Each test validates chart text and compares every diagnostic as gfec prints it.
#include "input_languages.h"
#include "validate_fixture.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec;
using test::kBot;
using test::Validated;

TEST_CASE("validate: conditions must be bool", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  period 10ms;
  var int n = 0;
  var bool b = false;
  var float f = 0;
  initial place A;
  transition A -> A when n;
  transition A -> A when Distance();
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:8:26: error: condition must be bool, not 'int' [type-mismatch]
   transition A -> A when n;
                          ^
t.sfc:9:26: error: condition must be bool, not 'float' [type-mismatch]
   transition A -> A when Distance();
                          ^~~~~~~~~~
)--");
}

TEST_CASE("validate: bool does not mix with numbers", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  period 10ms;
  var int n = 0;
  var bool b = false;
  var float f = 0;
  initial place A;
  transition A -> A when 1 && b;
  transition A -> A when b + 1 > 0;
  transition A -> A when b < b;
  transition A -> A when !n;
  transition A -> A when -b > 0;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:8:26: error: invalid operands to binary '&&' (have 'int' and 'bool') [type-mismatch]
   transition A -> A when 1 && b;
                          ^~~~~~
t.sfc:9:26: error: invalid operands to binary '+' (have 'bool' and 'int') [type-mismatch]
   transition A -> A when b + 1 > 0;
                          ^~~~~
t.sfc:10:26: error: invalid operands to binary '<' (have 'bool' and 'bool') [type-mismatch]
   transition A -> A when b < b;
                          ^~~~~
t.sfc:11:26: error: invalid operand to unary '!' (have 'int') [type-mismatch]
   transition A -> A when !n;
                          ^~
t.sfc:12:26: error: invalid operand to unary '-' (have 'bool') [type-mismatch]
   transition A -> A when -b > 0;
                          ^~
)--");
}

TEST_CASE("validate: bools compare with == and !=, ints and floats mix as in C", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  period 10ms;
  var int n = 0;
  var bool b = false;
  var float f = 0;
  initial place A;
  transition A -> A when b == (n > 1) && b != White();
  transition A -> A when n * 2.5 + f / 3 >= Distance() - Count();
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--()--");
  REQUIRE(r.model.charts[0].transitions[1].condition);
  CHECK(r.model.charts[0].transitions[1].condition->args[0].type == model::Type::Double);
}

TEST_CASE("validate: % takes ints only", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  period 10ms;
  var int n = 0;
  var bool b = false;
  var float f = 0;
  initial place A;
  transition A -> A when n % 2 == 0 && f % 2 == 0;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:8:40: error: invalid operands to binary '%' (have 'float' and 'int') [type-mismatch]
   transition A -> A when n % 2 == 0 && f % 2 == 0;
                                        ^~~~~
)--");
}

TEST_CASE("validate: calls: wrong argument count and types", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  period 10ms;
  var int n = 0;
  var bool b = false;
  var float f = 0;
  initial place A;
  place B { Motor(1); Motor(1, 2, 3); Motor(true, 0.5); Lamp(1); Lamp(n > 0); Motor(n, n); }
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:8:13: error: too few arguments to function 'Motor' (expected 2, have 1) [argument-count]
   place B { Motor(1); Motor(1, 2, 3); Motor(true, 0.5); Lamp(1); Lamp(n > 0); Motor(n, n); }
             ^~~~~~~~
bot.iface:6:3: note: 'Motor' declared here
   void Motor(int side, float speed);
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.sfc:8:23: error: too many arguments to function 'Motor' (expected 2, have 3) [argument-count]
   place B { Motor(1); Motor(1, 2, 3); Motor(true, 0.5); Lamp(1); Lamp(n > 0); Motor(n, n); }
                       ^~~~~~~~~~~~~~
bot.iface:6:3: note: 'Motor' declared here
   void Motor(int side, float speed);
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.sfc:8:45: error: incompatible type for argument 1 of 'Motor': expected 'int', have 'bool' [type-mismatch]
   place B { Motor(1); Motor(1, 2, 3); Motor(true, 0.5); Lamp(1); Lamp(n > 0); Motor(n, n); }
                                             ^~~~
bot.iface:6:3: note: 'Motor' declared here
   void Motor(int side, float speed);
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
t.sfc:8:62: error: incompatible type for argument 1 of 'Lamp': expected 'bool', have 'int' [type-mismatch]
   place B { Motor(1); Motor(1, 2, 3); Motor(true, 0.5); Lamp(1); Lamp(n > 0); Motor(n, n); }
                                                              ^
bot.iface:7:3: note: 'Lamp' declared here
   void Lamp(bool on);
   ^~~~~~~~~~~~~~~~~~~
)--");
}

TEST_CASE("validate: a void function is not a value, a value function may be a statement", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  period 10ms;
  var int n = 0;
  var bool b = false;
  var float f = 0;
  initial place A;
  place B { Count(); Black(); }
  transition A -> B when Go();
  transition B -> A when Go() == Stop();
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:9:26: error: 'Go' returns void; it cannot be used as a value [type-mismatch]
   transition A -> B when Go();
                          ^~~~
bot.iface:4:3: note: 'Go' declared here
   void Go();
   ^~~~~~~~~~
t.sfc:10:26: error: 'Go' returns void; it cannot be used as a value [type-mismatch]
   transition B -> A when Go() == Stop();
                          ^~~~
bot.iface:4:3: note: 'Go' declared here
   void Go();
   ^~~~~~~~~~
t.sfc:10:34: error: 'Stop' returns void; it cannot be used as a value [type-mismatch]
   transition B -> A when Go() == Stop();
                                  ^~~~~~
bot.iface:5:3: note: 'Stop' declared here
   void Stop();
   ^~~~~~~~~~~~
)--");
}

TEST_CASE("validate: a name that is not a value", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  period 10ms;
  var int n = 0;
  var bool b = false;
  var float f = 0;
  initial place A;
  place B { n = Count; f = S; }
  transition A -> B when A;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:8:17: error: 'Count' is a function, not a value [type-mismatch]
   place B { n = Count; f = S; }
                 ^~~~~
bot.iface:9:7: note: to call it, write 'Count()'
   int Count();
       ^~~~~
t.sfc:8:28: error: 'S' is a chart, not a value [type-mismatch]
   place B { n = Count; f = S; }
                            ^
t.sfc:9:26: error: 'A' is a place, not a value [type-mismatch]
   transition A -> B when A;
                          ^
t.sfc:9:26: note: to test whether it is active, write 'active(A)'
t.sfc:9:26: note: 'elapsed(A)' is the time it has been active
)--");
}

TEST_CASE("validate: assignment only to a var", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
const int GLOBAL = 1;
sfc S {
  period 10ms;
  var int n = 0;
  var bool b = false;
  var float f = 0;
  initial place A;
  const int LIMIT = 3;
  place B { LIMIT = 4; A = 1; GLOBAL = 2; Go = 3; nope = 4; }
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:10:13: error: cannot assign to constant 'LIMIT' [not-assignable]
   place B { LIMIT = 4; A = 1; GLOBAL = 2; Go = 3; nope = 4; }
             ^~~~~
t.sfc:9:13: note: 'LIMIT' declared here; only a 'var' can be assigned
   const int LIMIT = 3;
             ^~~~~
t.sfc:10:24: error: cannot assign to place 'A' [not-assignable]
   place B { LIMIT = 4; A = 1; GLOBAL = 2; Go = 3; nope = 4; }
                        ^
t.sfc:8:17: note: 'A' declared here; only a 'var' can be assigned
   initial place A;
                 ^
t.sfc:10:31: error: cannot assign to constant 'GLOBAL' [not-assignable]
   place B { LIMIT = 4; A = 1; GLOBAL = 2; Go = 3; nope = 4; }
                               ^~~~~~
t.sfc:2:11: note: 'GLOBAL' declared here; only a 'var' can be assigned
 const int GLOBAL = 1;
           ^~~~~~
t.sfc:10:43: error: cannot assign to function 'Go' [not-assignable]
   place B { LIMIT = 4; A = 1; GLOBAL = 2; Go = 3; nope = 4; }
                                           ^~
bot.iface:4:8: note: 'Go' declared here; only a 'var' can be assigned
   void Go();
        ^~
t.sfc:10:51: error: unknown variable 'nope' [unknown-name]
   place B { LIMIT = 4; A = 1; GLOBAL = 2; Go = 3; nope = 4; }
                                                   ^~~~
)--");
}

TEST_CASE("validate: elapsed needs a place of the same chart", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  period 10ms;
  var int n = 0;
  var bool b = false;
  var float f = 0;
  initial place A;
  place B;
  transition A -> B when elapsed(n) > 1s;
  transition A -> B when elapsed(Bee) > 1s;
  transition A -> B when elapsed(A, B) > 1s;
  transition A -> B when elapsed(1) > 1s;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:9:34: error: 'n' is a variable, not a place [type-mismatch]
   transition A -> B when elapsed(n) > 1s;
                                  ^
t.sfc:4:11: note: 'n' declared here
   var int n = 0;
           ^
t.sfc:10:34: error: unknown place 'Bee' [unknown-name]
   transition A -> B when elapsed(Bee) > 1s;
                                  ^~~
t.sfc:11:26: error: 'elapsed' takes one argument: the name of a place [elapsed]
   transition A -> B when elapsed(A, B) > 1s;
                          ^~~~~~~~~~~~~
t.sfc:12:26: error: 'elapsed' takes one argument: the name of a place [elapsed]
   transition A -> B when elapsed(1) > 1s;
                          ^~~~~~~~~~
)--");
}

TEST_CASE("validate: elapsed needs a period, reported once per chart", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  initial place A;
  place B;
  transition A -> B when elapsed(A) >= 500ms;
  transition B -> A when elapsed(B) >= 500ms;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:5:26: error: 'elapsed(A)' needs a period, but sfc 'S' declares none [missing-period]
   transition A -> B when elapsed(A) >= 500ms;
                          ^~~~~~~~~~
t.sfc:2:5: note: declare one in the chart, e.g. 'period 10ms;'
 sfc S {
     ^
)--");
}

TEST_CASE("validate: a duration needs a period too", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  initial place A;
  transition A -> A when 2s > 1s;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:4:26: error: duration '2s' needs a period, but sfc 'S' declares none [missing-period]
   transition A -> A when 2s > 1s;
                          ^~
t.sfc:2:5: note: declare one in the chart, e.g. 'period 10ms;'
 sfc S {
     ^
)--");
}

TEST_CASE("validate: durations are only compared with durations", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  period 10ms;
  var int n = 0;
  var bool b = false;
  var float f = 0;
  initial place A;
  place B;
  transition A -> B when elapsed(A) > 3;
  transition A -> B when elapsed(A) + 1s > 2s; // durations that add are times (§4): fine
  transition A -> B when 500ms;
  transition A -> B when Motor(1, 500ms) == 1;
  transition A -> B when elapsed(A) >= 1s && elapsed(A) != elapsed(B) && 2s > 1s;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:9:26: error: invalid operands to binary '>' (have 'duration' and 'int') [type-mismatch]
   transition A -> B when elapsed(A) > 3;
                          ^~~~~~~~~~~~~~
t.sfc:9:26: note: a duration can only be compared with another duration, as in 'elapsed(P) >= 500ms'
t.sfc:11:26: error: condition must be bool, not 'duration' [type-mismatch]
   transition A -> B when 500ms;
                          ^~~~~
t.sfc:11:26: note: a duration can only be compared with another duration, as in 'elapsed(P) >= 500ms'
t.sfc:12:35: error: incompatible type for argument 2 of 'Motor': expected 'float', have 'duration' [type-mismatch]
   transition A -> B when Motor(1, 500ms) == 1;
                                   ^~~~~
bot.iface:6:3: note: 'Motor' declared here
   void Motor(int side, float speed);
   ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~
)--");
}

TEST_CASE("validate: elapsed is not a statement", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  period 10ms;
  var int n = 0;
  var bool b = false;
  var float f = 0;
  initial place A;
  place B { elapsed(A); }
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:8:13: error: 'elapsed()' as a statement has no effect [type-mismatch]
   place B { elapsed(A); }
             ^~~~~~~~~~
)--");
}

TEST_CASE("validate: elapsed outside a chart and in a constant", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
const bool LATE = elapsed(A) > 1s;
sfc S {
  period 10ms;
  const bool EARLY = elapsed(A) < 1s;
  var bool late = elapsed(A) > 2s;
  initial place A;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:2:19: error: 'elapsed' can only be used inside an sfc or fsm [elapsed]
 const bool LATE = elapsed(A) > 1s;
                   ^~~~~~~~~~
t.sfc:5:22: error: a constant expression cannot read 'elapsed()' [not-constant]
   const bool EARLY = elapsed(A) < 1s;
                      ^~~~~~~~~~
t.sfc:6:19: error: a constant expression cannot read 'elapsed()' [not-constant]
   var bool late = elapsed(A) > 2s;
                   ^~~~~~~~~~
)--");
}

TEST_CASE("validate: constants must be constant expressions", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
const float F = Distance();
sfc S {
  var int n = 0;
  const int N = n + 1;
  var int m = n;
  var int k = Count();
  initial place A;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:2:17: error: a constant expression cannot call 'Distance' [not-constant]
 const float F = Distance();
                 ^~~~~~~~~~
t.sfc:5:17: error: a constant expression cannot read variable 'n' [not-constant]
   const int N = n + 1;
                 ^
t.sfc:6:15: error: a constant expression cannot read variable 'n' [not-constant]
   var int m = n;
               ^
t.sfc:7:15: error: a constant expression cannot call 'Count' [not-constant]
   var int k = Count();
               ^~~~~~~
)--");
}

TEST_CASE("validate: a constant defined in terms of itself", "[validate]") {
  Validated r({{"t.iface", R"--(const int A = B + 1;
const int B = C * 2;
const int C = A;
const int D = D;
)--"}});
  CHECK(r.text() == R"--(t.iface:1:11: error: constant 'A' is defined in terms of itself [not-constant]
 const int A = B + 1;
           ^
t.iface:4:11: error: constant 'D' is defined in terms of itself [not-constant]
 const int D = D;
           ^
)--");
}

TEST_CASE("validate: constant folding reports division by zero and overflow", "[validate]") {
  Validated r({{"t.iface", R"--(const int Z = 1 / 0;
const int M = 5 % (2 - 2);
const int BIG = 2000000000 * 2;
const int HUGE = 3000000000;
const double INF = 1e308 * 10;
sfc S {
  var int v = 1 / 0;
  initial place A;
}
)--"}});
  CHECK(r.text() == R"--(t.iface:1:15: error: division by zero in constant expression [not-constant]
 const int Z = 1 / 0;
               ^~~~~
t.iface:2:15: error: division by zero in constant expression [not-constant]
 const int M = 5 % (2 - 2);
               ^~~~~~~~~~~
t.iface:3:17: error: integer overflow in constant expression [not-constant]
 const int BIG = 2000000000 * 2;
                 ^~~~~~~~~~~~~~
t.iface:4:18: error: integer constant '3000000000' is too large for 'int' [not-constant]
 const int HUGE = 3000000000;
                  ^~~~~~~~~~
t.iface:5:20: error: floating-point overflow in constant expression [not-constant]
 const double INF = 1e308 * 10;
                    ^~~~~~~~~~
t.iface:7:15: error: division by zero in constant expression [not-constant]
   var int v = 1 / 0;
               ^~~~~
)--");
}

TEST_CASE("validate: constant initializers must have the constant's type", "[validate]") {
  Validated r({{"t.iface", R"--(const bool B = 1;
const int I = true;
const float D = 2s;
const string S = 1;
)--"}});
  CHECK(r.text() ==
        R"--(t.iface:1:16: error: cannot initialize 'B' of type 'bool' with a value of type 'int' [type-mismatch]
 const bool B = 1;
                ^
t.iface:2:15: error: cannot initialize 'I' of type 'int' with a value of type 'bool' [type-mismatch]
 const int I = true;
               ^~~~
t.iface:3:17: error: cannot initialize 'D' of type 'float' with a value of type 'duration' [type-mismatch]
 const float D = 2s;
                 ^~
t.iface:3:17: note: a duration can only be compared with another duration, as in 'elapsed(P) >= 500ms'
t.iface:4:18: error: cannot initialize 'S' of type 'string' with a value of type 'int' [type-mismatch]
 const string S = 1;
                  ^
)--");
}

TEST_CASE("validate: types: unknown names, and types not allowed where they stand", "[validate]") {
  Validated r({{"t.iface", R"--(interface Robot {
  integer Count();
  void Motor(void speed);
  string Name();
  flaot Speed(int x);
}
const void V = 1;
sfc S {
  var string s;
  var dobule d;
  initial place A;
}
)--"}});
  CHECK(r.text() == R"--(t.iface:2:3: error: unknown type name 'integer' [unknown-type]
   integer Count();
   ^~~~~~~
t.iface:3:14: error: type 'void' is not allowed for a parameter [bad-type]
   void Motor(void speed);
              ^~~~
t.iface:4:3: error: type 'string' is not allowed for a function result [bad-type]
   string Name();
   ^~~~~~
t.iface:5:3: error: unknown type name 'flaot' [unknown-type]
   flaot Speed(int x);
   ^~~~~
t.iface:5:3: note: did you mean 'float'?
t.iface:7:7: error: type 'void' is not allowed for a constant [bad-type]
 const void V = 1;
       ^~~~
t.iface:9:7: error: type 'string' is not allowed for a variable [bad-type]
   var string s;
       ^~~~~~
t.iface:10:7: error: unknown type name 'dobule' [unknown-type]
   var dobule d;
       ^~~~~~
t.iface:10:7: note: did you mean 'double'?
)--");
}

TEST_CASE("validate: an initializer's error is reported once, not again at each use", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
const int BAD = Count();
sfc S {
  var int n = BAD;
  initial place A { n = BAD + 1; }
  transition A -> A when BAD > 1;
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:2:17: error: a constant expression cannot call 'Count' [not-constant]
 const int BAD = Count();
                 ^~~~~~~
)--");
}

TEST_CASE("validate: calls of a function whose prototype has an error are not checked", "[validate]") {
  Validated r({{"t.sfc", R"--(interface Robot {
  void Move(integer speed);
}
sfc S {
  initial place A { Move(1, 2); }
}
)--"}});
  CHECK(r.text() == R"--(t.sfc:2:13: error: unknown type name 'integer' [unknown-type]
   void Move(integer speed);
             ^~~~~~~
)--");
}

TEST_CASE("validate: if conditions must be bool, both branches are checked", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  period 10ms;
  var int n = 0;
  initial place A {
    if (n) { Go(); }
    if (Count() > 1) { Stop(); } else if (Distance()) { Go(); } else { n = true; }
    entry { if (elapsed(A)) { Nope(); } }
  }
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text() == R"--(t.sfc:6:9: error: the condition of 'if' must be bool, not 'int' [type-mismatch]
     if (n) { Go(); }
         ^
t.sfc:7:43: error: the condition of 'if' must be bool, not 'float' [type-mismatch]
     if (Count() > 1) { Stop(); } else if (Distance()) { Go(); } else { n = true; }
                                           ^~~~~~~~~~
t.sfc:7:76: error: incompatible types when assigning to 'n' of type 'int' from type 'bool' [type-mismatch]
     if (Count() > 1) { Stop(); } else if (Distance()) { Go(); } else { n = true; }
                                                                            ^~~~
t.sfc:8:17: error: the condition of 'if' must be bool, not 'duration' [type-mismatch]
     entry { if (elapsed(A)) { Nope(); } }
                 ^~~~~~~~~~
t.sfc:8:17: note: a duration can only be compared with another duration, as in 'elapsed(P) >= 500ms'
t.sfc:8:31: error: unknown function 'Nope' [unknown-name]
     entry { if (elapsed(A)) { Nope(); } }
                               ^~~~
)--");
}

TEST_CASE("validate: if statements in the model", "[validate]") {
  Validated r({{"t.fsm", R"--(import "bot.iface";
fsm M {
  period 10ms;
  var int n = 0;
  initial state A {
    if (Black() && elapsed(A) >= 20ms) { Go(); n += 1; } else if (White()) { Stop(); } else { }
    if (n > 2) { Lamp(true); }
  }
}
)--"},
               {"bot.iface", kBot}});
  CHECK(r.text().empty());
  REQUIRE(r.model.charts.size() == 1);
  const auto &action = r.model.charts[0].places[0].action;
  REQUIRE(action.size() == 2);
  const model::Stmt &first = action[0];
  CHECK(first.kind == model::Stmt::Kind::If);
  CHECK(first.expr.type == model::Type::Bool);
  CHECK(first.then_block.size() == 2);
  CHECK(first.else_if);
  REQUIRE(first.else_block.size() == 1);
  const model::Stmt &second = first.else_block[0];
  CHECK(second.kind == model::Stmt::Kind::If);
  CHECK(second.then_block.size() == 1);
  CHECK(second.else_block.empty());  // `else { }`
  CHECK_FALSE(second.else_if);
  CHECK(action[1].else_block.empty());
  CHECK(r.model.charts[0].places[0].timed);  // elapsed() in an if marks the timer
}

TEST_CASE("validate: a message quotes an operator as written where the file is not chart text", "[validate]") {
  // Chart text writes C's operators, so its messages quote C's spelling. A reader for a language
  // that spells them otherwise (IEC 61131-3's `AND`, `NOT`) points an operator's range into its
  // own file, which is not chart text; no such reader exists yet (ALICA's conditions are
  // functions, docs/alica.md), so here a tree parsed from chart text gets its operators pointed
  // into such a file.
  auto messages = [](const char *pointed_at, bool chart_text) {
    test::FrontEnd fe({{"t.sfc", R"--(import "bot.iface";
sfc S {
  period 10ms;
  var int n = 0;
  initial place A;
  transition A -> A when Black() && n;
  transition A -> A when !n;
  transition A -> A when n < Black();
}
)--"},
                       {"bot.iface", kBot}});
    REQUIRE(fe.text() == "");
    const std::string text = pointed_at;
    // A language whose ranges are not chart text (its row says how its text is quoted).
    static const InputLanguage written{"written",
                                       "a language that spells its operators",
                                       {},
                                       nullptr,
                                       nullptr,
                                       /*chart_text=*/false,
                                       /*line_comment=*/{}};
    FileId file = fe.sources.add("t.st", text, chart_text ? chart_text_language() : written);
    auto at = [&](const std::string &op) {
      auto begin = static_cast<std::uint32_t>(text.find(op));
      return SourceRange{file, begin, begin + static_cast<std::uint32_t>(op.size())};
    };
    ast::Chart &chart = fe.loaded.program.files[0]->charts[0];
    chart.transitions[0].condition->set_op_range(at("AND"));
    chart.transitions[1].condition->set_op_range(at("NOT"));
    chart.transitions[2].condition->set_op_range({file, 0, 0});  // a node a reader made up
    validate(fe.loaded.program, fe.sources, fe.diag);
    std::string out;
    for (const auto &d : fe.diag.all()) out += d.message + "\n";
    return out;
  };
  CHECK(messages("Black() AND n; NOT n", false) == R"--(invalid operands to binary 'AND' (have 'bool' and 'int')
invalid operand to unary 'NOT' (have 'int')
invalid operands to binary '<' (have 'int' and 'bool')
)--");
  // In chart text the written operator is C's: the message does not read the range.
  CHECK(messages("Black() AND n; NOT n", true) == R"--(invalid operands to binary '&&' (have 'bool' and 'int')
invalid operand to unary '!' (have 'int')
invalid operands to binary '<' (have 'int' and 'bool')
)--");
}

TEST_CASE("validate: sized integers mix only where one type holds the other, constants must fit", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  var int16 a = 1;
  var uint16 b = 70000;
  var int n = 0;
  var uint8 u = 0;
  var int64 w = 3000000000;
  const int8 K = 100 + 28;
  initial place A {
    a = a + b;
    a = n;
    n = a + u;
    w = w + n;
    u = u + 256;
    a = int16(n) + 1;
    a = int8(200);
    n = 3000000000;
    u = 2.5;
  }
}
)--"},
               {"bot.iface", kBot}});
  const std::string t = r.text();
  INFO(t);
  CHECK(t.find("t.sfc:4:18: error: value 70000 does not fit in 'uint16' [not-constant]") != std::string::npos);
  CHECK(t.find("t.sfc:8:18: error: value 128 does not fit in 'int8' [not-constant]") != std::string::npos);
  CHECK(t.find("t.sfc:10:9: error: invalid operands to binary '+' (have 'int16' and 'uint16') [type-mismatch]") !=
        std::string::npos);
  CHECK(t.find("'int16' and 'uint16' do not mix: neither holds every value of the other; convert one, e.g. "
               "'int16(x)' or 'uint16(x)'") != std::string::npos);
  CHECK(t.find("t.sfc:11:9: error: incompatible types when assigning to 'a' of type 'int16' from type 'int' "
               "[type-mismatch]") != std::string::npos);
  CHECK(t.find("'int16' does not hold every value of 'int': convert explicitly, e.g. 'int16(x)'") != std::string::npos);
  CHECK(t.find("t.sfc:14:13: error: value 256 does not fit in 'uint8' [not-constant]") != std::string::npos);
  CHECK(t.find("t.sfc:16:9: error: value 200 does not fit in 'int8' [not-constant]") != std::string::npos);
  CHECK(t.find("t.sfc:17:9: error: integer constant '3000000000' is too large for 'int' [not-constant]") !=
        std::string::npos);
  CHECK(t.find("t.sfc:18:9: error: incompatible types when assigning to 'u' of type 'uint8' from type 'double'") !=
        std::string::npos);
  // `n = a + u` (int16 + uint8 is int16, which int holds), `w = w + n` and `a = int16(n) + 1` are fine.
  CHECK(t.find("t.sfc:12:") == std::string::npos);
  CHECK(t.find("t.sfc:13:") == std::string::npos);
  CHECK(t.find("t.sfc:15:") == std::string::npos);
  CHECK(r.fe.diag.error_count() == 8);
}

TEST_CASE("validate: a time mixes only with times, durations are times where one is meant", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  period 10ms;
  var time t = 2s;
  var time h = 1.5ms;
  var int n = 0;
  initial place A {
    t = t + 5;
    t = n;
    t = t * 3 + 100ms;
    t = t / 2 - elapsed(A);
  }
  transition A -> A when t > 0;
  transition A -> A when elapsed(A) >= t && elapsed(A) < 1s;
}
sfc P {
  period 2.5ms;
  var time t;
  initial place A { t = elapsed(A); }
}
)--"},
               {"bot.iface", kBot}});
  const std::string t = r.text();
  INFO(t);
  CHECK(t.find("t.sfc:5:16: error: duration '1.5ms' is not a whole number of milliseconds, which a 'time' counts "
               "[type-mismatch]") != std::string::npos);
  CHECK(t.find("t.sfc:8:9: error: invalid operands to binary '+' (have 'time' and 'int') [type-mismatch]") !=
        std::string::npos);
  CHECK(t.find("a 'time' mixes only with times and durations") != std::string::npos);
  CHECK(t.find("t.sfc:9:9: error: incompatible types when assigning to 't' of type 'time' from type 'int'") !=
        std::string::npos);
  CHECK(t.find("t.sfc:13:26: error: invalid operands to binary '>' (have 'time' and 'int')") != std::string::npos);
  CHECK(t.find("t.sfc:19:25: error: 'elapsed(A)' as a 'time' needs a period of whole milliseconds, not 2.5ms") !=
        std::string::npos);
  CHECK(r.fe.diag.error_count() == 5);
}
