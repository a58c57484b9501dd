// textDocument/completion that knows where the cursor is (docs/editors.md "Completion"):
//   - in a condition (`when`, `if (...)`, `post`, `expect`, the right of an assignment): the
//     functions that return a value, the vars and the constants (and true/false);
//   - in a transition's place lists, and in `elapsed(` `active(`: the chart's places;
//   - after `runs`: the charts;  after `var`/`const`, a parameter: the types;
//   - at the start of a statement or item: the keywords that may start one there (and, in a
//     place's body, the functions and vars an action starts with);
//   - in an import's string: the chart files and folders beside the document.
// The context comes from the compiler's tokens before the cursor, so it works while the text
// is broken; the names come from the text's own declarations and from the last syntax tree of
// the document (its imports' interfaces and constants).
#pragma once

#include "ast.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <string_view>

namespace gfec::lsp {

/// Where the cursor is, as completion sees it (exposed for the tests).
enum class CompletionContext {
  TopLevel,
  ChartItem,
  PlaceList,
  Condition,
  Statement,
  Charts,
  Types,
  Import,
  TestStep,
  TestSet,  ///< after `set` in a test: the tested chart's inputs and the sensing functions
  None
};

CompletionContext completion_context(std::string_view text, std::uint32_t offset);

/// The CompletionList for the cursor at byte `offset` of `text`. `program` is the document's
/// last syntax tree (null when there is none): the names its files declare. `directory` is the
/// document's folder, where an import's files are looked for.
nlohmann::json completion(std::string_view text, std::uint32_t offset, const ast::Program *program,
                          const std::string &directory);

}  // namespace gfec::lsp
