// Blocks (docs/language.md "Blocks"): declarations, instances, calls and members, each mistake a
// located error with did-you-mean; and the model a call lowers to (the body inlined per call).
#include "validate_fixture.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec;
using test::Validated;

TEST_CASE("validate: blocks, instances, calls and members", "[validate][blocks]") {
  Validated r({{"t.sfc", R"--(block Twice {
  in int x;
  out int y;
  var Twice inner;
  y = 2 * x;
}

sfc S {
  in bool P;
  out bool Q;
  out int N;
  var CTU c;
  var TONN t;
  var R_TRIG r = 1;
  in SR s;
  var int v;
  initial place A {
    c(CU = P, RR = P);
    c(CU = P, CU = P);
    c(PV = true);
    Q = c.QQ;
    Q = c.CU;
    c.Q = true;
    d(CU = P);
    v(x = 1);
    c(P);
    N = c;
    N = A.x;
    c.PV += 1;
  }
}
)--"}});
  CHECK(r.text() == R"--(t.sfc:13:7: error: unknown type name 'TONN' [unknown-type]
   var TONN t;
       ^~~~
t.sfc:13:7: note: did you mean the block 'TON'?
t.sfc:14:18: error: block instance 'r' takes no initial value: its members start as block 'R_TRIG' says [type-mismatch]
   var R_TRIG r = 1;
                  ^
t.sfc:15:3: error: block instance 's' is declared 'var', not 'in' [chart-io]
   in SR s;
   ^~~~~~~~
t.sfc:18:15: error: block 'CTU' has no input 'RR' [unknown-name]
     c(CU = P, RR = P);
               ^~
<standard blocks>:33:3: note: did you mean 'R'?
   in bool R;
   ^~~~~~~~~~
t.sfc:19:15: error: input 'CU' given twice [duplicate-name]
     c(CU = P, CU = P);
               ^~
t.sfc:20:12: error: incompatible types when assigning to 'PV' of type 'int16' from type 'bool' [type-mismatch]
     c(PV = true);
            ^~~~
t.sfc:21:11: error: block 'CTU' has no output 'QQ' [unknown-name]
     Q = c.QQ;
           ^~
<standard blocks>:35:3: note: did you mean 'Q'?
   out bool Q;
   ^~~~~~~~~~~
t.sfc:22:11: error: 'CU' is an input of block 'CTU', not an output [type-mismatch]
     Q = c.CU;
           ^~
<standard blocks>:32:3: note: 'CU' declared here
   in bool CU;
   ^~~~~~~~~~~
t.sfc:23:7: error: 'Q' is an output of block 'CTU', not an input [type-mismatch]
     c.Q = true;
       ^
<standard blocks>:35:3: note: 'Q' declared here
   out bool Q;
   ^~~~~~~~~~~
t.sfc:24:5: error: unknown block instance 'd' [unknown-name]
     d(CU = P);
     ^
t.sfc:25:5: error: 'v' is a variable, not a block instance [type-mismatch]
     v(x = 1);
     ^
t.sfc:16:11: note: 'v' declared here
   var int v;
           ^
t.sfc:26:5: error: a block's arguments are named: 'c(input = value, ...)' [type-mismatch]
     c(P);
     ^~~~
t.sfc:27:9: error: 'c' is a block instance, not a value [type-mismatch]
     N = c;
         ^
t.sfc:28:9: error: a path to a sub-chart's place is only read through 'active(...)'; 'a.b' reads output b of block instance a [syntax]
     N = A.x;
         ^~~
t.sfc:29:5: error: an input of a block instance is set with '=', not '+=' [not-assignable]
     c.PV += 1;
     ^~~~
t.sfc:4:7: error: block 'Twice' contains an instance of itself [type-mismatch]
   var Twice inner;
       ^~~~~
t.sfc:1:7: note: 'Twice' declared here
 block Twice {
       ^~~~~
)--");
}

TEST_CASE("validate: a misspelt block type is offered the block", "[validate][blocks]") {
  Validated r({{"t.sfc", "sfc S {\n  var CTUU c;\n  initial place A;\n}\n"}});
  CHECK(r.text() == R"--(t.sfc:2:7: error: unknown type name 'CTUU' [unknown-type]
   var CTUU c;
       ^~~~
t.sfc:2:7: note: did you mean the block 'CTU'?
)--");
}

TEST_CASE("validate: a call inlines the block's body over the instance's vars", "[validate][blocks]") {
  Validated r({{"t.sfc", R"--(block Inc {
  in int by = 1;
  out int n;
  var R_TRIG edge;
  edge(CLK = n > 2);
  n += by;
}
sfc S {
  out int N;
  var Inc a;
  var Inc b;
  initial place A {
    a(by = 2);
    b();
    N = a.n + b.n;
  }
}
)--"}});
  REQUIRE(r.text() == "");
  const model::Chart &c = r.model.charts[model::ChartId(0)];
  // N, then a's members (by, n, edge.CLK, edge.Q, edge.M), then b's.
  REQUIRE(c.vars.size() == 11);
  CHECK(c.vars[model::VarId(1)].name == "a.by");
  CHECK(c.vars[model::VarId(3)].name == "a.edge.CLK");
  CHECK(c.vars[model::VarId(6)].name == "b.by");
  CHECK(c.vars[model::VarId(6)].role == model::VarRole::Local);
  REQUIRE(c.vars[model::VarId(6)].init);
  CHECK(c.vars[model::VarId(6)].init->int_value == 1);
  // The instances: a's R_TRIG, a, b's R_TRIG, b.
  REQUIRE(c.instances.size() == 4);
  CHECK(c.instances[1].name == "a");
  CHECK(c.instances[0].name == "a.edge");
  CHECK(c.instances[3].first == model::VarId(6));
  const auto &body = c.places[model::PlaceId(0)].action;
  REQUIRE(body.size() == 3);
  const model::Stmt &call_a = body[0];
  CHECK(call_a.kind == model::Stmt::Kind::Invoke);
  CHECK(call_a.var == model::VarId(1));
  CHECK(call_a.code_begin == 1);  // one argument, then the body: edge(...), n += by
  REQUIRE(call_a.then_block.size() == 3);
  CHECK(call_a.then_block[0].var == model::VarId(1));
  const model::Stmt &inner = call_a.then_block[1];
  CHECK(inner.kind == model::Stmt::Kind::Invoke);
  CHECK(inner.var == model::VarId(3));                      // a.edge.CLK
  CHECK(call_a.then_block[2].var == model::VarId(2));       // a.n += a.by
  CHECK(body[1].then_block.back().var == model::VarId(7));  // b.n += b.by
  CHECK(body[1].code_begin == 0);
  bool used_inc = false, used_trig = false;
  for (const model::Block &b : r.model.blocks) {
    if (b.name == "Inc") used_inc = b.used && !b.standard;
    if (b.name == "R_TRIG") used_trig = b.used && b.standard;
  }
  CHECK(used_inc);
  CHECK(used_trig);
}
