// The loader: reads the main file and, transitively, every file it imports (docs/language.md §2),
// parsing each once. Missing files and import cycles are reported at the import.
#pragma once

#include "ast.h"
#include "diagnostics.h"
#include "file_system.h"

#include <string>
#include <vector>

namespace gfec {

/// The main file's language: from its extension (.pml is ALICA), or forced with -x.
enum class InputLanguage { Auto, Gfec, Alica };

struct LoadOptions {
  std::vector<std::string> include_dirs;  ///< -I, searched after the importing file's folder
  InputLanguage language = InputLanguage::Auto;
};

/// An element of a file that is not chart text (an ALICA state, transition, plan...): where it
/// is and how to name it, so diagnostics about it can say which one (docs/alica.md).
struct SourceElement {
  SourceRange range;
  std::string description;  ///< e.g. "ALICA state 'Init' (id 1542881176280) of plan 'Master'"
};

struct LoadResult {
  ast::Program program;                 ///< main file first, then imports in the order first reached
  std::vector<std::string> paths;       ///< the path of every file read, in the same order
  bool main_unreadable = false;         ///< the main file itself could not be read (an I/O error)
  std::vector<SourceElement> elements;  ///< ALICA input: every plan, state, transition... read
};

/// Adds to each diagnostic located in an ALICA file a note naming the element it points at
/// (kind, name, id): the validator's messages know only the gfec names (compiler/alica/).
void annotate_elements(Diagnostics &diag, const LoadResult &loaded);

LoadResult load_program(const std::string &main_path, const LoadOptions &options, const FileSystem &fs,
                        SourceManager &sources, Diagnostics &diag);

}  // namespace gfec
