// Conditions the C compilers can decide: a chart may write them (the validator's warnings say
// what it thinks of them), and its engine must still compile warning-free with gcc and clang at
// -std=c99 -Wall -Wextra -Wpedantic -Werror. The back end writes each such test as its value
// (c_expr.cc); these charts run in both engine forms and their logs, written by hand from the
// language's tick order (docs/language.md §7, "Sub-charts"), show that nothing else changed:
// calls before a decided pair are still made, in order.
#include "../run/c_backend_support.h"

#include <catch2/catch.hpp>

using namespace cbt;

namespace {

/// The log of `chart` (a file that runs kJob) on `script`, the same in both engine forms.
std::string run_both(const std::string &test, const std::string &chart, const std::string &script) {
  const char *job = R"(
interface Bot { bool Done(); bool Go(); void Mark(int n); }
fsm Job {
  initial state Work;
  success state Ok;
  Work -> Ok when Done();
})";
  std::string logs[2];
  const EngineForm forms[2] = {EngineForm::Readable, EngineForm::Scalable};
  for (int f = 0; f < 2; ++f) {
    auto compiled = compile_chart({{"chart.fsm", chart}, {"job.fsm", job}}, "chart.fsm", "engine.c", true, forms[f]);
    INFO(compiled->errors);
    REQUIRE(!compiled->diag.has_errors());
    logs[f] = compile_and_run(test + (f == 0 ? "" : "_scalable"), compiled->files, compiled->model,
                              compiled->the_chart(), script);
  }
  INFO("the scalable engine's log differs from the readable one's");
  CHECK(logs[1] == logs[0]);
  return logs[0];
}

}  // namespace

TEST_CASE("c engine tautologies: failed(K) && succeeded(K) and the other decided tests compile under -Werror",
          "[c_backend][run][compile]") {
  // clang rejected `m->K.status == -1 && m->K.status == 1` (-Wtautological-overlap-compare),
  // gcc and clang `v == v` (-Wtautological-compare), gcc `Go() && v == 3 && v == 4` ("'and' of
  // mutually exclusive equal-tests", which no -W option names).
  const char *chart = R"(
import "job.fsm";
fsm Check {
  period 10ms;
  var int v = 0;
  var bool b = false;
  const int C = 3;
  initial state K runs Job {
    if (v == v) { Mark(1); }
    if (v + 1 < (v + 1)) { Mark(2); }
    if (v > 3 && v < 2) { Mark(3); }
    if (Go() && v == C && v == 4) { Mark(4); }
    if (b == true || b == false) { Mark(5); }
    if (active(K) && active(Never)) { Mark(6); }
    if (elapsed(K) >= 20ms || elapsed(K) <= 10ms) { Mark(7); }
    if (Go() || v != 3 || v != 4) { Mark(8); }
    v += 1;
  }
  state Never;
  state Late;
  state Either { Mark(9); }
  K -> Never when failed(K) && succeeded(K);
  K -> Late when Go() && elapsed(K) > 50ms && elapsed(K) < 30ms;
  K -> Either when succeeded(K) || failed(K);
})";
  // Tick 1: K's conditions (Job's status 0: T1 asks Go, its pair never holds), K's action (`v ==
  // v` holds, `v + 1 < v + 1` does not, Go is asked before the pair that never holds, every
  // value of b is true or false, K and Never are never both active, every timer is >= 2 or <= 1
  // tick, `v != 3 || v != 4` always holds, so Go, asked first, decides nothing), then Job ticks.
  // Tick 2: Go holds (the pairs still decide), Done too: Job succeeds. Tick 3: succeeded(K): to
  // Either, whose action runs. Tick 4: Either stays.
  std::string ticks_in_k = "act Mark(1)\n"
                           "cond Go -> {go}\n"
                           "act Mark(5)\n"
                           "act Mark(7)\n"
                           "cond Go -> {go}\n"
                           "act Mark(8)\n";
  auto in_k = [&](const char *go) {
    std::string s = ticks_in_k;
    for (auto at = s.find("{go}"); at != std::string::npos; at = s.find("{go}")) s.replace(at, 4, go);
    return s;
  };
  std::string log = run_both("tautology_fsm", chart, "\nGo Done\n\n\n");
  CHECK(log == "tick 1\ncond Go -> 0\n" + in_k("0") + "cond Done -> 0\nstate K status 0\n" + "tick 2\ncond Go -> 1\n" +
                   in_k("1") + "cond Done -> 1\nstate K status 0\n" +
                   "tick 3\ncond Go -> 0\nact Mark(9)\nstate Either status 0\n"
                   "tick 4\nact Mark(9)\nstate Either status 0\n");
}

TEST_CASE("c engine tautologies: agent() == agent() and a condition its activity tests cannot change compile at -O2",
          "[c_backend][compile]") {
  // gcc and clang rejected `m->agent == m->agent`; gcc at -O1 and up the scalable form's
  // `!active(D) || !active(B) || active(D)` ("'or' of unmatched not-equal tests is always 1",
  // which no -W option names); both only under -Werror with the optimiser on for the second.
  const char *team = R"(
interface Bot { bool Go(); void Mark(int n); }
fsm Crew {
  team 3;
  initial state A { if (agent() == agent()) { Mark(1); } }
  state B;
  A -> B when Go() && agent() != agent();
  B -> A when Go();
})";
  const char *fork = R"(
interface Bot { bool Go(); void Mark(int n); }
sfc Pair {
  initial place P;
  place Q;
  place D { Mark(1); }
  place B;
  transition Fork: P -> (D, B) when Go();
  transition Join: (D, B) -> Q when Go();
  transition Back: Q -> P when !active(D) || !active(B) || active(D);
  transition Odd: D -> Q when Go() && (active(B) && !active(B));
})";
  struct Case {
    const char *name, *file, *text;
  };
  for (const Case &c : {Case{"tautology_team", "crew.fsm", team}, Case{"tautology_fork", "pair.sfc", fork}}) {
    for (EngineForm form : {EngineForm::Readable, EngineForm::Scalable}) {
      auto compiled = compile_chart({{c.file, c.text}}, c.file, "engine.c", true, form);
      INFO(c.name << "\n" << compiled->errors);
      REQUIRE(!compiled->diag.has_errors());
      const std::string &src = compiled->files.at(0).contents;
      CHECK(src.find("agent == m->agent") == std::string::npos);
      if (std::string(c.file) == "pair.sfc") {
        CHECK(src.find("true /* always, whatever its tests read: !active(D) || !active(B) || active(D) */") !=
              std::string::npos);
        CHECK(src.find("(false /* never, whatever its tests read: active(B) && !active(B) */)") != std::string::npos);
      }
      for (const char *level : {"-O0", "-O2"})
        check_compiles(std::string(c.name) + (form == EngineForm::Scalable ? "_scalable" : "") + level, compiled->files,
                       "engine.c", {level});
    }
  }
}
