#include "chart_picture.h"

#include "backend_registry.h"
#include "chart_nodes.h"

#include <fmt/format.h>

namespace gfec::lsp {

namespace {

class Elements {
public:
  Elements(const model::Model &m, const UriOf &uri_of) : m_(m), ranges_(m.sources()), uri_of_(uri_of) {}

  void add(const std::string &node, const char *kind, const std::string &name, const SourceRange &range) {
    if (!m_.sources().knows(range.file)) return;
    out_.push_back({{"node", node},
                    {"kind", kind},
                    {"name", name},
                    {"uri", uri_of_(m_.sources().file(range.file).path())},
                    {"range", ranges_.range(range)}});
  }

  /// As the DOT back end draws it (backends/dot/dot_chart.cc chart_body): places, transitions,
  /// then each sub-chart instance in its frame, its nodes under the instance's prefix.
  void chart(const model::Chart &c, const std::string &prefix, const std::string &path) {
    const char *place_kind = c.kind == model::Chart::Kind::Fsm ? "state" : "place";
    for (std::size_t i = 0; i < c.places.size(); ++i)
      add(chart_nodes::place(prefix, i), place_kind, path + std::string(c.places.at(i).name.str()),
          c.places.at(i).range);
    for (std::size_t i = 0; i < c.transitions.size(); ++i)
      add(chart_nodes::transition(prefix, i), "transition", path + std::string(c.transitions.at(i).name.str()),
          c.transitions.at(i).range);
    for (std::size_t i = 0; i < c.places.size(); ++i) {
      const model::Place &p = c.places.at(i);
      if (!p.runs) continue;
      const model::Chart &sub = m_.charts.at(p.runs);
      const std::string inner_path = path + std::string(p.name.str()) + ".";
      add(chart_nodes::instance_frame(prefix, i), "chart", inner_path.substr(0, inner_path.size() - 1), sub.range);
      chart(sub, chart_nodes::instance_prefix(prefix, i), inner_path);
    }
  }

  /// As backends/dot/dot_plan.cc draws it: actors, their supervisors, the global supervisors.
  void plan(const model::Plan &p) {
    for (std::size_t i = 0; i < p.actors.size(); ++i) {
      const model::ActorUse &a = p.actors.at(i);
      add(chart_nodes::actor(i), a.subplan ? "plan" : "actor", a.name, a.range);
      for (std::size_t s = 0; s < a.supervisors.size(); ++s)
        add(chart_nodes::supervisor(i, s), "supervisor", a.supervisors[s].name, a.supervisors[s].range);
    }
    for (std::size_t g = 0; g < p.globals.size(); ++g)
      add(chart_nodes::global_supervisor(g), "supervisor", p.globals[g].name, p.globals[g].range);
  }

  nlohmann::json take() { return std::move(out_); }

private:
  const model::Model &m_;
  SourceRanges ranges_;
  const UriOf &uri_of_;
  nlohmann::json out_ = nlohmann::json::array();
};

nlohmann::json no_picture(const nlohmann::json &version, const std::string &note) {
  return {{"version", version}, {"svg", nullptr}, {"note", note}, {"elements", nlohmann::json::array()}};
}

}  // namespace

nlohmann::json picture_elements(const model::Model &m, const pipeline::Selection &selection, const UriOf &uri_of) {
  Elements e(m, uri_of);
  if (selection.kind == pipeline::kSfc || selection.kind == pipeline::kFsm)
    e.chart(m.charts.at(selection.chart), "", "");
  if (selection.kind == pipeline::kPlan) e.plan(m.plans.at(selection.plan));
  return e.take();
}

nlohmann::json chart_picture(const pipeline::Compilation &compilation, const std::string &chart,
                             const nlohmann::json &version, const UriOf &uri_of, const ToolRunner &tools) {
  if (compilation.unreadable()) return no_picture(version, "the file cannot be read");
  if (compilation.diag.has_errors()) {
    // The client keeps its last good picture; the note says what keeps this one from being drawn.
    for (const Diagnostic &d : compilation.diag.all()) {
      if (d.severity != Severity::Error) continue;
      std::string where;
      if (compilation.sources.knows(d.range.file)) {
        const SourceFile &f = compilation.sources.file(d.range.file);
        where = fmt::format("{}:{}: ", f.path(), f.line_col(d.range.begin).line);
      }
      return no_picture(version, fmt::format("not redrawn: {} error{} in the text; the first: {}{}",
                                             compilation.diag.error_count(),
                                             compilation.diag.error_count() == 1 ? "" : "s", where, d.message));
    }
    return no_picture(version, "not redrawn: the text has errors");
  }
  pipeline::SelectionRequest request;
  request.name = chart;
  request.among = pipeline::kSfc | pipeline::kFsm | pipeline::kPlan;
  request.verb = "draw";
  const pipeline::Selection selection = pipeline::choose(compilation.model, request);
  if (!selection.chosen()) return no_picture(version, "nothing to draw: " + selection.error);

  EmitOptions emit;
  emit.output_path = "chart.svg";
  emit.source_name = compilation.sources.knows(compilation.model.main_file)
                         ? compilation.sources.file(compilation.model.main_file).path()
                         : "";
  if (selection.kind == pipeline::kPlan) emit.plan = selection.plan;
  else emit.chart = selection.chart;
  std::string svg;
  try {
    auto backend = make_backend("svg");
    svg = emit_to_memory(*backend, compilation.model, emit, tools).at(0).contents;
  } catch (const std::exception &e) {
    return no_picture(version, fmt::format("no picture of {}: {}", selection.name, e.what()));
  }
  return {{"version", version},
          {"svg", svg},
          {"note", fmt::format("{} {}", pipeline::kind_name(selection.kind), selection.name)},
          {"elements", picture_elements(compilation.model, selection, uri_of)}};
}

}  // namespace gfec::lsp
