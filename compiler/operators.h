// Operators shared by the syntax tree and the model, with their C spelling.
#pragma once

#include <cstdint>

namespace gfec {

// One byte each: every expression node of the syntax tree and the model holds one.
enum class UnaryOp : std::uint8_t { Not, Neg };
enum class BinaryOp : std::uint8_t { Mul, Div, Mod, Add, Sub, Lt, Le, Gt, Ge, Eq, Ne, And, Or };
enum class AssignOp : std::uint8_t { Set, Add, Sub };

/// The operator as C writes it ("!", "&&", "+=", ...); the language uses C's spelling.
const char *spelling(UnaryOp op);
const char *spelling(BinaryOp op);
const char *spelling(AssignOp op);
/// C precedence, higher binds tighter (|| is 1, * / % are 7).
int precedence(BinaryOp op);

}  // namespace gfec
