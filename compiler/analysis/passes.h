// The analyses' passes, one per kind of model; each reports warnings and appends its summary.
#pragma once

#include "analysis/sfc_states.h"
#include "diagnostics.h"
#include "model.h"

#include <string>

namespace gfec::analysis {

void check_sfc(const model::Model &m, const model::Chart &c, Diagnostics &diag, const Limits &limits,
               std::string &summary);
void check_fsm(const model::Model &m, const model::Chart &c, Diagnostics &diag, std::string &summary);
void check_plan(const model::Model &m, const model::Plan &p, Diagnostics &diag, std::string &summary);
/// Transitions whose condition needs two states of one fsm instance at once (dead-transition).
void check_exclusive_states(const model::Model &m, const model::Chart &c, Diagnostics &diag);

/// Where a place, transition or chart is named (the model keeps it), so that a warning
/// underlines the name rather than the whole declaration; the declaration if the name has no range.
template <typename T> SourceRange name_at(const T &x) {
  return x.name_range.end > x.name_range.begin ? x.name_range : x.range;
}

/// "1 place", "2 places": a count with its noun in the right number, for the summaries.
inline std::string counted(std::size_t n, const char *one, const char *many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace gfec::analysis
