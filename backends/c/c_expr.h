// Chart expressions and statements as C (LANGUAGE.md §4): the chart's own text, made readable
// and warning-free, with `#line` back to the chart around every statement.
#pragma once

#include "c_context.h"
#include "code_writer.h"

#include <string>
#include <string_view>
#include <vector>

namespace gfec::c_backend {

/// The C type of a chart type: "bool", "int", "float", "double".
const char *c_type(model::Type type);

/// `e` as a C expression.
std::string c_expr(const Context &c, const model::Expr &e);

/// `e` as the operand of `&&`: parenthesised unless it already is a bracket or a primary.
std::string c_condition(const Context &c, const model::Expr &e);

/// `bool f(void)`, `void Motor(int side, float speed)`: an interface function's prototype.
std::string c_prototype(const model::Function &f);

/// The statements, one per line at the current indentation, each preceded by `#line` to the
/// chart where needed. The caller writes `line_back()` after the code that follows.
void emit_statements(CodeWriter &w, const Context &c, const std::vector<model::Stmt> &stmts);

/// A `%{ %}` block (text: what is between the braces) with `#line` to where the text begins
/// (no #line without `sources`).
void emit_verbatim(CodeWriter &w, const SourceManager *sources, const SourceRange &range, std::string_view text);

} // namespace gfec::c_backend
