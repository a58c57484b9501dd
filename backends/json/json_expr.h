// JSON for the pieces every part of the model document shares: expressions (as source text and
// as a typed tree), statements, and source locations.
#pragma once

#include "model.h"

#include <nlohmann/json.hpp>

namespace gfec::json_backend {

using Json = nlohmann::ordered_json;

/// {"file", "line", "column", "end_line", "end_column"}: 1-based, end exclusive.
Json location(const model::Model &m, const SourceRange &range);

using model::in_chart_text;  ///< whether a range is chart text, shown as written (model.h)
using model::source_text;    ///< the text the user wrote for a range, whitespace runs folded (model.h)

/// What names in expressions refer to: the chart's vars and places, the plan's config.
struct Scope {
  const model::Chart *chart = nullptr;
  const model::Plan *plan = nullptr;
};

/// {"text": "...", "type": "bool", "tree": {...}}.
Json expression(const model::Model &m, const Scope &scope, const model::Expr &e);
/// An expression's "text": as written in chart text; for a chart read from an ALICA plan, whose
/// ranges point into JSON, the model's expression as --emit=chart spells it (`Arrived()`, `false`).
std::string expression_text(const model::Model &m, const Scope &scope, const model::Expr &e);
/// The tree alone: {"kind": "call", "function": "f", "args": [...]}, ...
Json expression_tree(const model::Model &m, const Scope &scope, const model::Expr &e);
Json statements(const model::Model &m, const Scope &scope, const std::vector<model::Stmt> &block);

}  // namespace gfec::json_backend
