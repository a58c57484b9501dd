// The validator's output: the model back ends read (docs/language.md §3-8, compiler/model.h).
#include "validate_fixture.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec;
using test::Validated;

namespace {

model::FunctionId function_id(const model::Model &m, const std::string &name) {
  for (model::FunctionId f : m.functions.ids())
    if (m.functions[f].name == name) return f;
  return {};
}

const model::Const &constant(const model::Model &m, const std::string &name) {
  for (const auto &c : m.consts)
    if (c.name == name) return c;
  FAIL("no constant " << name);
  return m.consts.front();
}

}  // namespace

TEST_CASE("validate model: functions in file order, a chart's functions by index", "[validate]") {
  Validated r({{"main.sfc", "import \"b.iface\";\nimport \"c.iface\";\n"
                            "interface Main { void Beep(); }\n"
                            "sfc S { initial place A { Right(); Beep(); } transition A -> A when Sense(); }\n"},
               {"b.iface", "interface B { bool Sense(); void Left(); }\n"},
               {"c.iface", "interface C { void Right(); }\n"}});
  REQUIRE(r.text() == "");
  const auto &m = r.model;
  REQUIRE(m.functions.size() == 4);
  CHECK(m.functions[0].name == "Beep");
  CHECK(m.functions[0].interface_name == "Main");
  CHECK(m.functions[1].name == "Sense");
  CHECK(m.functions[1].result == model::Type::Bool);
  CHECK(m.functions[2].name == "Left");
  CHECK(m.functions[3].name == "Right");
  CHECK(m.charts[0].functions == test::ids<model::FunctionId>({0, 1, 3}));
  CHECK(m.main_file == r.fe.loaded.program.files[0]->id);
  CHECK(&m.sources() == &r.fe.sources);
}

TEST_CASE("validate model: prototypes, including C's (void)", "[validate]") {
  Validated r({{"t.iface", "interface Bot { void Motor(int side, float); double Read(void); }\n"}});
  REQUIRE(r.text() == "");
  const auto &f = r.model.functions;
  REQUIRE(f.size() == 2);
  REQUIRE(f[0].params.size() == 2);
  CHECK(f[0].params[0].type == model::Type::Int);
  CHECK(f[0].params[0].name == "side");
  CHECK(f[0].params[1].type == model::Type::Float);
  CHECK(f[0].params[1].name == "");
  CHECK(f[1].params.empty());
  CHECK(f[1].result == model::Type::Double);
}

TEST_CASE("validate model: constants are folded to literals of their type", "[validate]") {
  Validated r({{"t.sfc", "const int N = 3;\n"
                         "const float HALF = N / 2.0;\n"
                         "const float ONE = 1;\n"
                         "const double CRUISE = 0.6;\n"
                         "const int Q = 7 / 2;\n"
                         "const int R = -7 % 3;\n"
                         "const int NEG = -N;\n"
                         "const int T = 2.9;\n"
                         "const bool B = !false && N > 2;\n"
                         "const string NAME = \"bot\";\n"
                         "const int LATER = EARLIER + 1;\n"
                         "const int EARLIER = 41;\n"}});
  REQUIRE(r.text() == "");
  const auto &m = r.model;
  auto check = [&](const char *name, model::Expr::Kind kind, model::Type type, const char *text) {
    INFO(name);
    const auto &c = constant(m, name);
    CHECK_FALSE(c.chart);
    CHECK(c.type == type);
    CHECK(c.value.kind == kind);
    CHECK(c.value.type == type);
    CHECK(c.value.text == text);
  };
  check("N", model::Expr::Kind::Int, model::Type::Int, "3");
  check("HALF", model::Expr::Kind::Float, model::Type::Float, "1.5");
  check("ONE", model::Expr::Kind::Float, model::Type::Float, "1.0");
  check("CRUISE", model::Expr::Kind::Float, model::Type::Double, "0.6");
  check("Q", model::Expr::Kind::Int, model::Type::Int, "3");
  check("R", model::Expr::Kind::Int, model::Type::Int, "-1");
  check("NEG", model::Expr::Kind::Int, model::Type::Int, "-3");
  check("T", model::Expr::Kind::Int, model::Type::Int, "2");
  check("NAME", model::Expr::Kind::String, model::Type::String, "bot");
  check("LATER", model::Expr::Kind::Int, model::Type::Int, "42");
  CHECK(constant(m, "B").value.kind == model::Expr::Kind::Bool);
  CHECK(constant(m, "B").value.bool_value);
}

