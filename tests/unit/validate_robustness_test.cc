// The validator never crashes: on syntax trees the parser patched up, with missing names and
// expressions, and on hand-made trees the parser would never produce.
#include "support.h"
#include "validate.h"
#include "validate/suggest.h"

#include <catch2/catch.hpp>

#include <memory>
#include <string>

using namespace gfec;

namespace {

ast::ExprPtr expr(ast::Expr::Kind kind) {
  auto e = std::make_unique<ast::Expr>();
  e->kind = kind;
  return e;
}

/// Every kind of expression with nothing in it.
ast::ExprPtr hollow(ast::Expr::Kind kind) {
  auto e = expr(kind);
  if (kind == ast::Expr::Kind::Unary || kind == ast::Expr::Kind::Paren) e->args.push_back(nullptr);
  if (kind == ast::Expr::Kind::Binary) {
    e->args.push_back(nullptr);
    e->args.push_back(expr(ast::Expr::Kind::Name));
  }
  if (kind == ast::Expr::Kind::Call) e->args.push_back(nullptr);
  return e;
}

const ast::Expr::Kind kKinds[] = {ast::Expr::Kind::Bool,   ast::Expr::Kind::Int,      ast::Expr::Kind::Float,
                                  ast::Expr::Kind::String, ast::Expr::Kind::Duration, ast::Expr::Kind::Name,
                                  ast::Expr::Kind::Call,   ast::Expr::Kind::Unary,    ast::Expr::Kind::Binary,
                                  ast::Expr::Kind::Paren};

}  // namespace

TEST_CASE("validate: hand-made trees with holes do not crash", "[validate]") {
  SourceManager sources;
  FileId id = sources.add("t.sfc", "");
  ast::Program program;
  program.files.push_back(nullptr);  // a file the loader could not parse
  auto file = std::make_unique<ast::File>();
  file->id = id;

  ast::Interface iface;
  ast::FunctionDecl f;
  f.params.push_back({});  // no type, no name
  iface.functions.push_back(std::move(f));
  file->interfaces.push_back(std::move(iface));

  ast::ValueDecl c;
  c.is_const = true;
  c.type.text = "int";
  c.name.text = "C";
  file->consts.push_back(std::move(c));  // no initialiser

  for (auto kind : {ast::Chart::Kind::Sfc, ast::Chart::Kind::Fsm}) {
    ast::Chart chart;
    chart.kind = kind;
    chart.name.text = kind == ast::Chart::Kind::Sfc ? "S" : "M";
    ast::Place p;
    p.initial = true;
    p.name.text = "A";
    for (auto k : kKinds) {
      ast::Stmt call;
      call.kind = ast::Stmt::Kind::Call;
      call.call = hollow(ast::Expr::Kind::Call);
      p.action.push_back(std::move(call));
      ast::Stmt assign;
      assign.kind = ast::Stmt::Kind::Assign;
      assign.value = hollow(k);
      p.action.push_back(std::move(assign));
    }
    p.action.push_back({});  // a call statement without its call
    chart.places.push_back(std::move(p));
    chart.places.push_back({});  // a place without a name
    for (auto k : kKinds) {
      ast::Transition t;
      t.condition = hollow(k);
      chart.transitions.push_back(std::move(t));  // no inputs, no outputs
    }
    ast::ValueDecl v;
    v.type.text = "bool";
    v.name.text = "v";
    v.init = hollow(ast::Expr::Kind::Binary);
    chart.values.push_back(std::move(v));
    file->charts.push_back(std::move(chart));
  }

  ast::Toolbox box;
  ast::Template t;
  t.kind = ast::Template::Kind::Actor;
  t.params.push_back({});
  box.templates.push_back(std::move(t));
  file->toolboxes.push_back(std::move(box));

  ast::Plan plan;
  plan.name.text = "P";
  plan.starts.push_back({});
  plan.config_blocks.push_back({});
  plan.config_blocks[0].push_back({});
  ast::ActorUse a;
  a.args.push_back(nullptr);
  a.rules.push_back({});
  ast::Supervise s;
  s.args.push_back(nullptr);
  s.rules.push_back({});
  a.supervisors.push_back(std::move(s));
  plan.actors.push_back(std::move(a));
  plan.global_supervisors.push_back({});
  file->plans.push_back(std::move(plan));

  program.files.push_back(std::move(file));
  Diagnostics diag;
  model::Model m = validate(program, sources, diag);
  CHECK(diag.has_errors());
  CHECK(m.charts.size() == 2);
  bool no_input = false;
  for (const auto &d : diag.all()) no_input = no_input || d.check() == "no-input" || d.check() == "fsm-transition";
  CHECK(no_input);
}

TEST_CASE("validate: an empty program is an empty model", "[validate]") {
  SourceManager sources;
  ast::Program program;
  Diagnostics diag;
  model::Model m = validate(program, sources, diag);
  CHECK_FALSE(diag.has_errors());
  CHECK(m.charts.empty());
  CHECK(&m.sources() == &sources);
}

TEST_CASE("validate: trees the parser patched up after syntax errors", "[validate]") {
  const char *broken[] = {
      "sfc S { initial place A { Go( } transition A -> ; }",
      "fsm M { initial state A post ; A -> B when ; state B }",
      "plan P { config { float = 1; } start ; actor a: Forward(1, ) { -> x; } }",
      "toolbox T { actor A(in float) -> ; supervisor S() events ; }",
      "interface I { void f(int, ); bool ( ); }\nconst int X = ;\nsfc Q { var int x = (1 + ; }",
  };
  for (const char *text : broken) {
    INFO(text);
    test::FrontEnd fe({{"t.sfc", text}});
    validate(fe.loaded.program, fe.sources, fe.diag);
    CHECK(fe.diag.has_errors());
  }
}

TEST_CASE("validate: did-you-mean among the validator's names", "[validate]") {
  using validation::Sym;
  using validation::Symbol;
  const std::string long_name(kMaxSuggestedLength, 'a');
  Symbol a{Sym::Var, 0, "laps", {}}, b{Sym::Var, 1, "speed", {}}, c{Sym::Var, 2, "y", {}}, d{Sym::Var, 3, "lamp", {}},
      e{Sym::Var, 4, long_name, {}};
  std::vector<const Symbol *> candidates{&a, &b, &c, &d, &e};
  CHECK(validation::closest("lap", candidates) == &a);  // "lamp" is as near, but declared later
  CHECK(validation::closest("spede", candidates) == &b);
  CHECK(validation::closest("x", candidates) == nullptr);              // `y` is one edit, but every letter of it
  CHECK(validation::closest("laps", candidates) == nullptr);           // itself is not a suggestion
  CHECK(validation::closest(long_name + "b", candidates) == nullptr);  // too long to be typed by hand
  CHECK(validation::closest(long_name.substr(1) + "b", candidates) == &e);
}
