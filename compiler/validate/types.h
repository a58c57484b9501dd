// Type names and the typing rules of §3 and §4, shared by chart expressions and plan formulas.
#pragma once

#include "ast.h"
#include "diagnostics.h"
#include "model.h"

#include <optional>
#include <string>

namespace gfec::validation {

/// Sets of types, for "which types may this declaration use".
enum TypeSet : unsigned {
  kBool = 1u << 0,
  kInt = 1u << 1,
  kFloat = 1u << 2,
  kDouble = 1u << 3,
  kVoid = 1u << 4,
  kString = 1u << 5,
  kObject = 1u << 6,
  kTime = 1u << 7,
  kSized = 1u << 8,  ///< int8 int16 int64 uint8 uint16 uint32 uint64
  kScalar = kBool | kInt | kFloat | kDouble,
  /// What a chart's variable or constant may be.
  kValue = kScalar | kTime | kSized,
};

/// The type `t` names, if it is in `allowed`; otherwise reports `unknown-type` (with a
/// did-you-mean) or `bad-type` ("type 'void' is not allowed for a parameter"). `use` names the
/// declaration for that message: "a parameter", "a variable", ...
std::optional<model::Type> lower_type(const ast::TypeName &t, unsigned allowed, const char *use, Diagnostics &diag);

/// C's usual arithmetic conversions over int, float and double.
model::Type promote(model::Type a, model::Type b);

/// The result of `op` on operands of these types, or nothing when C (restricted by §4: bool
/// does not mix with numbers; durations are only compared) would not accept it.
std::optional<model::Type> unary_type(UnaryOp op, model::Type operand);
std::optional<model::Type> binary_type(BinaryOp op, model::Type a, model::Type b);

/// The operator of a Unary or Binary `e` as its messages quote it: what the user wrote (the
/// source text of its range) in a file that is not chart text, whose language may spell `&&`
/// as `AND`; C's spelling otherwise, which is what chart text writes (operators.h).
std::string written_operator(const ast::Expr &e, const SourceManager &sources);

/// Whether a value of type `from` may be stored in (or passed as) `to`: numbers convert as in
/// C, bool only to bool, strings only to strings.
bool assignable(model::Type to, model::Type from);

}  // namespace gfec::validation
