// Loops, `break` and `return` (docs/language.md §10): parsed, checked with located errors, run by
// the interpreter as C runs them, and stopped by the interpreter's bound when they run away.
#include "iec/st_fragment.h"
#include "interpreter_support.h"
#include "validate_fixture.h"

#include <deque>

using namespace gfec;
using test::compile;
using test::parse_errors;
using test::run_log;
using test::ScriptedEnv;
using test::Validated;

namespace {

const char *const kIface = "interface Bot { void I(int v); int Si(); bool Sb(); }";

/// The calls the chart's one action makes on its first tick, and a run-time error if any.
std::string first_tick_calls(const std::string &action, const std::string &vars = "") {
  auto c = compile("sfc E {\n" + vars + "\n  initial place A { " + action + " }\n}\n", kIface);
  ScriptedEnv env(*c);
  env.script("Si", {3}).script("Sb", {1});
  std::string log = run_log(*c, env, 1);
  std::string calls;
  for (std::size_t at = 0, nl; (nl = log.find('\n', at)) != std::string::npos; at = nl + 1) {
    std::string_view line(log.data() + at, nl - at + 1);  // a million lines: search each line only
    if (line.compare(0, 7, "call I(") == 0 || line.find("error") != std::string_view::npos) calls += line;
  }
  return calls;
}

}  // namespace

TEST_CASE("loops: while, do and for parse as statements in every block") {
  test::FrontEnd fe({{"t.sfc", R"(
sfc S {
  var int i;
  initial place A {
    while (i < 3) { i += 1; if (i == 2) { break; } }
    do { i -= 1; } while (i > 0);
    for (i = 0; i < 4; i += 1) { return; }
    entry { for (i = 9; i >= 0; i -= 3) { } }
  }
}
)"}});
  CHECK(fe.text() == "");
  const ast::Place &a = fe.loaded.program.files.at(0)->charts.at(0).places.at(0);
  REQUIRE(a.action.size() == 3);
  CHECK(a.action[0].kind == ast::Stmt::Kind::While);
  CHECK(a.action[0].then_block.size() == 2);
  CHECK(a.action[0].then_block[1].then_block[0].kind == ast::Stmt::Kind::Break);
  CHECK(a.action[1].kind == ast::Stmt::Kind::DoWhile);
  CHECK(a.action[1].value->kind == ast::Expr::Kind::Binary);
  const ast::Stmt &f = a.action[2];
  CHECK(f.kind == ast::Stmt::Kind::For);
  REQUIRE(f.else_block.size() == 2);
  CHECK(f.else_block[0].assign_op == AssignOp::Set);
  CHECK(f.else_block[1].assign_op == AssignOp::Add);
  CHECK(f.then_block[0].kind == ast::Stmt::Kind::Return);
  CHECK(fe.sources.file(f.range.file).text().substr(f.range.begin, f.range.end - f.range.begin) ==
        "for (i = 0; i < 4; i += 1) { return; }");
  REQUIRE(a.entry());
  CHECK(a.entry()->at(0).else_block[1].assign_op == AssignOp::Sub);
}

TEST_CASE("loops: syntax errors say what the loop needs") {
  auto one = [](const std::string &stmt) {
    return parse_errors("sfc S {\n  var int i;\n  initial place A { " + stmt + " }\n}\n");
  };
  CHECK(one("for (; i < 3; i += 1) { }") ==
        "t.sfc:3:26: error: expected an assignment as the first part of 'for' (i = 0), found ';' [syntax]\n"
        "   initial place A { for (; i < 3; i += 1) { } }\n"
        "                          ^\n");
  CHECK(one("for (i = 0; ; i += 1) { }").find("expected the condition of 'for' (gfec's 'for' needs all three parts)") !=
        std::string::npos);
  CHECK(one("for (i = 0; i < 3; i++) { }").find("expected an assignment as the third part of 'for' (i += 1)") !=
        std::string::npos);
  CHECK(one("while (i < 3) i += 1;").find("expected '{' after the condition of 'while'") != std::string::npos);
  CHECK(one("do { } while (i < 3)").find("expected ';' after 'do { ... } while (...)'") != std::string::npos);
  CHECK(one("do { } until (i < 3);").find("expected 'while' after the body of 'do'") != std::string::npos);
  CHECK(one("return 3;").find("expected ';' after 'return' (a statement returns no value)") != std::string::npos);
}

TEST_CASE("loops: the validator checks conditions and break and refuses loops that cannot end", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  var int n = 0;
  initial place A {
    while (n) { n -= 1; }
    break;
    if (n > 0) { break; }
    while (true) { n += 1; }
    do { for (n = 0; n < 3; n += 1) { break; } } while (1 < 2);
    while (true) { while (n > 0) { break; } if (n == 0) { return; } }
    for (n = true; n < 3; n += 1) { }
  }
}
)--"},
               {"bot.iface", test::kBot}});
  CHECK(r.text() == R"--(t.sfc:5:12: error: the condition of 'while' must be bool, not 'int' [type-mismatch]
     while (n) { n -= 1; }
            ^
t.sfc:6:5: error: 'break' outside a loop [loop]
     break;
     ^~~~~~
t.sfc:6:5: note: 'break' ends the innermost 'while', 'do' or 'for' it is written in; 'return' ends the whole block
t.sfc:7:18: error: 'break' outside a loop [loop]
     if (n > 0) { break; }
                  ^~~~~~
t.sfc:7:18: note: 'break' ends the innermost 'while', 'do' or 'for' it is written in; 'return' ends the whole block
t.sfc:8:12: error: this 'while' loop never ends: its condition is always true and its body has no 'break' or 'return' [loop]
     while (true) { n += 1; }
            ^~~~
t.sfc:8:12: note: a tick must end: add a 'break' or 'return' that the body reaches, or a condition that becomes false
t.sfc:9:57: error: this 'while' loop never ends: its condition is always true and its body has no 'break' or 'return' [loop]
     do { for (n = 0; n < 3; n += 1) { break; } } while (1 < 2);
                                                         ^~~~~
t.sfc:9:57: note: a tick must end: add a 'break' or 'return' that the body reaches, or a condition that becomes false
t.sfc:11:14: error: incompatible types when assigning to 'n' of type 'int' from type 'bool' [type-mismatch]
     for (n = true; n < 3; n += 1) { }
              ^~~~
)--");
}

