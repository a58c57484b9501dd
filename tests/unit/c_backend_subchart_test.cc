// Compile-and-run tests of sub-charts in the C engine (docs/c-engine.md "Sub-charts"): places and
// states that run a chart, each with its own instance embedded in the parent's state. Every
// engine is compiled with gcc and clang at -std=c99 -Wall -Wextra -Wpedantic -Werror in the
// readable and the scalable form, linked with the logging harness and run; the expected logs are
// written by hand from the language's tick order (docs/language.md "Sub-charts"), never copied
// from an engine's output.
#include "../run/c_backend_support.h"

#include <catch2/catch.hpp>

#include <functional>

using namespace cbt;

namespace {

using Kind = model::Chart::Kind;

/// Runs the model's chart 0 in both engine forms; both must write the same log. `context`: also
/// both forms made with --context, whose every interface call (in instances at every depth too)
/// must receive the harness's device (c_backend_support.h), with the same log.
std::string run_both(const std::string &test, const model::Model &m, const std::string &script,
                     const std::string &defines = "", bool context = false) {
  std::string logs[4];
  const EngineForm forms[2] = {EngineForm::Readable, EngineForm::Scalable};
  for (int f = 0; f < (context ? 4 : 2); ++f) {
    auto files = emit_c(m, "engine.c", true, "hand.sfc", forms[f % 2], f < 2 ? "" : "void *");
    logs[f] = compile_and_run(test + (f % 2 == 0 ? "" : "_scalable") + (f < 2 ? "" : "_context"), files, m, m.charts[0],
                              script, defines, true, f >= 2);
  }
  INFO("the scalable engine's log differs from the readable one's");
  CHECK(logs[1] == logs[0]);
  if (context) {
    INFO("an engine with --context logs differently");
    CHECK(logs[2] == logs[0]);
    CHECK(logs[3] == logs[0]);
  }
  return logs[0];
}

/// The lines of `log` that `keep` keeps.
std::string lines_where(const std::string &log, const std::function<bool(const std::string &)> &keep) {
  std::istringstream in(log);
  std::string out;
  for (std::string line; std::getline(in, line);)
    if (keep(line)) out += line + "\n";
  return out;
}

/// sfc Top { A runs fsm Mid { M1 runs sfc Leaf { L1, L2 }, M2, success Ok }, B }, every place
/// and state with entry, action and exit calls of its own.
void three_levels(ChartBuilder &b) {
  // Chart 0 (compiled): Top.
  b.fn("TopGo", Type::Bool).fn("TopBack", Type::Bool).fn("TopIn").fn("TopAct").fn("TopOut").fn("TopB");
  auto &a = b.place("A", true, {b.act("TopAct")});
  a.entry = std::vector<Stmt>{b.act("TopIn")};
  a.exit = std::vector<Stmt>{b.act("TopOut")};
  b.place("B", false, {b.act("TopB")});
  b.transition({"A"}, {"B"}, b.call("TopGo"));
  b.transition({"B"}, {"A"}, b.call("TopBack"));
  // Chart 1: Mid.
  model::ChartId mid = b.begin_chart("Mid", Kind::Fsm);
  b.fn("MidGo", Type::Bool).fn("MidDone", Type::Bool).fn("MidIn").fn("MidAct").fn("MidOut").fn("Mid2");
  auto &m1 = b.place("M1", true, {b.act("MidAct")});
  m1.entry = std::vector<Stmt>{b.act("MidIn")};
  m1.exit = std::vector<Stmt>{b.act("MidOut")};
  b.place("M2", false, {b.act("Mid2")});
  b.place("Ok").terminal = model::Terminal::Success;
  b.transition({"M1"}, {"M2"}, b.call("MidGo"));
  b.transition({"M2"}, {"Ok"}, b.call("MidDone"));
  // Chart 2: Leaf.
  model::ChartId leaf = b.begin_chart("Leaf", Kind::Sfc);
  b.fn("LeafGo", Type::Bool).fn("LeafIn").fn("LeafAct").fn("LeafOut").fn("Leaf2");
  auto &l1 = b.place("L1", true, {b.act("LeafAct")});
  l1.entry = std::vector<Stmt>{b.act("LeafIn")};
  l1.exit = std::vector<Stmt>{b.act("LeafOut")};
  b.place("L2", false, {b.act("Leaf2")});
  b.transition({"L1"}, {"L2"}, b.call("LeafGo"));
  b.select(mid);
  b.runs("M1", leaf);
  b.select(model::ChartId(0));
  b.runs("A", mid);
}

}  // namespace

