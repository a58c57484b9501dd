// The validator: resolves names across files, type-checks, applies the rules of docs/language.md and
// lowers the syntax tree to the model. Every user error is reported here, never in a back end.
#pragma once

#include "ast.h"
#include "diagnostics.h"
#include "model.h"
#include "name_uses.h"

#include <functional>
#include <string>
#include <vector>

namespace gfec {

namespace scenario {
struct Suite;
}

struct ValidateOptions {
  /// Leave the syntax tree whole, for a client that reads it after validation (a language
  /// server: outlines, go-to-definition). By default each chart's statements, conditions and
  /// transition places are released as soon as they are lowered, so a large chart never holds
  /// both forms (docs/performance.md).
  bool keep_tree = false;
  /// The interface files, not imported, that declare a function of this name, as the import
  /// would name them: a note on "unknown function" says which to import. The caller, which has
  /// the file system and the search folders, answers (pipeline/missing_import.h); null: no note.
  std::function<std::vector<std::string>(const std::string &function)> declaring_files;
  /// Where to record what every name refers to (a language server's definition, references,
  /// rename); null: nowhere.
  NameUses *name_uses = nullptr;
};

/// Checks `program` and builds its model. The model is complete only when no error was reported.
/// Unless options.keep_tree, the program is consumed in part: after this only the declarations
/// of the syntax tree remain; drop it.
model::Model validate(ast::Program &program, const SourceManager &sources, Diagnostics &diag);
/// The same, keeping the checked `test` blocks of the main file in `tests` (gfec test). Both
/// check them; this one keeps them. A test's `elapsed(P)` marks P timed in the model.
model::Model validate(ast::Program &program, const SourceManager &sources, Diagnostics &diag, scenario::Suite &tests,
                      const ValidateOptions &options = {});

/// --context (docs/c-engine.md "Instance context"): every interface function the C engine of
/// `chart` calls (its sub-charts' too) takes the context first, so none has a C library
/// function's prototype: warns (-Wlibrary-function) about those named after a function gcc or
/// clang know, which the validator let through for having the library's own prototype.
void check_context_prototypes(const model::Model &model, model::ChartId chart, Diagnostics &diag);

}  // namespace gfec
