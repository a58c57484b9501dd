// Values as the generated C sees them: bool, 32-bit int, float, double and durations (unsigned
// tick counts). Whatever C leaves undefined (int overflow, division by zero, a float that does
// not fit an int) is not given a meaning: it raises RuntimeError, so the interpreter never
// agrees with an engine by accident.
#pragma once

#include "constant.h"
#include "model.h"
#include "source.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

namespace gfec::interp {

/// The interpreter computes with the constant evaluator's values (compiler/constant.h).
using Value = constant::Value;

/// Behaviour C leaves undefined or unportable, at the expression that would cause it.
class RuntimeError : public std::runtime_error {
public:
  RuntimeError(SourceRange range, const std::string &message) : std::runtime_error(message), range(range) {}
  SourceRange range;
};

/// `v` converted to `to` as C converts on assignment and argument passing. A number that does
/// not fit (a float into an int, a double beyond float's range) raises RuntimeError at `where`.
Value convert(const Value &v, model::Type to, SourceRange where);

/// The value as the log prints it: `true`/`false`, `42`, floats with 9 and doubles with 17
/// significant digits (printf's `%.9g` / `%.17g`, so that an engine prints the same).
std::string format_value(const Value &v);

/// The printf format and argument with which generated C (a test harness) prints `expr`, a value
/// of type `t`, exactly as format_value prints it; the C type itself is model::type_name(t).
std::pair<std::string, std::string> c_printf_of(model::Type t, const std::string &expr);

}  // namespace gfec::interp