TEST_CASE("c engine sub-charts: sfc in fsm in sfc, start, tick and stop innermost first", "[c_backend][subchart]") {
  ChartBuilder b("Top", Kind::Sfc);
  three_levels(b);
  std::string log = run_both("sub_three_levels", b.model(),
                             "\n"
                             "TopGo\n"
                             "TopBack\n"
                             "LeafGo MidGo\n"
                             "MidDone\n"
                             "TopGo\n",
                             "", true);
  CHECK(log == "tick 1\n"
               "act TopIn\n"  // Top's first tick: A enters (Mid was started by _init)
               "cond TopGo -> 0\n"
               "act TopAct\n"  // actions: A's block, then one tick of its Mid
               "act MidIn\n"   //   Mid's first tick: M1 enters (its Leaf started by Mid's init)
               "cond MidGo -> 0\n"
               "act MidAct\n"  //   M1's action, then one tick of its Leaf
               "act LeafIn\n"  //     Leaf's first tick: L1 enters
               "cond LeafGo -> 0\n"
               "act LeafAct\n"
               "av A\n"
               "tick 2\n"
               "cond TopGo -> 1\n"  // A -> B: A loses its activation
               "act LeafOut\n"      // stop Mid: stop M1's Leaf (L1's exit), then M1's exit,
               "act MidOut\n"
               "act TopOut\n"  // then A's own exit: innermost first
               "act TopB\n"
               "av B\n"
               "tick 3\n"
               "cond TopBack -> 1\n"  // T0 is not open: no TopGo
               "act TopIn\n"          // A gains activation: Mid reset (no code), then A's entry
               "act TopAct\n"
               "act MidIn\n"  // Mid's first tick again, and Leaf's
               "cond MidGo -> 0\n"
               "act MidAct\n"
               "act LeafIn\n"
               "cond LeafGo -> 0\n"
               "act LeafAct\n"
               "av A\n"
               "tick 4\n"
               "cond TopGo -> 0\n"
               "act TopAct\n"
               "cond MidGo -> 1\n"  // M1 -> M2: M1's Leaf stopped (L1 exits), M1 exits;
               "act LeafOut\n"      // Leaf does not tick (M1 is no longer current)
               "act MidOut\n"
               "act Mid2\n"
               "av A\n"
               "tick 5\n"
               "cond TopGo -> 0\n"
               "act TopAct\n"
               "cond MidDone -> 1\n"  // M2 -> Ok: terminal, no action
               "av A\n"
               "tick 6\n"
               "cond TopGo -> 1\n"  // stopping Mid in a terminal state runs nothing
               "act TopOut\n"
               "act TopB\n"
               "av B\n");
}

TEST_CASE("c engine sub-charts: X_instance_activation tells where each instance is, depth first",
          "[c_backend][subchart]") {
  ChartBuilder b("Top", Kind::Sfc);
  three_levels(b);
  // Instance 0 is A's Mid (an fsm), instance 1 M1's Leaf (an sfc: readable, or sequential in the
  // scalable form). A stopped instance keeps the state its last tick left; a restart resets it.
  std::string log = run_both("sub_instance_activation", b.model(),
                             "\n"
                             "LeafGo\n"
                             "MidGo\n"
                             "TopGo\n"
                             "TopBack\n",
                             "-DHARNESS_INSTANCES");
  const std::string shown = lines_where(log, [](const std::string &line) {
    for (const char *kept : {"tick ", "av ", "in ", "out of range"})
      if (line.rfind(kept, 0) == 0) return true;
    return false;
  });
  CHECK(shown == "tick 1\nav A\nin A: M1\nin A.M1: L1\n"
                 "tick 2\nav A\nin A: M1\nin A.M1: L2\n"    // L1 -> L2 inside M1
                 "tick 3\nav A\nin A: M2\nin A.M1: L2\n"    // M1 -> M2: Leaf stopped as it was
                 "tick 4\nav B\nin A: M2\nin A.M1: L2\n"    // A -> B: Mid stopped as it was
                 "tick 5\nav A\nin A: M1\nin A.M1: L1\n");  // B -> A: Mid and its Leaf restarted
  auto files = emit_c(b.model(), "engine.c", true, "hand.sfc");
  const std::string &h = files[1].contents;
  CHECK(h.find("Top_A_INSTANCE,") < h.find("Top_A_M1_INSTANCE,"));
  CHECK(h.find("uint32_t Top_instance_activation(const Top *m, int instance, int place);") != std::string::npos);
}

