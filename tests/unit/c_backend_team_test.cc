// Compile-and-run tests of team machines (docs/language.md "Teams", docs/c-engine.md "Team
// machines"): several engines of one chart run in lockstep under the reference exchange — every
// agent ticks in agent order, then every agent's X_state is reported to every other with
// X_report. The expected logs are written by hand from the language's rules.
#include "../run/c_backend_support.h"
#include "../run/shared_charts.h"

#include "interpreter/run_chart.h"

#include <catch2/catch.hpp>

#include <random>
#include <sstream>

using namespace cbt;
using gfec::test::charts::kCensus;

namespace {

/// A C main() for `agents` engines of a team machine. The script has one line per tick:
/// `F` or `F=v` answers every agent, `F@k` or `F@k=v` agent k only (and wins over `F`). Each
/// call is logged as in harness_source(), each agent's part of the tick after `agent k`.
/// `context`: the engine was made with --context; agent k's context is its number's slot in
/// `agent_ids`, and every call checks that it is the agent running now.
std::string team_harness(const model::Model &m, const model::Chart &chart, const std::string &header, int agents,
                         bool context = false) {
  const std::string &X = chart.name;
  std::string s =
      fmt::format("#include \"{}\"\n\n#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n\n", header);
  s += "static char script[1024]; /* this tick's line */\nstatic int agent_now; /* whose engine runs */\n\n";
  if (context)
    s += fmt::format("static int agent_ids[{}]; /* the engines' contexts */\n\n"
                     "static void expect_agent(const void *ctx)\n{{\n"
                     "    if (ctx != (const void *)&agent_ids[agent_now]) {{\n"
                     "        printf(\"wrong context\\n\");\n"
                     "        exit(3);\n"
                     "    }}\n}}\n\n",
                     agents);
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
  for (model::FunctionId fi : chart.functions) {
    const auto &f = m.functions[fi];
    std::string params, format, args;
    for (std::size_t i = 0; i < f.params.size(); ++i) {
      params += fmt::format("{}{} a{}", i ? ", " : "", model::type_name(f.params[i].type), i);
      format += fmt::format("{}%d", i ? ", " : "");
      args += fmt::format(", (int)a{}", i);
    }
    if (context) params = "void *ctx" + (params.empty() ? "" : ", " + params);
    if (params.empty()) params = "void";
    const std::string check = context ? "    expect_agent(ctx);\n" : "";
    if (f.result == Type::Void) {
      s += fmt::format("void {}({})\n{{\n{}    printf(\"act {}{}\\n\"{});\n}}\n\n", f.name, params, check, f.name,
                       f.params.empty() ? "" : "(" + format + ")", args);
    } else {
      std::string t = model::type_name(f.result);
      s += fmt::format("{0} {1}({2})\n{{\n{3}    {0} v = ({0})value_of(\"{1}\");\n"
                       "    printf(\"cond {1} -> %d\\n\", (int)v);\n    return v;\n}}\n\n",
                       t, f.name, params, check);
    }
  }
  s += fmt::format(
      "int main(void)\n{{\n    {0} m[{1}];\n    int tick = 0, k, j;\n"
      "    setvbuf(stdout, NULL, _IONBF, 0);\n"
      "    for (k = 0; k < {1}; ++k) {{\n        {0}_init(&m[k]);\n        {0}_set_agent(&m[k], k);\n{2}    }}\n"
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
      X, agents, context ? fmt::format("        {}_set_context(&m[k], &agent_ids[k]);\n", X) : "");
  return s;
}

/// Compiles the chart and runs `agents` engines of it on `script` with gcc and clang; the log.
/// `context`: the engines are made with --context, each given its own (team_harness()).
std::string run_team(const std::string &test, const std::string &chart, int agents, const std::string &script,
                     bool context = false) {
  auto compiled =
      compile_chart({{"chart.fsm", chart}}, "chart.fsm", "engine.c", true, EngineForm::Auto, context ? "void *" : "");
  INFO(compiled->errors);
  REQUIRE(!compiled->diag.has_errors());
  fs::path dir = scratch_dir("team_" + test);
  for (const auto &f : compiled->files) write_file(dir / base_name(f.path), f.contents);
  write_file(dir / "harness.c", team_harness(compiled->model, compiled->the_chart(), "engine.h", agents, context));
  write_file(dir / "script.txt", script);
  std::string first;
  for (const auto &cc : c_compilers()) {
    auto build =
        run_command(fmt::format("cd '{}' && {} {} harness.c engine.c -o run-{}", dir.string(), cc, kStrictFlags, cc),
                    dir / ("build-" + cc + ".log"));
    INFO(cc << " in " << dir.string() << ":\n" << build.output);
    REQUIRE(build.status == 0);
    auto run =
        run_command(fmt::format("cd '{}' && ./run-{} < script.txt", dir.string(), cc), dir / ("run-" + cc + ".log"));
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

}  // namespace

TEST_CASE("c engine team: the fetch example, three agents under the reference exchange", "[c_backend][run][team]") {
  const char *script = "Arrived@1 Arrived@2\nArrived Holding@1\nParked Holding\n";
  std::string log = run_team("fetch", kFetch, 3, script);
  // --context: each agent's engine gets its own context, and every call receives exactly it.
  CHECK(run_team("fetch_context", kFetch, 3, script, true) == log);
  CHECK(log ==
        "tick 1\n"
        "agent 0\ncond Arrived -> 0\nact DriveToItem\nstate Go status 0\n"  // team(Grab) is 0: no reports yet
        "agent 1\ncond Arrived -> 1\nact PickUp\nstate Grab status 0\n"
        "agent 2\ncond Arrived -> 1\nact PickUp\nstate Grab status 0\n"  // agent 1's Grab arrives only after the tick
        "tick 2\n"
        "agent 0\ncond Arrived -> 1\nact Park\nstate Yield status 0\n"  // team(Grab) is 2
        "agent 1\ncond Holding -> 1\nstate Got status 1\n"
        "agent 2\ncond Holding -> 0\nact PickUp\nstate Grab status 0\n"
        "tick 3\n"
        "agent 0\ncond Parked -> 1\nstate Left status 1\n"
        "agent 1\nstate Got status 1\n"
        "agent 2\ncond Holding -> 1\nstate Got status 1\n");
}

TEST_CASE("c engine team: team(S) counts the other agents' last reports, agent() is the own number",
          "[c_backend][run][team]") {
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

TEST_CASE("c engine team: X_report and X_set_agent ignore what is out of range, X_init forgets",
          "[c_backend][run][team]") {
  auto compiled = compile_chart({{"chart.fsm", kCensus}}, "chart.fsm", "engine.c");
  REQUIRE(!compiled->diag.has_errors());
  const std::string &h = compiled->files.at(1).contents;
  CHECK(h.find("enum { Census_TEAM_SIZE = 4 };") != std::string::npos);
  CHECK(h.find("int8_t reports[Census_TEAM_SIZE];") != std::string::npos);
  CHECK(h.find("void Census_set_agent(Census *m, int agent);") != std::string::npos);
  CHECK(h.find("void Census_report(Census *m, int agent, int state);") != std::string::npos);
  CHECK(h.find("int32_t Census_team(const Census *m, int state);") != std::string::npos);
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
    auto build =
        run_command(fmt::format("cd '{}' && {} {} main.c engine.c -o api-{}", dir.string(), cc, kStrictFlags, cc),
                    dir / ("build-" + cc + ".log"));
    INFO(build.output);
    REQUIRE(build.status == 0);
    auto run = run_command(fmt::format("cd '{}' && ./api-{}", dir.string(), cc), dir / ("run-" + cc + ".log"));
    REQUIRE(run.status == 0);
    CHECK(run.output == "0 0\n0 0\n1 2\n2 1\nact Count(2, 2, 1)\n2 0\n0 0\nact Count(0, 0, 0)\n");
  }
}

namespace {

/// The harness's script read by the interpreter: `F@k` / `F@k=v` for agent k, else `F` / `F=v`.
class ScriptInputs : public interp::Environment {
public:
  ScriptInputs(const model::Model &m, const std::vector<std::string> &lines, int agent)
      : m_(m), lines_(lines), agent_(agent) {}
  interp::Value call(model::FunctionId function, const std::vector<interp::Value> &, std::uint64_t tick) override {
    const model::Function &f = m_.functions.at(function);
    std::istringstream line(lines_.at(static_cast<std::size_t>(tick - 1)));
    double own = -1, shared = -1;
    for (std::string token; line >> token;) {
      auto eq = token.find('=');
      std::string key = token.substr(0, eq);
      double v = eq == std::string::npos ? 1 : std::stod(token.substr(eq + 1));
      if (key == f.name + "@" + std::to_string(agent_)) own = v;
      if (key == f.name) shared = v;
    }
    double v = own >= 0 ? own : shared >= 0 ? shared : 0;
    if (f.result == Type::Bool) return interp::Value::of_bool(v != 0);
    return interp::Value::of_int(static_cast<std::int32_t>(v));
  }

private:
  const model::Model &m_;
  const std::vector<std::string> &lines_;
  int agent_;
};

/// The interpreter's observable log in the team harness's words (`cond F -> 1`, `act F(1)`,
/// `state S status 0`; no `av`).
std::string in_harness_words(const std::string &log) {
  std::istringstream in(log);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("av ", 0) == 0) continue;
    if (line.rfind("state ", 0) == 0) {
      std::string name = line.substr(6, line.find(' ', 6) - 6);
      const char *status = line.find("succeeded") != std::string::npos ? "1"
                           : line.find("failed") != std::string::npos  ? "-1"
                                                                       : "0";
      out += "state " + name + " status " + status + "\n";
      continue;
    }
    if (line.rfind("call ", 0) == 0) {
      std::string call = line.substr(5);
      auto eq = call.find(" = ");
      if (eq != std::string::npos) {  // a sensing function without arguments
        std::string v = call.substr(eq + 3);
        if (v == "true") v = "1";
        if (v == "false") v = "0";
        out += "cond " + call.substr(0, call.find('(')) + " -> " + v + "\n";
        continue;
      }
      for (auto [from, to] : {std::pair<std::string, std::string>{"true", "1"}, {"false", "0"}})
        for (std::size_t at; (at = call.find(from)) != std::string::npos;) call.replace(at, from.size(), to);
      if (call.size() > 2 && call.compare(call.size() - 2, 2, "()") == 0) call.resize(call.size() - 2);
      out += "act " + call + "\n";
      continue;
    }
    out += line + "\n";
  }
  return out;
}

}  // namespace

