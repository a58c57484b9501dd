// Sub-charts (docs/language.md "Sub-charts"): which chart each `runs` names, charts that run
// themselves, charts that embed too many instances, and the period a sub-chart takes from the
// charts that run it. Runs before any chart body is lowered, because durations in a sub-chart
// are counted in its (inherited) period.
#include "validate/families.h"
#include "validate/suggest.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <functional>

namespace gfec::validation {

namespace {

/// One `runs`: place `place` of chart `parent` runs chart `child`.
struct Edge {
  model::ChartId parent;
  model::PlaceId place;
  model::ChartId child;
};

std::string period_text(double ms) { return ms > 0 ? fmt::format("period {:g}ms", ms) : std::string("no period"); }

const ast::Name &runs_name(const Context &cx, const Edge &e) {
  return *cx.charts[e.parent]->places[e.place.index()].runs();
}

/// Resolves the chart after each `runs`; reports unknown names, plans and terminal states.
std::vector<Edge> resolve_runs(Context &cx) {
  std::vector<Edge> edges;
  for (model::ChartId c : cx.charts.ids()) {
    const ast::Chart &chart = *cx.charts[c];
    cx.runs[c].assign(chart.places.size(), model::ChartId());
    for (std::size_t i = 0; i < chart.places.size(); ++i) {
      const model::PlaceId p(i);
      const ast::Place &place = chart.places[i];
      if (!place.runs() || place.runs()->text.empty()) continue;
      const ast::Name &name = *place.runs();
      if (place.terminal != ast::StateKind::Normal) {
        cx.diag.error(
            name.range, ErrorKind::TerminalRuns,
            fmt::format("terminal state '{}' cannot run a sub-chart: the machine has stopped there", place.name.text));
        continue;
      }
      const Symbol *sym = cx.c_names.resolve(name);
      if (!sym) sym = cx.plan_names.resolve(name);
      if (!sym) {
        auto &d = cx.diag.error(name.range, ErrorKind::UnknownName, fmt::format("unknown chart '{}'", name.text));
        suggest(d, name.text, cx.c_names.of({Sym::Chart}));
        continue;
      }
      if (sym->kind != Sym::Chart) {
        cx.diag
            .error(
                name.range, ErrorKind::TypeMismatch,
                fmt::format("'{}' is {}; a place or state runs an sfc or an fsm", name.text, with_article(sym->kind)))
            .note(sym->range, fmt::format("'{}' declared here", name.text));
        continue;
      }
      const model::ChartId child = sym->id<model::ChartId>();
      const ast::Chart &run = *cx.charts[child];
      if (!run.teams.empty()) {
        // A team machine talks to other agents through its root's API (docs/language.md "Teams").
        cx.diag
            .error(
                name.range, ErrorKind::TeamSubchart,
                fmt::format("fsm '{}' is a team machine; it can only be compiled as the root, not run as a sub-chart",
                            name.text))
            .note(run.teams.front().second, "it is made a team machine here");
        continue;
      }
      cx.runs[c][p] = child;
      edges.push_back({c, p, child});
    }
  }
  return edges;
}

/// Reports every cycle of `runs` once (one per back edge of a depth-first search), at its
/// first step, with a note at each step. Returns whether there was one.
bool report_cycles(Context &cx, const std::vector<Edge> &edges) {
  std::size_t n = cx.charts.size();
  IdMap<model::ChartId, std::vector<const Edge *>> out(n);
  for (const Edge &e : edges) out[e.parent].push_back(&e);
  enum Color { White, Grey, Black };
  IdMap<model::ChartId, Color> color(n, White);
  std::vector<const Edge *> stack;  // the edges from the search's root to the current chart
  bool found = false;
  // Depth first without recursion (a chain of thousands of charts would overflow the stack): a
  // frame per chart on the path, with the next of its edges to follow.
  struct Frame {
    model::ChartId chart;
    std::size_t next = 0;
  };
  std::vector<Frame> path;
  for (model::ChartId root : cx.charts.ids()) {
    if (color[root] != White) continue;
    color[root] = Grey;
    path.push_back({root});
    while (!path.empty()) {
      Frame &top = path.back();
      if (top.next == out[top.chart].size()) {
        color[top.chart] = Black;
        path.pop_back();
        if (!stack.empty() && !path.empty()) stack.pop_back();
        continue;
      }
      const Edge *e = out[top.chart][top.next++];
      if (color[e->child] == Grey) {
        std::vector<const Edge *> cycle;
        // The cycle starts with the edge on the path that leaves e->child (none for a self-loop).
        std::size_t first = stack.size();
        while (e->parent != e->child && first > 0) {
          --first;
          if (stack[first]->parent == e->child) break;
        }
        cycle.assign(stack.begin() + static_cast<std::ptrdiff_t>(first), stack.end());
        cycle.push_back(e);
        std::string steps = cx.model.charts[cycle.front()->parent].name;
        for (const Edge *s : cycle) steps += " -> " + cx.model.charts[s->child].name;
        const model::Chart &head = cx.model.charts[cycle.front()->parent];
        auto &d = cx.diag.error(runs_name(cx, *cycle.front()).range, ErrorKind::SubchartCycle,
                                cycle.size() == 1
                                    ? fmt::format("chart '{}' runs itself", head.name)
                                    : fmt::format("chart '{}' runs itself through other charts: {}", head.name, steps));
        for (const Edge *s : cycle) {
          const ast::Place &place = cx.charts[s->parent]->places[s->place.index()];
          d.note(runs_name(cx, *s).range,
                 fmt::format("{} '{}' of '{}' runs '{}'", place.is_state ? "state" : "place", place.name.text,
                             cx.model.charts[s->parent].name, cx.model.charts[s->child].name));
        }
        found = true;
        continue;
      }
      if (color[e->child] == Black) continue;
      stack.push_back(e);
      color[e->child] = Grey;
      path.push_back({e->child});
    }
  }
  return found;
}

/// How many sub-chart instances a compiled chart may embed, at every depth (docs/security.md,
/// docs/hierarchy.md): each is a struct and a copy of its chart's code in the engine, so the
/// engine and the compile grow with them. 65,536 is far beyond any hierarchy written by hand; the
/// back ends are linear in the instances, and 65,536 of a small chart compile in a few seconds
/// (docs/performance.md, "Sub-chart instances in the C back end").
constexpr std::uint64_t kMaxInstances = 65536;
/// How many levels of instances a compiled chart may nest below it, as deep as imports and ALICA
/// plans nest (docs/security.md): the back ends and the interpreter descend into an instance by
/// recursion (a chain of 30,000 charts overflowed the stack), and an instance's names in the C
/// engine follow its path (`Patrol_Search_Scan`), so that a chain of charts would cost the square
/// of its length. 200 levels of 65,536 instances bound both.
constexpr std::uint64_t kMaxDepth = 200;
/// How long an instance's path of names may be: the chart's name and the names of the places or
/// states that lead to the deepest instance, joined by one byte each. The engine's names for an
/// instance follow its path, and each level's names repeat the levels above, so 200 levels of
/// 4,000-character names wrote 972 MB of C (3.4 GB of memory); 4,096 bytes bound every name an
/// instance gives the engine, far beyond a path written by hand.
constexpr std::uint64_t kMaxInstancePath = 4096;
/// Where the counts stop growing: a tree of 20 levels of 10 would overflow 64 bits.
constexpr std::uint64_t kSaturated = std::uint64_t(1) << 62;

std::uint64_t add_saturating(std::uint64_t a, std::uint64_t b) { return a >= kSaturated - b ? kSaturated : a + b; }

std::string count_text(std::uint64_t n) {
  return n >= kSaturated ? fmt::format("at least {}", kSaturated) : std::to_string(n);
}

/// Of a chart's own `runs` (never empty), the one whose sub-chart has the largest `measure`
/// (levels below it, instances it brings): the first of equals, for the note of an error.
const Edge *largest(const std::vector<const Edge *> &runs, const IdMap<model::ChartId, std::uint64_t> &measure) {
  const Edge *best = runs.front();
  for (const Edge *e : runs)
    if (measure[e->child] > measure[best->child]) best = e;
  return best;
}

/// A chart that runs a sub-chart embeds an instance of it for every place or state that runs
/// it, and in each instance the instances it runs in turn: ten states that each run a chart of
/// ten states that each run ... multiply. Counts them per chart, and how many levels they nest
/// (once each, children first: linear in the charts and the `runs`), and reports every chart of
/// the main file that embeds more than kMaxInstances or nests them deeper than kMaxDepth and that
/// no chart of the main file runs: the roots a compile picks. The graph has no cycle here.
void check_instances(Context &cx, const std::vector<Edge> &edges) {
  std::size_t n = cx.charts.size();
  IdMap<model::ChartId, std::vector<const Edge *>> out(n);
  IdMap<model::ChartId, bool> run_in_main(n, false);
  for (const Edge &e : edges) {
    out[e.parent].push_back(&e);
    if (cx.in_main_file(cx.charts[e.parent]->range)) run_in_main[e.child] = true;
  }
  // Post-order without recursion, so a long chain of charts costs no stack.
  IdMap<model::ChartId, std::uint64_t> count(n, 0);
  IdMap<model::ChartId, std::uint64_t> depth(n, 0);  // levels of instances below the chart; at most n
  IdMap<model::ChartId, std::uint64_t> path(n, 0);   // bytes of the longest path of names below it
  IdMap<model::ChartId, bool> done(n, false);
  std::vector<std::pair<model::ChartId, std::size_t>> stack;  // a chart and its next edge
  for (model::ChartId root : cx.charts.ids()) {
    if (done[root]) continue;
    stack.push_back({root, 0});
    while (!stack.empty()) {
      auto &[c, next] = stack.back();
      if (next < out[c].size()) {
        model::ChartId child = out[c][next++]->child;
        if (!done[child]) stack.push_back({child, 0});
        continue;
      }
      std::uint64_t total = 0;
      for (const Edge *e : out[c]) {
        total = add_saturating(total, add_saturating(1, count[e->child]));
        depth[c] = std::max(depth[c], 1 + depth[e->child]);
        const std::uint64_t here = cx.charts[c]->places[e->place.index()].name.text.size() + 1;
        path[c] = std::max(path[c], add_saturating(here, path[e->child]));
      }
      count[c] = total;
      done[c] = true;
      stack.pop_back();
    }
  }
  for (model::ChartId c : cx.charts.ids()) {
    const ast::Chart &chart = *cx.charts[c];
    if (run_in_main[c] || !cx.in_main_file(chart.range)) continue;
    const char *kind = chart.kind == ast::Chart::Kind::Fsm ? "fsm" : "sfc";
    if (depth[c] > kMaxDepth) {
      const Edge *deepest = largest(out[c], depth);
      const ast::Place &place = chart.places[deepest->place.index()];
      const std::string &child = cx.model.charts[deepest->child].name;
      cx.diag
          .error(chart.name.range, ErrorKind::SubchartDepth,
                 fmt::format("{} '{}' nests sub-chart instances {} levels deep, more than the {} gfec compiles", kind,
                             chart.name.text, depth[c], kMaxDepth))
          .note(runs_name(cx, *deepest).range,
                fmt::format("{} '{}' runs '{}', which goes the deepest: {} levels ('{}' and the {} below it)",
                            place.is_state ? "state" : "place", place.name.text, child, depth[c], child,
                            depth[deepest->child]));
    }
    if (depth[c] <= kMaxDepth && chart.name.text.size() + path[c] > kMaxInstancePath) {
      const Edge *longest = largest(out[c], path);
      const ast::Place &place = chart.places[longest->place.index()];
      cx.diag
          .error(chart.name.range, ErrorKind::SubchartDepth,
                 fmt::format("{} '{}' has sub-chart instances whose path of names is {} bytes long, more than the {} "
                             "gfec compiles (the engine names an instance after its path)",
                             kind, chart.name.text, count_text(chart.name.text.size() + path[c]), kMaxInstancePath))
          .note(runs_name(cx, *longest).range,
                fmt::format("{} '{}' runs '{}', whose instances have the longest path",
                            place.is_state ? "state" : "place", place.name.text, cx.model.charts[longest->child].name));
    }
    if (count[c] <= kMaxInstances) continue;
    const Edge *most = largest(out[c], count);
    const ast::Place &place = chart.places[most->place.index()];
    const std::string &child = cx.model.charts[most->child].name;
    const std::uint64_t brings = add_saturating(1, count[most->child]);
    cx.diag
        .error(chart.name.range, ErrorKind::SubchartInstances,
               fmt::format("{} '{}' embeds {} sub-chart instances, more than the {} gfec compiles", kind,
                           chart.name.text, count_text(count[c]), kMaxInstances))
        .note(runs_name(cx, *most).range,
              fmt::format("{} '{}' runs '{}', which brings the most: {}", place.is_state ? "state" : "place",
                          place.name.text, child, count_text(brings)) +
                  (brings >= kSaturated ? std::string()
                                        : fmt::format(" ('{}' and the {} it embeds)", child, count[most->child])));
  }
}

/// The period a chart declares (the first one, if valid), or 0.
double declared_period(const ast::Chart &c) { return !c.periods.empty() && c.periods[0].ms > 0 ? c.periods[0].ms : 0; }

/// A sub-chart runs at its parent's rate: one that declares a period must declare the parent's;
/// one that declares none takes it. Runs parents first (the graph has no cycle here).
void inherit_periods(Context &cx, const std::vector<Edge> &edges) {
  std::size_t n = cx.charts.size();
  IdMap<model::ChartId, std::vector<const Edge *>> runners(n);
  for (const Edge &e : edges) runners[e.child].push_back(&e);
  IdMap<model::ChartId, int> state(n, 0);  // 0 not yet, 1 in progress, 2 done
  IdMap<model::ChartId, double> effective(n, 0);
  IdMap<model::ChartId, const Edge *> inherited_from(n, nullptr);
  std::function<double(model::ChartId)> period = [&](model::ChartId i) -> double {
    if (state[i] == 2) return effective[i];
    if (state[i] == 1) return 0;  // unreachable without cycles; keeps a bug from recursing forever
    state[i] = 1;
    const ast::Chart &chart = *cx.charts[i];
    double own = declared_period(chart);
    effective[i] = own;
    for (const Edge *e : runners[i]) {
      double parent = period(e->parent);
      const std::string &parent_name = cx.model.charts[e->parent].name;
      const ast::Name &at = runs_name(cx, *e);
      if (own > 0) {
        if (parent == own) continue;
        cx.diag
            .error(at.range, ErrorKind::Period,
                   fmt::format("sub-chart '{}' declares {} but '{}', which runs it, has {}", chart.name.text,
                               period_text(own), parent_name, period_text(parent)))
            .note(chart.periods[0].range, "a sub-chart runs at the period of the chart that runs it; "
                                          "remove this period or make the two equal");
        continue;
      }
      if (!inherited_from[i]) {
        inherited_from[i] = e;
        effective[i] = parent;
        continue;
      }
      if (parent == effective[i]) continue;
      const Edge &first = *inherited_from[i];
      cx.diag
          .error(at.range, ErrorKind::Period,
                 fmt::format("sub-chart '{}' would run at {} here but at {} in '{}'; it declares no period of its own",
                             chart.name.text, period_text(parent), period_text(effective[i]),
                             cx.model.charts[first.parent].name))
          .note(runs_name(cx, first).range, fmt::format("'{}' is also run here", chart.name.text));
    }
    state[i] = 2;
    return effective[i];
  };
  for (model::ChartId c : cx.charts.ids()) {
    period(c);
    if (declared_period(*cx.charts[c]) <= 0 && cx.charts[c]->periods.empty()) cx.inherited_period[c] = effective[c];
  }
}

}  // namespace

void resolve_subcharts(Context &cx) {
  cx.runs.assign(cx.charts.size(), IdMap<model::PlaceId, model::ChartId>());
  cx.inherited_period.assign(cx.charts.size(), 0);
  std::vector<Edge> edges = resolve_runs(cx);
  if (edges.empty()) return;
  if (report_cycles(cx, edges)) return;
  check_instances(cx, edges);
  inherit_periods(cx, edges);
}

}  // namespace gfec::validation
