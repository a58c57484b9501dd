// The sfc analyses: what the reachable activation states (conditions free) say about a chart.
#include "analysis_support.h"

using namespace gfec;
using test::analyze_text;
using test::compile;
using test::headlines;

namespace {
const char *kBot = "interface Bot { bool Go(); bool Left(); bool Right(); void Log(int n); }";
}  // namespace

TEST_CASE("analysis sfc: the line follower is safe, live and quiet") {
  auto c = compile(R"(
sfc LineFollower {
  initial place LeftFw; place LeftStop; initial place RightFw; place RightStop;
  LeftFw -> LeftStop when Left();
  LeftStop -> LeftFw when !Left();
  RightFw -> RightStop when Right();
  RightStop -> RightFw when !Right();
}
)",
                   kBot);
  std::string report;
  CHECK(analyze_text(*c, true, {}, &report) == "");
  CHECK(report == "sfc LineFollower: 4 places, 4 transitions\n"
                  "  activation states: 4 (all of them)\n"
                  "  safe: no place ever holds more than one activation\n"
                  "  deadlocks: none\n"
                  "  never active: 0 places; never firing: 0 transitions\n");
}

TEST_CASE("analysis sfc: a place that gains activation every tick is unbounded") {
  auto c = compile(R"(
sfc Pump {
  initial place S;
  place P;
  transition Again: S -> (S, P) when Go();
}
)",
                   kBot);
  CHECK(analyze_text(*c, false) ==
        "t.sfc:5:9: warning: place 'P' can gain activation without bound [-Wunbounded-place]\n"
        "   place P;\n"
        "         ^\n"
        "t.sfc:5:9: note: a cycle adds to it every time round: tick 1: Again\n");
}

TEST_CASE("analysis sfc: two producers make a place unsafe (more than one activation)") {
  auto c = compile(R"(
sfc Two {
  initial place A;
  initial place B;
  place P;
  A -> P;
  B -> P when Go();
  P -> A when Left();
}
)",
                   kBot);
  std::string all = analyze_text(*c);
  CHECK(headlines(all) == "t.sfc:6:9: warning: place 'P' can hold 2 activations at once [-Wunsafe-place]\n"
                          "t.sfc:6:9: note: for example after tick 1: T0, T1\n");
  CHECK(analyze_text(*c, false) == "");  // -Wunsafe-place is off by default: counters are allowed
}

TEST_CASE("analysis sfc: a join whose inputs exclude each other is dead and deadlocks the chart") {
  auto c = compile(R"(
sfc Choice {
  initial place S;
  place L;
  place R;
  place J;
  transition GoLeft: S -> L when Left();
  transition GoRight: S -> R when !Left();
  transition Both: (L, R) -> J;
}
)",
                   kBot);
  CHECK(headlines(analyze_text(*c, false)) ==
        "t.sfc:3:5: warning: sfc 'Choice' can reach a state in which nothing can fire any more: R [-Wdeadlock]\n"
        "t.sfc:3:5: note: it gets there after tick 1: GoRight\n"
        "t.sfc:10:14: note: 'Both' waits for 'L'\n"
        "t.sfc:7:9: warning: place 'J' can never become active: no reachable activation state holds it "
        "[-Wunreachable-place]\n"
        "t.sfc:10:14: warning: join 'Both' can never fire: its input places 'L' and 'R' are never active at the same "
        "time [-Wdead-join]\n");
}

TEST_CASE("analysis sfc: an unconditional transition declared first starves a later one") {
  auto c = compile(R"(
sfc Starve {
  initial place A;
  place B;
  place C;
  transition First: A -> B;
  transition Second: A -> C when Go();
  B -> A;
}
)",
                   kBot);
  CHECK(headlines(analyze_text(*c, false)) ==
        "t.sfc:6:9: warning: place 'C' can never become active: no reachable activation state holds it "
        "[-Wunreachable-place]\n"
        "t.sfc:8:14: warning: transition 'Second' can never fire: whenever it is open, a transition declared before "
        "it without a condition takes the activation first [-Wdead-transition]\n");
}

