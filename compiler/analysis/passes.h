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

/// The range of `name` inside the declaration `decl` (its first whole-word occurrence), so that
/// a warning underlines the name rather than the whole declaration.
SourceRange name_in(const model::Model &m, SourceRange decl, const std::string &name);

/// "1 place", "2 places": a count with its noun in the right number, for the summaries.
inline std::string counted(std::size_t n, const char *one, const char *many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

} // namespace gfec::analysis
