// Plan argument formulas (docs/language.md §8) as C++: an `in` argument becomes an afp::In<T> made
// from a constant, an entry, or a lambda over afp::ConfigView that computes the formula as C
// would (int arithmetic stays int); an `out` argument becomes an afp::Out<T> naming its entry.
// Nothing is parsed at run time: the runtime only converts the result to the parameter's type.
#pragma once

#include "model.h"

#include <string>

namespace gfec::cpp_backend {

/// The functions the generated file defines for its formulas, when some formula needs them.
/// Named before the formulas are converted, apart from the file's classes (a template `text`).
struct FormulaHelpers {
  std::string text_fn = "text";      ///< a number as text (the runtime's format)
  std::string divide_fn = "divide";  ///< int / int; throws on division by zero
  bool text = false;                 ///< some formula joins a computed number to a string
  bool divide = false;               ///< some formula divides an int by an int
};

/// `afp::in<float>(afp::entry("walldist"))`, `afp::in<float>(-60)`, or
/// `afp::in<float>([](const afp::ConfigView& c) { return c.get<float>("walldist") - 5; })`:
/// the argument for an `in` parameter of type `param` of a template used in `plan`. Records in
/// `helpers` what the text needs.
std::string in_argument(const model::Plan &plan, const model::Expr &formula, model::Type param,
                        FormulaHelpers &helpers);

/// `afp::out<float>("wallangle")`: the argument for an `out` parameter of type `param`, bound
/// to a config entry of `plan` (an Expr of Kind::Config).
std::string out_argument(const model::Plan &plan, const model::Expr &entry, model::Type param);

/// `afp::Value(30.0f)`: a config entry's folded initial value as a value of the entry's type
/// (the runtime takes the entry's type from it).
std::string initial_value(const model::Expr &literal, model::Type type);

}  // namespace gfec::cpp_backend
