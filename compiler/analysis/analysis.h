// The static analyses (docs/verification.md): what a chart or plan can do whatever its
// conditions say. Each finding is a named warning (compiler/diagnostic_kinds.def); `gfec --analyze` prints them all
// with a summary per chart and plan.
//
//   sfc   unsafe and unbounded places, deadlocks, places and transitions no reachable state
//         uses, joins whose inputs are never active together, forks whose branches never meet
//   fsm   states from which no terminal state is reachable, transitions shadowed by an earlier
//         one with the same or a weaker precondition
//   plan  config entries read before anything writes them, supervisors that can fire together
#pragma once

#include "analysis/sfc_states.h"
#include "diagnostics.h"
#include "model.h"

#include <string>

namespace gfec::analysis {

/// Runs, on every chart and plan of the main file, the analyses whose warnings are on in
/// `diag`, and reports what they find there. Costs nothing when they are all off.
void analyze(const model::Model &model, Diagnostics &diag, const Limits &limits = {});

/// Runs every analysis on every chart and plan of the main file (the warnings go to `diag`, as
/// its options allow) and returns a summary, one block per chart and plan.
std::string analysis_report(const model::Model &model, Diagnostics &diag, const Limits &limits = {});

}  // namespace gfec::analysis