TEST_CASE("loops: the model holds the loop with its header and its body", "[validate]") {
  Validated r({{"t.sfc", R"--(import "bot.iface";
sfc S {
  var int n = 0;
  initial place A { for (n = 0; n < Count(); n += 2) { Go(); if (Black()) { return; } } }
}
)--"},
               {"bot.iface", test::kBot}});
  CHECK(r.text().empty());
  const auto &action = r.model.charts[0].places[0].action;
  REQUIRE(action.size() == 1);
  const model::Stmt &f = action[0];
  CHECK(f.kind == model::Stmt::Kind::For);
  CHECK(f.expr.type == model::Type::Bool);
  REQUIRE(f.else_block.size() == 2);
  CHECK(f.else_block[0].kind == model::Stmt::Kind::Assign);
  CHECK(f.else_block[1].op == AssignOp::Add);
  REQUIRE(f.then_block.size() == 2);
  CHECK(f.then_block[1].then_block[0].kind == model::Stmt::Kind::Return);
}

TEST_CASE("loops: the interpreter runs them as C does") {
  // for: init once, test, body, step; break skips the step.
  CHECK(first_tick_calls("for (i = 0; i < 3; i += 1) { I(i); } I(i);", "var int i;") ==
        "call I(0)\ncall I(1)\ncall I(2)\ncall I(3)\n");
  CHECK(first_tick_calls("for (i = 0; i < 9; i += 1) { if (i == 2) { break; } I(i); } I(i);", "var int i;") ==
        "call I(0)\ncall I(1)\ncall I(2)\n");
  // while tests first, do after the body.
  CHECK(first_tick_calls("while (i > 0) { I(i); } do { I(i); i -= 1; } while (i > -2); I(i);", "var int i;") ==
        "call I(0)\ncall I(-1)\ncall I(-2)\n");
  // The condition is evaluated before each pass: its calls are made each time.
  CHECK(first_tick_calls("while (i < Si()) { i += 2; } I(i);", "var int i;") == "call I(4)\n");
  // break ends the innermost loop only; return ends the whole block, from any depth.
  CHECK(first_tick_calls("for (i = 0; i < 2; i += 1) { for (j = 0; j < 5; j += 1) { if (j > i) { break; } "
                         "I(10 * i + j); } } I(99);",
                         "var int i; var int j;") == "call I(0)\ncall I(10)\ncall I(11)\ncall I(99)\n");
  CHECK(first_tick_calls("while (Sb()) { for (i = 0; i < 5; i += 1) { if (i == 1) { return; } I(i); } } I(99);",
                         "var int i;") == "call I(0)\n");
}

