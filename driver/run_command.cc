#include "run_command.h"

#include "commands.h"
#include "escape.h"
#include "backend_registry.h"
#include "diagnostic_report.h"
#include "driver.h"
#include "external_tool.h"
#include "interpreter/input_trace.h"
#include "interpreter/machine.h"
#include "interpreter/value.h"
#include "interpreter/run_chart.h"
#include "live_page.h"
#include "output_files.h"
#include "pipeline/compilation.h"
#include "recording.h"
#include "runnable_chart.h"
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

/// The most ticks one run may take: the log is streamed, so memory does not grow with the
/// ticks, but a typo such as --ticks 10000000000 would otherwise run for hours (docs/cli.md).
constexpr std::uint64_t kMaxRunTicks = 10000000;
/// With --html the page keeps every tick's frame: at most this many.
constexpr std::uint64_t kMaxHtmlTicks = 100000;

struct RunOptions {
  std::string input;
  std::string inputs_csv;
  long long ticks = 0;        ///< 0: one per row of the trace, or 10
  int agents = 0;             ///< a team machine's agents (with agents_given)
  bool agents_given = false;  ///< --agents was given; else a team machine runs all its agents
  std::string chart;
  bool observable = false;  ///< only the observable layer, unindented: what engines print
  bool hooks = false;
  bool check_post = false;
  std::string html;  ///< the run viewer page ("" = none)
  Options report;    ///< -I, -x, -W..., -f...: as gfec's (add_front_end_options)
};

/// The run viewer's recording of an interpreter run (docs/viewer.md), built as the run goes
/// (feed() after each tick): the chart's picture, the activation after each tick (of the chart
/// and of each running sub-chart instance) and what each tick did, taken from the run's log.
/// Frame k is tick k + 1; there is no world and no robot. It keeps every frame, so a run with
/// --html is bounded by kMaxHtmlTicks.
class RunViewer {
public:
  RunViewer(const model::Model &model, model::ChartId chart, const RunOptions &o)
      : c_(model.charts.at(chart)), fsm_(c_.kind == model::Chart::Kind::Fsm),
        period_ms_(c_.period_ms > 0 ? c_.period_ms : 10.0),
        rec_("gfec run", c_.name, fsm_ ? "fsm" : "sfc", o.input, period_ms_ / 1000), o_(o) {
    // The timeline's rows: the chart's places, then each sub-chart instance's rows, depth first
    // in declaration order (the order of gfec run's `av` lines and of the picture's frames).
    std::vector<viewer::Row> rows;
    std::vector<viewer::Instance> instances;
    viewer::outline_rows(chart_outline(model, chart), rows, instances);
    for (const viewer::Row &row : rows) rec_.add_row(row);
    for (const viewer::Instance &in : instances) {
      rec_.add_instance(in);
      first_row_[in.path] = in.first;
    }
    const auto [svg, note] = chart_picture(model, chart, o.input);
    rec_.set_picture(svg, note);
    // The vars' initial values as the interpreter's _init sets them; each tick's `set` lines
    // then give their changes. A team's agents each have their own vars, which the log does
    // not tell apart: their declarations only.
    interp::Machine initial(model, chart);
    std::string unknown;
    try {
      initial.init();
    } catch (const std::exception &e) {
      unknown = e.what();  // the run reports it, located, at its first tick
    }
    for (model::VarId v : c_.vars.ids())
      rec_.add_var(model::type_name(c_.vars[v].type), c_.vars[v].name,
                   unknown.empty() ? interp::format_value(initial.vars()[v]) : "?");
    if (!unknown.empty()) rec_.set_vars_note("no initial values: " + unknown);
    if (c_.team > 0 && !c_.vars.empty())
      rec_.set_vars_note("each agent of the team has its own vars: their initial values");
  }

