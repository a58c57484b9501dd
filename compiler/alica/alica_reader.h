// The ALICA front end: reads ALICA's JSON plan files (.pml plans, .beh behaviours, .pty plan
// types, .tsk tasks, .cnd conditions) and produces the same syntax tree the parser would, so
// the validator, the model and every back end work unchanged. docs/alica.md has the mapping.
#pragma once

#include "diagnostics.h"
#include "file_system.h"
#include "import_result.h"

#include <string>

namespace gfec {

/// Adds to each diagnostic from index `first` on located in an ALICA file a note naming the element it points at
/// (kind, name, id): the validator's messages know only the gfec names. The ALICA row's
/// annotate hook (compiler/input_languages.h).
void annotate_elements(Diagnostics &diag, const LoadResult &loaded, std::size_t first);

}  // namespace gfec

namespace gfec::alica {

/// ALICA's row of the input-language table (alica_language.cc): its extensions, this reader.
const InputLanguage &language();

/// Reads the plan in `main_path` (whose text is `text`) and every file it references into
/// `result`: the main plan's file first, then the others in the order first reached.
void read_alica_program(const std::string &main_path, std::string text, const LoadOptions &options,
                        const FileSystem &fs, SourceManager &sources, Diagnostics &diag, LoadResult &result);

}  // namespace gfec::alica