TEST_CASE("validate model: a chart's constants, vars and what it reads", "[validate]") {
  Validated r({{"t.sfc", "const int UNUSED = 1;\n"
                         "const int LIMIT = 3;\n"
                         "sfc S {\n"
                         "  const float CRUISE = 0.5;\n"
                         "  var int laps = LIMIT - 1;\n"
                         "  var bool done;\n"
                         "  initial place A { laps += 1; done = laps >= LIMIT; }\n"
                         "  transition A -> A when done && CRUISE > 0;\n"
                         "}\n"}});
  REQUIRE(r.text() == "");
  const auto &m = r.model;
  REQUIRE(m.consts.size() == 3);
  CHECK(m.consts[2].name == "CRUISE");
  CHECK(m.consts[2].chart == model::ChartId(0));
  const auto &c = m.charts[0];
  CHECK(c.consts == test::ids<model::ConstId>({1, 2}));
  REQUIRE(c.vars.size() == 2);
  CHECK(c.vars[0].name == "laps");
  REQUIRE(c.vars[0].init);
  CHECK(c.vars[0].init->kind == model::Expr::Kind::Binary);  // computed by _init, as written
  CHECK(c.vars[0].init->args[0].kind == model::Expr::Kind::Const);
  CHECK(c.vars[0].init->args[0].constant() == model::ConstId(1));
  CHECK_FALSE(c.vars[1].init);
  CHECK(c.vars[1].type == model::Type::Bool);
  REQUIRE(c.places[0].action.size() == 2);
  const auto &add = c.places[0].action[0];
  CHECK(add.kind == model::Stmt::Kind::Assign);
  CHECK(add.var == model::VarId(0));
  CHECK(add.op == AssignOp::Add);
  CHECK(add.expr.kind == model::Expr::Kind::Int);
  const auto &set = c.places[0].action[1];
  CHECK(set.var == model::VarId(1));
  CHECK(set.expr.kind == model::Expr::Kind::Binary);
  CHECK(set.expr.args[0].kind == model::Expr::Kind::Var);
  CHECK(set.expr.args[0].var() == model::VarId(0));
}

TEST_CASE("validate model: durations become whole ticks, rounded up", "[validate]") {
  Validated r({{"t.sfc", "sfc S {\n"
                         "  period 10ms;\n"
                         "  initial place A;\n"
                         "  place B;\n"
                         "  place C;\n"
                         "  transition A -> B when elapsed(A) >= 25ms;\n"
                         "  transition B -> C when elapsed(B) >= 0.1s;\n"
                         "  transition C -> A when elapsed(A) < 1.5s || 0ms == elapsed(C);\n"
                         "}\n"
                         "sfc R {\n"
                         "  period 30ms;\n"
                         "  initial place A;\n"
                         "  transition A -> A when elapsed(A) > 100ms;\n"
                         "}\n"}});
  // Only R's `>` can mean other than it says (-Wtimer-rounding); 25ms >= and 1.5s < are exact.
  REQUIRE(r.text() ==
          "t.sfc:13:39: warning: 100ms is not a whole number of periods (30ms): timers count whole ticks, so "
          "'elapsed(A) > 100ms' means 'elapsed(A) > 120ms' [-Wtimer-rounding]\n"
          "   transition A -> A when elapsed(A) > 100ms;\n"
          "                                       ^~~~~\n");
  const auto &c = r.model.charts[0];
  CHECK(c.period_ms == 10);
  auto ticks = [](const model::Transition &t, int side) { return t.condition->args[side]; };
  const model::Expr e25 = ticks(c.transitions[0], 1);
  CHECK(e25.kind == model::Expr::Kind::Ticks);
  CHECK(e25.type == model::Type::Duration);
  CHECK(e25.ticks == 3);
  CHECK(e25.float_value == 25);
  CHECK(ticks(c.transitions[1], 1).ticks == 10);  // 0.1s is 100.00000000000001 ms: still 10 ticks
  const auto &either = *c.transitions[2].condition;
  CHECK(either.args[0].args[1].ticks == 150);
  CHECK(either.args[1].args[0].ticks == 0);
  const model::Expr elapsed = ticks(c.transitions[0], 0);
  // A positive duration below the period is one tick, never 0 ("at once").
  Validated tiny(
      {{"t.sfc", "sfc S {\n  period 10ms;\n  initial place A;\n  place B;\n"
                 "  transition A -> B when elapsed(A) >= 1e-9ms;\n  transition B -> A when elapsed(B) >= 0ms;\n}\n"}});
  REQUIRE(tiny.text() == "");
  CHECK(ticks(tiny.model.charts[0].transitions[0], 1).ticks == 1);
  CHECK(ticks(tiny.model.charts[0].transitions[1], 1).ticks == 0);
  CHECK(elapsed.kind == model::Expr::Kind::Elapsed);
  CHECK(elapsed.place() == model::PlaceId(0));
  CHECK(c.places[0].timed);
  CHECK(c.places[1].timed);
  CHECK(c.places[2].timed);
  CHECK(ticks(r.model.charts[1].transitions[0], 1).ticks == 4);
}

