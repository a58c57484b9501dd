// Scenario tests (docs/testing-charts.md): the `test` block's syntax, its checks with their
// located messages, and a test run on the reference interpreter evaluated step by step.
#include "scenario/reference_run.h"
#include "scenario/scenario.h"
#include "scenario/snapshot.h"
#include "support.h"
#include "validate.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec;

namespace {

const char *const kChart = R"--(interface Bot {
  bool Black();
  int Count();
  float Level();
  void Go();
  void Motor(int side, float speed);
  int Sense(int k);
}
interface Other { bool Door(); }
sfc Line {
  period 10ms;
  var int laps = 0;
  initial place A { Go(); }
  place B { Motor(1, 0.5); laps += 1; }
  A -> B when Black();
  B -> A when Count() > 2;
}
fsm Machine {
  initial state S0 { Go(); }
  success state Done;
  S0 -> Done when Black();
}
plan P { start a; actor a: Nothing() { X -> terminate; } }
sfc Press {
  in bool Start;
  in int8 Force = 5;
  out int Seen = 0;
  var int n = 0;
  initial place Up { Seen = Force; }
  place Down { Seen = Force; }
  Up -> Down when Start;
}
)--";

struct Checked {
  scenario::Suite suite;
  test::Pipeline fe;
  model::Model &model = fe.model;

  explicit Checked(const std::string &tests)
      : fe("t.test", test::files({{"t.test", "import \"bot.sfc\";\n" + tests}, {"bot.sfc", kChart}}), {}, &suite) {}
  std::string text() const { return fe.text(); }
  /// The diagnostics about the test file only (the plan in bot.sfc has its own errors).
  std::string test_errors() const {
    std::string out;
    for (const auto &d : fe.diag.all())
      if (fe.sources.file(d.range.file).path() == "t.test") out += render_text(d, fe.sources);
    return out;
  }
};

}  // namespace

TEST_CASE("a test block parses into its steps", "[scenario]") {
  // `tick 010` is ten ticks: integer literals are decimal (docs/language.md §1), never octal.
  test::FrontEnd fe({{"t.test", "test \"x\" of Line { tick; tick 3; set Black = true; expect called Go(1) && calls Go "
                                "== 2 && status == 0 && state(S); tick 010; }\n"}});
  REQUIRE(fe.text() == "");
  const auto &t = fe.loaded.program.files.front()->tests.at(0);
  CHECK(t.name == "x");
  CHECK(t.chart.text == "Line");
  REQUIRE(t.steps.size() == 5);
  CHECK(t.steps[0].count == 1);
  CHECK(t.steps[1].count == 3);
  CHECK(t.steps[2].kind == ast::TestStep::Kind::Set);
  CHECK(t.steps[2].function.text == "Black");
  CHECK(t.steps[3].kind == ast::TestStep::Kind::Expect);
  CHECK(t.steps[4].count == 10);
}

TEST_CASE("tick, set, expect, called, calls and status are keywords only inside a test", "[scenario]") {
  // Elsewhere they stay names: an interface may declare a function `tick`, a chart a var `status`.
  test::FrontEnd fe(
      {{"t.sfc", "interface I { void tick(); bool expect(); }\n"
                 "sfc C { var int status = 0; var int calls = 1; initial place A { tick(); status = calls; }\n"
                 "  A -> A when expect(); }\n"}});
  CHECK(fe.text() == "");
}

TEST_CASE("test blocks report syntax errors where they are", "[scenario]") {
  CHECK(test::parse_errors("test \"x\" Line { tick; }\n") ==
        "t.sfc:1:10: error: expected 'of' and the chart after the test's name, found 'Line' [syntax]\n"
        " test \"x\" Line { tick; }\n"
        "          ^~~~\n");
  CHECK(test::parse_errors("test \"x\" of Line { wait; }\n") ==
        "t.sfc:1:20: error: expected a test step ('tick', 'set' or 'expect'), found 'wait' [syntax]\n"
        " test \"x\" of Line { wait; }\n"
        "                    ^~~~\n");
  CHECK(test::parse_errors("test \"x\" of Line { tick x; }\n") ==
        "t.sfc:1:25: error: expected a number of ticks, a duration or ';' after 'tick', found 'x' [syntax]\n"
        " test \"x\" of Line { tick x; }\n"
        "                         ^\n");
}

