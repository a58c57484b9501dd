// Did-you-mean: every unknown name is checked against the names that could have been meant.
#pragma once

#include "diagnostics.h"
#include "validate/names.h"

#include <string_view>
#include <vector>

namespace gfec::validation {

/// Edit distance: insert, delete, substitute, or swap two neighbours; each costs 1.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// edit_distance(a, b) if it is at most k, else k + 1: the work is that of a band 2k + 1 wide,
/// and stops as soon as the distance must exceed k.
std::size_t edit_distance_within(std::string_view a, std::string_view b, std::size_t k);

/// Names longer than this get no did-you-mean (nobody mistypes a name that long by hand, and the
/// edit distance costs the product of the lengths).
constexpr std::size_t kMaxSuggestedLength = 64;

/// The candidate a typo most likely meant, or null when none is close enough. Ties go to the
/// earlier declaration, so the note is deterministic.
const Symbol *closest(std::string_view name, const std::vector<const Symbol *> &candidates);

/// Adds the note "did you mean 'X'?" (at X's declaration) when a close candidate exists.
void suggest(Diagnostic &d, std::string_view name, const std::vector<const Symbol *> &candidates);

}  // namespace gfec::validation
