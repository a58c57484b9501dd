// The table of named warnings: the names -W<name>, -Wno-<name> and the "[-W<name>]" suffix use.
#pragma once

#include <optional>
#include <string_view>

namespace gfec {

/// Every warning gfec can give. Errors carry a check name too, but cannot be turned off.
enum class Warning {
  UnreachablePlace,   ///< a place or state no activation can reach
  DeadTransition,     ///< a transition that can never open
  Conflict,           ///< transitions sharing an input place, settled by declaration order
  UnreachableActor,   ///< a plan actor no path reaches
  Verbatim,           ///< verbatim code the validator cannot check
  // The static analyses (compiler/analysis/, docs/verification.md).
  UnsafePlace,        ///< an sfc place can hold more than one activation
  UnboundedPlace,     ///< an sfc place's activation can grow without bound
  Deadlock,           ///< a reachable sfc state in which active places wait and nothing can fire
  DeadJoin,           ///< a join whose input places are never active together
  UnjoinedFork,       ///< a fork whose branches never meet again in a join
  AnalysisLimit,      ///< an analysis stopped at its bound: its findings are incomplete
  TrapState,          ///< an fsm state from which no terminal state can be reached
  ShadowedTransition, ///< an fsm transition an earlier one always pre-empts
  UninitializedConfig,///< a plan reads a config entry that nothing has written
  SupervisorRace,     ///< two supervisors of one actor can fire in the same step
  UnusedChart,        ///< a chart of the main file that the compiled hierarchy leaves out
  AlicaIgnored,       ///< an ALICA plan element gfec has no counterpart for (docs/alica.md)
  Count_
};

struct WarningInfo {
  Warning id;
  std::string_view name;
  bool on_by_default;
  std::string_view summary;
};

/// The whole table, in enum order.
const WarningInfo *warning_table();
const WarningInfo &warning_info(Warning w);
std::optional<Warning> find_warning(std::string_view name);

} // namespace gfec
