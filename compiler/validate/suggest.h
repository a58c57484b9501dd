// Did-you-mean among the validator's names: an unknown name is checked against the names that
// could have been meant (the choosing itself is support/did_you_mean.h).
#pragma once

#include "did_you_mean.h"
#include "diagnostics.h"
#include "validate/names.h"

#include <string_view>
#include <vector>

namespace gfec::validation {

/// The candidate a typo most likely meant, or null when none is close enough: a third of the
/// name may be wrong, never every letter of the candidate, and a name longer than
/// kMaxSuggestedLength gets none. Ties go to the earlier declaration, so the note is deterministic.
const Symbol *closest(std::string_view name, const std::vector<const Symbol *> &candidates);

/// Adds the note "did you mean 'X'?" (at X's declaration) when a close candidate exists.
void suggest(Diagnostic &d, std::string_view name, const std::vector<const Symbol *> &candidates);

}  // namespace gfec::validation
