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
    {Warning::UnsafePlace, "unsafe-place", false, "an sfc place can hold more than one activation"},
    {Warning::UnboundedPlace, "unbounded-place", true, "an sfc place's activation can grow without bound"},
    {Warning::Deadlock, "deadlock", true, "a reachable sfc state where active places wait and nothing can fire"},
    {Warning::DeadJoin, "dead-join", true, "a join whose input places are never active together"},
    {Warning::UnjoinedFork, "unjoined-fork", false, "a fork whose branches never meet again in a join"},
    {Warning::AnalysisLimit, "analysis-limit", false, "an analysis stopped at its bound; its findings are incomplete"},
    {Warning::TrapState, "trap-state", true, "an fsm state from which no success or failure state is reachable"},
    {Warning::ShadowedTransition, "shadowed-transition", true, "an fsm transition that an earlier one always pre-empts"},
    {Warning::UninitializedConfig, "uninitialized-config", true, "a plan may read a config entry before anything writes it"},
    {Warning::SupervisorRace, "supervisor-race", false, "two supervisors of one actor can fire in the same step"},
    {Warning::UnusedChart, "unused-chart", true, "a chart of the main file that the compiled chart neither is nor runs"},
    {Warning::AlicaIgnored, "alica-ignored", true, "an ALICA plan element with no gfec counterpart, ignored"},
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
