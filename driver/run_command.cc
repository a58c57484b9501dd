#include "run_command.h"

#include "backend_registry.h"
#include "diagnostic_report.h"
#include "driver.h"
#include "external_tool.h"
#include "interpreter/input_trace.h"
#include "interpreter/run_chart.h"
#include "output_files.h"
#include "pipeline/compilation.h"
#include "recording.h"
#include "viewer_page.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <memory>
#include <ostream>
#include <sstream>
#include <vector>

namespace gfec {

namespace {

struct RunOptions {
  std::string input;
  std::string inputs_csv;
  std::uint64_t ticks = 0;
  int agents = 0;             ///< a team machine's agents (with agents_given)
  bool agents_given = false;  ///< --agents was given; else a team machine runs all its agents
  std::string chart;
  bool observable = false;  ///< only the observable layer, unindented: what engines print
  bool hooks = false;
  bool check_post = false;
  std::string html;  ///< the run viewer page ("" = none)
  Options report;    ///< -I, -x, -W..., -f...: as gfec's (add_front_end_options)
};

/// Chart `c` and the charts its places run, depth first, as the recording builder reads them;
/// returns c's index in `outline`.
int outline_chart(const model::Model &model, model::ChartId c, viewer::ChartOutline &outline) {
  const model::Chart &chart = model.charts.at(c);
  const int index = static_cast<int>(outline.charts.size());
  outline.charts.push_back({chart.name, {}});
  std::vector<viewer::ChartOutline::Place> places;
  for (model::PlaceId i : chart.places.ids()) {
    const model::Place &p = chart.places[i];
    places.push_back(
        {p.name.str(), p.terminal != model::Terminal::None, p.runs ? outline_chart(model, p.runs, outline) : -1});
  }
  outline.charts[static_cast<std::size_t>(index)].places = std::move(places);
  return index;
}

/// The run viewer's recording of an interpreter run (docs/viewer.md): the chart's picture, the
/// activation after each tick (of the chart and of each running sub-chart instance) and what
/// each tick did, taken from the run's log. Frame k is tick k + 1; there is no world and no robot.
nlohmann::json viewer_data(const model::Model &model, model::ChartId chart, const interp::RunResult &r,
                           const RunOptions &o) {
  const model::Chart &c = model.charts.at(chart);
  const bool fsm = c.kind == model::Chart::Kind::Fsm;
  const double period_ms = c.period_ms > 0 ? c.period_ms : 10.0;
  viewer::RecordingBuilder rec("gfec run", c.name, fsm ? "fsm" : "sfc", o.input, period_ms / 1000);
  // The timeline's rows: the chart's places, then each sub-chart instance's rows, depth first in
  // declaration order (the order of gfec run's `av` lines and of the picture's frames).
  viewer::ChartOutline outline;
  outline_chart(model, chart, outline);
  std::vector<viewer::Row> rows;
  std::vector<viewer::Instance> instances;
  viewer::outline_rows(outline, rows, instances);
  for (const viewer::Row &row : rows) rec.add_row(row);
  // Each instance path's first row ("" the chart's own).
  std::map<std::string, std::size_t> first_row{{"", 0}};
  for (const viewer::Instance &in : instances) {
    rec.add_instance(in);
    first_row[in.path] = in.first;
  }
  std::string svg, note;
  try {
    EmitOptions emit;
    emit.chart = chart;
    emit.output_path = "chart.svg";
    emit.source_name = o.input;
    if (auto backend = make_backend("svg"))
      svg = emit_to_memory(*backend, model, emit, run_external_tool).at(0).contents;
  } catch (const std::exception &e) { note = fmt::format("no diagram: {}", e.what()); }
  rec.set_picture(svg, note);
  long frame = -1;
  std::vector<std::string> tick_calls;
  std::string status = "running";
  std::vector<std::size_t> on;  // the rows active after the current tick
  auto finish_tick = [&] {
    if (frame >= 0) {
      rec.record_calls(frame, tick_calls);
      rec.add_tick(on);
    }
    tick_calls.clear();
    on.clear();
  };
  // "av 1 0 2" (the chart) or "av Search.Grab: 0 1" (a running instance): whose line, and the rest.
  auto owner = [](const std::string &text, std::size_t from) {
    std::size_t space = text.find(' ', from);
    if (space != std::string::npos && space > from && text[space - 1] == ':')
      return std::make_pair(text.substr(from, space - 1 - from), space + 1);
    return std::make_pair(std::string(), from);
  };
  for (const interp::Event &e : r.log.events()) {
    switch (e.kind) {
    case interp::EventKind::Tick:
      finish_tick();
      ++frame;
      break;
    case interp::EventKind::Av:
    case interp::EventKind::InstanceAv: {
      // The activation of each place after the tick; an instance's line only while it runs.
      auto [path, rest] = owner(e.text, 3);
      auto first = first_row.find(path);
      if (first == first_row.end()) break;
      std::istringstream counts(e.text.substr(rest));
      unsigned long n = 0;
      for (std::size_t p = 0; counts >> n; ++p)
        if (n > 0) on.push_back(first->second + p);
      break;
    }
    case interp::EventKind::InstanceState: break;  // its rows say it; not the run's status
    case interp::EventKind::State: {
      // "state Z3 succeeded": the status is the last word.
      std::string now = e.text.substr(e.text.rfind(' ') + 1);
      if (now != status) rec.add_event(frame, "status", now);
      status = now;
      break;
    }
    case interp::EventKind::Fire: rec.add_event(frame, fsm ? "state" : "fire", e.text); [[fallthrough]];
    default:
      if (interp::layer_of(e.kind) != interp::Layer::Hooks)
        tick_calls.push_back(std::string(static_cast<std::size_t>(2 * std::max(0, e.depth - 1)), ' ') + e.text);
    }
    if (frame >= 0) rec.record_status(frame, status);
  }
  finish_tick();
  const long frames = rec.frames();
  rec.set_title(
      fmt::format("{} ({}): {} after {} tick{}", c.name, fsm ? "fsm" : "sfc", status, frames, frames == 1 ? "" : "s"),
      fmt::format("gfec run {}{}{} \u00b7 reference interpreter \u00b7 period {:g} ms", o.input,
                  o.inputs_csv.empty() ? "" : " --inputs ", o.inputs_csv, period_ms));
  return rec.data();
}

int run_with(const RunOptions &o, DiagnosticReport &report, std::ostream &out) {
  pipeline::FrontEndOptions f = front_end_options(o.report);
  f.analyze = false;  // a run reports what happens, not what the analyses would find
  pipeline::Compilation c(f);
  c.front_end(o.input);
  if (c.unreadable()) {
    report.tool_error(o.input, cannot_read(o.input), false);
    return kExitUsageOrIo;
  }
  report.add(o.input, c.diag, c.sources);
  if (c.diag.has_errors()) return kExitInputError;
  const model::Model &model = c.model;

  // The sfc or fsm of the main file to run: the one no chart runs (docs/language.md
  // "Sub-charts"), or the one --chart names.
  pipeline::SelectionRequest request;
  request.name = o.chart;
  request.among = pipeline::kSfc | pipeline::kFsm;
  request.verb = "run";
  pipeline::Selection target = pipeline::choose(model, request);
  if (!target.chosen()) {
    report.tool_error(o.input, target.error, true);
    return kExitUsageOrIo;
  }
  const model::ChartId chart = target.chart;
  // A team machine runs as a team (docs/cli.md): every agent by default, or --agents of them.
  const int team = model.charts[chart].team;
  int agents = 1;
  if (team > 0) agents = o.agents_given ? o.agents : team;
  if (o.agents_given && (o.agents < 1 || o.agents > std::max(team, 1))) {
    report.tool_error(o.input,
                      team > 0 ? fmt::format("--agents {}: '{}' is a team of 1 to {} agents", o.agents,
                                             model.charts[chart].name, team)
                               : fmt::format("--agents {}: '{}' is no team machine; it runs as one agent", o.agents,
                                             model.charts[chart].name),
                      false);
    return kExitUsageOrIo;
  }

  RealFileSystem fs;
  Diagnostics trace_diag;
  std::unique_ptr<interp::InputTrace> trace;
  if (!o.inputs_csv.empty()) {
    auto text = fs.read(o.inputs_csv);
    if (!text) {
      report.tool_error(o.inputs_csv, cannot_read(o.inputs_csv), false);
      return kExitUsageOrIo;
    }
    FileId id = c.sources.add(o.inputs_csv, *text);
    trace = std::make_unique<interp::InputTrace>(model, c.sources, id, trace_diag, agents);
    report.add(o.inputs_csv, trace_diag, c.sources);
    if (trace_diag.has_errors()) return kExitInputError;
  } else {
    trace = std::make_unique<interp::InputTrace>(model);
  }
  // Without --ticks: up to the trace's last row (its tick, or its number), or ten.
  std::uint64_t ticks = o.ticks ? o.ticks : trace->last_tick() ? trace->last_tick() : 10;

  interp::MachineOptions engine;
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
  out << r.log.render(render) << std::flush;
  report.add(o.input, run_diag, c.sources);
  if (!o.html.empty()) {
    // Never over the chart, a file it imports or the inputs (docs/security.md).
    std::vector<std::string> inputs{o.input, o.inputs_csv};
    for (FileId i = 0; i < c.sources.size(); ++i) inputs.push_back(c.sources.file(i).path());
    std::string failed = write_atomically({{o.html, viewer::page(viewer_data(model, chart, r, o))}}, inputs);
    if (!failed.empty()) {
      report.tool_error(o.html, failed, false);
      return kExitUsageOrIo;
    }
  }
  return r.completed ? kExitOk : kExitInputError;
}

}  // namespace

int run_command(int argc, const char *const *argv, std::ostream &out, std::ostream &err) {
  RunOptions o;
  CLI::App app{"gfec run - runs an sfc or fsm in the reference interpreter and prints what happens each tick",
               "gfec run"};
  app.footer("The trace is CSV: a header naming interface functions, then one row per tick with what\n"
             "each returns; with a `tick` column a row holds from its tick until the next row's. A\n"
             "function without a column returns 0 (false); past the last row the last row holds. A team machine runs "
             "every agent: a column `F@k` is what F returns to agent k.\n"
             "Exit status: 0 ran, 1 errors in the chart or the trace, or undefined behaviour\n"
             "while running, 2 usage or I/O error. Documentation: docs/verification.md");
  app.add_option("chart", o.input, "The chart file")->required();
  app.add_option("--inputs", o.inputs_csv, "CSV input trace: a column per sensing function, a row per tick")
      ->type_name("FILE");
  app.add_option("--ticks", o.ticks, "Ticks to run (default: up to the trace's last row, or 10)")->type_name("N");
  CLI::Option *agents = app.add_option("--agents", o.agents,
                                       "A team machine: how many of its agents run, in lockstep (default: all of them)")
                            ->type_name("N");
  app.add_option("--chart", o.chart, "The chart to run when the file declares several")->type_name("NAME");
  app.add_flag("--observable", o.observable,
               "Print only what an engine's caller can see (calls, activation, state), unindented");
  app.add_flag("--hooks", o.hooks, "Also print what the observation hooks report (lost, gained, enabled)");
  app.add_option("--html", o.html, "Also write the run viewer: a self-contained HTML page of the run (docs/viewer.md)")
      ->type_name("FILE");
  app.add_flag("--check-post", o.check_post, "Evaluate a terminal state's postcondition on entering it");
  FrontEndFlags front_end;
  add_front_end_options(app, o.report, front_end);
  if (auto code = parse_subcommand(app, argc, argv, out, err, "run")) return *code;
  o.agents_given = agents->count() > 0;
  // The text style gfec run has always printed: no line-number gutter unless asked for.
  o.report.line_numbers = false;
  if (std::string why = front_end.apply(o.report); !why.empty()) {
    err << "gfec: error: " << why << "\nRun 'gfec run --help' for the options.\n";
    return kExitUsageOrIo;
  }
  auto report = make_report(o.report, err);
  return finish_report(*report, run_with(o, *report, out), err);
}

}  // namespace gfec