TEST_CASE("validate model: transitions are named T<position> unless named", "[validate]") {
  Validated r({{"t.sfc", "sfc S {\n"
                         "  initial place A;\n"
                         "  place B;\n"
                         "  place C;\n"
                         "  transition A -> (B, C);\n"
                         "  join: (B, C) -> A;\n"
                         "  transition A -> A;\n"
                         "}\n"}});
  REQUIRE(r.text() == "");
  const auto &t = r.model.charts[0].transitions;
  REQUIRE(t.size() == 3);
  CHECK(t[0].name == "T0");
  CHECK_FALSE(t[0].named);
  CHECK(t[0].outputs == test::ids<model::PlaceId>({1, 2}));
  CHECK_FALSE(t[0].condition);
  CHECK(t[1].name == "join");
  CHECK(t[1].named);
  CHECK(t[1].inputs == test::ids<model::PlaceId>({1, 2}));
  CHECK(t[2].name == "T2");
}

TEST_CASE("validate model: entry and exit blocks, verbatim code", "[validate]") {
  Validated r({{"main.sfc", "import \"lib.sfc\";\n%{ #include \"main.h\" %}\n"
                            "sfc S { initial place A { entry { Go(); } %{ x++; %} exit { Go(); } } }\n"},
               {"lib.sfc", "%{ #include \"lib.h\" %}\ninterface L { void Go(); }\nsfc Lib { initial place X; }\n"}});
  REQUIRE(r.text() == "");
  const auto &m = r.model;
  REQUIRE(m.verbatims.size() == 2);
  CHECK(m.verbatims[0].text.find("lib.h") != std::string::npos);
  CHECK(m.verbatims[1].text.find("main.h") != std::string::npos);
  REQUIRE(m.charts.size() == 2);
  CHECK(m.charts[0].in_main_file);
  CHECK_FALSE(m.charts[1].in_main_file);
  const auto &a = m.charts[0].places[0];
  REQUIRE(a.entry);
  REQUIRE(a.exit);
  CHECK(a.entry->size() == 1);
  REQUIRE(a.action.size() == 1);
  CHECK(a.action[0].kind == model::Stmt::Kind::Verbatim);
  CHECK(a.action[0].verbatim->find("x++;") != std::string::npos);
}

TEST_CASE("validate model: toolboxes and their templates", "[validate]") {
  Validated r({{"t.toolbox", "toolbox Box {\n"
                             "  actor Move(in float d, out int n) -> OK | BLOCKED;\n"
                             "  supervisor Watch(in object o) events HIT, MISS period 5ms;\n"
                             "}\n"}});
  REQUIRE(r.text() == "");
  const auto &m = r.model;
  REQUIRE(m.toolboxes.size() == 1);
  CHECK(m.toolboxes[0].templates == test::ids<model::TemplateId>({0, 1}));
  REQUIRE(m.templates.size() == 2);
  const auto &move = m.templates[0];
  CHECK(move.kind == model::Template::Kind::Actor);
  CHECK(move.toolbox == model::ToolboxId(0));
  REQUIRE(move.params.size() == 2);
  CHECK(move.params[1].dir == model::ParamDir::Out);
  CHECK(move.params[1].type == model::Type::Int);
  CHECK(move.outcomes == std::vector<std::string>{"OK", "BLOCKED"});
  const auto &watch = m.templates[1];
  CHECK(watch.kind == model::Template::Kind::Supervisor);
  CHECK(watch.params[0].type == model::Type::Object);
  CHECK(watch.outcomes == std::vector<std::string>{"HIT", "MISS"});
  CHECK(watch.period_ms == 5);
}

