// Small pieces the IEC readers and their lowering share: IEC names compare case-insensitively
// (upper()), and CASE and multi-name declarations need a copy of an expression (clone()).
#pragma once

#include "ast.h"

#include <string>
#include <string_view>

namespace gfec::iec {

/// `s` in upper case (ASCII): how IEC keywords and names compare.
std::string upper(std::string_view s);

/// A deep copy of `e`; names and spellings keep viewing the file's text and strings.
ast::ExprPtr clone(const ast::Expr &e);

}  // namespace gfec::iec