TEST_CASE("a valid test is lowered to its checked form", "[scenario]") {
  Checked c("test \"t\" of Line { set Black = true; set Count = 2.9; set Level = 1; tick 2;\n"
            "  expect active(B) && laps == 1 && called Motor(1, 0.5) && calls Go == 0 && elapsed(B) >= 10ms; }\n");
  CHECK(c.test_errors() == "");
  REQUIRE(c.suite.tests.size() == 1);
  const auto &t = c.suite.tests[0];
  REQUIRE(t.steps.size() == 5);
  CHECK(t.steps[0].value == "true");
  CHECK(t.steps[1].value == "2");  // converted as C converts: 2.9 to int is 2
  CHECK(t.steps[2].value == "1");
  CHECK(t.steps[3].count == 2);
  const auto &e = t.steps[4].expect;
  CHECK(e.type == model::Type::Bool);
  // elapsed(B) in a test keeps B's timer in the engine, so that both engines can report it
  CHECK(c.model.charts[t.chart].places[1].timed);
}

TEST_CASE("set converts its constant to the function's type as C converts, bool included", "[scenario]") {
  Checked c("test \"t\" of Line { set Black = 2; set Black = 0.0; set Count = true; set Level = false; }\n");
  CHECK(c.test_errors() == "");
  REQUIRE(c.suite.tests.size() == 1);
  const auto &t = c.suite.tests[0];
  REQUIRE(t.steps.size() == 4);
  CHECK(t.steps[0].value == "true");  // any non-zero number is true
  CHECK(t.steps[1].value == "false");
  CHECK(t.steps[2].value == "1");
  CHECK(t.steps[3].value == "0");
  // Arguments of `called F(ARGS)` follow the chart's rule: bool and numbers do not mix.
  CHECK(Checked("test \"t\" of Line { tick; expect called Motor(true, 0.5); }\n")
            .test_errors()
            .rfind("t.test:2:46: error: argument 1 of 'Motor' must be 'int', not 'bool' [type-mismatch]\n", 0) == 0);
}

TEST_CASE("an unknown chart is reported with a did-you-mean", "[scenario]") {
  CHECK(Checked("test \"t\" of Lien { tick; }\n").test_errors() ==
        "t.test:2:13: error: unknown chart 'Lien' [unknown-name]\n"
        " test \"t\" of Lien { tick; }\n"
        "             ^~~~\n"
        "bot.sfc:10:5: note: did you mean 'Line'?\n"
        " sfc Line {\n"
        "     ^~~~\n");
  CHECK(Checked("test \"t\" of P { tick; }\n")
            .test_errors()
            .rfind("t.test:2:13: error: 'P' is a plan; tests run an sfc or fsm [test]\n", 0) == 0);
}

TEST_CASE("unknown functions and places in a test are reported with a did-you-mean", "[scenario]") {
  CHECK(Checked("test \"t\" of Line { set Blak = true; }\n").test_errors() ==
        "t.test:2:24: error: unknown function 'Blak' [unknown-name]\n"
        " test \"t\" of Line { set Blak = true; }\n"
        "                        ^~~~\n"
        "bot.sfc:2:8: note: did you mean 'Black'?\n"
        "   bool Black();\n"
        "        ^~~~~\n");
  CHECK(Checked("test \"t\" of Machine { expect state(Dnoe); }\n").test_errors() ==
        "t.test:2:36: error: unknown state 'Dnoe' [unknown-name]\n"
        " test \"t\" of Machine { expect state(Dnoe); }\n"
        "                                    ^~~~\n"
        "bot.sfc:20:17: note: did you mean 'Done'?\n"
        "   success state Done;\n"
        "                 ^~~~\n");
  CHECK(Checked("test \"t\" of Line { expect called Goo; }\n").test_errors() ==
        "t.test:2:34: error: unknown function 'Goo' [unknown-name]\n"
        " test \"t\" of Line { expect called Goo; }\n"
        "                                  ^~~\n"
        "bot.sfc:5:8: note: did you mean 'Go'?\n"
        "   void Go();\n"
        "        ^~\n");
}

