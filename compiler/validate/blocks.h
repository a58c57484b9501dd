// Blocks (docs/language.md "Blocks"): the declarations of function blocks, their instances in
// charts and blocks, calls of instances and reads of their outputs. A call is inlined: the model
// holds the block's body once per call, over the instance's own vars (model.h, Stmt::Invoke), so
// that the interpreter, the engines and the analyses need nothing of their own for it.
#pragma once

#include "validate/context.h"
#include "validate/expr.h"

namespace gfec::validation {

/// Declares every block of every file (before any chart is validated).
void collect_blocks(Context &cx);
/// Validates the blocks no chart has used, so that each reports its own errors.
void validate_unused_blocks(Context &cx);

/// `var B inst;` in the chart or block of `s`, when B names a block: declares the instance and
/// its vars and returns true. False: `v` is no instance (the caller declares a plain var).
bool declare_instance(Context &cx, ChartScope &s, const ast::ValueDecl &v);

/// `inst.q` (an ast Path of two names): an output of an instance.
std::optional<model::Expr> lower_member(const ast::Expr &path, ExprScope &s);
/// `inst.a = e;`: sets an input of an instance (its target's text holds the '.').
std::optional<model::Stmt> lower_member_assign(const ast::Stmt &st, ExprScope &s);
/// `inst(a = e, ...);` (Kind::Invoke), or `inst();` (a Call naming an instance).
std::optional<model::Stmt> lower_invoke(const ast::Stmt &st, ExprScope &s);
/// Whether `name` names an instance in the chart of `s` (so `name()` is a block call).
bool names_instance(const ast::Name &name, ExprScope &s);

}  // namespace gfec::validation
