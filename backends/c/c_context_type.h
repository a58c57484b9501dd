// The instance context's C type as the engine uses it (--context-type, docs/c-engine.md
// "Instance context"): read once, by the reader the driver checks the option with
// (compiler/naming/c_type_name.h), rather than split into words wherever it is needed.
#pragma once

#include <string>
#include <vector>

namespace gfec::c_backend {

struct ContextType {
  /// `spelling` as --context-type gave it; empty: no context. Throws std::invalid_argument for
  /// a name the driver would have refused.
  explicit ContextType(const std::string &spelling);

  std::string spelling;            ///< `struct motor *`; empty: the engine has no context
  std::vector<std::string> words;  ///< its identifiers (`struct`, `motor`): no field may take one
  std::string tag_keyword;         ///< `struct` or `union` when it names a tag, else empty
  std::string tag;                 ///< the tag (`motor`), declared before the prototypes use it

  /// The context as a parameter called `name`: `struct motor *name`, `bus_t name`.
  std::string param(const std::string &name) const;
};

}  // namespace gfec::c_backend