TEST_CASE("c engine team: the engines and the interpreter agree on random inputs", "[c_backend][run][team]") {
  const std::string golden = read_file(fs::path(GFEC_SOURCE_DIR) / "tests" / "golden" / "c" / "team_fetch.fsm");
  struct Case {
    const char *name;
    std::string chart;
    int agents;
  };
  const Case cases[] = {{"fetch", kFetch, 4}, {"census", kCensus, 3}, {"golden", golden, 2}};
  for (const Case &k : cases) {
    auto compiled = compile_chart({{"chart.fsm", k.chart}}, "chart.fsm", "engine.c");
    REQUIRE(!compiled->diag.has_errors());
    const model::Chart &chart = compiled->the_chart();
    for (unsigned seed = 1; seed <= 3; ++seed) {
      std::mt19937 rng(seed * 7919u + static_cast<unsigned>(k.agents));
      std::vector<std::string> lines;
      std::string script;
      for (int tick = 0; tick < 40; ++tick) {
        std::string line;
        for (model::FunctionId fi : chart.functions) {
          const auto &f = compiled->model.functions[fi];
          if (f.result == Type::Void) continue;
          for (int a = 0; a < k.agents; ++a) {
            unsigned r = rng() % 4;
            if (f.result == Type::Bool && r == 0) line += fmt::format("{}@{} ", f.name, a);
            if (f.result == Type::Int) line += fmt::format("{}@{}={} ", f.name, a, r);
          }
        }
        lines.push_back(line);
        script += line + "\n";
      }
      std::string c_log = run_team(fmt::format("random_{}_{}", k.name, seed), k.chart, k.agents, script);
      std::vector<std::unique_ptr<ScriptInputs>> inputs;
      std::vector<interp::Environment *> envs;
      for (int a = 0; a < k.agents; ++a) {
        inputs.push_back(std::make_unique<ScriptInputs>(compiled->model, lines, a));
        envs.push_back(inputs.back().get());
      }
      Diagnostics diag;
      interp::RunResult r = interp::run_team(compiled->model, compiled->chart, envs, lines.size(), {}, diag);
      REQUIRE(r.completed);
      INFO(k.name << " seed " << seed << ", script:\n" << script);
      CHECK(in_harness_words(r.log.render({})) == c_log);
    }
  }
}
