// Compile-and-run tests of team machines (docs/language.md "Teams", docs/c-engine.md "Team
// machines"): several engines of one chart run in lockstep under the reference exchange — every
// agent ticks in agent order, then every agent's X_state is reported to every other with
// X_report. The expected logs are written by hand from the language's rules.
#include "../run/c_backend_support.h"

#include <catch2/catch.hpp>

using namespace cbt;

namespace {

/// A C main() for `agents` engines of a team machine. The script has one line per tick:
/// `F` or `F=v` answers every agent, `F@k` or `F@k=v` agent k only (and wins over `F`). Each
/// call is logged as in harness_source(), each agent's part of the tick after `agent k`.
std::string team_harness(const model::Model &m, const model::Chart &chart, const std::string &header, int agents) {
  const std::string &X = chart.name;
  std::string s = fmt::format("#include \"{}\"\n\n#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n\n", header);
  s += "static char script[1024]; /* this tick's line */\nstatic int agent_now; /* whose engine runs */\n\n";
  s += "static const char *const state_names[] = {";
  for (const auto &p : chart.places) s += fmt::format("\"{}\", ", p.name);
  s += "NULL};\n\n";
  s += "/* The value of token `key` or `key=v` of the script, or -1 if there is none. */\n"
       "static double token(const char *key)\n{\n"
       "    size_t n = strlen(key);\n"
       "    const char *p = script;\n"
       "    while (*p != '\\0') {\n"
       "        size_t len = strcspn(p, \" \\n\");\n"
       "        if (len >= n && strncmp(p, key, n) == 0 && (len == n || p[n] == '=')) {\n"
       "            return len == n ? 1 : atof(p + n + 1);\n"
       "        }\n"
       "        p += len;\n"
       "        while (*p == ' ' || *p == '\\n') ++p;\n"
       "    }\n"
       "    return -1;\n}\n\n"
       "static double value_of(const char *name)\n{\n"
       "    char own[128];\n"
       "    double v;\n"
       "    sprintf(own, \"%s@%d\", name, agent_now);\n"
       "    v = token(own);\n"
       "    if (v < 0) v = token(name);\n"
       "    return v < 0 ? 0 : v;\n}\n\n";
  for (int fi : chart.functions) {
    const auto &f = m.functions[static_cast<std::size_t>(fi)];
    std::string params, format, args;
    for (std::size_t i = 0; i < f.params.size(); ++i) {
      params += fmt::format("{}{} a{}", i ? ", " : "", model::type_name(f.params[i].type), i);
      format += fmt::format("{}%d", i ? ", " : "");
      args += fmt::format(", (int)a{}", i);
    }
    if (params.empty()) params = "void";
    if (f.result == Type::Void) {
      s += fmt::format("void {}({})\n{{\n    printf(\"act {}{}\\n\"{});\n}}\n\n", f.name, params, f.name,
                       f.params.empty() ? "" : "(" + format + ")", args);
    } else {
      std::string t = model::type_name(f.result);
      s += fmt::format("{0} {1}({2})\n{{\n    {0} v = ({0})value_of(\"{1}\");\n"
                       "    printf(\"cond {1} -> %d\\n\", (int)v);\n    return v;\n}}\n\n",
                       t, f.name, params);
    }
  }
  s += fmt::format("int main(void)\n{{\n    {0} m[{1}];\n    int tick = 0, k, j;\n"
                   "    setvbuf(stdout, NULL, _IONBF, 0);\n"
                   "    for (k = 0; k < {1}; ++k) {{\n        {0}_init(&m[k]);\n        {0}_set_agent(&m[k], k);\n    }}\n"
                   "    while (fgets(script, sizeof script, stdin) != NULL) {{\n"
                   "        printf(\"tick %d\\n\", ++tick);\n"
                   "        for (k = 0; k < {1}; ++k) {{\n"
                   "            agent_now = k;\n"
                   "            printf(\"agent %d\\n\", k);\n"
                   "            {0}_run(&m[k]);\n"
                   "            printf(\"state %s status %d\\n\", state_names[{0}_state(&m[k])], {0}_status(&m[k]));\n"
                   "        }}\n"
                   "        /* the reference exchange */\n"
                   "        for (k = 0; k < {1}; ++k) {{\n"
                   "            for (j = 0; j < {1}; ++j) {{\n"
                   "                {0}_report(&m[j], k, {0}_state(&m[k]));\n"
                   "            }}\n"
                   "        }}\n"
                   "    }}\n    return 0;\n}}\n",
                   X, agents);
  return s;
}

/// Compiles the chart and runs `agents` engines of it on `script` with gcc and clang; the log.
std::string run_team(const std::string &test, const std::string &chart, int agents, const std::string &script) {
  auto compiled = compile_chart({{"chart.fsm", chart}}, "chart.fsm", "engine.c");
  INFO(compiled->errors);
  REQUIRE(!compiled->diag.has_errors());
  fs::path dir = scratch_dir("team_" + test);
  for (const auto &f : compiled->files) write_file(dir / base_name(f.path), f.contents);
  write_file(dir / "harness.c", team_harness(compiled->model, compiled->the_chart(), "engine.h", agents));
  write_file(dir / "script.txt", script);
  std::string first;
  for (const auto &cc : c_compilers()) {
    auto build = run_command(fmt::format("cd '{}' && {} {} harness.c engine.c -o run-{}", dir.string(), cc, kStrictFlags, cc),
                             dir / ("build-" + cc + ".log"));
    INFO(cc << " in " << dir.string() << ":\n" << build.output);
    REQUIRE(build.status == 0);
    auto run = run_command(fmt::format("cd '{}' && ./run-{} < script.txt", dir.string(), cc), dir / ("run-" + cc + ".log"));
    REQUIRE(run.status == 0);
    if (first.empty()) first = run.output;
    else CHECK(run.output == first);
  }
  return first;
}

const char *kFetch = R"(
interface Bot { bool Arrived(); bool Holding(); bool Parked(); void DriveToItem(); void PickUp(); void Park(); }
fsm Fetch {
  team 4;                                  // at most 4 agents run this machine together
  initial state Go { DriveToItem(); }
  state Grab { PickUp(); }
  state Yield { Park(); }
  success state Got;
  success state Left;
  Go -> Grab when Arrived() && team(Grab) == 0;     // nobody else is picking it up
  Go -> Yield when team(Grab) > 0;
  Grab -> Got when Holding();
  Yield -> Left when Parked();
})";