TEST_CASE("set needs a parameterless sensing function of the chart's interface", "[scenario]") {
  CHECK(Checked("test \"t\" of Line { set Go = true; }\n").test_errors() ==
        "t.test:2:24: error: 'set' needs a sensing function without parameters; 'Go' returns void [test]\n"
        " test \"t\" of Line { set Go = true; }\n"
        "                        ^~\n"
        "bot.sfc:5:3: note: 'Go' declared here\n"
        "   void Go();\n"
        "   ^~~~~~~~~~\n");
  CHECK(Checked("test \"t\" of Line { set Sense = 1; }\n")
            .test_errors()
            .rfind("t.test:2:24: error: 'set' needs a sensing function without parameters; 'Sense' takes parameters "
                   "[test]\n",
                   0) == 0);
  CHECK(Checked("test \"t\" of Line { set Door = true; }\n")
            .test_errors()
            .rfind("t.test:2:24: error: 'Door' belongs to interface 'Other', which chart 'Line' and its sub-charts do "
                   "not use [test]\n",
                   0) == 0);
  CHECK(Checked("test \"t\" of Line { set Black = 10ms; }\n").test_errors() ==
        "t.test:2:32: error: the value of 'Black' must be 'bool', not 'duration' [type-mismatch]\n"
        " test \"t\" of Line { set Black = 10ms; }\n"
        "                                ^~~~\n");
  CHECK(Checked("test \"t\" of Line { set Count = laps; }\n").test_errors() ==
        "t.test:2:32: error: a constant expression cannot read variable 'laps' [not-constant]\n"
        " test \"t\" of Line { set Count = laps; }\n"
        "                                ^~~~\n");
}

TEST_CASE("set of a chart's input is lowered to the input and its converted constant", "[scenario]") {
  Checked c("test \"t\" of Press { set Start = true; set Force = -128; set Force = 2 * 3; tick; expect Start; }\n");
  CHECK(c.test_errors() == "");
  REQUIRE(c.suite.tests.size() == 1);
  const auto &t = c.suite.tests[0];
  REQUIRE(t.steps.size() == 5);
  const model::Chart &press = c.model.charts[t.chart];
  REQUIRE(t.steps[0].input);
  CHECK(press.vars[t.steps[0].input].name == "Start");
  CHECK(!t.steps[0].function);
  CHECK(t.steps[0].value == "true");
  REQUIRE(t.steps[1].input);
  CHECK(press.vars[t.steps[1].input].name == "Force");
  CHECK(t.steps[1].value == "-128");
  CHECK(t.steps[2].value == "6");
}

TEST_CASE("set names an input or a sensing function, and an input's value fits its type", "[scenario]") {
  // An unknown name: the did-you-mean offers the chart's inputs beside the functions.
  CHECK(Checked("test \"t\" of Press { set Strat = true; }\n").test_errors() ==
        "t.test:2:25: error: unknown input or function 'Strat' [unknown-name]\n"
        " test \"t\" of Press { set Strat = true; }\n"
        "                         ^~~~~\n"
        "bot.sfc:25:11: note: did you mean 'Start'?\n"
        "   in bool Start;\n"
        "           ^~~~~\n");
  CHECK(Checked("test \"t\" of Press { set Blak = true; }\n")
            .test_errors()
            .rfind("t.test:2:25: error: unknown input or function 'Blak' [unknown-name]\n"
                   " test \"t\" of Press { set Blak = true; }\n"
                   "                         ^~~~\n"
                   "bot.sfc:2:8: note: did you mean 'Black'?\n",
                   0) == 0);
  // An output, a variable or a place cannot be set.
  CHECK(Checked("test \"t\" of Press { set Seen = 1; }\n").test_errors() ==
        "t.test:2:25: error: 'Seen' is an output ('out') of 'Press': 'set' sets only the chart's inputs ('in', "
        "'inout') and "
        "sensing functions [test]\n"
        " test \"t\" of Press { set Seen = 1; }\n"
        "                         ^~~~\n"
        "bot.sfc:27:11: note: 'Seen' declared here\n"
        "   out int Seen = 0;\n"
        "           ^~~~\n");
  CHECK(Checked("test \"t\" of Press { set n = 1; }\n")
            .test_errors()
            .rfind("t.test:2:25: error: 'n' is a variable ('var') of 'Press': 'set' sets only the chart's inputs "
                   "('in', 'inout') and sensing functions [test]\n",
                   0) == 0);
  CHECK(
      Checked("test \"t\" of Press { set Up = true; }\n")
          .test_errors()
          .rfind(
              "t.test:2:25: error: 'Up' is a place of 'Press': 'set' sets only the chart's inputs ('in', 'inout') and "
              "sensing functions [test]\n",
              0) == 0);
  // A value out of a sized input's range is an error at the constant, as for an initialiser.
  CHECK(Checked("test \"t\" of Press { set Force = 128; }\n").test_errors() ==
        "t.test:2:33: error: value 128 does not fit in 'int8' [not-constant]\n"
        " test \"t\" of Press { set Force = 128; }\n"
        "                                 ^~~\n");
  CHECK(Checked("test \"t\" of Press { set Force = -129; }\n")
            .test_errors()
            .rfind("t.test:2:33: error: value -129 does not fit in 'int8' [not-constant]\n", 0) == 0);
  // The chart's types: a bool input takes true or false, a sized integer no fraction.
  CHECK(Checked("test \"t\" of Press { set Start = 1; }\n").test_errors() ==
        "t.test:2:33: error: the value of 'Start' must be 'bool', not 'int' [type-mismatch]\n"
        " test \"t\" of Press { set Start = 1; }\n"
        "                                 ^\n");
  CHECK(Checked("test \"t\" of Press { set Force = 2.5; }\n")
            .test_errors()
            .rfind("t.test:2:33: error: the value of 'Force' must be 'int8', not 'double' [type-mismatch]\n", 0) == 0);
  CHECK(Checked("test \"t\" of Press { set Force = n; }\n")
            .test_errors()
            .rfind("t.test:2:33: error: a constant expression cannot read variable 'n' [not-constant]\n", 0) == 0);
}

