// The driver: runs the pipeline for the command line's options, prints diagnostics in the
// chosen format and writes outputs atomically. The only place that decides exit codes.
#pragma once

#include "options.h"
#include "pipeline/compilation.h"

#include <iosfwd>

namespace gfec {

/// Exit codes, as gcc users expect them.
enum ExitCode { kExitOk = 0, kExitInputError = 1, kExitUsageOrIo = 2 };

int run(const Options &options, std::ostream &out, std::ostream &err);

/// `gfec FILE...` (commands.h): reads the command line (options.h) and runs it.
int compile_command(int argc, const char *const *argv, std::ostream &out, std::ostream &err);

class DiagnosticReport;

/// Ends `report` (a SARIF file is written then) and gives the command's exit code: `code`, or
/// kExitUsageOrIo, said on `err`, when the report cannot be finished.
int finish_report(DiagnosticReport &report, int code, std::ostream &err);

/// What the front end takes from the command line (-I, -x, -W..., -fmax-errors).
pipeline::FrontEndOptions front_end_options(const Options &o);

}  // namespace gfec