const char *kCensus = R"(
interface Bot { bool Move(); void Count(int me, int go, int wait); }
fsm Census {
  team 4;
  initial state Go { Count(agent(), team(Go), team(Wait)); }
  state Wait { Count(agent(), team(Go), team(Wait)); }
  Go -> Wait when Move();
  Wait -> Go when Move();
})";

} // namespace

TEST_CASE("c engine team: the fetch example, three agents under the reference exchange", "[c_backend][run][team]") {
  std::string log = run_team("fetch", kFetch, 3, "Arrived@1 Arrived@2\nArrived Holding@1\nParked Holding\n");
  CHECK(log == "tick 1\n"
               "agent 0\ncond Arrived -> 0\nact DriveToItem\nstate Go status 0\n"  // team(Grab) is 0: no reports yet
               "agent 1\ncond Arrived -> 1\nact PickUp\nstate Grab status 0\n"
               "agent 2\ncond Arrived -> 1\nact PickUp\nstate Grab status 0\n"     // agent 1's Grab arrives only after the tick
               "tick 2\n"
               "agent 0\ncond Arrived -> 1\nact Park\nstate Yield status 0\n"      // team(Grab) is 2
               "agent 1\ncond Holding -> 1\nstate Got status 1\n"
               "agent 2\ncond Holding -> 0\nact PickUp\nstate Grab status 0\n"
               "tick 3\n"
               "agent 0\ncond Parked -> 1\nstate Left status 1\n"
               "agent 1\nstate Got status 1\n"
               "agent 2\ncond Holding -> 1\nstate Got status 1\n");
}

