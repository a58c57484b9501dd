// `gfec run CHART [--inputs trace.csv] [--ticks N]`: runs a chart in the reference interpreter
// and prints its per-tick log, so that a chart can be tried without hardware
// (docs/verification.md describes the log and the CSV format).
#pragma once

#include <iosfwd>

namespace gfec {

/// argv[0] is "run". Prints the log to `out` and diagnostics to `err`; returns the exit code
/// (0 ok, 1 errors in the chart or the trace or undefined behaviour while running, 2 usage or I/O).
int run_command(int argc, const char *const *argv, std::ostream &out, std::ostream &err);

}  // namespace gfec
