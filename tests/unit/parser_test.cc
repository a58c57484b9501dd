#include "parser.h"

#include "support.h"

#include <catch2/catch.hpp>

using namespace gfec;
using test::FrontEnd;
using test::parse_errors;

namespace {

const ast::File &only_file(const FrontEnd &fe) {
  REQUIRE(fe.loaded.program.files.size() == 1);
  return *fe.loaded.program.files[0];
}

}  // namespace

TEST_CASE("parser: an sfc with places, fork/join transitions, vars and entry/exit") {
  FrontEnd fe({{"t.sfc", R"(
sfc Demo {
  period 10ms;
  var int laps = 0;
  const float CRUISE = 0.6;
  initial place A { entry { laps += 1; } Go(CRUISE); exit { Stop(); } }
  place B;
  place C {}
  transition Split: A -> (B, C) when Ready() && !(laps >= 3);
  (B, C) -> A;
  transition B -> C when elapsed(B) >= 500ms;
}
)"}});
  CHECK(fe.text() == "");
  const ast::Chart &c = only_file(fe).charts.at(0);
  CHECK(c.kind == ast::Chart::Kind::Sfc);
  CHECK(c.name.text == "Demo");
  REQUIRE(c.periods.size() == 1);
  CHECK(c.periods[0].ms == 10);
  REQUIRE(c.values.size() == 2);
  CHECK_FALSE(c.values[0].is_const);
  CHECK(c.values[1].is_const);
  REQUIRE(c.places.size() == 3);
  CHECK(c.places[0].initial);
  CHECK(c.places[0].entry() != nullptr);
  CHECK(c.places[0].exit() != nullptr);
  CHECK(c.places[0].action.size() == 1);
  CHECK_FALSE(c.places[1].has_body);
  CHECK(c.places[2].has_body);
  REQUIRE(c.transitions.size() == 3);
  CHECK(c.transitions[0].named);
  CHECK(c.transitions[0].name.text == "Split");
  CHECK(c.transitions[0].outputs().size() == 2);
  CHECK(c.transitions[1].inputs().size() == 2);
  CHECK(c.transitions[1].condition == nullptr);
  const ast::Expr &cond = *c.transitions[0].condition;
  CHECK(cond.kind == ast::Expr::Kind::Binary);
  CHECK(cond.binary_op == BinaryOp::And);
  CHECK(cond.args[1]->kind == ast::Expr::Kind::Unary);
  CHECK(cond.args[1]->args[0]->kind == ast::Expr::Kind::Paren);
  const ast::Expr &timer = *c.transitions[2].condition;
  CHECK(timer.args[0]->kind == ast::Expr::Kind::Call);
  CHECK(timer.args[1]->kind == ast::Expr::Kind::Duration);
  CHECK(timer.args[1]->duration_ms == 500);
}

TEST_CASE("parser: C precedence and left associativity") {
  FrontEnd fe({{"t.sfc", "sfc X { initial place A; A -> A when a || b && c == d + e * f - g; }"}});
  REQUIRE(fe.text() == "");
  const ast::Expr &e = *only_file(fe).charts[0].transitions[0].condition;
  CHECK(e.binary_op == BinaryOp::Or);
  const ast::Expr &and_ = *e.args[1];
  CHECK(and_.binary_op == BinaryOp::And);
  const ast::Expr &eq = *and_.args[1];
  CHECK(eq.binary_op == BinaryOp::Eq);
  const ast::Expr &sub = *eq.args[1];  // (d + e*f) - g
  CHECK(sub.binary_op == BinaryOp::Sub);
  CHECK(sub.args[0]->binary_op == BinaryOp::Add);
  CHECK(sub.args[0]->args[1]->binary_op == BinaryOp::Mul);
}

TEST_CASE("parser: an operator's range is the operator as written, apart from its operands") {
  // Spaces, brackets and a comment around the operators: the range holds the operator alone.
  FrontEnd fe({{"t.sfc", "sfc X { initial place A; A -> A when (a)  &&/* c */!  b <= -c; }"}});
  REQUIRE(fe.text() == "");
  const std::string &text = fe.sources.file(0).text();
  auto written = [&](const ast::Expr &e) {
    const SourceRange &r = e.op_range();
    CHECK(r.file == e.range.file);
    CHECK(e.range.begin <= r.begin);
    CHECK(r.end <= e.range.end);
    return text.substr(r.begin, r.end - r.begin);
  };
  const ast::Expr &and_ = *only_file(fe).charts[0].transitions[0].condition;  // (a) && ((!b) <= (-c))
  REQUIRE(and_.binary_op == BinaryOp::And);
  CHECK(written(and_) == "&&");
  CHECK(and_.op_range().begin == text.find("&&"));
  const ast::Expr &le = *and_.args[1];
  REQUIRE(le.binary_op == BinaryOp::Le);
  CHECK(written(le) == "<=");
  REQUIRE(le.args[0]->kind == ast::Expr::Kind::Unary);
  CHECK(written(*le.args[0]) == "!");
  CHECK(le.args[0]->op_range().begin == text.find('!'));
  CHECK(written(*le.args[1]) == "-");
  // An operator has no name: the range sits where a name would, and no text comes with it.
  CHECK(and_.name.text.empty());
}

TEST_CASE("parser: fsm states, terminal states with post, bare transitions") {
  FrontEnd fe({{"t.fsm", R"(
fsm M {
  initial state Z0 { Go(); }
  success state Done post Placed();
  failure state Failed;
  Z0 -> Done when Arrived();
  transition giveUp: Z0 -> Failed when Stuck();
}
)"}});
  REQUIRE(fe.text() == "");
  const ast::Chart &c = only_file(fe).charts.at(0);
  CHECK(c.kind == ast::Chart::Kind::Fsm);
  REQUIRE(c.places.size() == 3);
  CHECK(c.places[0].is_state);
  CHECK(c.places[1].terminal == ast::StateKind::Success);
  CHECK(c.places[1].post() != nullptr);
  CHECK(c.places[2].terminal == ast::StateKind::Failure);
  CHECK(c.transitions[1].named);
  CHECK(c.transitions[1].name.text == "giveUp");
}

TEST_CASE("parser: interface prototypes") {
  FrontEnd fe({{"t.iface", "interface R { bool f(); void g(void); void Motor(int side, float); }"}});
  REQUIRE(fe.text() == "");
  const ast::Interface &i = only_file(fe).interfaces.at(0);
  REQUIRE(i.functions.size() == 3);
  CHECK(i.functions[0].params.empty());
  CHECK(i.functions[1].params.empty());
  REQUIRE(i.functions[2].params.size() == 2);
  CHECK(i.functions[2].params[0].name->text == "side");
  CHECK_FALSE(i.functions[2].params[1].name.has_value());
}

TEST_CASE("parser: toolbox and plan") {
  FrontEnd fe({{"t.plan", R"(
toolbox T {
  actor Forward(in float distance) -> OK | FAIL;
  supervisor Check(in float d, out int n) events HIT | MISS period 10ms;
}
plan P {
  config { float d = 30; string s; }
  supervise esc: Check(d) { HIT -> terminate; MISS -> ignore; }
  start a;
  actor a: Forward(d * 2 + 1) { OK -> a; FAIL -> terminate; supervise t: Check(1) { HIT -> a; MISS -> ignore; } }
  computation b: Forward(-d);
}
)"}});
  REQUIRE(fe.text() == "");
  const ast::File &f = only_file(fe);
  const ast::Toolbox &tb = f.toolboxes.at(0);
  REQUIRE(tb.templates.size() == 2);
  CHECK(tb.templates[0].outcomes.size() == 2);
  CHECK(tb.templates[1].kind == ast::Template::Kind::Supervisor);
  CHECK(tb.templates[1].params[1].dir == ast::ParamDir::Out);
  CHECK(tb.templates[1].period->ms == 10);
  const ast::Plan &p = f.plans.at(0);
  CHECK(p.config_blocks.at(0).size() == 2);
  CHECK(p.global_supervisors.size() == 1);
  CHECK(p.global_supervisors[0].rules[1].target == ast::Rule::Target::Ignore);
  CHECK(p.starts.size() == 1);
  REQUIRE(p.actors.size() == 2);
  CHECK(p.actors[0].supervisors.size() == 1);
  CHECK(p.actors[0].rules.size() == 2);
  CHECK(p.actors[1].written_as_computation);
}

TEST_CASE("parser: one run reports every independent syntax error") {
  CHECK(parse_errors("sfc X {\n  initial place A { Go( }\n  place B { x = ; }\n  place C;\n}\n") ==
        "t.sfc:2:25: error: expected an expression, found '}' [syntax]\n"
        "   initial place A { Go( }\n"
        "                         ^\n"
        "t.sfc:3:17: error: expected an expression, found ';' [syntax]\n"
        "   place B { x = ; }\n"
        "                 ^\n");
}

TEST_CASE("parser: a missing semicolon at the end of a line is reported there and the next token in a note") {
  CHECK(parse_errors("sfc X {\n  initial place A;\n  A -> A\n}\n") ==
        "t.sfc:3:9: error: expected ';' after the transition at the end of the line [syntax]\n"
        "   A -> A\n"
        "         ^\n"
        "t.sfc:4:1: note: before '}' on the next line\n"
        " }\n"
        " ^\n");
}

TEST_CASE("parser: declarations in the wrong place") {
  CHECK(parse_errors("var int x = 1;\nsfc X { initial place A; }") ==
        "t.sfc:1:1: error: 'var' declares chart state and belongs inside an sfc or fsm [syntax]\n"
        " var int x = 1;\n"
        " ^~~\n");
  CHECK(parse_errors("place A;") == "t.sfc:1:1: error: expected a declaration (import, interface, sfc, fsm, toolbox, "
                                    "plan, const or test), found 'place' [syntax]\n"
                                    " place A;\n"
                                    " ^~~~~\n");
}

TEST_CASE("parser: deep nesting is refused cleanly, not by a stack overflow") {
  std::string deep =
      "sfc X { initial place A; A -> A when " + std::string(100000, '(') + "x" + std::string(100000, ')') + "; }";
  std::string text = parse_errors(deep);
  CHECK(text.find("error: expression nested too deeply (more than 256 levels) [nesting]") != std::string::npos);
  std::string bangs = "sfc X { initial place A; A -> A when " + std::string(100000, '!') + "x; }";
  CHECK(parse_errors(bangs).find("[nesting]") != std::string::npos);
}

TEST_CASE("parser: if, else if and else are statements in every block") {
  FrontEnd fe({{"t.sfc", R"(
fsm M {
  initial state A {
    entry { if (Ready()) { Go(); } }
    if (x > 1) { Go(); n = 2; } else if (Late()) { Stop(); } else { if (y) { } }
    exit { if (z) { Stop(); } else { Go(); } }
  }
}
)"}});
  CHECK(fe.text() == "");
  const ast::Place &a = only_file(fe).charts.at(0).places.at(0);
  REQUIRE(a.action.size() == 1);
  const ast::Stmt &s = a.action[0];
  CHECK(s.kind == ast::Stmt::Kind::If);
  CHECK(s.value->kind == ast::Expr::Kind::Binary);
  CHECK(s.then_block.size() == 2);
  CHECK(s.has_else);
  CHECK(s.else_if);
  REQUIRE(s.else_block.size() == 1);
  const ast::Stmt &inner = s.else_block[0];
  CHECK(inner.kind == ast::Stmt::Kind::If);
  CHECK(inner.value->kind == ast::Expr::Kind::Call);
  CHECK(inner.has_else);
  CHECK_FALSE(inner.else_if);
  REQUIRE(inner.else_block.size() == 1);
  CHECK(inner.else_block[0].kind == ast::Stmt::Kind::If);
  CHECK(inner.else_block[0].then_block.empty());
  CHECK_FALSE(inner.else_block[0].has_else);
  // The statement's range runs from `if` to the last closing brace.
  CHECK(fe.sources.file(s.range.file).text().substr(s.range.begin, s.range.end - s.range.begin) ==
        "if (x > 1) { Go(); n = 2; } else if (Late()) { Stop(); } else { if (y) { } }");
  REQUIRE(a.entry());
  CHECK(a.entry()->at(0).kind == ast::Stmt::Kind::If);
  CHECK_FALSE(a.entry()->at(0).has_else);
  REQUIRE(a.exit());
  CHECK(a.exit()->at(0).has_else);
  CHECK_FALSE(a.exit()->at(0).else_if);
}

TEST_CASE("parser: if and else mistakes") {
  CHECK(parse_errors("sfc X {\n  initial place A { if Ready() { Go(); } }\n}\n") ==
        "t.sfc:2:24: error: expected '(' after 'if', found 'Ready' [syntax]\n"
        "   initial place A { if Ready() { Go(); } }\n"
        "                        ^~~~~\n");
  CHECK(parse_errors("sfc X {\n  initial place A { if (Ready()) Go(); }\n}\n") ==
        "t.sfc:2:34: error: expected '{' after the condition of 'if' (the branches of an 'if' are blocks), "
        "found 'Go' [syntax]\n"
        "   initial place A { if (Ready()) Go(); }\n"
        "                                  ^~\n");
  CHECK(parse_errors("sfc X {\n  initial place A { Go(); else { Stop(); } }\n}\n") ==
        "t.sfc:2:27: error: expected a statement ('else' must follow the block of an 'if'), found 'else' [syntax]\n"
        "   initial place A { Go(); else { Stop(); } }\n"
        "                           ^~~~\n");
  CHECK(parse_errors("sfc X {\n  initial place A { if (a) { } else Stop(); }\n}\n") ==
        "t.sfc:2:37: error: expected '{' or 'if' after 'else', found 'Stop' [syntax]\n"
        "   initial place A { if (a) { } else Stop(); }\n"
        "                                     ^~~~\n");
  // Deeply nested blocks are refused like deep expressions.
  std::string deep = "sfc X { initial place A { ";
  for (int i = 0; i < 3000; ++i) deep += "if (a) { ";
  deep += std::string(3000, '}') + " } }";
  CHECK(parse_errors(deep).find("[nesting]") != std::string::npos);
}

TEST_CASE("parser: team declarations and team(S)") {
  FrontEnd fe({{"t.sfc", R"(
fsm M {
  team 4;
  team 1;
  initial state A { if (team(A) > agent()) { Go(); } }
}
)"}});
  CHECK(fe.text() == "");
  const ast::Chart &c = only_file(fe).charts.at(0);
  REQUIRE(c.teams.size() == 2);
  CHECK(c.teams[0].first == 4);
  CHECK(c.teams[1].first == 1);  // the validator checks the sizes
  const ast::Expr &cond = *c.places.at(0).action.at(0).value;
  const ast::Expr &team = *cond.args.at(0);
  CHECK(team.kind == ast::Expr::Kind::Call);
  CHECK(team.name.text == "team");
  REQUIRE(team.args.size() == 1);
  CHECK(team.args[0]->name.text == "A");
  CHECK(cond.args.at(1)->name.text == "agent");
  CHECK(
      parse_errors("fsm X {\n  team four;\n}\n") ==
      "t.sfc:2:8: error: expected integer after 'team' (the number of agents, e.g. 'team 4;'), found 'four' [syntax]\n"
      "   team four;\n"
      "        ^~~~\n");
  CHECK(
      parse_errors("fsm X {\n  initial state A { n = team; }\n}\n") ==
      "t.sfc:2:29: error: expected '(' after 'team' (team(S) counts the other agents in state S), found ';' [syntax]\n"
      "   initial state A { n = team; }\n"
      "                             ^\n");
}

TEST_CASE("loader: imports are found beside the importer, read once, and cycles are errors") {
  FrontEnd ok({{"dir/main.sfc", "import \"a.iface\"; import \"b.iface\";"},
               {"dir/a.iface", "import \"b.iface\";"},
               {"dir/b.iface", "import \"a.iface\";"}});
  CHECK(ok.loaded.paths == std::vector<std::string>{"dir/main.sfc", "dir/a.iface", "dir/b.iface"});
  CHECK(ok.text() == "dir/b.iface:1:8: error: import cycle: 'dir/a.iface' imports itself [import-cycle]\n"
                     " import \"a.iface\";\n"
                     "        ^~~~~~~~~\n"
                     "dir/a.iface:1:8: note: 'dir/a.iface' imports 'dir/b.iface'\n"
                     " import \"b.iface\";\n"
                     "        ^~~~~~~~~\n"
                     "dir/b.iface:1:8: note: 'dir/b.iface' imports 'dir/a.iface'\n");

  FrontEnd missing({{"m.sfc", "\nimport \"nothere.iface\";"}});
  CHECK(missing.text() == "m.sfc:2:8: error: cannot find imported file 'nothere.iface' [import]\n"
                          " import \"nothere.iface\";\n"
                          "        ^~~~~~~~~~~~~~~\n"
                          "m.sfc:2:8: note: looked for 'nothere.iface'\n");

  FrontEnd diamond({{"m.sfc", "import \"a.iface\"; import \"c.iface\";"},
                    {"a.iface", "import \"c.iface\";"},
                    {"c.iface", "interface C { void f(); }"}});
  CHECK(diamond.text() == "");
  CHECK(diamond.loaded.paths.size() == 3);
}

TEST_CASE("parser: sub-charts: 'runs' after the name, paths only inside active()") {
  FrontEnd fe({{"t.sfc", R"(
sfc Top {
  initial place Search runs Fetch { Beep(); }
  place Retry runs Fetch;
  success state Done runs X post Ok();
  transition Search -> Retry when active(Search.Grab.Hand) || active(Retry) && !succeeded(Search);
}
)"}});
  CHECK(fe.text() == "");
  const ast::Chart &c = only_file(fe).charts.at(0);
  REQUIRE(c.places.size() == 3);
  REQUIRE(c.places[0].runs());
  CHECK(c.places[0].runs()->text == "Fetch");
  CHECK(c.places[0].has_body);
  REQUIRE(c.places[1].runs());
  CHECK(c.places[1].runs()->text == "Fetch");
  CHECK(!c.places[1].has_body);
  REQUIRE(c.places[2].runs());  // parsed; the validator rejects `runs` on a terminal state
  CHECK(c.places[2].post());
  const ast::Expr &cond = *c.transitions.at(0).condition;
  REQUIRE(cond.kind == ast::Expr::Kind::Binary);
  const ast::Expr &active_path = *cond.args[0];
  REQUIRE(active_path.kind == ast::Expr::Kind::Call);
  CHECK(active_path.name.text == "active");
  REQUIRE(active_path.args.size() == 1);
  const ast::Expr &path = *active_path.args[0];
  REQUIRE(path.kind == ast::Expr::Kind::Path);
  REQUIRE(path.args.size() == 3);
  CHECK(path.args[0]->name.text == "Search");
  CHECK(path.args[1]->name.text == "Grab");
  CHECK(path.args[2]->name.text == "Hand");
  const ast::Expr &active_one = *cond.args[1]->args[0];
  REQUIRE(active_one.args.size() == 1);
  CHECK(active_one.args[0]->kind == ast::Expr::Kind::Name);
}

TEST_CASE("parser: a path outside active() parses (a block's member), a path cut short is a syntax error") {
  // `a.b` reads output b of block instance a (docs/language.md "Blocks"): the validator says
  // what else a path is.
  CHECK(parse_errors("sfc S { initial place A; A -> A when elapsed(A.B) > 1s; }") == "");
  CHECK(parse_errors("sfc S { initial place A; A -> A when active(A.); }") ==
        "t.sfc:1:47: error: expected identifier after '.' (a place or state of the sub-chart), found ')' [syntax]\n"
        " sfc S { initial place A; A -> A when active(A.); }\n"
        "                                               ^\n");
  CHECK(parse_errors("sfc S { initial place A runs; }") ==
        "t.sfc:1:29: error: expected identifier after 'runs' (the sfc or fsm to run), found ';' [syntax]\n"
        " sfc S { initial place A runs; }\n"
        "                             ^\n");
}
