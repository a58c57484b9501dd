// Conditions as propositions: `&&`, `||`, `!`, `==` and `!=` between bools, brackets and
// literals are logic; every other subexpression (a call, a comparison, a var) is an atom, the
// same atom wherever it is written the same way. This decides whether one condition implies
// another, by truth table, when they have few atoms.
#pragma once

#include "model.h"

#include <functional>
#include <optional>

namespace gfec::analysis {

/// Whether `a` implies `b` (a null condition is `true`); nothing when there are too many atoms.
std::optional<bool> implies(const model::Expr *a, const model::Expr *b);

/// Whether `e` can hold only where two of its atoms that `exclusive` says never hold together
/// (two states of one fsm instance) would both hold: false in every row of the truth table
/// that respects `exclusive`, though true in some other row (a condition false in every row is
/// constant, which the validator reports). Nothing when there are too many atoms.
std::optional<bool> needs_exclusive(const model::Expr &e,
                                    const std::function<bool(const model::Expr &, const model::Expr &)> &exclusive);

}  // namespace gfec::analysis
