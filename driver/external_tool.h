// Running the external programs some outputs go through (--emit=svg: Graphviz's dot). The
// driver owns processes and files: back ends only name the tool (backend.h, OutputSink::filter).
#pragma once

#include "backend.h"

#include <string>

namespace gfec {

/// Runs `tool` with `input` on its standard input and returns its standard output. Throws
/// std::runtime_error with a message for the user when it cannot be started (then with
/// `tool.if_missing`) or exits with an error (then with what it printed on standard error).
std::string run_external_tool(const ExternalTool &tool, const std::string &input);

}  // namespace gfec
