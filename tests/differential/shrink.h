// Shrinking a failing case: removes transitions, places, statements, blocks, variables and
// ticks, and replaces expressions by their parts or by literals, for as long as the case still
// fails the same way. What is left is the smallest chart and trace that shows the bug.
#pragma once

#include "harness.h"

namespace gfec::diff {

/// Shrinks `c` (which fails with `verdict` under `config`) in place; returns its last outcome.
Outcome shrink(const Harness &h, Case &c, const Config &config, Verdict verdict, int *steps = nullptr);

}  // namespace gfec::diff
