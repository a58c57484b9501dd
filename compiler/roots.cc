#include "roots.h"

#include <fmt/format.h>

namespace gfec {

std::vector<model::ChartId> root_charts(const model::Model &m) {
  IdMap<model::ChartId, bool> run(m.charts.size(), false);
  for (const auto &c : m.charts)
    for (const auto &p : c.places)
      if (m.charts.contains(p.runs)) run[p.runs] = true;
  std::vector<model::ChartId> roots;
  for (model::ChartId i : m.charts.ids())
    if (m.charts[i].in_main_file && !run[i]) roots.push_back(i);
  return roots;
}

model::ChartId default_root(const model::Model &m) {
  std::vector<model::ChartId> roots = root_charts(m);
  return roots.size() == 1 ? roots.front() : model::ChartId::none();
}

IdMap<model::ChartId, bool> charts_in_tree(const model::Model &m, model::ChartId root) {
  IdMap<model::ChartId, bool> in(m.charts.size(), false);
  std::vector<model::ChartId> work;
  if (m.charts.contains(root)) work.push_back(root);
  while (!work.empty()) {
    model::ChartId c = work.back();
    work.pop_back();
    if (in[c]) continue;
    in[c] = true;
    for (const auto &p : m.charts[c].places)
      if (p.runs) work.push_back(p.runs);
  }
  return in;
}

void warn_unused_charts(const model::Model &m, model::ChartId root, Diagnostics &diag) {
  IdMap<model::ChartId, bool> in = charts_in_tree(m, root);
  bool hierarchy = false;
  for (model::ChartId i : in.ids())
    if (in[i] && i != root) hierarchy = true;
  if (!hierarchy) return;
  const model::Chart &r = m.charts[root];
  for (model::ChartId i : m.charts.ids()) {
    const model::Chart &c = m.charts[i];
    if (!c.in_main_file || in[i]) continue;
    diag.warning(Warning::UnusedChart, c.range,
                 fmt::format("{} '{}' is neither compiled nor run by '{}', the chart being compiled",
                             c.kind == model::Chart::Kind::Fsm ? "fsm" : "sfc", c.name, r.name))
        .note(r.range, fmt::format("to use it, let a place or state of '{}' run it ('runs {}')", r.name, c.name));
  }
}

}  // namespace gfec
