#include "c_context_type.h"

#include "naming/c_type_name.h"

#include <stdexcept>
#include <utility>

namespace gfec::c_backend {

ContextType::ContextType(const std::string &s) {
  if (s.empty()) return;  // no context
  naming::CTypeName type;
  if (std::string why = naming::read_c_type_name(s, type); !why.empty())
    throw std::invalid_argument("context type '" + s + "': " + why + " (the driver checks --context-type)");
  spelling = std::move(type.spelling);
  words = std::move(type.words);
  // `const struct motor *`, `struct motor const *`: the word after the keyword is the tag; a
  // bare `struct *` names none.
  for (std::size_t i = 0; i + 1 < words.size(); ++i)
    if (words[i] == "struct" || words[i] == "union") {
      tag_keyword = words[i];
      tag = words[i + 1];
      break;
    }
}

std::string ContextType::param(const std::string &name) const {
  return !spelling.empty() && spelling.back() == '*' ? spelling + name : spelling + " " + name;
}

}  // namespace gfec::c_backend
