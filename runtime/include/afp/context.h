// What an actor or a supervisor sees of the run it takes part in.
#pragma once

#include <chrono>
#include <string_view>

#include "afp/configuration.h"

namespace afp {

/// Plan time: simulated time in the stepped executor, time since the start of
/// the run in the threaded one. Chrono literals convert: `10ms`.
using Duration = std::chrono::nanoseconds;

namespace detail {
class Services;
}

/// Handed by the executor to start(), step() and check(): reads the
/// configuration, writes outputs to the component's shadow copy, tells the time.
/// Only the runtime makes contexts.
class Context {
 public:
  /// The live configuration (In parameters read it).
  ConfigView config() const;

  /// The current plan time.
  Duration now() const;

  /// Writes an output to this component's shadow copy, converted to the
  /// entry's type (Out parameters use it). Throws ConfigError or
  /// ConversionError, which makes the component end in error.
  void write(std::string_view entry, const Value& value);

  /// For the runtime only: a context over its services and a shadow.
  Context(detail::Services& services, Shadow& shadow) : services_(&services), shadow_(&shadow) {}

  /// For the runtime only (sub-plans run on their parent's services).
  detail::Services& services() const { return *services_; }

 private:
  detail::Services* services_;
  Shadow* shadow_;
};

}  // namespace afp