TEST_CASE("validate model: plans, rules by outcome, sub-plans, constants in formulas", "[validate]") {
  Validated r({{"main.plan", "import \"box.toolbox\";\n"
                             "const float K = 2;\n"
                             "plan Main {\n"
                             "  config { float d = K * 10; string label = 7; int n; }\n"
                             "  supervise stop: Watch() { MISS -> ignore; HIT -> terminate; }\n"
                             "  start nav;\n"
                             "  actor nav: Sub() { ERROR -> terminate; OK -> move; INTERRUPTED -> nav; }\n"
                             "  actor move: Move(d * K, n) { BLOCKED -> nav; OK -> terminate; }\n"
                             "}\n"
                             "plan Sub { start m; actor m: Move(1, n) { OK -> terminate; BLOCKED -> terminate; }"
                             "  config { int n; } }\n"},
               {"box.toolbox", "toolbox Box {\n"
                               "  actor Move(in float d, out int n) -> OK | BLOCKED;\n"
                               "  supervisor Watch() events HIT | MISS;\n"
                               "}\n"}});
  REQUIRE(r.text() == "");
  const auto &m = r.model;
  REQUIRE(m.plans.size() == 2);
  const auto &p = m.plans[0];
  CHECK(p.in_main_file);
  CHECK(p.toolboxes == test::ids<model::ToolboxId>({0}));
  REQUIRE(p.config.size() == 3);
  CHECK(p.config[0].init->text == "20.0");
  CHECK(p.config[1].init->kind == model::Expr::Kind::String);
  CHECK(p.config[1].init->text == "7");
  CHECK_FALSE(p.config[2].init);
  REQUIRE(p.globals.size() == 1);
  CHECK(p.globals[0].templ == model::TemplateId(1));
  REQUIRE(p.globals[0].rules.size() == 2);
  CHECK(p.globals[0].rules[0].outcome == 0);
  CHECK(p.globals[0].rules[0].target.kind == model::RuleTarget::Kind::Terminate);
  CHECK(p.globals[0].rules[1].target.kind == model::RuleTarget::Kind::Ignore);
  CHECK(p.start == model::ActorId(0));
  const auto &nav = p.actors[0];
  CHECK_FALSE(nav.templ);
  CHECK(nav.subplan == model::PlanId(1));
  REQUIRE(nav.rules.size() == 3);
  CHECK(nav.rules[0].outcome == 0);  // OK
  CHECK(nav.rules[0].target.actor == model::ActorId(1));
  CHECK(nav.rules[1].target.actor == model::ActorId(0));  // INTERRUPTED
  CHECK(nav.rules[2].target.kind == model::RuleTarget::Kind::Terminate);
  const auto &move = p.actors[1];
  CHECK(move.templ == model::TemplateId(0));
  REQUIRE(move.args.size() == 2);
  CHECK(move.args[0].dir == model::ParamDir::In);
  const auto &formula = move.args[0].formula;
  CHECK(formula.kind == model::Expr::Kind::Binary);
  CHECK(formula.args[0].kind == model::Expr::Kind::Config);
  CHECK(formula.args[0].config() == model::ConfigId(0));
  CHECK(formula.args[1].kind == model::Expr::Kind::Float);  // K, replaced by its value
  CHECK(formula.args[1].text == "2.0");
  CHECK(move.args[1].dir == model::ParamDir::Out);
  CHECK(move.args[1].formula.kind == model::Expr::Kind::Config);
  CHECK(move.args[1].formula.config() == model::ConfigId(2));
  CHECK(move.rules[0].outcome == 0);
  CHECK(move.rules[1].outcome == 1);
  CHECK_FALSE(function_id(m, "none"));
}

TEST_CASE("validate model: named actions in declaration order, each with its associations", "[validate][iec]") {
  // docs/language.md §14: the actions table the back ends' action control reads; L marks the
  // place timed (its timer feeds the control), and B, holding L, is timed while A is not.
  Validated r({{"m.sfc", R"--(sfc Press {
  period 100ms;
  out int Count;
  action Tally { Count += 1; }
  action Idle { }
  initial place A { P Tally; N Tally; }
  place B { L Tally 250ms; R Tally; }
  A -> B when true;
}
)--"}});
  const model::Chart &c = r.model.charts.front();
  REQUIRE(c.actions.size() == 2);
  const model::Action &tally = c.actions[model::ActionId(0)];
  CHECK(tally.name == "Tally");
  CHECK(tally.body.size() == 1);
  REQUIRE(tally.associations.size() == 4);
  CHECK(tally.associations[0].place == model::PlaceId(0));
  CHECK(tally.associations[0].qualifier == model::Qualifier::P);
  CHECK(tally.associations[1].qualifier == model::Qualifier::N);
  CHECK(tally.associations[2].place == model::PlaceId(1));
  CHECK(tally.associations[2].qualifier == model::Qualifier::L);
  CHECK(tally.associations[2].duration_ms == 250);
  CHECK(tally.associations[2].ticks == 3);  // 250ms at 100ms: rounded up (§5.3)
  CHECK(tally.associations[3].qualifier == model::Qualifier::R);
  CHECK(c.actions[model::ActionId(1)].associations.empty());
  CHECK(!c.places[model::PlaceId(0)].timed);
  CHECK(c.places[model::PlaceId(1)].timed);
  CHECK(r.text().find("error") == std::string::npos);
}
