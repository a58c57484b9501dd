#include "value.h"

#include "constant.h"

#include <fmt/format.h>

#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdio>

namespace gfec::interp {

namespace {

/// A floating value as an int, as C truncates it; beyond int's range C leaves it undefined.
Value to_int(double d, SourceRange where) {
  auto r = constant::convert(constant::Value::of_double(d), model::Type::Int);
  if (!r) throw RuntimeError(where, fmt::format("{} does not fit in an int (undefined behaviour in C)", d));
  return Value::of_int(static_cast<std::int32_t>(r.value.i));
}

/// A double as a float: a finite double beyond float's range does not convert (C11 6.3.1.5).
Value to_float(double d, SourceRange where) {
  auto r = constant::convert(constant::Value::of_double(d), model::Type::Float);
  if (!r) throw RuntimeError(where, fmt::format("{} does not fit in a float (undefined behaviour in C)", d));
  return Value::of_float(static_cast<float>(r.value.f));
}

}  // namespace

Value convert(const Value &v, model::Type to, SourceRange where) {
  if (v.type == to) return v;
  if (model::is_sized(to) || model::is_sized(v.type)) {
    // The sized integers: exact, and a value that does not fit its type stops the run
    // (docs/targets.md "Sized integers").
    auto r = constant::convert(v, to);
    if (r) return r.value;
    if (r.fault == constant::Fault::DoesNotFit)
      throw RuntimeError(where, fmt::format("{} does not fit in '{}'", constant::text(v), model::type_name(to)));
  }
  switch (to) {
  case model::Type::Int:
    if (v.type == model::Type::Float || v.type == model::Type::Double) return to_int(v.f, where);
    if (v.type == model::Type::Bool) return Value::of_int(v.b ? 1 : 0);
    break;
  case model::Type::Float:
    if (v.type == model::Type::Int) return Value::of_float(static_cast<float>(v.i));
    if (v.type == model::Type::Double) return to_float(v.f, where);
    if (v.type == model::Type::Bool) return Value::of_float(v.b ? 1.0f : 0.0f);
    break;
  case model::Type::Double:
    if (v.type == model::Type::Int) return Value::of_double(static_cast<double>(v.i));
    if (v.type == model::Type::Float) return Value::of_double(v.f);
    if (v.type == model::Type::Bool) return Value::of_double(v.b ? 1.0 : 0.0);
    break;
  case model::Type::Bool:
    // The validator keeps numbers out of bools; a stray one converts as C's _Bool would.
    if (v.type == model::Type::Int || v.type == model::Type::Duration) return Value::of_bool(v.i != 0);
    if (v.type == model::Type::Float || v.type == model::Type::Double) return Value::of_bool(v.f != 0);
    break;
  default: break;
  }
  throw RuntimeError(where, fmt::format("cannot convert a value of type '{}' to '{}'", model::type_name(v.type),
                                        model::type_name(to)));
}

std::string format_value(const Value &v) {
  char buffer[64];
  switch (v.type) {
  case model::Type::Bool: return v.b ? "true" : "false";
  case model::Type::Float: std::snprintf(buffer, sizeof buffer, "%.9g", v.f); return buffer;
  case model::Type::Double: std::snprintf(buffer, sizeof buffer, "%.17g", v.f); return buffer;
  case model::Type::Time: return "T#" + constant::decimal(v) + "ms";  // IEC's spelling (docs/iec.md)
  default: return constant::decimal(v);
  }
}

std::pair<std::string, std::string> c_printf_of(model::Type t, const std::string &expr) {
  switch (t) {
  case model::Type::Bool: return {"%s", fmt::format("{} ? \"true\" : \"false\"", expr)};
  case model::Type::Int: return {"%d", expr};
  case model::Type::Time: return {"T#%lldms", "(long long)" + expr};
  case model::Type::Int8:
  case model::Type::Int16:
  case model::Type::Int64: return {"%lld", "(long long)" + expr};
  case model::Type::UInt8:
  case model::Type::UInt16:
  case model::Type::UInt32:
  case model::Type::UInt64: return {"%llu", "(unsigned long long)" + expr};
  case model::Type::Float: return {"%.9g", "(double)" + expr};
  default: return {"%.17g", expr};
  }
}

}  // namespace gfec::interp
