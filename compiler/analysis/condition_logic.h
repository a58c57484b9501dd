// Conditions as propositions: `&&`, `||`, `!`, `==` and `!=` between bools, brackets and
// literals are logic; every other subexpression (a call, a comparison, a var) is an atom, the
// same atom wherever it is written the same way. This decides whether one condition implies
// another, by truth table, when they have few atoms.
#pragma once

#include "model.h"

#include <optional>

namespace gfec::analysis {

/// Whether `a` implies `b` (a null condition is `true`); nothing when there are too many atoms.
std::optional<bool> implies(const model::Expr *a, const model::Expr *b);

}  // namespace gfec::analysis
