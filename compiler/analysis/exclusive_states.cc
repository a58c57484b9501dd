// Conditions that need two states of one fsm at once: `active(P.S) && active(P.T)` can never
// hold, since an fsm instance is in exactly one state whenever a condition reads it (docs/language.md
// "Sub-charts"). Such a transition is dead, and the engine's two tests of one state field are
// what clang's -Wtautological-overlap-compare rejects under -Werror: better said at the chart.
#include "analysis/condition_logic.h"
#include "analysis/passes.h"

#include <fmt/format.h>

#include <algorithm>

namespace gfec::analysis {

namespace {

/// The chart whose place `path.back()` is, following the places' sub-charts from `c`.
const model::Chart *chart_of_last(const model::Model &m, const model::Chart &c,
                                  const std::vector<model::PlaceId> &path) {
  const model::Chart *at = &c;
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    const auto &place = at->places.at(path[k]);
    if (!place.runs) return nullptr;
    at = &m.charts.at(place.runs);
  }
  return at;
}

}  // namespace

void check_exclusive_states(const model::Model &m, const model::Chart &c, Diagnostics &diag) {
  auto exclusive = [&](const model::Expr &a, const model::Expr &b) {
    if (a.kind != model::Expr::Kind::Active || b.kind != model::Expr::Kind::Active) return false;
    if (a.path.empty() || a.path.size() != b.path.size() || a.path.back() == b.path.back()) return false;
    if (!std::equal(a.path.begin(), a.path.end() - 1, b.path.begin())) return false;
    const model::Chart *owner = chart_of_last(m, c, a.path);
    return owner && owner->kind == model::Chart::Kind::Fsm;
  };
  for (const auto &t : c.transitions)
    if (t.condition && needs_exclusive(*t.condition, exclusive) == true)
      diag.warning(Warning::DeadTransition, name_at(t),
                   fmt::format("transition '{}' can never fire: its condition needs two states of one fsm to be "
                               "active at the same time",
                               t.name));
}

}  // namespace gfec::analysis
