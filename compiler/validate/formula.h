// Plan argument formulas (§8): constants, config entries, + - * / and brackets, and string
// concatenation with +. Nothing else of the expression language is allowed in a plan.
#pragma once

#include "validate/context.h"

#include <optional>
#include <set>
#include <string>

namespace gfec::validation {

/// A plan's own names, and what it uses, while the plan is validated.
struct PlanScope {
  PlanScope(const ast::Plan &a, model::Plan &o) : ast(a), out(o) {}

  const ast::Plan &ast;
  model::Plan &out;
  /// Config entries, actors and supervisors: all become members of the generated plan class.
  Namespace names;
  std::set<std::string> unknown;         ///< unknown names already reported
  std::set<model::ToolboxId> toolboxes;  ///< toolboxes whose templates the plan uses
};

/// Lowers a formula. `constant` (a config initialiser): only literals and file-level constants.
/// A file-level constant is replaced by its value, so generated plans need no constants.
std::optional<model::Expr> lower_formula(const ast::Expr *e, Context &cx, PlanScope &s, bool constant);

/// Whether the runtime converts a value of type `from` to `to` (§8): int, float and double
/// among each other, numbers to strings and strings to numbers (checked when the plan runs);
/// bool and object only to themselves.
bool convertible(model::Type to, model::Type from);

}  // namespace gfec::validation
