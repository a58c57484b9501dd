#include "run_command.h"

#include "diagnostic_printer.h"
#include "driver.h"
#include "interpreter/input_trace.h"
#include "interpreter/run_chart.h"
#include "loader.h"
#include "validate.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <ostream>
#include <vector>

namespace gfec {

namespace {

struct RunOptions {
  std::string input;
  std::string inputs_csv;
  std::uint64_t ticks = 0;
  int agents = 0;            ///< a team machine's agents (with agents_given)
  bool agents_given = false; ///< --agents was given; else a team machine runs all its agents
  std::string chart;
  std::vector<std::string> include_dirs;
  bool observable = false;  ///< only the observable layer, unindented: what engines print
  bool hooks = false;
  bool check_post = false;
};

void print(const Diagnostics &diag, const SourceManager &sources, std::ostream &err) {
  for (const auto &d : diag.all()) err << render_text(d, sources);
}

/// The sfc or fsm of the main file to run: the only one, or the one --chart names.
int choose_chart(const model::Model &m, const RunOptions &o, std::ostream &err) {
  std::vector<int> candidates;
  std::string names;
  for (std::size_t i = 0; i < m.charts.size(); ++i)
    if (m.charts[i].in_main_file) {
      candidates.push_back(static_cast<int>(i));
      names += fmt::format("{}'{}'", names.empty() ? "" : ", ", m.charts[i].name);
    }
  if (!o.chart.empty()) {
    for (int c : candidates)
      if (m.charts[static_cast<std::size_t>(c)].name == o.chart) return c;
    err << fmt::format("{}: error: no sfc or fsm named '{}' to run{}\n", o.input, o.chart,
                       names.empty() ? "" : " (the file declares " + names + ")");
    return -1;
  }
  if (candidates.size() == 1) return candidates.front();
  if (candidates.empty())
    err << fmt::format("{}: error: nothing to run: the file declares no sfc or fsm\n", o.input);
  else
    err << fmt::format("{}: error: the file declares several charts ({}); choose one with --chart NAME\n", o.input,
                       names);
  return -1;
}

int run_with(const RunOptions &o, std::ostream &out, std::ostream &err) {
  SourceManager sources;
  Diagnostics diag;
  RealFileSystem fs;
  LoadResult loaded = load_program(o.input, {o.include_dirs}, fs, sources, diag);
  if (loaded.main_unreadable) {
    err << fmt::format("gfec: error: cannot read '{}'\n", o.input);
    return kExitUsageOrIo;
  }
  model::Model model;
  if (!diag.has_errors()) model = validate(loaded.program, sources, diag);
  print(diag, sources, err);
  if (diag.has_errors()) return kExitInputError;

  int chart = choose_chart(model, o, err);
  if (chart < 0) return kExitUsageOrIo;
  // A team machine runs as a team (docs/cli.md): every agent by default, or --agents of them.
  const int team = model.charts[static_cast<std::size_t>(chart)].team;
  int agents = 1;
  if (team > 0) agents = o.agents_given ? o.agents : team;
  if (o.agents_given && (o.agents < 1 || o.agents > std::max(team, 1))) {
    err << (team > 0 ? fmt::format("gfec: error: --agents {}: '{}' is a team of 1 to {} agents\n", o.agents,
                                   model.charts[static_cast<std::size_t>(chart)].name, team)
                     : fmt::format("gfec: error: --agents {}: '{}' is no team machine; it runs as one agent\n",
                                   o.agents, model.charts[static_cast<std::size_t>(chart)].name));
    return kExitUsageOrIo;
  }

  Diagnostics trace_diag;
  std::unique_ptr<interp::InputTrace> trace;
  if (!o.inputs_csv.empty()) {
    auto text = fs.read(o.inputs_csv);
    if (!text) {
      err << fmt::format("gfec: error: cannot read '{}'\n", o.inputs_csv);
      return kExitUsageOrIo;
    }
    FileId id = sources.add(o.inputs_csv, *text);
    trace = std::make_unique<interp::InputTrace>(model, sources, id, trace_diag, agents);
    print(trace_diag, sources, err);
    if (trace_diag.has_errors()) return kExitInputError;
  } else {
    trace = std::make_unique<interp::InputTrace>(model);
  }
  // Without --ticks: one tick per row of the trace, or ten.
  std::uint64_t ticks = o.ticks ? o.ticks : trace->rows() ? trace->rows() : 10;

  interp::EngineOptions engine;
  engine.check_post = o.check_post;
  Diagnostics run_diag;
  interp::RunResult r;
  if (team > 0) {
    std::vector<interp::InputTrace::Agent> inputs;
    for (int k = 0; k < agents; ++k) inputs.emplace_back(*trace, k);
    std::vector<interp::Environment *> envs;
    for (auto &i : inputs) envs.push_back(&i);
    r = interp::run_team(model, chart, envs, ticks, engine, run_diag);
  } else {
    r = interp::run_chart(model, chart, *trace, ticks, engine, run_diag);
  }
  interp::RenderOptions render;
  render.hooks = o.hooks;
  render.explain = !o.observable;
  render.indent = !o.observable;
  out << r.log.render(render);
  print(run_diag, sources, err);
  return r.completed ? kExitOk : kExitInputError;
}

} // namespace

int run_command(int argc, const char *const *argv, std::ostream &out, std::ostream &err) {
  RunOptions o;
  CLI::App app{"gfec run - runs an sfc or fsm in the reference interpreter and prints what happens each tick",
               "gfec run"};
  app.footer("The trace is CSV: a header naming interface functions, then one row per tick with what\n"
             "each returns. A function without a column returns 0 (false); past the last row the last\n"
             "row holds. A team machine runs every agent: a column `F@k` is what F returns to agent k.\n"
             "Exit status: 0 ran, 1 errors in the chart or the trace, or undefined behaviour\n"
             "while running, 2 usage or I/O error. Documentation: docs/verification.md");
  app.add_option("chart", o.input, "The chart file")->required();
  app.add_option("--inputs", o.inputs_csv, "CSV input trace: a column per sensing function, a row per tick")
      ->type_name("FILE");
  app.add_option("--ticks", o.ticks, "Ticks to run (default: one per row of the trace, or 10)")->type_name("N");
  CLI::Option *agents = app.add_option("--agents", o.agents,
                 "A team machine: how many of its agents run, in lockstep (default: all of them)")
      ->type_name("N");
  app.add_option("--chart", o.chart, "The chart to run when the file declares several")->type_name("NAME");
  app.add_option("-I", o.include_dirs, "Add DIR to the folders searched for imports")
      ->type_name("DIR")
      ->allow_extra_args(false);
  app.add_flag("--observable", o.observable,
               "Print only what an engine's caller can see (calls, activation, state), unindented");
  app.add_flag("--hooks", o.hooks, "Also print what the observation hooks report (lost, gained, enabled)");
  app.add_flag("--check-post", o.check_post, "Evaluate a terminal state's postcondition on entering it");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError &e) {
    int code = app.exit(e, out, err);
    if (code != 0) err << "Run 'gfec run --help' for the options.\n";
    return code == 0 ? kExitOk : kExitUsageOrIo;
  }
  o.agents_given = agents->count() > 0;
  return run_with(o, out, err);
}

} // namespace gfec
