// Running the external programs some outputs go through (--emit=svg: Graphviz's dot). The
// driver owns processes and files: back ends only name the tool (backend.h, OutputSink::filter).
#pragma once

#include "backend.h"

#include <stdexcept>
#include <string>

namespace gfec {

/// How long an external tool may run, in seconds, unless GFEC_TOOL_TIMEOUT says otherwise (0:
/// no limit): Graphviz's time grows about fourfold with each level of a legal sub-chart
/// hierarchy, so a hostile chart could otherwise hold gfec for hours (docs/security.md).
constexpr double kDefaultToolTimeLimit = 60;
/// The limit in force: GFEC_TOOL_TIMEOUT if it is a number from 0 to 1e7, else the default.
double external_tool_time_limit();

/// The error of a tool stopped at its time limit: the chart is too large to draw in time, so
/// the input's fault (exit 1), unlike a tool that is missing (exit 2).
struct ToolTimeLimit : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Runs `tool` with `input` on its standard input and returns its standard output. Throws
/// std::runtime_error with a message for the user when it cannot be started (then with
/// `tool.if_missing`), exits with an error (then with what it printed on standard error) or
/// outlives the time limit (then it is stopped). SIGINT, SIGTERM or SIGHUP while it runs stop
/// it and remove the temporary files, then act as they would have.
std::string run_external_tool(const ExternalTool &tool, const std::string &input);

}  // namespace gfec
