// Operators shared by the syntax tree and the model, with their C spelling.
#pragma once

namespace gfec {

enum class UnaryOp { Not, Neg };
enum class BinaryOp { Mul, Div, Mod, Add, Sub, Lt, Le, Gt, Ge, Eq, Ne, And, Or };
enum class AssignOp { Set, Add, Sub };

/// The operator as C writes it ("!", "&&", "+=", ...); the language uses C's spelling.
const char *spelling(UnaryOp op);
const char *spelling(BinaryOp op);
const char *spelling(AssignOp op);
/// C precedence, higher binds tighter (|| is 1, * / % are 7).
int precedence(BinaryOp op);

} // namespace gfec
