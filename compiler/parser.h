// The recursive-descent parser: tokens to syntax tree, one file at a time. Each parse function
// carries its grammar rule as a `//G` comment; grammar/gfec.ebnf is the same grammar in one place.
#pragma once

#include "ast.h"
#include "diagnostics.h"

#include <memory>

namespace gfec {

/// How deep expressions may nest before the parser refuses (no stack overflow on any input):
/// brackets, unary operators, calls and each binary operator of a chain count one level, so
/// every later recursive walk of an expression (validator, back ends, interpreter) is bounded.
constexpr int kMaxNesting = 256;
/// The branches of one `if ... else if ...` chain, at most: each is a level of the syntax tree
/// and of the model, and the passes over them recurse.
constexpr int kMaxElseIfChain = 1024;

/// Parses one file. Syntax errors are reported to `diag`; the parser recovers at the next
/// declaration or statement, so one run reports every independent error.
std::unique_ptr<ast::File> parse_file(const SourceManager &sources, FileId file, Diagnostics &diag);

}  // namespace gfec
