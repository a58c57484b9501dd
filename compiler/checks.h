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
