// Parameters of actors and supervisors. An In parameter is a formula over the
// configuration (compiled to C++ by the code generator) whose result is
// converted to the parameter's type; an Out parameter names the entry it
// writes, through the component's shadow copy.
//
//   std::make_unique<Forward>(ee, afp::in<float>([](const afp::ConfigView& c) {
//     return c.get<float>("walldist") - 5; }))
//   std::make_unique<SearchWall>(ee, afp::out<float>("wallangle"))
#pragma once

#include <functional>
#include <string>
#include <type_traits>
#include <utility>

#include "afp/configuration.h"
#include "afp/context.h"
#include "afp/value.h"

namespace afp {

/// A formula: computes a value from the configuration.
using Formula = std::function<Value(const ConfigView&)>;

/// The formula that reads one entry as it is (no arithmetic).
Formula entry(std::string name);

/// An input parameter of type T: a formula plus the conversion to T.
template <class T>
class In {
  static_assert(is_value_type_v<T>, "afp values are int, float, double, bool, std::string or afp::Object");

 public:
  /// An input computed by a formula.
  explicit In(Formula formula) : formula_(std::move(formula)) {}

  /// The input's value now; read it in start() ("inputs are read when the
  /// actor starts"). Throws ConfigError or ConversionError (the actor then
  /// ends in error).
  T read(const Context& ctx) const { return evaluate(ctx.config()); }

  /// The input's value over a configuration view.
  T evaluate(const ConfigView& config) const { return convert<T>(formula_(config)); }

 private:
  Formula formula_;
};

/// Makes an In<T> from a formula (anything callable with a ConfigView that
/// returns something a Value is made of) or from a constant:
/// `in<float>(100000)`, `in<float>(entry("wallangle"))`, `in<float>([](auto& c) {...})`.
template <class T, class F>
In<T> in(F&& source) {
  if constexpr (std::is_invocable_v<F&, const ConfigView&>) {
    return In<T>(Formula(std::forward<F>(source)));
  } else {
    return In<T>(Formula([constant = Value(std::forward<F>(source))](const ConfigView&) { return constant; }));
  }
}

/// An output parameter of type T, bound to a configuration entry (never a formula).
template <class T>
class Out {
  static_assert(is_value_type_v<T>, "afp values are int, float, double, bool, std::string or afp::Object");

 public:
  /// An output written to the named entry.
  explicit Out(std::string entry) : entry_(std::move(entry)) {}

  /// The entry written.
  const std::string& entry() const { return entry_; }

  /// Writes to the component's shadow copy; committed only if this component
  /// ends the actor (the actor finishes, or the supervisor interrupts it).
  void write(Context& ctx, T value) const { ctx.write(entry_, Value(std::move(value))); }

 private:
  std::string entry_;
};

/// Makes an Out<T> bound to the named entry: `out<float>("wallangle")`.
template <class T>
Out<T> out(std::string entry) {
  return Out<T>(std::move(entry));
}

}  // namespace afp
