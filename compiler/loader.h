// The loader: reads the main file and, transitively, every file it imports (LANGUAGE.md §2),
// parsing each once. Missing files and import cycles are reported at the import.
#pragma once

#include "ast.h"
#include "diagnostics.h"
#include "file_system.h"

#include <string>
#include <vector>

namespace gfec {

struct LoadOptions {
  std::vector<std::string> include_dirs;  ///< -I, searched after the importing file's folder
};

struct LoadResult {
  ast::Program program;            ///< main file first, then imports in the order first reached
  std::vector<std::string> paths;  ///< the path of every file read, in the same order
  bool main_unreadable = false;    ///< the main file itself could not be read (an I/O error)
};

LoadResult load_program(const std::string &main_path, const LoadOptions &options, const FileSystem &fs,
                        SourceManager &sources, Diagnostics &diag);

} // namespace gfec
