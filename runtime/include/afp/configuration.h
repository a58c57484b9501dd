// The configuration: the plan's pool of named, typed entries, shared by the
// plan, its sub-plans and the application (which may read and write it by
// name while the plan runs), plus the shadow copy that holds outputs until the
// component that ends an actor is known.
#pragma once

#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "afp/value.h"

namespace afp {

/// An entry is unknown, or is declared twice with different types.
class ConfigError : public Error {
 public:
  using Error::Error;
};

/// Pending writes of one component (an actor or one supervisor check): the
/// "shadow copy" of docs/runtime.md, kept as the entries written rather than a full copy.
/// Values are already converted to their entries' types.
class Shadow {
 public:
  /// Records a write; a later write to the same entry replaces it.
  void write(std::string_view entry, Value value);

  /// The writes, in the order the entries were first written.
  const std::vector<std::pair<std::string, Value>>& writes() const { return writes_; }

  /// Forgets every write (the component did not end the actor).
  void clear() { writes_.clear(); }

 private:
  std::vector<std::pair<std::string, Value>> writes_;
};

/// The entries by name. Every member is thread-safe: the application may read
/// and write entries from any thread while a plan runs.
class Configuration {
 public:
  Configuration() = default;
  Configuration(const Configuration&) = delete;
  Configuration& operator=(const Configuration&) = delete;

  /// Declares an entry holding the type's default value. If the entry exists
  /// with the same type it keeps its value; with another type: ConfigError.
  void declare(const std::string& name, Type type);

  /// Declares an entry with an initial value (whose type is the entry's type);
  /// an existing entry of that type keeps its value (the application may have
  /// set it before the plan starts); with another type: ConfigError.
  void declare(const std::string& name, const Value& initial);

  /// True if the entry is declared.
  bool contains(std::string_view name) const;

  /// The entry's declared type; ConfigError if unknown.
  Type type_of(std::string_view name) const;

  /// The entry's value; ConfigError if unknown.
  Value value(std::string_view name) const;

  /// The entry's value converted to T; ConfigError or ConversionError.
  template <class T>
  T get(std::string_view name) const {
    return convert<T>(value(name));
  }

  /// Sets the entry, converting the value to the entry's type; ConfigError if
  /// unknown, ConversionError if the value does not convert (entry unchanged).
  void set(std::string_view name, const Value& value);

  /// Applies a shadow's writes at once (no reader sees half of them).
  void commit(const Shadow& shadow);

  /// The declared names, sorted.
  std::vector<std::string> names() const;

 private:
  mutable std::mutex mutex_;
  std::map<std::string, Value, std::less<>> entries_;
};

/// Read access to the configuration, as formulas and In parameters see it.
class ConfigView {
 public:
  /// Views a configuration (which must outlive the view).
  explicit ConfigView(const Configuration& config) : config_(&config) {}

  /// The entry's value; ConfigError if unknown.
  Value value(std::string_view name) const { return config_->value(name); }

  /// The entry's value converted to T (e.g. get<float>("walldist")).
  template <class T>
  T get(std::string_view name) const {
    return config_->get<T>(name);
  }

 private:
  const Configuration* config_;
};

}  // namespace afp
