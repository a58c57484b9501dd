#include "validate/suggest.h"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace gfec::validation {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // The classic table, two rows back kept for transpositions ("flaot" is one typo from "float").
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), row(b.size() + 1);
  std::iota(previous.begin(), previous.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) row[j] = std::min(row[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, row);
  }
  return previous[b.size()];
}

const Symbol *closest(std::string_view name, const std::vector<const Symbol *> &candidates) {
  // The table costs the product of the lengths: a hostile 40k-character name against every
  // candidate took seconds. Longer names are not typed by hand, so they get no suggestion.
  if (name.size() > kMaxSuggestedLength) return nullptr;
  // About a third of the name may be wrong (at least one letter): close enough to be a typo,
  // far enough apart that short unrelated names are not offered.
  std::size_t limit = std::max<std::size_t>(1, (name.size() + 1) / 3);
  const Symbol *best = nullptr;
  std::size_t best_distance = limit + 1;
  for (const Symbol *c : candidates) {
    const std::string_view candidate = c->name();
    if (candidate == name) continue;
    // Each letter of difference in length costs at least one edit.
    std::size_t gap = candidate.size() > name.size() ? candidate.size() - name.size() : name.size() - candidate.size();
    if (gap > limit) continue;
    std::size_t d = edit_distance(name, candidate);
    if (d < best_distance && d < candidate.size()) {
      best = c;
      best_distance = d;
    }
  }
  return best;
}

void suggest(Diagnostic &d, std::string_view name, const std::vector<const Symbol *> &candidates) {
  // The diagnostic's range is the unknown name itself: the fix-it replaces it.
  if (const Symbol *s = closest(name, candidates))
    d.fix(d.range, s->name()).note(s->range, fmt::format("did you mean '{}'?", s->name()));
}

}  // namespace gfec::validation
