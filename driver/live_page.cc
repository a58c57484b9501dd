#include "live_page.h"

#include "backend_registry.h"
#include "chart_nodes.h"
#include "driver.h"
#include "escape.h"
#include "external_tool.h"
#include "live_server.h"
#include "output_files.h"

#include <fmt/format.h>

#include <ostream>
#include <thread>
#include <unistd.h>

namespace gfec {

namespace {

int outline_into(const model::Model &model, model::ChartId c, viewer::ChartOutline &outline) {
  const model::Chart &chart = model.charts.at(c);
  const int index = static_cast<int>(outline.charts.size());
  outline.charts.push_back({chart.name, {}});
  std::vector<viewer::ChartOutline::Place> places;
  for (model::PlaceId i : chart.places.ids()) {
    const model::Place &p = chart.places[i];
    places.push_back(
        {p.name.str(), p.terminal != model::Terminal::None, p.runs ? outline_into(model, p.runs, outline) : -1});
  }
  outline.charts[static_cast<std::size_t>(index)].places = std::move(places);
  return index;
}

}  // namespace

viewer::ChartOutline chart_outline(const model::Model &model, model::ChartId c) {
  viewer::ChartOutline outline;
  outline_into(model, c, outline);
  return outline;
}

namespace {

/// The picture of the chart or plan `emit` names.
std::pair<std::string, std::string> picture(EmitOptions emit, const model::Model &model, const std::string &input) {
  try {
    emit.output_path = "chart.svg";
    emit.source_name = input;
    if (auto backend = make_backend("svg"))
      return {emit_to_memory(*backend, model, emit, run_external_tool).at(0).contents, ""};
    return {"", "no diagram: this gfec has no svg back end"};
  } catch (const ToolTimeLimit &) { throw; } catch (const std::exception &e) {
    return {"", fmt::format("no diagram: {}", e.what())};
  }
}

}  // namespace

std::pair<std::string, std::string> chart_picture(const model::Model &model, model::ChartId c,
                                                  const std::string &input) {
  EmitOptions emit;
  emit.chart = c;
  return picture(emit, model, input);
}

live::LiveChart live_plan(const model::Model &model, const trace::PlanLayout &layout, const std::string &input,
                          std::string source) {
  const model::Plan &plan = model.plans.at(layout.plan);
  live::LiveChart out;
  out.name = plan.name;
  out.kind = "plan";
  out.file = input;
  // A plan has no period (its executor steps it): 10 ms frames, a stepped executor's usual step.
  out.period = 0.01;
  for (const trace::PlanLevel &level : layout.levels) {
    out.level_rows.push_back(out.rows.size());
    for (std::size_t a = 0; a < level.actors.size(); ++a) {
      if (level.path.empty()) out.rows.push_back({level.actors[a], chart_nodes::actor(a), false, "", -1});
      else out.rows.push_back({level.path + "/" + level.actors[a], "", false, level.path, -1});
    }
    if (!level.path.empty())
      out.instances.push_back(
          {level.path, model.plans.at(level.plan).name, out.level_rows.back(), level.actors.size(), 0});
  }
  // The trace numbers the supervisors as the wiring adds them: the globals, then each actor's.
  for (std::size_t g = 0; g < plan.globals.size(); ++g)
    out.supervisor_nodes.push_back(chart_nodes::global_supervisor(g));
  std::size_t a = 0;
  for (const model::ActorUse &actor : plan.actors) {
    for (std::size_t s = 0; s < actor.supervisors.size(); ++s)
      out.supervisor_nodes.push_back(chart_nodes::supervisor(a, s));
    ++a;
  }
  EmitOptions emit;
  emit.plan = layout.plan;
  std::tie(out.svg, out.svg_note) = picture(emit, model, input);
  out.source = std::move(source);
  return out;
}

live::LiveChart live_chart(const model::Model &model, model::ChartId c, const std::string &input, std::string source) {
  const model::Chart &chart = model.charts.at(c);
  live::LiveChart out;
  out.name = chart.name;
  out.kind = chart.kind == model::Chart::Kind::Fsm ? "fsm" : "sfc";
  out.file = input;
  out.period = (chart.period_ms > 0 ? chart.period_ms : 10.0) / 1000;
  viewer::outline_rows(chart_outline(model, c), out.rows, out.instances);
  std::tie(out.svg, out.svg_note) = chart_picture(model, c, input);
  out.source = std::move(source);
  return out;
}

int serve_live_page(live::LiveRecording &recording, const std::string &address, bool allow_remote,
                    const std::function<void()> &read_stream, std::ostream &err) {
  std::string host;
  int port = 0;
  std::string why = live::parse_address(address, host, port);
  live::LiveServer server(recording);
  if (why.empty()) why = server.bind(host, port, allow_remote);
  if (!why.empty()) {
    err << "gfec monitor: error: --http " << text::printable(address) << ": " << text::printable(why) << "\n";
    return kExitUsageOrIo;
  }
  server.start();
  err << "gfec monitor: the live page is at " << server.url() << " (Ctrl-C stops)" << std::endl;
  read_stream();
  err << "gfec monitor: the stream ended; the page stays at " << server.url() << " until Ctrl-C" << std::endl;
  // The page of the ended run stays up; SIGINT or SIGTERM ends the process (nothing is written).
  for (;;) ::pause();
}

}  // namespace gfec