  void feed(const std::vector<interp::Event> &events) {
    for (const interp::Event &e : events) {
      // Whose statements run now: a sub-chart instance's places are named by their path ("A.S").
      if (e.kind == interp::EventKind::Entry || e.kind == interp::EventKind::Action ||
          e.kind == interp::EventKind::Exit)
        in_instance_ = e.text.find('.') != std::string::npos;
      else if (e.kind == interp::EventKind::RunInstance || e.kind == interp::EventKind::Start ||
               e.kind == interp::EventKind::Stop)
        in_instance_ = true;
      else if (e.kind == interp::EventKind::Assign && !in_instance_ && c_.team == 0 && frame_ >= 0) record_var(e.text);
      switch (e.kind) {
      case interp::EventKind::Tick:
        finish_tick();
        ++frame_;
        break;
      case interp::EventKind::Av:
      case interp::EventKind::InstanceAv: {
        // The activation of each place after the tick; an instance's line only while it runs.
        auto [path, rest] = owner(e.text, 3);
        auto first = first_row_.find(path);
        if (first == first_row_.end()) break;
        std::istringstream counts(e.text.substr(rest));
        unsigned long n = 0;
        for (std::size_t p = 0; counts >> n; ++p)
          if (n > 0) on_.push_back(first->second + p);
        break;
      }
      case interp::EventKind::InstanceState: break;  // its rows say it; not the run's status
      case interp::EventKind::State: {
        // "state Z3 succeeded": the status is the last word.
        std::string now = e.text.substr(e.text.rfind(' ') + 1);
        if (now != status_) rec_.add_event(frame_, "status", now);
        status_ = now;
        break;
      }
      case interp::EventKind::Fire: rec_.add_event(frame_, fsm_ ? "state" : "fire", e.text); [[fallthrough]];
      default:
        if (interp::layer_of(e.kind) != interp::Layer::Hooks)
          tick_calls_.push_back(std::string(static_cast<std::size_t>(2 * std::max(0, e.depth - 1)), ' ') + e.text);
      }
      if (frame_ >= 0) rec_.record_status(frame_, status_);
    }
  }

  nlohmann::json finish() {
    finish_tick();
    const long frames = rec_.frames();
    rec_.set_title(fmt::format("{} ({}): {} after {} tick{}", c_.name, fsm_ ? "fsm" : "sfc", status_, frames,
                               frames == 1 ? "" : "s"),
                   fmt::format("gfec run {}{}{} \u00b7 reference interpreter \u00b7 period {:g} ms", o_.input,
                               o_.inputs_csv.empty() ? "" : " --inputs ", o_.inputs_csv, period_ms_));
    return rec_.data();
  }

private:
  void finish_tick() {
    if (frame_ >= 0) {
      rec_.record_calls(frame_, tick_calls_);
      rec_.add_tick(on_);
    }
    tick_calls_.clear();
    on_.clear();
  }
  /// "set parts = 3": the chart's var `parts` is 3 after this tick.
  void record_var(const std::string &text) {
    std::size_t eq = text.find(" = ");
    if (text.rfind("set ", 0) != 0 || eq == std::string::npos) return;
    std::string name = text.substr(4, eq - 4);
    for (model::VarId v : c_.vars.ids())
      if (c_.vars[v].name == name) rec_.record_var(v.index(), frame_, text.substr(eq + 3));
  }
  /// "av 1 0 2" (the chart) or "av Search.Grab: 0 1" (a running instance): whose line, and the rest.
  static std::pair<std::string, std::size_t> owner(const std::string &text, std::size_t from) {
    std::size_t space = text.find(' ', from);
    if (space != std::string::npos && space > from && text[space - 1] == ':')
      return std::make_pair(text.substr(from, space - 1 - from), space + 1);
    return std::make_pair(std::string(), from);
  }

  const model::Chart &c_;
  const bool fsm_;
  const double period_ms_;
  viewer::RecordingBuilder rec_;
  const RunOptions &o_;
  std::map<std::string, std::size_t> first_row_{{"", 0}};  ///< each instance path's first row
  long frame_ = -1;
  std::vector<std::string> tick_calls_;
  std::string status_ = "running";
  std::vector<std::size_t> on_;  ///< the rows active after the current tick
  bool in_instance_ = false;     ///< the statements running now are a sub-chart instance's
};