TEST_CASE("c engine sub-charts: a chart without sub-charts has no instance API", "[c_backend][subchart]") {
  ChartBuilder b("Flat", Kind::Sfc);
  b.fn("Go", Type::Bool);
  b.place("A", true);
  b.place("B");
  b.transition({"A"}, {"B"}, b.call("Go"));
  for (const auto &f : emit_c(b.model(), "engine.c", true, "hand.sfc")) {
    CHECK(f.contents.find("_instance_activation") == std::string::npos);
    CHECK(f.contents.find("INSTANCE") == std::string::npos);
  }
}

namespace {

/// sfc Two { P runs Job, Q runs Job (the same chart twice), W reads them, R }, fsm Job counts its
/// ticks in a var and succeeds from its second tick on when JobOk().
void two_places(ChartBuilder &b) {
  b.fn("Go", Type::Bool).fn("Again", Type::Bool).fn("Back", Type::Bool).fn("Pa").fn("Qa");
  b.fn("Look", Type::Void, {{Type::Bool, "succeeded_p"}, {Type::Bool, "q_runs"}});
  b.place("P", true, {b.act("Pa")});
  b.place("Q", true, {b.act("Qa")});
  b.place("W", true);
  b.place("R");
  model::ChartId job = b.begin_chart("Job", Kind::Fsm);
  b.fn("JobOk", Type::Bool).fn("Count", Type::Void, {{Type::Int, "n"}});
  b.var("n", Type::Int);
  b.place("Run", true, {b.assign("n", AssignOp::Add, ChartBuilder::int_lit("1")), b.act("Count", {b.var_ref("n")})});
  b.place("Done").terminal = model::Terminal::Success;
  b.transition({"Run"}, {"Done"},
               ChartBuilder::bin(BinaryOp::And,
                                 ChartBuilder::bin(BinaryOp::Ge, b.var_ref("n"), ChartBuilder::int_lit("2")),
                                 b.call("JobOk")));
  b.select(model::ChartId(0));
  b.runs("P", job);
  b.runs("Q", job);
  b.chart().places[2].action = {b.act("Look", {b.status("P", true), b.active({"Q", "Run"})})};
  b.transition({"P"}, {"R"}, ChartBuilder::bin(BinaryOp::And, b.status("P", true), b.call("Go")));
  b.transition({"Q"}, {"Q"}, ChartBuilder::bin(BinaryOp::And, b.active({"P"}), b.call("Again")));
  b.transition({"R"}, {"P"}, b.call("Back"));
}

}  // namespace

TEST_CASE("c engine sub-charts: one chart in two places, lose and regain, conditions read the start of the tick",
          "[c_backend][subchart]") {
  ChartBuilder b("Two", Kind::Sfc);
  two_places(b);
  std::string log = run_both("sub_two_places", b.model(),
                             "\n"
                             "JobOk\n"
                             "JobOk\n"
                             "Go Again\n"
                             "Back\n",
                             "", true);
  CHECK(log == "tick 1\n"
               // T0: succeeded(P) is false (P's Job runs): Go is not called. T1: active(P) holds.
               "cond Again -> 0\n"
               "act Pa\n"
               "act Count(1)\n"  // P's Job: n >= 2 is false, JobOk is not called
               "act Qa\n"
               "act Count(1)\n"  // Q's Job: an instance of its own
               "act Look(0, 1)\n"
               "av P Q W\n"
               "tick 2\n"
               "cond Again -> 0\n"
               "act Pa\n"
               "act Count(2)\n"
               "act Qa\n"
               "act Count(2)\n"
               "act Look(0, 1)\n"
               "av P Q W\n"
               "tick 3\n"
               "cond Again -> 0\n"  // the conditions see P's Job as its last tick left it
               "act Pa\n"
               "cond JobOk -> 1\n"  // P's Job succeeds in the actions step...
               "act Qa\n"
               "cond JobOk -> 1\n"  // ...and Q's
               "act Look(1, 0)\n"   // ...which W's action, later in the step, already sees
               "av P Q W\n"
               "tick 4\n"
               "cond Go -> 1\n"     // T0: succeeded(P) now holds; P's activation is consumed
               "cond Again -> 1\n"  // T1: active(P) reads the start of the tick: still true
               "act Qa\n"           // Q lost and regained its activation: its Job goes on
               "act Look(0, 0)\n"   // (succeeded, not restarted); P is inactive: false
               "av Q W R\n"
               "tick 5\n"
               "cond Back -> 1\n"  // T1 not tried further: active(P) is false at the start
               "act Pa\n"          // P regained activation: its Job restarted from n = 0
               "act Count(1)\n"
               "act Qa\n"
               "act Look(0, 0)\n"
               "av P Q W\n");
}

