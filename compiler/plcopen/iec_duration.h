// IEC 61131-3 durations as PLCopen files write them: a TIME literal (`T#2s`, `TIME#1m30s`,
// `t#1.5s`, `T#2s_500ms`) in an action's `duration` and a task's `interval`, or an XML Schema
// duration (`PT0.01S`) that some producers write for the interval.
#pragma once

#include <optional>
#include <string_view>

namespace gfec::plcopen {

/// The duration in milliseconds, or nullopt if `text` is neither form (or negative).
std::optional<double> duration_ms(std::string_view text);

}  // namespace gfec::plcopen
