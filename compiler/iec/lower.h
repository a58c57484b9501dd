// The one lowering of an IEC program (iec_model.h) into the chart syntax tree (ast.h), shared by
// the ST and the PLCopen XML readers: docs/iec.md "What a program is in gfec's chart language".
#pragma once

#include "ast.h"
#include "diagnostics.h"
#include "iec/iec_model.h"

#include <optional>

namespace gfec::iec {

/// The scan period of `pou`: the INTERVAL of the one task of `project` that runs it, or nullopt
/// (none runs it, or it has no INTERVAL). Two tasks with different intervals running it are an
/// error at the second one.
/// The chart type (docs/iec.md "What a program is in gfec's chart language") of an IEC
/// elementary type gfec reads, given in upper case (`INT` is `int16`, `TIME` is `time`), or null.
const char *chart_type(const std::string &iec);

std::optional<ast::Period> period_of(const Project &project, const Pou &pou, Diagnostics &diag);

/// Lowers every PROGRAM of `project` into `file` (each with the period of the task that runs
/// it, or `period_ms` when given: --period, which wins over every task), every FUNCTION_BLOCK
/// into a block of `file` (docs/iec.md "Function blocks"), and reports a FUNCTION as not
/// supported yet. Returns how many charts it added.
std::size_t lower(Project &&project, ast::File &file, Diagnostics &diag,
                  std::optional<double> period_ms = std::nullopt);

}  // namespace gfec::iec