TEST_CASE("c engine sub-charts: instances are static, named after their path, embedded in the root's struct",
          "[c_backend][subchart]") {
  ChartBuilder b("Top", Kind::Sfc);
  three_levels(b);
  for (EngineForm form : {EngineForm::Readable, EngineForm::Scalable}) {
    auto files = emit_c(b.model(), "engine.c", true, "hand.sfc", form);
    const std::string &c = files[0].contents, &h = files[1].contents;
    CHECK(c.find("static void Top_A_run(struct Top_A *m)") != std::string::npos);
    CHECK(c.find("static void Top_A_M1_run(struct Top_A_M1 *m)") != std::string::npos);
    CHECK(c.find("static void Top_A_M1_stop(struct Top_A_M1 *m)") != std::string::npos);
    CHECK(c.find("void Top_run(Top *m)") != std::string::npos);
    // The header: the instances' complete types (the root embeds them), the root's API only.
    CHECK(h.find("struct Top_A_M1 {") < h.find("struct Top_A {"));
    CHECK(h.find("struct Top_A A;") != std::string::npos);
    CHECK(h.find("Top_A_run") == std::string::npos);
    CHECK(h.find("Top_A_M1 M1;") != std::string::npos);
    // Every function any instance calls is declared.
    for (const char *f : {"bool TopGo(void);", "bool MidGo(void);", "void LeafAct(void);"})
      CHECK(h.find(f) != std::string::npos);
  }
}

namespace {

/// fsm Mission { S1 runs sfc Par { A, B runs fsm Tiny { t1, t2 }, C: (A, B) -> C }, S2 }: an fsm
/// at the root, parallel places stopped in declaration order, a path three levels deep.
void mission(ChartBuilder &b) {
  b.fn("Leave", Type::Bool).fn("Back", Type::Bool).fn("E1").fn("S1a").fn("X1").fn("S2a");
  auto &s1 = b.place("S1", true, {b.act("S1a")});
  s1.entry = std::vector<Stmt>{b.act("E1")};
  s1.exit = std::vector<Stmt>{b.act("X1")};
  b.place("S2", false, {b.act("S2a")});
  model::ChartId par = b.begin_chart("Par", Kind::Sfc);
  b.fn("Join", Type::Bool).fn("InA").fn("Aa").fn("OutA").fn("OutB").fn("Ca");
  auto &a = b.place("A", true, {b.act("Aa")});
  a.entry = std::vector<Stmt>{b.act("InA")};
  a.exit = std::vector<Stmt>{b.act("OutA")};
  b.place("B", true).exit = std::vector<Stmt>{b.act("OutB")};
  b.place("C", false, {b.act("Ca")});
  b.transition({"A", "B"}, {"C"}, b.call("Join"));
  model::ChartId tiny = b.begin_chart("Tiny", Kind::Fsm);
  b.fn("TinyGo", Type::Bool).fn("Ta").fn("OutT");
  b.place("t1", true, {b.act("Ta")}).exit = std::vector<Stmt>{b.act("OutT")};
  b.place("t2");
  b.transition({"t1"}, {"t2"}, b.call("TinyGo"));
  b.select(par);
  b.runs("B", tiny);
  b.select(model::ChartId(0));
  b.runs("S1", par);
  b.transition({"S1"}, {"S2"}, ChartBuilder::bin(BinaryOp::And, b.active({"S1", "B", "t2"}), b.call("Leave")));
  b.transition({"S2"}, {"S1"}, ChartBuilder::bin(BinaryOp::Or, b.active({"S1", "B"}), b.call("Back")));
}

/// The log without the hooks' lines.
std::string without_hooks(const std::string &log) {
  return lines_where(log, [](const std::string &line) { return line.rfind("hook ", 0) != 0; });
}

}  // namespace

