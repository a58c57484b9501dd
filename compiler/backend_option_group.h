// A back end's own command-line options, as a group its registry row declares: the driver's
// parser names none of them, and the back end alone reads what they give (EmitOptions::backend).
#pragma once

#include "backend.h"
#include "diagnostics.h"
#include "model.h"
#include "pipeline/compilation.h"

#include <memory>
#include <string>

namespace CLI {
class App;
}

namespace gfec {

class BackendOptionGroup {
public:
  virtual ~BackendOptionGroup() = default;
  /// Declares the options on the compiler's command line; the values land in the group.
  virtual void add_to(CLI::App &app) = 0;
  /// After the parse: reads the values; "" or the usage error.
  virtual std::string check() = 0;
  /// The option to name when one was given but another back end was chosen ("--context"), or
  /// "" when none was given.
  virtual std::string given() const = 0;
  /// Whose options they are, for that message: "the C engine".
  virtual const char *owner() const = 0;
  /// Warnings the options add about what was selected (the C engine's --context:
  /// -Wlibrary-function), once it is known.
  virtual void check_selection(const model::Model &, const pipeline::Selection &, Diagnostics &) const {}
  /// What the back end reads: EmitOptions::backend.
  virtual std::shared_ptr<const BackendOptions> options() const = 0;
};

}  // namespace gfec
