#include "validate/suggest.h"

#include <fmt/format.h>

namespace gfec::validation {

const Symbol *closest(std::string_view name, const std::vector<const Symbol *> &candidates) {
  // The table costs the product of the lengths: a hostile 40k-character name against every
  // candidate took seconds. Longer names are not typed by hand, so they get no suggestion.
  if (name.size() > kMaxSuggestedLength) return nullptr;
  const std::size_t limit = typo_limit(name.size());
  NearestName nearest(name, limit);
  const Symbol *best = nullptr;
  for (const Symbol *c : candidates) {
    const std::string_view candidate = c->name();
    if (candidate == name) continue;
    // A candidate every letter of which would change is no typo of it (`x` is not `y`); only a
    // candidate no longer than the limit can be that far.
    if (candidate.size() <= limit && edit_distance(name, candidate) >= candidate.size()) continue;
    if (nearest.offer(candidate)) best = c;
  }
  return best;
}

void suggest(Diagnostic &d, std::string_view name, const std::vector<const Symbol *> &candidates) {
  if (d.dropped) return;  // past the error limit: nobody will read the note
  // The diagnostic's range is the unknown name itself: the fix-it replaces it.
  if (const Symbol *s = closest(name, candidates))
    d.fix(d.range, s->name()).note(s->range, fmt::format("did you mean '{}'?", s->name()));
}

}  // namespace gfec::validation
