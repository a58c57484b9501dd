// The ALICA front end: reads ALICA's JSON plan files (.pml plans, .beh behaviours, .pty plan
// types, .tsk tasks, .cnd conditions) and produces the same syntax tree the parser would, so
// the validator, the model and every back end work unchanged. docs/alica.md has the mapping.
#pragma once

#include "loader.h"

#include <string>

namespace gfec::alica {

/// True for a path read as ALICA when no -x says otherwise: a .pml plan.
bool is_alica_path(const std::string &path);

/// Reads the plan in `main_path` (whose text is `text`) and every file it references into
/// `result`: the main plan's file first, then the others in the order first reached.
void read_alica_program(const std::string &main_path, std::string text, const LoadOptions &options,
                        const FileSystem &fs, SourceManager &sources, Diagnostics &diag, LoadResult &result);

}  // namespace gfec::alica
