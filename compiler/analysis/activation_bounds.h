// A structural bound on an sfc's activation (docs/verification.md, docs/c-engine.md): weights
// w(p) >= 1 such that no transition outputs more weight than it consumes make sum(w * AV) a
// quantity no tick increases, whatever the conditions say, so AV(p) <= W0 / w(p), W0 being the
// weight of the initial marking, and the total activation never exceeds W0.
//
// Unlike the state space of sfc_states.h, which explores reachable markings up to a budget and
// can only say "unbounded somewhere" or give up on a large chart, the weights are a proof found
// in time linear in the chart, for charts of any size. The pipeline records the bound on every
// chart once after validation (compiler/pipeline/compilation.cc), whether or not the warnings'
// analyses run, and the back ends read it from the model (model::Chart::activation).
#pragma once

#include "model.h"

namespace gfec::analysis {

/// The bound the weights prove for `chart`; not bounded when the search finds no weights (the
/// chart pumps activation, or proving it would take more than a budget proportional to the
/// chart) or when a place's bound would not fit 32 bits. Sound whatever it answers.
model::ActivationBound prove_activation_bound(const model::Chart &chart);

/// The largest activation of a place, and of all places together, over every reachable state
/// of an sfc, when the bounded exploration of sfc_states.h (its default limits, as --analyze's)
/// saw them all without acceleration; not bounded otherwise.
model::ActivationBound exact_activation_bound(const model::Chart &chart);

/// Records on every chart of `model` the tighter of prove_activation_bound and
/// exact_activation_bound (an fsm is bounded by 1), so that the C engine's header and
/// --analyze name one number.
void record_activation_bounds(model::Model &model);

}  // namespace gfec::analysis