TEST_CASE("analysis sfc: forks whose branches never meet, places with no way out are ends, not deadlocks") {
  auto c = compile(R"(
sfc Apart {
  initial place S;
  place L;
  place R;
  place EndL;
  place EndR;
  transition Split: S -> (L, R) when Go();
  L -> EndL;
  R -> EndR;
}
)",
                   kBot);
  CHECK(headlines(analyze_text(*c)) ==
        "t.sfc:9:14: warning: the branches that fork 'Split' starts ('L' and 'R') never meet again in a join "
        "[-Wunjoined-fork]\n"
        "t.sfc:9:14: note: each branch runs on its own; a join (A, B) -> C synchronises them\n");
  auto joined = compile(R"(
sfc Together {
  initial place S;
  place L;
  place R;
  place J;
  transition Split: S -> (L, R) when Go();
  (L, R) -> J;
  J -> S;
}
)",
                        kBot);
  CHECK(analyze_text(*joined) == "");
}

TEST_CASE("analysis sfc: the exploration is bounded and says so") {
  auto c = compile(R"(
sfc Many {
  initial place A0; place B0; initial place A1; place B1; initial place A2; place B2; initial place A3; place B3;
  A0 -> B0 when Go(); B0 -> A0 when Go();
  A1 -> B1 when Go(); B1 -> A1 when Go();
  A2 -> B2 when Go(); B2 -> A2 when Go();
  A3 -> B3 when Go(); B3 -> A3 when Go();
}
)",
                   kBot);
  analysis::Limits small;
  small.max_states = 5;
  std::string report;
  // -Wanalysis-limit is off by default: a large chart is not a mistake; --analyze turns it on.
  CHECK(analyze_text(*c, false, small) == "");
  CHECK(headlines(analyze_text(*c, true, small, &report)) ==
        "t.sfc:3:5: warning: the analysis of sfc 'Many' stopped after 5 activation states and 16 tick outcomes; what "
        "it says about unreachable places, dead transitions and joins is left out [-Wanalysis-limit]\n");
  CHECK(report.find("activation states: 5 (stopped at the limit of 5 states; incomplete)") != std::string::npos);
  CHECK(analyze_text(*c) == "");  // 16 states: within the default limit
}

TEST_CASE("analysis sfc: a chart of any size costs a bounded amount of work") {
  // A ring of 200000 places with one token: as many states as places, each as large as the
  // chart. The work budget stops the exploration after a few states, without a deep recursion.
  const int n = 200000;
  std::string text = "sfc Ring {\n  initial place P0;\n";
  for (int i = 1; i < n; ++i) text += "  place P" + std::to_string(i) + ";\n";
  for (int i = 0; i < n; ++i)
    text += "  P" + std::to_string(i) + " -> P" + std::to_string((i + 1) % n) + " when Go();\n";
  text += "}\n";
  auto c = compile(text, kBot);
  analysis::Limits limits;
  auto space = analysis::explore(c->model.charts.at(0), limits);
  CHECK(space.limit_hit);
  CHECK(space.states.size() < 100);
  CHECK(space.work <= limits.max_work + 3 * (2 * n + 1));
  std::string report;
  CHECK(headlines(analyze_text(*c, true, limits, &report)).find("[-Wanalysis-limit]") != std::string::npos);
  CHECK(report.find("incomplete") != std::string::npos);

  // A small ring is explored whole, and a long chain of unconditional transitions (no branch at
  // all) neither recurses nor stops early.
  auto small =
      compile("sfc Ring { initial place A; place B; place C; A -> B when Go(); B -> C when Go(); C -> A; }", kBot);
  CHECK(analysis::explore(small->model.charts.at(0)).exact());
  std::string chain = "sfc Chain {\n  initial place Q0;\n";
  for (int i = 1; i < 20000; ++i) chain += "  place Q" + std::to_string(i) + ";\n";
  for (int i = 0; i + 1 < 20000; ++i) chain += "  Q" + std::to_string(i) + " -> Q" + std::to_string(i + 1) + ";\n";
  chain += "}\n";
  auto long_chain = compile(chain, kBot);
  auto chain_space = analysis::explore(long_chain->model.charts.at(0), limits);
  CHECK(chain_space.outcomes >= 1);
}

TEST_CASE("analysis sfc: a self-loop that changes no marking still fires, so it is not dead") {
  // Firing L -> L leaves the marking as it was: the exploration keeps one firing set per
  // resulting marking, and must still count L -> L as fired (it once called it dead).
  auto c = compile(R"(
sfc Pair {
  initial place L { Go(); }
  initial place R;
  place J;
  (L, R) -> J when x();
  J -> (L, R) when y();
  L -> L when x() && y();
}
)",
                   "interface Bot { bool x(); bool y(); void Go(); }");
  CHECK(analyze_text(*c) == "");
}
