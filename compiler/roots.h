// Which chart a file compiles (docs/language.md "Sub-charts"): by default the one chart of the
// main file that no chart runs. The driver, `gfec run` and the back ends all ask here, so the
// rule is written once.
#pragma once

#include "diagnostics.h"
#include "model.h"

#include <string>
#include <vector>

namespace gfec {

/// The charts of the main file that no chart runs, in declaration order: the candidates for
/// the compiled (root) chart. Exactly one is the default; otherwise `--chart` chooses.
std::vector<model::ChartId> root_charts(const model::Model &m);

/// The default root: the only candidate of root_charts, or none when there is none or several.
model::ChartId default_root(const model::Model &m);

/// Per chart: whether compiling `root` runs it, i.e. it is `root` or a chart that `root` runs,
/// directly or through other charts.
IdMap<model::ChartId, bool> charts_in_tree(const model::Model &m, model::ChartId root);

/// Warns (-Wunused-chart) about each chart of the main file that the compiled `root` neither is
/// nor runs, when `root` runs sub-charts: a hierarchy that leaves out a chart of its own file
/// most likely forgot a `runs`.
void warn_unused_charts(const model::Model &m, model::ChartId root, Diagnostics &diag);

}  // namespace gfec
