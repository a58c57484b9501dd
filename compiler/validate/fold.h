// Constant evaluation: folds constants and config initialisers to literals, and tells the
// checks which conditions are constant (a transition `when false` is dead).
#pragma once

#include "constant.h"
#include "model.h"
#include "validate/context.h"

#include <optional>
#include <string>

namespace gfec::validation {

/// A compile-time value: the one evaluator's (compiler/constant.h).
using Value = constant::Value;

/// Evaluates `e` with C's semantics (compiler/constant.h: int arithmetic in 32 bits, float in
/// float, && and || short-circuit); a literal or an expression check_constant() folded gives the
/// value the model stores. Not constant (a call, a var, a timer...) gives nothing. Division by
/// zero and overflow are reported when `diag` is given, silently give nothing otherwise.
std::optional<Value> evaluate(const model::Expr &e, const model::Model &model, Diagnostics *diag);

/// One rule for numbers wherever they stand (docs/language.md, "Numbers"): `x` (a literal, or
/// an operator just lowered) is evaluated as C would at compile time if its operands are
/// constant; an int literal past INT_MAX, a float literal past DBL_MAX, int overflow, float
/// overflow and division by zero are errors at the expression, and give nothing. Each is
/// reported once: an operand that failed is no longer constant above it. A constant `x` comes
/// back folded: its value stored in it for every later stage (model.h, Expr::folded).
std::optional<model::Expr> check_constant(std::optional<model::Expr> x, const model::Model &model, Diagnostics &diag);

/// An int or floating literal of the syntax tree with its value, parsed here once for every
/// later stage; an int above INT_MAX, or a floating literal beyond double's range or so small
/// that it reads as 0 (`1e-999`), is an error.
std::optional<model::Expr> number_literal(const ast::Expr &e, Diagnostics &diag);

/// The literal for `v` as a value of type `to` (numbers convert as C converts them; a number
/// becomes a string as it would be printed). `spelling`, when given, is kept for a literal the
/// user wrote, so generated code shows `0.6` rather than `0.59999999999999998`.
std::optional<model::Expr> to_literal(const Value &v, model::Type to, SourceRange range, Diagnostics &diag,
                                      const model::Expr *spelling = nullptr);

/// A constant `v` that is not 0 but would be 0 as a `to` (a double below float's smallest
/// value converted to float): C converts it, but the generated literal (`1e-46f`) is one that C
/// compilers refuse with -Werror, so the validator treats it as not fitting, as one too large.
bool underflows_float(const Value &v, model::Type to);

/// How many constants deep an initialiser may read before folding gives up.
constexpr int kMaxConstDepth = 1000;

/// Folds constant `index` of the model (on first use, in its own scope) and returns its
/// literal, or null if its declaration has an error (reported once, where it is).
const model::Expr *fold_const(Context &cx, model::ConstId index);

}  // namespace gfec::validation
