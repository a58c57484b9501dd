// The validator's pass over `test` blocks (docs/testing-charts.md), run after every chart is
// validated: it needs their scopes' names and their lowered variables.
#pragma once

#include "scenario/scenario.h"
#include "validate/context.h"
#include "validate/expr.h"

namespace gfec::validation {

/// The most ticks one `tick N;` may run: a typo such as `tick 1000000000;` is an error rather
/// than a run that seems to hang.
constexpr long long kMaxTicksPerStep = 1000000;

/// The most ticks all the tests of one file may run together (each on the reference interpreter
/// and on the C engine): a file of many long tests is an error at the step that goes past it,
/// rather than a run that seems to hang (docs/testing-charts.md).
constexpr long long kMaxTicksPerFile = 10000000;

/// Checks the tests of the main file and appends those without errors to `out`.
void validate_tests(Context &cx, scenario::Suite &out);

}  // namespace gfec::validation