TEST_CASE("c engine sub-charts: an fsm runs an sfc whose parallel places stop in declaration order",
          "[c_backend][subchart]") {
  ChartBuilder b("Mission", Kind::Fsm);
  mission(b);
  const std::string script = "\n"
                             "TinyGo\n"
                             "Leave\n"
                             "Back\n"
                             "Join\n"
                             "Leave\n";
  std::string log = run_both("sub_mission", b.model(), script);
  CHECK(log == "tick 1\n"
               "act E1\n"  // Mission's first tick: S1 enters
               // S1 -> S2: active(S1.B.t2) is false (Tiny is in t1): Leave is not called
               "act S1a\n"
               "act InA\n"  // Par's first tick: A enters; B has no entry
               "cond Join -> 0\n"
               "act Aa\n"  // A's action; B has none, but its Tiny ticks
               "cond TinyGo -> 0\n"
               "act Ta\n"
               "state S1 status 0\n"
               "tick 2\n"
               "act S1a\n"
               "cond Join -> 0\n"
               "act Aa\n"
               "cond TinyGo -> 1\n"  // t1 -> t2: t1's exit; t2 has no action
               "act OutT\n"
               "state S1 status 0\n"
               "tick 3\n"
               "cond Leave -> 1\n"  // active(S1.B.t2) holds: S1 -> S2. Stop Par: A exits,
               "act OutA\n"         // then B stops its Tiny (t2: no exit) and exits;
               "act OutB\n"
               "act X1\n"  // then S1's own exit
               "act S2a\n"
               "state S2 status 0\n"
               "tick 4\n"
               "cond Back -> 1\n"  // active(S1.B) is false while S1 is not current
               "act E1\n"          // S1 entered: Par reset, then S1's entry
               "act S1a\n"
               "act InA\n"  // Par's first tick again, Tiny's too
               "cond Join -> 0\n"
               "act Aa\n"
               "cond TinyGo -> 0\n"
               "act Ta\n"
               "state S1 status 0\n"
               "tick 5\n"
               "act S1a\n"         // (Tiny in t1: no Leave)
               "cond Join -> 1\n"  // (A, B) -> C: A exits, then B: Tiny stopped (t1's
               "act OutA\n"        // exit), then B's exit
               "act OutT\n"
               "act OutB\n"
               "act Ca\n"
               "state S1 status 0\n"
               "tick 6\n"
               "act S1a\n"  // B is inactive: active(S1.B.t2) is false
               "act Ca\n"
               "state S1 status 0\n");
  // The hooks are the root's: a hooks build logs Mission's changes and otherwise the same.
  std::string hooked = run_both("sub_mission_hooks", b.model(), script, "-DMission_HOOKS");
  CHECK(hooked.find("hook gained S2") != std::string::npos);
  CHECK(without_hooks(hooked) == log);
}

TEST_CASE("c engine sub-charts: an fsm's exit block sees the state left as current, its entry the new one",
          "[c_backend][subchart]") {
  ChartBuilder b("Door", Kind::Fsm);
  b.fn("Close", Type::Bool).fn("Saw", Type::Void, {{Type::Bool, "open"}, {Type::Bool, "shut"}});
  b.place("Open", true);
  b.place("Shut");
  b.chart().places[0].exit = std::vector<Stmt>{b.act("Saw", {b.active({"Open"}), b.active({"Shut"})})};
  b.chart().places[1].entry = std::vector<Stmt>{b.act("Saw", {b.active({"Open"}), b.active({"Shut"})})};
  b.transition({"Open"}, {"Shut"}, b.call("Close"));
  std::string log = run_both("sub_fsm_exit", b.model(), "\nClose\n\n");
  CHECK(log == "tick 1\n"
               "cond Close -> 0\n"
               "state Open status 0\n"
               "tick 2\n"
               "cond Close -> 1\n"
               "act Saw(1, 0)\n"  // Open's exit: Shut becomes current only after it
               "act Saw(0, 1)\n"  // Shut's entry
               "state Shut status 0\n"
               "tick 3\n"
               "state Shut status 0\n");
}
