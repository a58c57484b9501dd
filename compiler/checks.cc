#include "checks.h"

namespace gfec {

namespace {
// Order must follow enum Warning.
const WarningInfo kWarnings[] = {
    {Warning::UnreachablePlace, "unreachable-place", true, "a place or state no activation can reach"},
    {Warning::DeadTransition, "dead-transition", true, "a transition that can never open"},
    {Warning::Conflict, "conflict", false, "transitions sharing an input place, settled by declaration order"},
    {Warning::UnreachableActor, "unreachable-actor", true, "a plan actor no path reaches"},
    {Warning::Verbatim, "verbatim", false, "verbatim code that the validator cannot check"},
};
static_assert(sizeof(kWarnings) / sizeof(kWarnings[0]) == static_cast<int>(Warning::Count_));
} // namespace

const WarningInfo *warning_table() { return kWarnings; }
const WarningInfo &warning_info(Warning w) { return kWarnings[static_cast<int>(w)]; }

std::optional<Warning> find_warning(std::string_view name) {
  for (const auto &w : kWarnings)
    if (w.name == name) return w.id;
  return std::nullopt;
}

} // namespace gfec