int run_with(const RunOptions &o, DiagnosticReport &report, std::ostream &out) {
  const RunnableChart loaded = load_runnable_chart(o.report, o.input, o.chart, "run", report);
  if (loaded.exit_code != kExitOk) return loaded.exit_code;
  pipeline::Compilation &c = *loaded.compilation;  // the trace's CSV joins its sources
  const model::Model &model = c.model;
  const model::ChartId chart = loaded.chart;
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
      report.tool_error(o.inputs_csv, cannot_read(o.inputs_csv, text.why), false);
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
  const std::uint64_t ticks = o.ticks              ? static_cast<std::uint64_t>(o.ticks)
                              : trace->last_tick() ? trace->last_tick()
                                                   : 10;
  if (ticks > kMaxRunTicks || (!o.html.empty() && ticks > kMaxHtmlTicks)) {
    report.tool_error(o.inputs_csv.empty() ? o.input : o.inputs_csv,
                      fmt::format("{} ticks is more than gfec run runs{}: at most {} (docs/cli.md)", ticks,
                                  o.html.empty() ? "" : " with --html", o.html.empty() ? kMaxRunTicks : kMaxHtmlTicks),
                      false);
    return kExitUsageOrIo;
  }

  // The page's picture is drawn before the run, so a chart too large to draw costs no run.
  std::unique_ptr<RunViewer> viewer;
  if (!o.html.empty()) {
    try {
      viewer = std::make_unique<RunViewer>(model, chart, o);
    } catch (const ToolTimeLimit &e) {
      report.tool_error(o.input, e.what(), false);
      return kExitInputError;
    }
  }
  interp::RenderOptions render;
  render.hooks = o.hooks;
  render.explain = !o.observable;
  render.indent = !o.observable;
  // Each tick's lines are printed (and recorded) as soon as it ends, then dropped: the log of a
  // long run is never held whole.
  auto after_tick = [&](interp::EventLog &log) {
    out << log.render(render);
    if (viewer) viewer->feed(log.events());
    log.clear();
  };
  interp::MachineOptions engine;
  engine.check_post = o.check_post;
  Diagnostics run_diag;
  interp::RunResult r;
  if (team > 0) {
    std::vector<interp::InputTrace::Agent> inputs;
    for (int k = 0; k < agents; ++k) inputs.emplace_back(*trace, k);
    std::vector<interp::Environment *> envs;
    for (auto &i : inputs) envs.push_back(&i);
    r = interp::run_team(model, chart, envs, ticks, engine, run_diag, after_tick);
  } else {
    r = interp::run_chart(model, chart, *trace, ticks, engine, run_diag, after_tick);
  }
  after_tick(r.log);  // what the tick that stopped the run did
  out << std::flush;
  report.add(o.input, run_diag, c.sources);
  if (viewer) {
    // Never over the chart, a file it imports or the inputs (docs/security.md).
    std::vector<std::string> inputs{o.input, o.inputs_csv};
    for (FileId i = 0; i < c.sources.size(); ++i) inputs.push_back(c.sources.file(i).path());
    std::string failed = write_atomically({{o.html, viewer::page(viewer->finish())}}, inputs);
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
             "while running, 2 usage or I/O error.\n" +
             documentation_line("verification.md"));
  app.add_option("chart", o.input, "The chart file")->required();
  app.add_option("--inputs", o.inputs_csv, "CSV input trace: a column per sensing function, a row per tick")
      ->type_name("FILE");
  app.add_option("--ticks", o.ticks, "Ticks to run (default: up to the trace's last row, or 10)")
      ->type_name("N")
      ->check(CLI::Range(1LL, static_cast<long long>(kMaxRunTicks)));
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
    err << "gfec: error: " << text::printable(why) << "\nRun 'gfec run --help' for the options.\n";
    return kExitUsageOrIo;
  }
  auto report = make_report(o.report, err);
  return finish_report(*report, run_with(o, *report, out), err);
}

}  // namespace gfec