TEST_CASE("called F(ARGS) is checked against F's prototype with constant arguments", "[scenario]") {
  CHECK(Checked("test \"t\" of Line { expect called Motor(1); }\n")
            .test_errors()
            .rfind("t.test:2:34: error: too few arguments to function 'Motor' (expected 2, have 1) [argument-count]\n",
                   0) == 0);
  CHECK(Checked("test \"t\" of Line { expect called Motor(1, true); }\n")
            .test_errors()
            .rfind("t.test:2:43: error: argument 2 of 'Motor' must be 'float', not 'bool' [type-mismatch]\n", 0) == 0);
  CHECK(Checked("test \"t\" of Line { expect called Motor(laps, 1); }\n")
            .test_errors()
            .rfind("t.test:2:40: error: a constant expression cannot read variable 'laps' [not-constant]\n", 0) == 0);
}

TEST_CASE("tick N needs N >= 1, an expectation must be bool and calls no code", "[scenario]") {
  CHECK(Checked("test \"t\" of Line { tick 0; }\n").test_errors() ==
        "t.test:2:25: error: 'tick 0' runs no tick: the count must be at least 1 [test]\n"
        " test \"t\" of Line { tick 0; }\n"
        "                         ^\n");
  CHECK(Checked("test \"t\" of Line { tick 1000001; }\n").test_errors() ==
        "t.test:2:25: error: 'tick N' runs at most 1000000 ticks at a time [test]\n"
        " test \"t\" of Line { tick 1000001; }\n"
        "                         ^~~~~~~\n");
  // Beyond any integer: the lexer's error, once.
  CHECK(Checked("test \"t\" of Line { tick 99999999999999999999999; }\n")
            .test_errors()
            .rfind("t.test:2:25: error: integer literal is too large [syntax]\n", 0) == 0);
  CHECK(Checked("test \"t\" of Line { expect calls Go; }\n").test_errors() ==
        "t.test:2:27: error: an expectation must be bool, not 'int' [type-mismatch]\n"
        " test \"t\" of Line { expect calls Go; }\n"
        "                           ^~~~~~~~\n");
  CHECK(
      Checked("test \"t\" of Line { expect Black(); }\n").test_errors() ==
      "t.test:2:27: error: an expectation calls no chart code: 'Black' cannot be called here [test]\n"
      " test \"t\" of Line { expect Black(); }\n"
      "                           ^~~~~~~\n"
      "t.test:2:27: note: 'called Black' says whether the chart called it in the last tick, 'calls Black' how often\n");
  CHECK(Checked("test \"t\" of Line { expect calls Go == true; }\n")
            .test_errors()
            .rfind("t.test:2:27: error: invalid operands to binary '==' (have 'int' and 'bool') [type-mismatch]\n",
                   0) == 0);
}

TEST_CASE("state(S) and status need an fsm", "[scenario]") {
  CHECK(Checked("test \"t\" of Line { expect state(A); }\n").test_errors() ==
        "t.test:2:27: error: 'state()' needs an fsm, but 'Line' is an sfc [test]\n"
        " test \"t\" of Line { expect state(A); }\n"
        "                           ^~~~~~~~\n");
  CHECK(Checked("test \"t\" of Line { expect status == 0; }\n").test_errors() ==
        "t.test:2:27: error: 'status' needs an fsm, but 'Line' is an sfc [test]\n"
        " test \"t\" of Line { expect status == 0; }\n"
        "                           ^~~~~~\n");
  CHECK(Checked("test \"t\" of Machine { expect state(S1) && status == 1; }\n")
            .test_errors()
            .rfind("t.test:2:36: error: unknown state 'S1' [unknown-name]\n", 0) == 0);
  CHECK(Checked("test \"t\" of Machine { tick; expect state(S0) && status == 0; }\n").test_errors() == "");
}