TEST_CASE("c engine team: team(S) counts the other agents' last reports, agent() is the own number", "[c_backend][run][team]") {
  std::string log = run_team("census", kCensus, 4, "Move@1 Move@3\n\nMove@0\n\n");
  CHECK(log == "tick 1\n"
               "agent 0\ncond Move -> 0\nact Count(0, 0, 0)\nstate Go status 0\n"
               "agent 1\ncond Move -> 1\nact Count(1, 0, 0)\nstate Wait status 0\n"
               "agent 2\ncond Move -> 0\nact Count(2, 0, 0)\nstate Go status 0\n"
               "agent 3\ncond Move -> 1\nact Count(3, 0, 0)\nstate Wait status 0\n"
               "tick 2\n"  // reported: Go Wait Go Wait; each counts the others only
               "agent 0\ncond Move -> 0\nact Count(0, 1, 2)\nstate Go status 0\n"
               "agent 1\ncond Move -> 0\nact Count(1, 2, 1)\nstate Wait status 0\n"
               "agent 2\ncond Move -> 0\nact Count(2, 1, 2)\nstate Go status 0\n"
               "agent 3\ncond Move -> 0\nact Count(3, 2, 1)\nstate Wait status 0\n"
               "tick 3\n"  // agent 0 moves; the others still see its old report
               "agent 0\ncond Move -> 1\nact Count(0, 1, 2)\nstate Wait status 0\n"
               "agent 1\ncond Move -> 0\nact Count(1, 2, 1)\nstate Wait status 0\n"
               "agent 2\ncond Move -> 0\nact Count(2, 1, 2)\nstate Go status 0\n"
               "agent 3\ncond Move -> 0\nact Count(3, 2, 1)\nstate Wait status 0\n"
               "tick 4\n"  // reported: Wait Wait Go Wait
               "agent 0\ncond Move -> 0\nact Count(0, 1, 2)\nstate Wait status 0\n"
               "agent 1\ncond Move -> 0\nact Count(1, 1, 2)\nstate Wait status 0\n"
               "agent 2\ncond Move -> 0\nact Count(2, 0, 3)\nstate Go status 0\n"
               "agent 3\ncond Move -> 0\nact Count(3, 1, 2)\nstate Wait status 0\n");
}

TEST_CASE("c engine team: X_report and X_set_agent ignore what is out of range; X_init forgets", "[c_backend][run][team]") {
  auto compiled = compile_chart({{"chart.fsm", kCensus}}, "chart.fsm", "engine.c");
  REQUIRE(!compiled->diag.has_errors());
  const std::string &h = compiled->files.at(1).contents;
  CHECK(h.find("enum { Census_TEAM_SIZE = 4 };") != std::string::npos);
  CHECK(h.find("int8_t reports[Census_TEAM_SIZE];") != std::string::npos);
  CHECK(h.find("void Census_set_agent(Census *m, int agent);") != std::string::npos);
  CHECK(h.find("void Census_report(Census *m, int agent, int state);") != std::string::npos);
  CHECK(h.find("int Census_team(const Census *m, int state);") != std::string::npos);
  fs::path dir = scratch_dir("team_api");
  for (const auto &f : compiled->files) write_file(dir / base_name(f.path), f.contents);
  write_file(dir / "main.c", R"(#include "engine.h"
#include <stdio.h>
bool Move(void) { return false; }
void Count(int me, int go, int wait) { printf("act Count(%d, %d, %d)\n", me, go, wait); }
static void counts(const Census *m) { printf("%d %d\n", Census_team(m, Census_Go), Census_team(m, Census_Wait)); }
int main(void)
{
    Census m;
    Census_init(&m);
    counts(&m);
    Census_set_agent(&m, 2);
    Census_report(&m, 2, Census_Wait);      /* its own number */
    Census_report(&m, 4, Census_Wait);      /* no such agent */
    Census_report(&m, -1, Census_Wait);
    Census_report(&m, 0, Census_PLACE_COUNT); /* no such state */
    Census_report(&m, 0, -1);
    counts(&m);
    Census_report(&m, 0, Census_Wait);
    Census_report(&m, 1, Census_Go);
    Census_report(&m, 3, Census_Wait);
    counts(&m);
    Census_report(&m, 3, Census_Go);        /* a newer report replaces the last */
    counts(&m);
    Census_set_agent(&m, 7);                /* out of range: still agent 2 */
    Census_run(&m);
    Census_set_agent(&m, 0);                /* agent 0's own report no longer counts */
    counts(&m);
    Census_init(&m);                        /* agent 0 again, no reports */
    counts(&m);
    Census_run(&m);
    return 0;
}
)");
  for (const auto &cc : c_compilers()) {
    auto build = run_command(fmt::format("cd '{}' && {} {} main.c engine.c -o api-{}", dir.string(), cc, kStrictFlags, cc),
                             dir / ("build-" + cc + ".log"));
    INFO(build.output);
    REQUIRE(build.status == 0);
    auto run = run_command(fmt::format("cd '{}' && ./api-{}", dir.string(), cc), dir / ("run-" + cc + ".log"));
    REQUIRE(run.status == 0);
    CHECK(run.output == "0 0\n0 0\n1 2\n2 1\nact Count(2, 2, 1)\n2 0\n0 0\nact Count(0, 0, 0)\n");
  }
}
