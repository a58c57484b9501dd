// The IEC structured-text reader (compiler/iec/, docs/iec.md "Reading structured text"): the
// fragment entry points the PLCopen XML reader calls map positions back into the file through
// their breakpoints; expressions keep the operator the user wrote; CASE becomes its if chain;
// names are respelled as declared; PRIORITY orders a divergence.
#include "iec/lower.h"
#include "iec/st_fragment.h"
#include "iec/st_reader.h"

#include <catch2/catch.hpp>

#include <deque>
#include <string>

using namespace gfec;

namespace {

std::string text_of(const std::string &file, const SourceRange &r) { return file.substr(r.begin, r.end - r.begin); }

}  // namespace

TEST_CASE("iec st: fragment offsets map to file offsets through the breakpoints", "[iec]") {
  // The file holds `a &lt; b` at offset 10; the fragment is the unescaped `a < b`.
  iec::FragmentPlace place{3, {{0, 10}, {3, 16}}};
  CHECK(place.offset(0) == 10);
  CHECK(place.offset(2) == 12);  // `<`, the first byte of `&lt;`
  CHECK(place.offset(4) == 17);  // `b`
  SourceRange lt = place.range(2, 3);
  CHECK(lt.file == 3);
  CHECK(lt.begin == 12);
  CHECK(lt.end == 13);
  CHECK(iec::FragmentPlace::at(1, 40).range(1, 4).begin == 41);
}

TEST_CASE("iec st: an expression fragment keeps the user's operators and points into the file", "[iec]") {
  const std::string file = "<inline><ST>Level &gt;= 3 AND NOT Fill.X</ST></inline>";
  const std::string fragment = "Level >= 3 AND NOT Fill.X";
  // `&gt;` (4 bytes) became `>` (1): the byte after it is 3 further on in the file.
  iec::FragmentPlace place{0, {{0, 12}, {7, 22}}};
  std::deque<std::string> strings;
  Diagnostics diag;
  ast::ExprPtr e = iec::parse_st_expression(fragment, place, strings, diag);
  REQUIRE(e);
  CHECK_FALSE(diag.has_errors());
  REQUIRE(e->kind == ast::Expr::Kind::Binary);
  CHECK(e->binary_op == BinaryOp::And);
  CHECK(text_of(file, e->op_range()) == "AND");
  const ast::Expr &ge = *e->args[0];
  CHECK(ge.binary_op == BinaryOp::Ge);
  CHECK(text_of(file, ge.op_range()) == "&gt;=");
  CHECK(text_of(file, ge.range) == "Level &gt;= 3");
  const ast::Expr &active = *e->args[1]->args[0];
  CHECK(active.kind == ast::Expr::Kind::Call);
  CHECK(active.name.text == "active");
  CHECK(active.args[0]->name.text == "Fill");
  CHECK(text_of(file, active.range) == "Fill.X");

  Diagnostics bad;
  CHECK_FALSE(iec::parse_st_expression("a == b", iec::FragmentPlace::at(0, 5), strings, bad));
  REQUIRE(bad.error_count() == 1);
  CHECK(bad.all().front().range.begin == 7);
  CHECK(bad.all().front().message.find("'='") != std::string::npos);
}

TEST_CASE("iec st: a statement fragment: CASE is its if chain, literals are made decimal", "[iec]") {
  std::deque<std::string> strings;
  Diagnostics diag;
  auto b = iec::parse_st_statements("CASE n OF 1: x := 16#1F; 2..3: x := 1_000; ELSE x := 0; END_CASE;",
                                    iec::FragmentPlace::at(0, 0), strings, diag);
  REQUIRE(b);
  CHECK_FALSE(diag.has_errors());
  REQUIRE(b->size() == 1);
  const ast::Stmt &s = b->front();
  REQUIRE(s.kind == ast::Stmt::Kind::If);
  CHECK(s.value->binary_op == BinaryOp::Eq);
  CHECK(s.then_block[0].value->text() == "31");
  REQUIRE(s.else_block.size() == 1);
  CHECK(s.else_if);
  const ast::Stmt &range = s.else_block[0];
  CHECK(range.value->kind == ast::Expr::Kind::Paren);
  CHECK(range.then_block[0].value->text() == "1000");
  CHECK(range.has_else);
  CHECK_FALSE(range.else_if);

  Diagnostics loop;
  CHECK_FALSE(
      iec::parse_st_statements("FOR i := 1 TO 3 DO CONTINUE; END_FOR;", iec::FragmentPlace::at(0, 0), strings, loop));
  REQUIRE(loop.error_count() == 1);
  CHECK(loop.all().front().check() == "not-supported");
}

TEST_CASE("iec st: a program lowers into an sfc with respelled names, ordered transitions and its period", "[iec]") {
  const std::string text = "PROGRAM Lamp\n"
                           "  VAR_INPUT Go : BOOL; END_VAR\n"
                           "  VAR_OUTPUT On : BOOL; END_VAR\n"
                           "  INITIAL_STEP Off: END_STEP\n"
                           "  STEP Lit: light(n); END_STEP\n"
                           "  STEP Blink: END_STEP\n"
                           "  TRANSITION FROM off TO lit := GO; END_TRANSITION\n"
                           "  TRANSITION (PRIORITY := 1) FROM Off TO Blink := NOT go; END_TRANSITION\n"
                           "  ACTION Light: on := TRUE; END_ACTION\n"
                           "END_PROGRAM\n"
                           "CONFIGURATION C TASK T (INTERVAL := T#20ms); PROGRAM I WITH T : lamp; END_CONFIGURATION\n";
  ast::File file;
  iec::Project project;
  Diagnostics diag;
  iec::read_st(text, 0, file.strings, diag, project);
  REQUIRE(project.pous.size() == 1);
  REQUIRE(project.tasks.size() == 1);
  CHECK(iec::lower(std::move(project), file, diag) == 1);
  CHECK_FALSE(diag.has_errors());
  REQUIRE(file.charts.size() == 1);
  const ast::Chart &c = file.charts[0];
  REQUIRE(c.periods.size() == 1);
  CHECK(c.periods[0].ms == 20);
  REQUIRE(c.transitions.size() == 2);
  CHECK(c.transitions[0].outputs()[0].text == "Blink");  // PRIORITY 1 before the one without
  CHECK(c.transitions[1].inputs()[0].text == "Off");     // `off` respelled as declared
  CHECK(c.transitions[1].outputs()[0].text == "Lit");
  CHECK(c.transitions[1].condition->name.text == "Go");
  REQUIRE(c.places[1].extras);
  CHECK(c.places[1].extras->associations[0].action.text == "Light");
  CHECK(c.places[1].extras->associations[0].qualifier.text == "N");
  CHECK(c.actions[0].body[0].target->text == "On");
}
