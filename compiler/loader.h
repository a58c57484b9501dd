// The loader: reads the main file in its input language (compiler/input_languages.h) and,
// through that language's reader, every file it refers to. Chart text's reader is here: it
// reads what the main file imports, transitively (docs/language.md §2), parsing each once;
// missing files and import cycles are reported at the import.
#pragma once

#include "diagnostics.h"
#include "file_system.h"
#include "import_result.h"

#include <string>

namespace gfec {

/// Reads `main_path` with the reader of options.language, or of the language its extension
/// (and text) say. result.language is that language once the file was read.
LoadResult load_program(const std::string &main_path, const LoadOptions &options, const FileSystem &fs,
                        SourceManager &sources, Diagnostics &diag);

/// Chart text's reader (its row: chart_text_language()): parses the main file and what it imports.
void read_chart_program(const std::string &main_path, std::string text, const LoadOptions &options,
                        const FileSystem &fs, SourceManager &sources, Diagnostics &diag, LoadResult &result);

/// Runs the main file's language's annotate hook, if it has one (input_languages.h), on the
/// diagnostics from index `first` on: each is annotated once.
void annotate_diagnostics(Diagnostics &diag, const LoadResult &loaded, std::size_t first = 0);

}  // namespace gfec
