// The validator on the seed samples: no diagnostics, and the model the back ends will read.
#include "diagnostic_printer.h"
#include "support.h"

#include <catch2/catch.hpp>

#include <memory>
#include <string>

using namespace gfec;

namespace {

/// One sample from samples/ through the pipeline, every warning on.
struct Sample : test::Pipeline {
  explicit Sample(const std::string &name)
      : Pipeline(std::string(GFEC_SOURCE_DIR) + "/samples/" + name, RealFileSystem(), test::all_warnings()) {}
};

}  // namespace

TEST_CASE("validate: the line follower sample", "[validate]") {
  Sample s("line_follower.sfc");
  CHECK(s.text() == "");
  REQUIRE(s.model.charts.size() == 1);
  const auto &c = s.model.charts[0];
  CHECK(c.name == "LineFollower");
  CHECK(c.kind == model::Chart::Kind::Sfc);
  CHECK(c.in_main_file);
  CHECK(c.period_ms == 10);
  REQUIRE(c.places.size() == 4);
  CHECK(c.places[0].name == "LeftFw");
  CHECK(c.places[0].initial);
  CHECK_FALSE(c.places[1].initial);
  CHECK(c.places[2].initial);
  REQUIRE(c.transitions.size() == 4);
  CHECK(c.transitions[0].name == "T0");
  CHECK_FALSE(c.transitions[0].named);
  CHECK(c.transitions[3].name == "T3");
  CHECK(c.transitions[1].inputs == test::ids<model::PlaceId>({1}));
  CHECK(c.transitions[1].outputs == test::ids<model::PlaceId>({0}));
  REQUIRE(c.transitions[0].condition);
  CHECK(c.transitions[0].condition->kind == model::Expr::Kind::Call);
  CHECK(s.model.functions[c.transitions[0].condition->function()].name == "Left_IR_Black");
  REQUIRE(s.model.functions.size() == 8);
  CHECK(s.model.functions[0].name == "Left_IR_Black");
  CHECK(s.model.functions[0].interface_name == "LineBot");
  CHECK(c.functions == test::ids<model::FunctionId>({0, 1, 2, 3, 4, 5, 6, 7}));
  REQUIRE(c.places[0].action.size() == 1);
  CHECK(c.places[0].action[0].kind == model::Stmt::Kind::Call);
  CHECK(s.model.functions[c.places[0].action[0].expr.function()].name == "Left_FW");
}

TEST_CASE("validate: the clean-up sample", "[validate]") {
  Sample s("cleanup.fsm");
  CHECK(s.text() == "");
  REQUIRE(s.model.charts.size() == 1);
  const auto &c = s.model.charts[0];
  CHECK(c.kind == model::Chart::Kind::Fsm);
  REQUIRE(c.places.size() == 6);
  CHECK(c.places[4].name == "Done");
  CHECK(c.places[4].terminal == model::Terminal::Success);
  CHECK(c.places[5].terminal == model::Terminal::Failure);
  REQUIRE(c.places[4].post);
  CHECK(s.model.functions[c.places[4].post->function()].name == "ItemAtDestination");
  REQUIRE(c.transitions.size() == 8);
  CHECK(c.transitions[7].inputs == test::ids<model::PlaceId>({0}));
  CHECK(c.transitions[7].outputs == test::ids<model::PlaceId>({5}));
  CHECK(c.functions.size() == 10);
}

TEST_CASE("validate: the wall-follow sample", "[validate]") {
  Sample s("wall_follow.plan");
  CHECK(s.text() == "");
  REQUIRE(s.model.plans.size() == 1);
  REQUIRE(s.model.toolboxes.size() == 1);
  CHECK(s.model.templates.size() == 8);
  const auto &p = s.model.plans[0];
  CHECK(p.in_main_file);
  CHECK(p.toolboxes == test::ids<model::ToolboxId>({0}));
  REQUIRE(p.config.size() == 2);
  CHECK(p.config[0].name == "walldist");
  REQUIRE(p.config[0].init);
  CHECK(p.config[0].init->kind == model::Expr::Kind::Float);
  CHECK(p.config[0].init->text == "30.0");
  CHECK_FALSE(p.config[1].init);
  REQUIRE(p.actors.size() == 6);
  CHECK(p.start == model::ActorId(0));
  REQUIRE(p.globals.size() == 1);
  CHECK(p.globals[0].rules.size() == 1);
  CHECK(p.globals[0].rules[0].target.kind == model::RuleTarget::Kind::Terminate);
  const auto &follow = p.actors[4];
  CHECK(follow.name == "followWall");
  REQUIRE(follow.rules.size() == 3);
  for (int k = 0; k < 3; ++k) CHECK(follow.rules[k].outcome == k);
  CHECK(follow.rules[1].target.actor == model::ActorId(2));
  REQUIRE(follow.args.size() == 3);
  CHECK(follow.args[1].formula.kind == model::Expr::Kind::Binary);
  const auto &find = p.actors[2];
  REQUIRE(find.args.size() == 1);
  CHECK(find.args[0].dir == model::ParamDir::Out);
  CHECK(find.args[0].formula.kind == model::Expr::Kind::Config);
  CHECK(find.args[0].formula.config() == model::ConfigId(1));
  REQUIRE(p.actors[0].supervisors.size() == 2);
  CHECK(s.model.templates[p.actors[0].supervisors[1].templ].name == "CheckLane");
  CHECK(s.model.templates[6].period_ms == 10);
}
