// The spaces between two tokens of one line in the canonical layout (docs/formatting.md).
#pragma once

#include "token.h"

namespace gfec::format {

/// Whether a '-', '+' or '!' after `previous` is a sign (unary) rather than a binary operator:
/// it is unless `previous` ends an operand.
bool is_unary_position(Tok previous);

/// Whether one space separates `left` and `right` on one line (else none). `left_unary`: `left`
/// is a sign or '!' (is_unary_position held for it).
bool space_between(Tok left, bool left_unary, Tok right);

}  // namespace gfec::format