TEST_CASE("loops: the interpreter stops a loop that runs away, at the loop") {
  CHECK(first_tick_calls("while (Sb()) { i += 1; } I(i);", "var int i;") ==
        "t.sfc:4:21: error: this loop ran more than 1000000 times in one tick: gfec run stops it (an engine on a "
        "target would hang) during tick 1 [runtime]\n");
  // The count is per execution of the loop statement: a million passes in all is fine.
  CHECK(first_tick_calls("for (i = 0; i < 2000; i += 1) { for (j = 0; j < 999; j += 1) { n += 1; } } I(n);",
                         "var int i; var int j; var int n;") == "call I(1998000)\n");
}

TEST_CASE("loops: IEC FOR, WHILE, REPEAT, EXIT and RETURN read as the chart's loops", "[iec]") {
  std::deque<std::string> strings;
  auto read = [&](std::string_view text, Diagnostics &diag) {
    return iec::parse_st_statements(text, iec::FragmentPlace::at(0, 0), strings, diag);
  };
  Diagnostics diag;
  auto b = read("FOR i := 1 TO n DO EXIT; END_FOR; FOR i := 9 TO 0 BY -3 DO RETURN; END_FOR "
                "FOR i := 0 TO 5 BY s DO END_FOR; WHILE x < 3 DO x := x + 1; END_WHILE; "
                "REPEAT x := x - 1; UNTIL x = 0 END_REPEAT; y := MOD(x, 4);",
                diag);
  REQUIRE(b);
  CHECK_FALSE(diag.has_errors());
  REQUIRE(b->size() == 6);
  const ast::Stmt &up = (*b)[0];
  REQUIRE(up.kind == ast::Stmt::Kind::For);
  CHECK(up.value->binary_op == BinaryOp::Le);
  CHECK(up.else_block[1].assign_op == AssignOp::Add);
  CHECK(up.else_block[1].value->text() == "1");
  CHECK(up.then_block[0].kind == ast::Stmt::Kind::Break);
  const ast::Stmt &down = (*b)[1];
  CHECK(down.value->binary_op == BinaryOp::Ge);  // a literal negative step counts down
  CHECK(down.else_block[1].assign_op == AssignOp::Sub);
  CHECK(down.else_block[1].value->text() == "3");
  CHECK(down.then_block[0].kind == ast::Stmt::Kind::Return);
  const ast::Stmt &by = (*b)[2];
  CHECK(by.value->binary_op == BinaryOp::Or);  // the step's sign is tested before each pass
  CHECK(by.else_block[1].value->kind == ast::Expr::Kind::Name);
  CHECK((*b)[3].kind == ast::Stmt::Kind::While);
  const ast::Stmt &repeat = (*b)[4];
  CHECK(repeat.kind == ast::Stmt::Kind::DoWhile);
  CHECK(repeat.value->unary_op == UnaryOp::Not);  // UNTIL c: again while !(c)
  CHECK((*b)[5].value->args[0]->binary_op == BinaryOp::Mod);

  auto one_error = [&](const std::string &text) {
    Diagnostics d;
    read(text, d);
    REQUIRE(d.error_count() == 1);
    return d.all().front().check() + ": " + d.all().front().message;
  };
  CHECK(one_error("EXIT;") == "loop: 'EXIT' outside a loop: it ends the innermost FOR, WHILE or REPEAT");
  CHECK(one_error("FOR i := 1 TO 3 BY 0 DO x := i; END_FOR;") ==
        "loop: the step of 'FOR' is 0: the loop would never end");
  CHECK(one_error("FOR i := 1 TO 3 x := i; END_FOR;") == "syntax: expected 'DO' after the header of 'FOR', not 'x'");
  CHECK(one_error("REPEAT x := 1; END_REPEAT;") ==
        "syntax: expected 'UNTIL' to end the body of 'REPEAT', not 'END_REPEAT'");
  CHECK(one_error("WHILE TRUE DO CONTINUE; END_WHILE;").rfind("not-supported: ", 0) == 0);
}
