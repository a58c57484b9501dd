// A C type name as the C engine's instance context takes it (--context-type, docs/c-engine.md
// "Instance context"): the driver checks the user's spelling with it and the C back end reads its
// words, so both split the same text the same way.
#pragma once

#include <string>
#include <vector>

namespace gfec::naming {

/// Only the words and `*` of a C type name (a typedef from <stdint.h>, `void *`,
/// `struct motor *`, `const struct bus *`), never code: the name is written into engine.h as it
/// stands.
struct CTypeName {
  std::string spelling;            ///< normalised: `struct  motor*` -> `struct motor *`
  std::vector<std::string> words;  ///< its identifiers and keywords, in order
};

/// Reads `text` into `out`; returns why it is not such a type name (`out` is then left as it
/// was), or "".
std::string read_c_type_name(const std::string &text, CTypeName &out);

}  // namespace gfec::naming
