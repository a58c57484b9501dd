#include "roots.h"

#include <fmt/format.h>

namespace gfec {

std::vector<int> root_charts(const model::Model &m) {
  std::vector<bool> run(m.charts.size(), false);
  for (const auto &c : m.charts)
    for (const auto &p : c.places)
      if (p.runs >= 0 && static_cast<std::size_t>(p.runs) < run.size()) run[static_cast<std::size_t>(p.runs)] = true;
  std::vector<int> roots;
  for (std::size_t i = 0; i < m.charts.size(); ++i)
    if (m.charts[i].in_main_file && !run[i]) roots.push_back(static_cast<int>(i));
  return roots;
}

int default_root(const model::Model &m) {
  std::vector<int> roots = root_charts(m);
  return roots.size() == 1 ? roots.front() : -1;
}

std::vector<bool> charts_in_tree(const model::Model &m, int root) {
  std::vector<bool> in(m.charts.size(), false);
  std::vector<int> work;
  if (root >= 0 && static_cast<std::size_t>(root) < m.charts.size()) work.push_back(root);
  while (!work.empty()) {
    int c = work.back();
    work.pop_back();
    if (in[static_cast<std::size_t>(c)]) continue;
    in[static_cast<std::size_t>(c)] = true;
    for (const auto &p : m.charts[static_cast<std::size_t>(c)].places)
      if (p.runs >= 0) work.push_back(p.runs);
  }
  return in;
}

void warn_unused_charts(const model::Model &m, int root, Diagnostics &diag) {
  std::vector<bool> in = charts_in_tree(m, root);
  bool hierarchy = false;
  for (std::size_t i = 0; i < in.size(); ++i)
    if (in[i] && static_cast<int>(i) != root) hierarchy = true;
  if (!hierarchy) return;
  const model::Chart &r = m.charts[static_cast<std::size_t>(root)];
  for (std::size_t i = 0; i < m.charts.size(); ++i) {
    const model::Chart &c = m.charts[i];
    if (!c.in_main_file || in[i]) continue;
    diag.warning(Warning::UnusedChart, c.range,
                 fmt::format("{} '{}' is neither compiled nor run by '{}', the chart being compiled",
                             c.kind == model::Chart::Kind::Fsm ? "fsm" : "sfc", c.name, r.name))
        .note(r.range, fmt::format("to use it, let a place or state of '{}' run it ('runs {}')", r.name, c.name));
  }
}

}  // namespace gfec
