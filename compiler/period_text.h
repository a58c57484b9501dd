// A scan period as a user writes it on a command line or in an editor's settings (`gfec --period`,
// the language server's `period`): docs/iec.md "The scan".
#pragma once

#include <optional>
#include <string_view>

namespace gfec {

/// The period in milliseconds: a duration of the chart language (`10ms`, `1.5s`) or an IEC TIME
/// literal (`T#10ms`, `TIME#1s500ms`, `t#2s`); nullopt when it is neither or not above 0.
std::optional<double> parse_period(std::string_view written);

}  // namespace gfec