TEST_CASE("a test runs on the reference interpreter and its expectations are evaluated", "[scenario]") {
  Checked c("test \"t\" of Line { tick; expect active(A) && called Go; set Black = true; tick;\n"
            "  expect active(B) && called Motor(1, 0.5) && !called Motor(0, 0.5) && calls Go == 1 && laps == 1;\n"
            "  expect active(A); }\n");
  REQUIRE(c.test_errors() == "");
  const scenario::Test &t = c.suite.tests.at(0);
  scenario::Run run = scenario::run_reference(c.model, t);
  REQUIRE(run.error == "");
  REQUIRE(run.recorded() == 3);
  // Tick 2: the transition fires (the sensing call), then B's action runs; B -> A was not open.
  CHECK(run.at(2)->at(0).calls.size() == 2);
  CHECK(run.at(2)->at(0).calls[0].text == "Black()");
  CHECK(run.at(2)->at(0).calls[1].text == "Motor(1, 0.5)");
  auto first = scenario::evaluate(t.steps[1].expect, run.at(1)->at(0), c.model, t.chart);
  CHECK(first.holds);
  auto second = scenario::evaluate(t.steps[4].expect, run.at(2)->at(0), c.model, t.chart);
  CHECK(!second.holds);  // calls Go == 1 fails: A's action no longer runs
  auto third = scenario::evaluate(t.steps[5].expect, run.at(2)->at(0), c.model, t.chart);
  CHECK(!third.holds);
  REQUIRE(third.operands.size() == 1);
  CHECK(third.operands[0].value == "false");
}

TEST_CASE("the reference run gives a set input its value before every later tick", "[scenario]") {
  Checked c("test \"t\" of Press { tick; set Force = -7; set Start = true; tick; }\n");
  REQUIRE(c.test_errors() == "");
  const scenario::Test &t = c.suite.tests.at(0);
  scenario::Run run = scenario::run_reference(c.model, t);
  REQUIRE(run.error == "");
  REQUIRE(run.recorded() == 3);
  const model::Chart &press = c.model.charts[t.chart];
  model::VarId start, force, seen;
  for (model::VarId v : press.vars.ids()) {
    if (press.vars[v].name == "Start") start = v;
    if (press.vars[v].name == "Force") force = v;
    if (press.vars[v].name == "Seen") seen = v;
  }
  // Tick 1: not set yet, the inputs keep their initial values.
  const scenario::Snapshot &first = run.at(1)->at(0);
  CHECK(!first.vars[start].b);
  CHECK(first.vars[force].i == 5);
  CHECK(first.vars[seen].i == 5);
  CHECK(first.activation[model::PlaceId(0)] == 1);
  // Tick 2: both set before it; Up -> Down fires and Down reads the new Force.
  const scenario::Snapshot &second = run.at(2)->at(0);
  CHECK(second.vars[start].b);
  CHECK(second.vars[force].i == -7);
  CHECK(second.vars[seen].i == -7);
  CHECK(second.activation[model::PlaceId(1)] == 1);
}

TEST_CASE("two runs that differ are told apart by their first differing call", "[scenario]") {
  Checked c("test \"t\" of Line { tick; }\n");
  REQUIRE(c.test_errors() == "");
  scenario::Run run = scenario::run_reference(c.model, c.suite.tests.at(0));
  scenario::Snapshot other = run.at(1)->at(0);
  const model::ChartId line(0);
  CHECK(scenario::compare(run.at(1)->at(0), other, c.model, line, "reference", "engine") == "");
  other.calls.push_back(other.calls.back());
  CHECK(scenario::compare(run.at(1)->at(0), other, c.model, line, "reference", "engine") ==
        "call 3: reference no call, engine 'Go()'");
  other = run.at(1)->at(0);
  other.activation[model::PlaceId(1)] = 1;
  CHECK(scenario::compare(run.at(1)->at(0), other, c.model, line, "reference", "engine") ==
        "activation of 'B': reference 0, engine 1");
}
