// What each name in the source refers to, as the validator resolved it: every declaration and
// every use it looked up, with both ranges. A language server's definition, references, rename
// and hover read this instead of resolving names a second time (docs/editors.md). Recorded
// only when asked for (FrontEndOptions::record_name_uses): a compiler run pays nothing.
#pragma once

#include "source.h"

#include <vector>

namespace gfec {

namespace validation {

/// What a name denotes; one enum for every namespace so messages can describe any clash.
enum class Sym {
  Interface,
  Function,
  Param,
  Const,
  Chart,
  Place,
  State,
  Transition,
  Var,
  Toolbox,
  Template,
  TemplateParam,
  ResultState,
  Event,
  Plan,
  ConfigEntry,
  Actor,
  Supervisor,
  Block,
  Instance,
};

}  // namespace validation

struct NameUse {
  SourceRange at;    ///< the name as written here
  SourceRange decl;  ///< the name in its declaration (`at` itself for a declaration)
  validation::Sym kind;
  int index = -1;  ///< the element of the model table `kind` belongs to; -1: none (an interface, an error)
  bool declaration() const { return at.file == decl.file && at.begin == decl.begin; }
};

/// Every NameUse of one compilation, in the order the validator met them. A name in a `test`
/// block and its chart's scope rebuilt for it may be recorded twice; the readers look names up
/// by range, so a repeat changes no answer.
struct NameUses {
  std::vector<NameUse> list;

  /// The name written over byte `offset` of `file` (its end included: a cursor just after a
  /// name is on it), or null.
  const NameUse *at(FileId file, std::uint32_t offset) const {
    for (const NameUse &u : list)
      if (u.at.file == file && u.at.begin <= offset && offset <= u.at.end) return &u;
    return nullptr;
  }
  /// Every place the declaration `decl` is written, itself included, each once, in file and
  /// offset order.
  std::vector<SourceRange> of(const SourceRange &decl) const;
};

}  // namespace gfec
